/**
 * @file DeformationProblem.h
 * @brief What every deformation method reads: the mesh's nodes and their prescribed boundary
 * motion, and the one check of it.
 */
#ifndef dgmf_DeformationProblem_h
#define dgmf_DeformationProblem_h

#include "dgmf/BoundaryMotion.h"
#include "dgmf/CellMesh.h"
#include "dgmf/NodeKind.h"
#include "dgmf/Progress.h"
#include "dgmf/RigidMotion.h"
#include "dgmf/SlipPlanes.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dgmf
{

/**
 * The nodes of a mesh and the motion of its boundary, in the caller's memory (3 coordinates per
 * node for points and displacements). A method reads only what it needs (MethodNeeds).
 */
struct DeformationProblem
{
  int Dimension = 3; ///< 2 (a plane z = constant) or 3
  /// The extrusion axis (0 x, 1 y, 2 z) when this is the 2D problem of a one-cell-thick mesh's
  /// layer (ReduceToLayer), for messages in the mesh's own axes; -1 otherwise.
  int LayerAxis = -1;
  std::size_t NumberOfNodes = 0;         ///< nodes of the mesh
  const double* Points = nullptr;        ///< original positions
  const NodeKind* Kinds = nullptr;       ///< interior, static or moving boundary
  const double* Displacement = nullptr;  ///< shape deformation d (or total motion), or null
  const std::int32_t* BodyIds = nullptr; ///< per node: 0, or the moving body 1, 2, ...; or null
  std::int32_t NumberOfBodies = 0;       ///< the largest body id (0 without BodyIds)
  /// The rigid motion of body k at Motions[k - 1]: one per body, and at least one (the moving
  /// nodes without body ids are body 1). Ignored when ExtractRigidMotion.
  std::vector<RigidMotion> Motions = std::vector<RigidMotion>(1);
  /// The rigid motions are fitted to Displacement, then the total motion of the moving nodes.
  bool ExtractRigidMotion = false;
  /// The extracted motions are fitted to each body's distinct positions in increasing order
  /// (ExtractBodyMotions' distinctPositions): a distributed run's nodes, whose order and copies
  /// differ from process to process. Default: false (the nodes in their order).
  bool FitDistinctPositions = false;
  const CellMesh* Cells = nullptr;         ///< the cells (MethodNeeds::Cells), or null
  const double* BoundaryWeights = nullptr; ///< per node: boundary area or length (IDW), or null
  /// The slip (symmetry) boundaries: their SlipBoundary nodes stay in their planes.
  SlipConstraint Slip;
  /// Told how far a long method (sub-steps, the quality guard) is; may stop it (Aborted).
  dgmf::Progress Progress;

  /// True when each moving body is handled apart: body ids are given, or the motions extracted.
  bool UsesBodies() const { return this->NumberOfBodies > 0 || this->ExtractRigidMotion; }
};

/// The error for a problem without boundary nodes (ValidateProblem and DelaunayMapping).
constexpr const char* NoBoundaryNodeMessage =
  "No node is a boundary node (the marker is 0 everywhere, or no displacement is non-zero): mark "
  "the boundary nodes 1 (static), 2 (moving) or 3 (slip). Nothing was deformed.";

/// The error for point coordinates out of range (dgmf::FirstOutOfRange), `value` the index of
/// the first bad coordinate (3 per point).
std::string OutOfRangePointsMessage(std::size_t value);

/**
 * Checks one rigid motion of `problem`: finite and within +-720 degrees, about an axis of non-zero
 * length, and in the plane of a 2D mesh. Throws std::invalid_argument with the message for the
 * user, `which` first ("Body 2: "). ValidateProblem checks each body's motion with it; a series
 * checks the motion its laws reach at their largest.
 */
void ValidateMotion(
  const DeformationProblem& problem, const RigidMotion& motion, const std::string& which);

/**
 * Checks everything a method relies on and returns the warnings (e.g. no moving node). Throws
 * std::invalid_argument, with a message for the user, for: a dimension other than 2 or 3, no node,
 * missing points or kinds, a displacement that is not finite, or not in the plane of a 2D mesh,
 * too few rigid motions for the bodies, a rigid motion that is not finite, turns beyond
 * +-720 degrees, or leaves the plane of a 2D mesh, and slip nodes that are not SlipBoundary nodes
 * or have no plane. With `checkPoints`, also non-finite point
 * coordinates (the graph methods check them when the graph is built: DelaunayMapping). With
 * `displacementEverywhere` (a method that reads every node's displacement, DGMF1), a warning
 * counts the static nodes with a non-zero displacement, which never move; without, the nodes
 * other than the moving ones with a non-zero displacement, which the method ignores.
 */
std::vector<std::string> ValidateProblem(
  const DeformationProblem& problem, bool checkPoints, bool displacementEverywhere = false);

/**
 * The total motion of the boundary nodes, as the interpolation methods (DGM, DGRBF, RBF, IDW)
 * use it: each moving node's rigid motion (its body's) plus its displacement, or with extracted
 * motions the displacement itself; zero on static nodes.
 */
BoundaryMotion GatherTotalBoundaryMotion(const DeformationProblem& problem);

/**
 * Node kinds from boundary-marker values of any numeric type (0 interior, 1 static, 2 moving,
 * 3 slip).
 * Throws std::invalid_argument naming the first other value and its node; the message continues
 * a sentence that names the array ("The boundary-marker array 'X' has the value ..."). The values
 * may be a part of the nodes' that starts at node `firstNode` (for the message).
 */
template <typename Values>
void MarkerToNodeKinds(const Values& values, NodeKind* kinds, std::size_t firstNode = 0)
{
  std::size_t i = 0;
  for (const auto value : values)
  {
    const double v = static_cast<double>(value);
    if (v != 0.0 && v != 1.0 && v != 2.0 && v != 3.0)
    {
      ThrowBadMarkerValue(v, firstNode + i);
    }
    kinds[i++] = static_cast<NodeKind>(static_cast<int>(v));
  }
}

/**
 * Body ids from the values of a body-id array (one per node), applied to the node kinds: a node
 * with an id > 0 becomes a moving boundary node; a moving node with id 0 becomes static when
 * `markerGiven` is false (its kind came from a non-zero displacement). Returns the largest id.
 * Throws std::invalid_argument for an id that is negative, not a whole number or above 1e6, an id
 * on an interior node, or (with a marker) a node marked moving with id 0; the message continues
 * a sentence that names the array ("The body-id array 'X' has the value ...").
 */
std::int32_t ResolveBodyIds(const double* values, std::size_t numberOfNodes, bool markerGiven,
  NodeKind* kinds, std::int32_t* bodyIds);

} // namespace dgmf

#endif
