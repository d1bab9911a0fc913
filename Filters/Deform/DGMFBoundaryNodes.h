/**
 * @file DGMFBoundaryNodes.h
 * @brief The nodes on a mesh's boundary facets (DGMFBoundaryDetection) and the boundary area
 * (length) each represents (private to the DGMF::Filters module).
 */
#ifndef DGMFBoundaryNodes_h
#define DGMFBoundaryNodes_h

#include "DGMFBoundaryDetection.h"

#include "vtkType.h"

#include <cstdint>
#include <vector>

namespace dgmf_vtk
{

/// One flag per point: 1 for the nodes of the boundary facets (and their coincident copies).
std::vector<std::uint8_t> FlagBoundaryNodes(const BoundaryFacets& facets, vtkIdType numberOfPoints);

/**
 * One value per point: the boundary area (3D) or length (2D) a node represents, each facet's
 * measure shared equally among its nodes; 0 for nodes on no facet. `points` holds 3 doubles per
 * point.
 */
std::vector<double> ComputeBoundaryNodeWeights(
  const BoundaryFacets& facets, const double* points, vtkIdType numberOfPoints, int dimension);

} // namespace dgmf_vtk

#endif
