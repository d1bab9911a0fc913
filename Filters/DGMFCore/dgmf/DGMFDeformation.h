/**
 * @file DGMFDeformation.h
 * @brief Steps 6-7 of DGMF (Documentation/architecture.md): the new position of every node with
 * one moving body (paper Eqs. 3-7).
 */
#ifndef dgmf_DGMFDeformation_h
#define dgmf_DGMFDeformation_h

#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/RigidMotion.h"

#include <vector>

namespace dgmf
{

/// Where the shape deformation d of an interior node comes from.
enum class DeformationMode : int
{
  DGMF1 =
    1, ///< d is given at every node (a known function of position, e.g. the twisted bar's bump)
  DGMF2 = 2 ///< d is given at the moving boundary nodes and interpolated by paper Eq. 7 (default)
};

/**
 * The shape deformation of the graph vertices: the displacement of each moving vertex's node,
 * zero at static vertices (3 doubles per vertex). `displacement` (3 per node) may be null.
 */
std::vector<double> GatherVertexDeformation(
  const DelaunayMapping& mapping, const double* displacement);

/**
 * Paper Eq. 7 at a node of a graph element: d = sum w_k d_k / sum w_k over the element's
 * vertices v_k with `isSource(v_k)` (the moving vertices, or one body's), d_k their deformation
 * (3 per vertex in `vertexDeformation`); 0 when there is none (or their weights are all 0).
 * Continuous across shared faces: on a face the weight of the opposite vertex is 0, so both
 * elements give the same d. One body and each of several bodies use this same arithmetic.
 */
template <typename IsSource>
inline void InterpolateSourceDeformation(const std::int32_t* vertices, const double* w, int n,
  const double* vertexDeformation, const IsSource& isSource, double d[3])
{
  double sum[3] = { 0.0, 0.0, 0.0 };
  double weight = 0.0;
  for (int k = 0; k < n; ++k)
  {
    if (isSource(vertices[k]))
    {
      const double* dk = vertexDeformation + 3 * static_cast<std::size_t>(vertices[k]);
      sum[0] += w[k] * dk[0];
      sum[1] += w[k] * dk[1];
      sum[2] += w[k] * dk[2];
      weight += w[k];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    d[c] = weight > 0.0 ? sum[c] / weight : 0.0;
  }
}

/// InterpolateSourceDeformation over the moving vertices of `element`.
void InterpolateMovingDeformation(const DelaunayMapping& mapping, const double* vertexDeformation,
  std::int32_t element, const double* weights, double d[3]);

/**
 * Moves every node (paper Eqs. 3-6): x' = c + R(f angles)(x - c) + f t + f d, with f the damping
 * factor of the node (ComputeDampingFactor), d its shape deformation (DGMF1: its own displacement;
 * DGMF2: Eq. 7). Moving boundary nodes get their exact prescribed motion (f = 1, own
 * displacement); static boundary nodes do not move. `displacement` (3 per node) may be null
 * (no shape deformation). `deformed` receives 3 coordinates per node and may not alias `points`.
 */
void DeformDGMF(const DelaunayMapping& mapping, const double* f, const RigidMotion& motion,
  const double* displacement, DeformationMode mode, const double* points, double* deformed,
  const ParallelFor& parallelFor);

} // namespace dgmf

#endif
