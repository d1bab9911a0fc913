/**
 * @file DampingField.h
 * @brief Steps 4-5 of DGMF (Documentation/architecture.md): the interpolated boundary value r and
 * the damping factor f of every node.
 */
#ifndef dgmf_DampingField_h
#define dgmf_DampingField_h

#include "dgmf/DampingFunction.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"

#include <algorithm>
#include <cstdint>

namespace dgmf
{

/// Throws std::invalid_argument unless r0s is a finite number >= 1.
void CheckStaticR0(double staticR0);

/**
 * Paper Eq. 1 at a node of a graph element: r = sum_k w_k r0(v_k) over the element's `n`
 * vertices with barycentric coordinates `w`, at most r0s (round-off must not leave [0, r0s]).
 * `r0(v)` is the value of vertex v: 0 on the vertices the motion comes from, r0s elsewhere. One
 * body and each of several bodies (MultiBodyDeformation) use this same arithmetic.
 */
template <typename VertexR0>
inline double InterpolateR(
  const std::int32_t* vertices, const double* w, int n, double staticR0, const VertexR0& r0)
{
  double sum = 0.0;
  for (int k = 0; k < n; ++k)
  {
    sum += w[k] * r0(vertices[k]);
  }
  return std::min(sum, staticR0);
}

/**
 * r = sum_i e_i r0_i over the vertices of each node's Delaunay element (paper Eq. 1), with
 * r0 = 0 at moving and r0 = staticR0 (r0s >= 1) at static boundary vertices; so r = 0 on the
 * moving boundary and r = r0s on the static boundary. Writes one value per node into `r`.
 * Throws std::invalid_argument if staticR0 < 1 or is not finite.
 */
void ComputeBoundaryDistanceField(
  const DelaunayMapping& mapping, double staticR0, double* r, const ParallelFor& parallelFor);

/**
 * f = u(r) for r <= 1, 0 beyond (paper Eq. 2), written into `f` (one value per node).
 * Boundary nodes get exactly f = 1 (moving) and f = 0 (static).
 */
void ComputeDampingFactor(const DelaunayMapping& mapping, DampingFunction u, const double* r,
  double* f, const ParallelFor& parallelFor);

/**
 * ComputeBoundaryDistanceField and ComputeDampingFactor in one pass over the nodes (the same
 * values, bit for bit): each node's f from its r while both are at hand, instead of a second
 * pass that reads r and the kinds again (what a first deformation needs).
 */
void ComputeDampingField(const DelaunayMapping& mapping, double staticR0, DampingFunction u,
  double* r, double* f, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
