/**
 * @file DGMFFacetCounting.h
 * @brief The boundary facets of a mesh of any cell type by counting how many cells use each of
 * VTK's own faces or edges (mid-edge nodes of higher-order cells included): the path for the
 * cells the face matching does not read (private to the DGMF::Filters module).
 */
#ifndef DGMFFacetCounting_h
#define DGMFFacetCounting_h

#include "DGMFBoundaryDetection.h"

#include "vtkDataSetAttributes.h"
#include "vtkType.h"
#include "vtkUnsignedCharArray.h"

class vtkUnstructuredGrid;

namespace dgmf_vtk
{
/// Appends the facet of `count` points `ids` to `facets`.
inline void AddFacet(BoundaryFacets& facets, const vtkIdType* ids, vtkIdType count)
{
  facets.Ids.insert(facets.Ids.end(), ids, ids + count);
  facets.Offsets.push_back(static_cast<vtkIdType>(facets.Ids.size()));
}

/// Whether `cell` is a ghost cell (vtkGhostType DUPLICATECELL) of a mesh with `ghosts` (or none).
inline bool IsGhostCell(vtkUnsignedCharArray* ghosts, vtkIdType cell)
{
  return ghosts && (ghosts->GetValue(cell) & vtkDataSetAttributes::DUPLICATECELL) != 0;
}

/**
 * Appends the edges of `mesh`'s 2D cells that one cell uses (keyed by their end nodes), each
 * with VTK's edge points (end nodes, then mid-edge nodes), in the order of the cells and of their
 * edges. Ghost cells count as cells; their own boundary edges are left out.
 */
void FindBoundaryEdgesByCounting(vtkUnstructuredGrid* mesh, BoundaryFacets& facets);

/**
 * Appends the faces of `mesh`'s 3D cells that one cell uses (keyed by their corner nodes), each
 * with VTK's face points (corners, then mid-edge and mid-face nodes), and every 2D cell of the
 * grid, in the order of the cells and of their faces. Ghost cells count as cells; their own
 * boundary faces are left out. (vtkGeometryFilter of VTK 9.2 gives wrong original point ids for
 * quadratic cells: interior nodes were taken for boundary nodes until 2026-11-30.)
 */
void FindBoundaryFacesByCounting(vtkUnstructuredGrid* mesh, BoundaryFacets& facets);
} // namespace dgmf_vtk

#endif
