/**
 * @file DampingField.h
 * @brief Steps 3-4 of DGMF: the interpolated boundary value r and the damping factor f of every
 * node.
 */
#ifndef dgmf_DampingField_h
#define dgmf_DampingField_h

#include "dgmf/DampingFunction.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"

namespace dgmf
{

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

} // namespace dgmf

#endif
