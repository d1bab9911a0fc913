/**
 * @file DGMFBoundaryDetection.h
 * @brief The boundary of a mesh: its boundary faces (3D) or edges (2D), and whether a composite
 * input's patches close it (private to the DGMF::Filters module). The nodes on them:
 * DGMFBoundaryNodes.h.
 */
#ifndef DGMFBoundaryDetection_h
#define DGMFBoundaryDetection_h

#include "vtkType.h"

#include <cstdint>
#include <vector>

class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// The boundary facets of a mesh, as lists of input point ids.
struct BoundaryFacets
{
  std::vector<vtkIdType> Offsets{ 0 }; ///< facet f uses Ids[Offsets[f] .. Offsets[f+1])
  std::vector<vtkIdType> Ids;
  /// For meshes with coincident points: the first point at the position of each point (the
  /// facets use these). Empty when every point has its own position.
  std::vector<vtkIdType> Canonical;

  std::size_t Size() const { return this->Offsets.size() - 1; }
};

/**
 * The boundary of a mesh.
 * - 3D meshes: the faces used by one 3D cell, plus any 2D cell of the grid (typically boundary
 *   patches), sorted by their point ids. The faces come from the core's face matching
 *   (dgmf::FindBoundaryFaces, on the vtkSMPTools threads) for linear cells and polyhedra, by
 *   counting each of VTK's cell faces (DGMFFacetCounting.h) when the grid has other 3D cells
 *   (quadratic, Lagrange: their faces carry mid-edge nodes) or 2D cells other than polygons. The
 * same facets in the same order whatever the number of threads.
 * - 2D meshes: the edges used by one 2D cell only, in the order of their cells and of VTK's
 *   edges (end nodes first, then mid-edge nodes of higher-order cells): by the face matching for
 *   polygons, by counting each edge's cells in a hash map when there are quadratic cells.
 * Coincident nodes with different ids are the same node here (a partition interface or a ghost
 * layer duplicates them): a face between two cells that share only coincident copies is inside.
 * The faces of ghost cells (the outer side of a ghost layer) are not the boundary.
 * `distinctPoints`: the caller knows that no two points coincide (a merged composite input), so
 * they are not looked for (one hash lookup per point saved).
 */
BoundaryFacets FindBoundaryFacets(
  vtkUnstructuredGrid* mesh, int dimension, bool distinctPoints = false);

/**
 * FindBoundaryFacets of `mesh` with the polygons of `patches` (a composite input's boundary
 * patches, kept apart on the same points: CompositeMesh::GetPatches) as 2D cells of it: the
 * same facets as for one grid with both grids' cells. `patches` may be null.
 */
BoundaryFacets FindBoundaryFacets(
  vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches, int dimension, bool distinctPoints);

/**
 * The boundary of a mesh as FindBoundaryFacets gives it, always by VTK's own means: 3D faces from
 * vtkGeometryFilter, 2D edges by counting each edge's cells in a hash map (the paths for cells the
 * face matching does not read, and the reference the tests compare it with).
 */
BoundaryFacets FindBoundaryFacetsByGeometryFilter(
  vtkUnstructuredGrid* mesh, int dimension = 3, bool distinctPoints = false);

/**
 * Whether the 2D cells of a 3D mesh close it: every face of its 3D cells that no other 3D cell
 * has is one of its polygons (triangles, quads, pixels, polygons), and every polygon is such a
 * face (dgmf::FacesPairUp: one pass over the cells, no memory, decided by a 64-bit hash). The
 * boundary's nodes are then the polygons' nodes: a composite input whose boundary patches cover
 * the volume's boundary needs no search for it. False for meshes without polygons, with ghost
 * cells, or with cells the face matching does not read (quadratic and Lagrange cells, 2D cells
 * other than polygons).
 */
bool PolygonsCloseTheMesh(vtkUnstructuredGrid* mesh);

/// PolygonsCloseTheMesh of `mesh` with the polygons of `patches` (on the same points; may be
/// null) as 2D cells of it.
bool PolygonsCloseTheMesh(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches);

} // namespace dgmf_vtk

#endif
