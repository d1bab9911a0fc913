#include "DGMFFacetCounting.h"

#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dgmf_vtk
{
namespace
{
struct PairHash
{
  std::size_t operator()(const std::pair<vtkIdType, vtkIdType>& p) const
  {
    return std::hash<vtkIdType>()(p.first) * 1000003u ^ std::hash<vtkIdType>()(p.second);
  }
};

/// The number of corner nodes of a cell's face (the first of its points): 3 or 4 for the faces
/// of higher-order cells, every point for a linear face (a polyhedron's polygon too).
vtkIdType CornersOf(vtkCell* face)
{
  if (face->IsLinear())
  {
    return face->GetNumberOfPoints();
  }
  switch (face->GetCellType())
  {
    case VTK_QUADRATIC_TRIANGLE:
    case VTK_BIQUADRATIC_TRIANGLE:
    case VTK_LAGRANGE_TRIANGLE:
    case VTK_BEZIER_TRIANGLE:
    case VTK_HIGHER_ORDER_TRIANGLE:
      return 3;
    default:
      return std::min<vtkIdType>(4, face->GetNumberOfPoints());
  }
}
} // namespace

void FindBoundaryEdgesByCounting(vtkUnstructuredGrid* mesh, BoundaryFacets& facets)
{
  // Count how many 2D cells use each edge (keyed by its end nodes); edges used once are on the
  // boundary.
  using EdgeKey = std::pair<vtkIdType, vtkIdType>;
  std::unordered_map<EdgeKey, int, PairHash> uses;
  uses.reserve(static_cast<std::size_t>(2 * mesh->GetNumberOfCells()));
  vtkNew<vtkGenericCell> cell;
  std::vector<vtkIdType> ids;
  // Ghost cells count as cells (their edges with real cells are inside), but their own boundary
  // edges (the outer side of the ghost layer) are not the mesh's boundary.
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  for (int pass = 0; pass < 2; ++pass)
  {
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      mesh->GetCell(c, cell);
      if (cell->GetCellDimension() != 2)
      {
        continue;
      }
      if (pass == 1 && IsGhostCell(ghosts, c))
      {
        continue;
      }
      for (int e = 0; e < cell->GetNumberOfEdges(); ++e)
      {
        vtkIdList* edge = cell->GetEdge(e)->GetPointIds();
        const vtkIdType a = edge->GetId(0);
        const vtkIdType b = edge->GetId(1);
        const EdgeKey key(std::min(a, b), std::max(a, b));
        if (pass == 0)
        {
          ++uses[key];
        }
        else if (uses[key] == 1)
        {
          ids.assign(edge->GetPointer(0), edge->GetPointer(0) + edge->GetNumberOfIds());
          AddFacet(facets, ids.data(), edge->GetNumberOfIds());
        }
      }
    }
  }
}

void FindBoundaryFacesByCounting(vtkUnstructuredGrid* mesh, BoundaryFacets& facets)
{
  // Count how many 3D cells use each face (keyed by its sorted corner nodes); faces used once are
  // on the boundary. Only for the meshes the face matching does not read: a map is enough.
  std::map<std::vector<vtkIdType>, int> uses;
  vtkNew<vtkGenericCell> cell;
  std::vector<vtkIdType> key, ids;
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  for (int pass = 0; pass < 2; ++pass)
  {
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      mesh->GetCell(c, cell);
      const int dimension = cell->GetCellDimension();
      if (pass == 1 && IsGhostCell(ghosts, c))
      {
        continue;
      }
      if (dimension == 2 && pass == 1) // a patch's face, as the face matching takes it
      {
        vtkIdList* points = cell->GetPointIds();
        AddFacet(facets, points->GetPointer(0), points->GetNumberOfIds());
      }
      if (dimension != 3)
      {
        continue;
      }
      for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
      {
        vtkCell* face = cell->GetFace(f);
        vtkIdList* points = face->GetPointIds();
        key.assign(points->GetPointer(0), points->GetPointer(0) + CornersOf(face));
        std::sort(key.begin(), key.end());
        if (pass == 0)
        {
          ++uses[key];
        }
        else if (uses[key] == 1)
        {
          ids.assign(points->GetPointer(0), points->GetPointer(0) + points->GetNumberOfIds());
          AddFacet(facets, ids.data(), points->GetNumberOfIds());
        }
      }
    }
  }
}
} // namespace dgmf_vtk
