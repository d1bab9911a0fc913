#include "DGMFFacetCounting.h"

#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
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

/// A face by its corner nodes: the smallest four, sorted, and how many it has (a polygon of
/// more corners is known by its four smallest: two faces of a conforming mesh sharing four
/// corners are one face).
struct FaceKey
{
  std::array<vtkIdType, 4> Corners;
  vtkIdType Count;
  bool operator==(const FaceKey& other) const
  {
    return this->Corners == other.Corners && this->Count == other.Count;
  }
};

struct FaceKeyHash
{
  std::size_t operator()(const FaceKey& key) const
  {
    std::uint64_t h = static_cast<std::uint64_t>(key.Count) * 0x9e3779b97f4a7c15ull;
    for (vtkIdType id : key.Corners)
    {
      h = (h ^ static_cast<std::uint64_t>(id)) * 0xff51afd7ed558ccdull;
      h ^= h >> 32;
    }
    return static_cast<std::size_t>(h);
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
  // on the boundary.
  std::unordered_map<FaceKey, int, FaceKeyHash> uses;
  uses.reserve(static_cast<std::size_t>(3 * mesh->GetNumberOfCells()));
  vtkNew<vtkGenericCell> cell;
  std::vector<vtkIdType> corners, ids;
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
        corners.assign(points->GetPointer(0), points->GetPointer(0) + CornersOf(face));
        std::sort(corners.begin(), corners.end());
        FaceKey key{ { -1, -1, -1, -1 }, static_cast<vtkIdType>(corners.size()) };
        std::copy_n(corners.begin(), std::min<std::size_t>(4, corners.size()), key.Corners.begin());
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
