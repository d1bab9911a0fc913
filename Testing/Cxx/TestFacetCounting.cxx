// The boundary of meshes of higher-order cells (DGMFFacetCounting.h, through FindBoundaryFacets):
// the faces of VTK's own cells counted, mid-edge nodes included; with coincident points and ghost
// cells as the face matching takes them (TestBoundaryDetection.cxx).
#include "DGMFBoundaryDetection.h"
#include "DGMFBoundaryNodes.h"
#include "DGMFSMPTools.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

TEST(BoundaryDetection, QuadraticCellsStillGetTheirMidEdgeNodesOnTheBoundary)
{
  // One quadratic hexahedron: the face matching does not read such cells, vtkGeometryFilter
  // does, and every one of its 20 nodes lies on its boundary.
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  const double corners[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  for (const auto& c : corners)
  {
    points->InsertNextPoint(c);
  }
  const int edges[12][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 },
    { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
  for (const auto& e : edges)
  {
    points->InsertNextPoint(0.5 * (corners[e[0]][0] + corners[e[1]][0]),
      0.5 * (corners[e[0]][1] + corners[e[1]][1]), 0.5 * (corners[e[0]][2] + corners[e[1]][2]));
  }
  mesh->SetPoints(points);
  std::vector<vtkIdType> ids(20);
  for (vtkIdType k = 0; k < 20; ++k)
  {
    ids[static_cast<std::size_t>(k)] = k;
  }
  mesh->InsertNextCell(VTK_QUADRATIC_HEXAHEDRON, 20, ids.data());
  dgmf_vtk::BoundaryFacets facets;
  dgmf_vtk::RunWithThreads(1, [&]() { facets = dgmf_vtk::FindBoundaryFacets(mesh, 3); });
  const auto flags = dgmf_vtk::FlagBoundaryNodes(facets, 20);
  EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), 20);
}

namespace
{
/**
 * 2 x 2 x 2 quadratic hexahedra in [0, 2]^3, their points by doubled coordinates in `ids`. With
 * `split`, the cells of x >= 1 have their own copies of the points of x = 1 (coincident points);
 * with `ghosts`, those cells are ghost cells (DUPLICATECELL).
 */
vtkSmartPointer<vtkUnstructuredGrid> QuadraticBox(
  bool split, bool ghosts, std::map<std::array<int, 4>, vtkIdType>& ids)
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> ghost;
  ghost->SetName(vtkDataSetAttributes::GhostArrayName());
  const auto point = [&](int x, int y, int z, int copy)
  {
    const auto found =
      ids.emplace(std::array<int, 4>{ x, y, z, copy }, points->GetNumberOfPoints());
    if (found.second)
    {
      points->InsertNextPoint(0.5 * x, 0.5 * y, 0.5 * z);
    }
    return found.first->second;
  };
  const int corner[8][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 0, 2, 0 }, { 0, 0, 2 },
    { 2, 0, 2 }, { 2, 2, 2 }, { 0, 2, 2 } };
  const int edges[12][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 },
    { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
      {
        const int copy = split && i == 1 ? 1 : 0;
        std::vector<vtkIdType> cell;
        for (const auto& c : corner)
        {
          cell.push_back(point(2 * i + c[0], 2 * j + c[1], 2 * k + c[2], copy));
        }
        for (const auto& e : edges)
        {
          cell.push_back(point(2 * i + (corner[e[0]][0] + corner[e[1]][0]) / 2,
            2 * j + (corner[e[0]][1] + corner[e[1]][1]) / 2,
            2 * k + (corner[e[0]][2] + corner[e[1]][2]) / 2, copy));
        }
        mesh->InsertNextCell(VTK_QUADRATIC_HEXAHEDRON, 20, cell.data());
        ghost->InsertNextValue(ghosts && i == 1 ? vtkDataSetAttributes::DUPLICATECELL : 0);
      }
  mesh->SetPoints(points);
  if (ghosts)
  {
    mesh->GetCellData()->AddArray(ghost);
  }
  return mesh;
}
} // namespace

TEST(BoundaryDetection, QuadraticCellsInsideAMeshAreNotOnTheBoundary)
{
  // 2 x 2 x 2 quadratic hexahedra in [0, 2]^3: the boundary nodes are exactly the nodes on the
  // box's surface (vtkGeometryFilter's original point ids, read until 2026-11-30, named interior
  // nodes and left 3 face nodes out). The same with the cells of x >= 1 on their own copies of
  // the points of x = 1 (the faces between the copies are inside), and with those cells ghost
  // cells (the interface is inside; the ghost cells' own outer faces are not the boundary).
  for (const auto& [split, ghosts] : { std::pair{ false, false }, std::pair{ true, false },
         std::pair{ false, true }, std::pair{ true, true } })
  {
    std::map<std::array<int, 4>, vtkIdType> ids;
    vtkSmartPointer<vtkUnstructuredGrid> mesh = QuadraticBox(split, ghosts, ids);
    dgmf_vtk::BoundaryFacets facets;
    dgmf_vtk::RunWithThreads(1, [&]() { facets = dgmf_vtk::FindBoundaryFacets(mesh, 3); });
    const auto flags = dgmf_vtk::FlagBoundaryNodes(facets, mesh->GetNumberOfPoints());
    for (const auto& [key, id] : ids)
    {
      const int x = key[0], y = key[1], z = key[2];
      const bool outer = x == 0 || x == 4 || y == 0 || y == 4 || z == 0 || z == 4;
      // With ghosts, only the faces of the cells of x <= 1 count.
      const bool expected = ghosts ? outer && x <= 2 : outer;
      // Facets use the first of coincident points: a copy's flag is its first point's.
      const auto canonical =
        facets.Canonical.empty() ? id : facets.Canonical[static_cast<std::size_t>(id)];
      EXPECT_EQ(flags[static_cast<std::size_t>(canonical)] != 0, expected)
        << "split " << split << " ghosts " << ghosts << ": node " << id << " at " << x << " " << y
        << " " << z << " copy " << key[3];
    }
  }
}
