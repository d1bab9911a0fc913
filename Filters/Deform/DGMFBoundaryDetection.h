/**
 * @file DGMFBoundaryDetection.h
 * @brief Finds the boundary nodes of a mesh when no boundary-marker array is given
 * (private to the DGMF::Filters module).
 */
#ifndef DGMFBoundaryDetection_h
#define DGMFBoundaryDetection_h

#include <cstdint>
#include <vector>

class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/**
 * One flag per point: 1 for the nodes of the mesh's boundary, 0 otherwise.
 * - 3D meshes: the nodes of the boundary faces of the 3D cells, from vtkGeometryFilter (faces used
 *   by one cell), plus the nodes of any 2D cell of the grid (typically boundary patches).
 * - 2D meshes: the nodes of the edges used by exactly one 2D cell.
 * Coincident nodes with different ids are kept apart (no point merging).
 */
std::vector<std::uint8_t> FindBoundaryNodes(vtkUnstructuredGrid* mesh, int dimension);

} // namespace dgmf_vtk

#endif
