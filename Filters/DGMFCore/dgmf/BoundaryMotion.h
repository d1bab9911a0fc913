/**
 * @file BoundaryMotion.h
 * @brief The total motion of the boundary nodes, as the interpolation methods (DGM, DGRBF, RBF,
 * IDW) see it: one displacement per boundary node, rigid part and shape deformation together.
 */
#ifndef dgmf_BoundaryMotion_h
#define dgmf_BoundaryMotion_h

#include "dgmf/NodeKind.h"
#include "dgmf/RigidMotion.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/// The boundary nodes of a mesh with their original positions and total displacements.
struct BoundaryMotion
{
  int Dimension = 3;                 ///< 2 (x, y used) or 3
  std::vector<std::int32_t> Nodes;   ///< mesh node id of each boundary node, increasing
  std::vector<double> Positions;     ///< 3 per boundary node: original coordinates
  std::vector<double> Displacements; ///< 3 per boundary node: prescribed position - original
  /// Per boundary node, the boundary length (2D) or area (3D) it represents (IDW weights A_i).
  /// Empty: every node counts as 1.
  std::vector<double> Weights;

  std::size_t Size() const { return this->Nodes.size(); }
};

/**
 * Collects the boundary nodes (kind != Interior) with their total motion: moving nodes
 * x' - x with x' = c + R(angles)(x - c) + t + d (d: their own displacement, may be null),
 * static nodes 0.
 */
BoundaryMotion GatherBoundaryMotion(int dimension, const double* points, std::size_t numberOfNodes,
  const NodeKind* kinds, const RigidMotion& motion, const double* displacement);

/**
 * Moves every boundary node of `deformed` to its own prescribed position: the original point plus
 * its total displacement (3 coordinates per mesh node in `points` and `deformed`).
 */
void ApplyBoundaryMotion(const BoundaryMotion& boundary, const double* points, double* deformed);

} // namespace dgmf

#endif
