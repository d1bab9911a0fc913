/**
 * @file DGMDeformation.h
 * @brief Delaunay graph mapping (Liu, Qin, Xia 2006): each node follows its graph element.
 */
#ifndef dgmf_DGMDeformation_h
#define dgmf_DGMDeformation_h

#include "dgmf/BoundaryMotion.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"

#include <vector>

namespace dgmf
{

/**
 * The total displacement of every graph vertex (3 per vertex): that of the node the vertex
 * carries (DelaunayMapping::GetVertexNode). `boundary` must list the same boundary nodes as the
 * mapping (both come from the same node kinds).
 */
std::vector<double> GatherVertexDisplacement(
  const DelaunayMapping& mapping, const BoundaryMotion& boundary);

/**
 * DGM: the graph's vertices move with the boundary and every interior node keeps its barycentric
 * coordinates: x' = x + sum_i e_i D_i. Boundary nodes get their own displacement. Returns the
 * number of graph elements inverted by the motion (DGM's failure mode: the result is still
 * produced).
 */
std::size_t DeformDGM(const DelaunayMapping& mapping, const BoundaryMotion& boundary,
  const double* points, double* deformed, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
