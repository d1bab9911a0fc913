// The adapter's boundary detection (DGMFBoundaryDetection): the faces of one 3D cell by the core's
// face matching against vtkGeometryFilter's, 2D edges against the hash-map count, the order and
// the areas the same with any number of threads, and whether its polygons close a mesh. Part of
// DGMFAdapterTests.
#include "DGMFBoundaryDetection.h"
#include "DGMFBoundaryNodes.h"
#include "DGMFSMPTools.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace
{
/// A box of n^3 cubes, each split into 6 tetrahedra about its diagonal, with every point moved by
/// up to a tenth of the spacing (a fixed pseudo-random jitter: boundary faces of many areas), the
/// cells in a fixed shuffled order.
vtkSmartPointer<vtkUnstructuredGrid> JitteredTetrahedra(int n)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::uint64_t state = 12345;
  const auto jitter = [&]()
  {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return 0.1 * (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
  };
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        points->InsertNextPoint(i + jitter(), j + jitter(), k + jitter());
      }
    }
  }
  grid->SetPoints(points);
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  const int paths[6][3] = { { 1, 2, 4 }, { 1, 4, 2 }, { 2, 1, 4 }, { 2, 4, 1 }, { 4, 1, 2 },
    { 4, 2, 1 } };
  std::vector<std::array<vtkIdType, 4>> cells;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        // Corner c of the cube: x + 1 if c & 1, y + 1 if c & 2, z + 1 if c & 4.
        const auto corner = [&](int c)
        { return static_cast<vtkIdType>(id(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))); };
        for (const auto& path : paths)
        {
          cells.push_back({ corner(0), corner(path[0]), corner(path[0] + path[1]), corner(7) });
        }
      }
    }
  }
  // In a shuffled order, as a mesh generator's cells are (not along the point numbering).
  for (std::size_t c = cells.size() - 1; c > 0; --c)
  {
    state = state * 6364136223846793005u + 1442695040888963407u;
    std::swap(cells[c], cells[(state >> 33) % (c + 1)]);
  }
  grid->Allocate(static_cast<vtkIdType>(cells.size()));
  for (const auto& tetra : cells)
  {
    grid->InsertNextCell(VTK_TETRA, 4, tetra.data());
  }
  return grid;
}
} // namespace

TEST(BoundaryDetection, FacesComeSortedByTheirPointIds)
{
  auto mesh = JitteredTetrahedra(12);
  dgmf_vtk::BoundaryFacets facets;
  dgmf_vtk::RunWithThreads(1, [&]() { facets = dgmf_vtk::FindBoundaryFacets(mesh, 3); });
  ASSERT_EQ(facets.Size(), static_cast<std::size_t>(6 * 2 * 12 * 12));
  const auto begin = [&](std::size_t f) { return facets.Ids.begin() + facets.Offsets[f]; };
  std::size_t unsorted = 0;
  for (std::size_t f = 1; f < facets.Size(); ++f)
  {
    unsorted +=
      std::lexicographical_compare(begin(f), begin(f + 1), begin(f - 1), begin(f)) ? 1 : 0;
  }
  EXPECT_EQ(unsorted, 0u);
}

TEST(BoundaryDetection, SameFacesAndAreasWithOneAndTwoThreads)
{
  // vtkGeometryFilter's threads emit the faces in an order that changes from run to run; IDW's
  // boundary areas summed in that order changed in the last bit (issue 17: the wing fold's IDW
  // output differed by one ulp at thousands of nodes from run to run with two threads).
  auto mesh = JitteredTetrahedra(30);
  const auto points = static_cast<vtkDoubleArray*>(mesh->GetPoints()->GetData());
  const auto run = [&](int threads, dgmf_vtk::BoundaryFacets& facets, std::vector<double>& areas)
  {
    dgmf_vtk::RunWithThreads(threads,
      [&]()
      {
        facets = dgmf_vtk::FindBoundaryFacets(mesh, 3);
        areas = dgmf_vtk::ComputeBoundaryNodeWeights(
          facets, points->GetPointer(0), mesh->GetNumberOfPoints(), 3);
      });
  };
  dgmf_vtk::BoundaryFacets reference;
  std::vector<double> referenceAreas;
  run(1, reference, referenceAreas);
  int differentFaces = 0, differentAreas = 0;
  for (int repeat = 0; repeat < 8; ++repeat)
  {
    dgmf_vtk::BoundaryFacets facets;
    std::vector<double> areas;
    run(2, facets, areas);
    differentFaces += facets.Ids != reference.Ids || facets.Offsets != reference.Offsets ? 1 : 0;
    differentAreas += areas != referenceAreas ? 1 : 0;
  }
  EXPECT_EQ(differentFaces, 0) << "runs with 2 threads whose faces differ from 1 thread's (of 8)";
  EXPECT_EQ(differentAreas, 0) << "runs with 2 threads whose areas differ from 1 thread's (of 8)";
}

namespace
{
/// Cells added to a grid with a ghost flag each; Finish() gives the grid its vtkGhostType array.
struct GhostFlaggedCells
{
  vtkUnstructuredGrid* Grid;
  vtkNew<vtkUnsignedCharArray> Ghosts;

  /// Flags the cell just inserted (a ghost: DUPLICATECELL).
  void Flag(bool ghost)
  {
    this->Ghosts->InsertNextValue(ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
  }
  void Add(int type, std::vector<vtkIdType> ids, bool ghost)
  {
    this->Grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
    this->Flag(ghost);
  }
  void Finish()
  {
    this->Ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
    this->Grid->GetCellData()->AddArray(this->Ghosts);
  }
};

/**
 * A 4 x 4 x 4 block of unit cubes cut into every kind of 3D cell the face matching reads:
 * hexahedra, voxels, two wedges, five tetrahedra, six pyramids about the cube's centre, and
 * polyhedra; the cubes of x >= 2 use their own copies of the points of the plane x = 2
 * (coincident points, as at a partition interface); two quads and a pixel of the boundary x = 0
 * as 2D cells; the last layer of cubes in z are ghost cells. Neighbours cut differently share
 * no face (a quad against two triangles), as in any non-conforming mesh.
 */
vtkSmartPointer<vtkUnstructuredGrid> EveryCellKind()
{
  const int n = 4;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        points->InsertNextPoint(i, j, k);
      }
    }
  }
  const vtkIdType copies = points->GetNumberOfPoints(); // the copies of the plane x = 2
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      points->InsertNextPoint(2, j, k);
    }
  }
  grid->SetPoints(points);
  GhostFlaggedCells cells{ grid };
  const auto add = [&](int type, std::vector<vtkIdType> ids, bool ghost)
  { cells.Add(type, std::move(ids), ghost); };
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        // Corner c: x + 1 if c & 1, y + 1 if c & 2, z + 1 if c & 4; the copies at x = 2 for x >= 2.
        const auto corner = [&](int c)
        {
          const int x = i + (c & 1);
          const int y = j + (c >> 1 & 1);
          const int z = k + (c >> 2 & 1);
          return static_cast<vtkIdType>(i >= 2 && x == 2 ? copies + y + (n + 1) * z : id(x, y, z));
        };
        const vtkIdType h[8] = { corner(0), corner(1), corner(3), corner(2), corner(4), corner(5),
          corner(7), corner(6) };
        const bool ghost = k == n - 1;
        switch ((i + 2 * j + 3 * k) % 6)
        {
          case 0:
            add(VTK_HEXAHEDRON, { h, h + 8 }, ghost);
            break;
          case 1:
            add(VTK_VOXEL,
              { corner(0), corner(1), corner(2), corner(3), corner(4), corner(5), corner(6),
                corner(7) },
              ghost);
            break;
          case 2:
            add(VTK_WEDGE, { h[0], h[1], h[2], h[4], h[5], h[6] }, ghost);
            add(VTK_WEDGE, { h[0], h[2], h[3], h[4], h[6], h[7] }, ghost);
            break;
          case 3:
            add(VTK_TETRA, { h[0], h[1], h[2], h[5] }, ghost);
            add(VTK_TETRA, { h[0], h[2], h[3], h[7] }, ghost);
            add(VTK_TETRA, { h[0], h[5], h[7], h[4] }, ghost);
            add(VTK_TETRA, { h[2], h[7], h[5], h[6] }, ghost);
            add(VTK_TETRA, { h[0], h[2], h[7], h[5] }, ghost);
            break;
          case 4:
          {
            const vtkIdType centre = points->InsertNextPoint(i + 0.5, j + 0.5, k + 0.5);
            const int quads[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
              { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
            for (const auto& q : quads)
            {
              add(VTK_PYRAMID, { h[q[0]], h[q[1]], h[q[2]], h[q[3]], centre }, ghost);
            }
            break;
          }
          default:
          {
            // The hexahedron's faces as a polyhedron.
            const int faces[6][4] = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 },
              { 3, 7, 6, 2 }, { 0, 3, 2, 1 }, { 4, 5, 6, 7 } };
            std::vector<vtkIdType> stream{ 6 };
            for (const auto& f : faces)
            {
              stream.push_back(4);
              for (int v : f)
              {
                stream.push_back(h[v]);
              }
            }
            grid->InsertNextCell(VTK_POLYHEDRON, 8, h, 6, stream.data() + 1);
            cells.Flag(ghost);
            break;
          }
        }
      }
    }
  }
  add(VTK_QUAD, { id(0, 0, 0), id(0, 1, 0), id(0, 1, 1), id(0, 0, 1) }, false);
  add(VTK_QUAD, { id(0, 1, 0), id(0, 2, 0), id(0, 2, 1), id(0, 1, 1) }, false);
  add(VTK_PIXEL, { id(0, 2, 0), id(0, 3, 0), id(0, 2, 1), id(0, 3, 1) }, false);
  cells.Finish();
  grid->SetPoints(points); // with the pyramids' centres
  return grid;
}

/// Each facet as its point ids from the smallest, in its own direction; all facets sorted.
std::vector<std::vector<vtkIdType>> Normalised(const dgmf_vtk::BoundaryFacets& facets)
{
  std::vector<std::vector<vtkIdType>> all;
  for (std::size_t f = 0; f < facets.Size(); ++f)
  {
    std::vector<vtkIdType> ids(
      facets.Ids.begin() + facets.Offsets[f], facets.Ids.begin() + facets.Offsets[f + 1]);
    std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
    all.push_back(ids);
  }
  std::sort(all.begin(), all.end());
  return all;
}
} // namespace

TEST(BoundaryDetection, TheFaceMatchingFindsTheFacesVtkGeometryFilterFinds)
{
  auto mesh = EveryCellKind();
  dgmf_vtk::BoundaryFacets matched, reference;
  dgmf_vtk::RunWithThreads(2,
    [&]()
    {
      matched = dgmf_vtk::FindBoundaryFacets(mesh, 3);
      reference = dgmf_vtk::FindBoundaryFacetsByGeometryFilter(mesh);
    });
  // 5 x 4 x 4 outer squares of which the x = 0 and z faces of the last (ghost) layer are left
  // out, the faces between differently cut cubes, the 2D cells: many more than 6 x 16.
  EXPECT_GT(reference.Size(), 6u * 16u);
  EXPECT_EQ(Normalised(matched), Normalised(reference));
  EXPECT_EQ(matched.Canonical, reference.Canonical);
  EXPECT_FALSE(matched.Canonical.empty()); // the copies of the plane x = 2 were found
  const auto flags = dgmf_vtk::FlagBoundaryNodes(matched, mesh->GetNumberOfPoints());
  EXPECT_EQ(flags, dgmf_vtk::FlagBoundaryNodes(reference, mesh->GetNumberOfPoints()));
}

TEST(BoundaryDetection, TheEdgeMatchingFindsTheEdgesTheCountingFinds)
{
  // A 6 x 4 grid of unit squares in z = 0 cut into quads, triangle pairs, pixels and polygons
  // (some with a point in the middle of an edge, which makes that edge non-conforming); the
  // squares of x >= 3 on their own copies of the points of x = 3; the top row ghost cells.
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  const int nx = 6, ny = 4;
  const auto id = [](int i, int j) { return static_cast<vtkIdType>(i + (nx + 1) * j); };
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      points->InsertNextPoint(i, j, 0.0);
    }
  }
  const vtkIdType copies = points->GetNumberOfPoints();
  for (int j = 0; j <= ny; ++j)
  {
    points->InsertNextPoint(3.0, j, 0.0);
  }
  GhostFlaggedCells cells{ mesh };
  const auto add = [&](int type, std::vector<vtkIdType> ids, bool ghost)
  { cells.Add(type, std::move(ids), ghost); };
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const auto corner = [&](int di, int dj)
      { return i >= 3 && i + di == 3 ? copies + j + dj : id(i + di, j + dj); };
      const vtkIdType a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
      const bool ghost = j == ny - 1;
      switch ((i + 2 * j) % 4)
      {
        case 0:
          add(VTK_QUAD, { a, b, c, d }, ghost);
          break;
        case 1:
          add(VTK_TRIANGLE, { a, b, c }, ghost);
          add(VTK_TRIANGLE, { a, c, d }, ghost);
          break;
        case 2:
          add(VTK_PIXEL, { a, b, d, c }, ghost);
          break;
        default:
        {
          const vtkIdType middle = points->InsertNextPoint(i + 0.5, j, 0.0);
          add(VTK_POLYGON, { a, middle, b, c, d }, ghost);
          break;
        }
      }
    }
  }
  mesh->SetPoints(points);
  cells.Finish();
  dgmf_vtk::BoundaryFacets matched, counted;
  dgmf_vtk::RunWithThreads(2,
    [&]()
    {
      matched = dgmf_vtk::FindBoundaryFacets(mesh, 2);
      counted = dgmf_vtk::FindBoundaryFacetsByGeometryFilter(mesh, 2);
    });
  EXPECT_GT(counted.Size(), 2u * (nx + ny)); // the outline and the non-conforming edges
  EXPECT_FALSE(matched.Canonical.empty());   // the copies of x = 3 were found
  EXPECT_EQ(matched.Ids, counted.Ids);       // the same edges, in the same order
  EXPECT_EQ(matched.Offsets, counted.Offsets);
}

TEST(BoundaryDetection, PolygonsCloseTheMeshOnlyWhenTheyAreExactlyItsBoundaryFaces)
{
  auto volume = JitteredTetrahedra(16); // 24,576 cells: several blocks of the parity's pass
  const dgmf_vtk::BoundaryFacets facets = dgmf_vtk::FindBoundaryFacets(volume, 3);
  ASSERT_EQ(facets.Size(), static_cast<std::size_t>(6 * 2 * 16 * 16));
  // The volume and its boundary triangles (a reader's boundary patches) in one grid, the
  // triangles' points in reverse order; `skip` leaves out one, `twice` repeats one.
  const auto addTriangles = [&](vtkUnstructuredGrid* mesh, std::size_t skip, std::size_t twice)
  {
    for (std::size_t f = 0; f < facets.Size(); ++f)
    {
      std::vector<vtkIdType> ids(
        facets.Ids.begin() + facets.Offsets[f], facets.Ids.begin() + facets.Offsets[f + 1]);
      std::reverse(ids.begin(), ids.end());
      for (int copy = 0; copy < (f == skip ? 0 : f == twice ? 2 : 1); ++copy)
      {
        mesh->InsertNextCell(VTK_TRIANGLE, static_cast<vtkIdType>(ids.size()), ids.data());
      }
    }
  };
  const auto withPatches = [&](std::size_t skip, std::size_t twice)
  {
    auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
    mesh->DeepCopy(volume);
    addTriangles(mesh, skip, twice);
    return mesh;
  };
  // The same triangles kept apart, on the volume's points (a composite input's patches:
  // CompositeMesh::GetPatches).
  const auto patchesApart = [&](std::size_t skip, std::size_t twice)
  {
    auto patches = vtkSmartPointer<vtkUnstructuredGrid>::New();
    patches->SetPoints(volume->GetPoints());
    patches->Allocate(static_cast<vtkIdType>(facets.Size()));
    addTriangles(patches, skip, twice);
    return patches;
  };
  const std::size_t none = facets.Size();
  for (int threads : { 1, 2 })
  {
    dgmf_vtk::RunWithThreads(threads,
      [&]()
      {
        EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(volume)) << "no polygons";
        EXPECT_TRUE(dgmf_vtk::PolygonsCloseTheMesh(withPatches(none, none))) << "closed";
        EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(withPatches(17, none))) << "one missing";
        EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(withPatches(none, 17))) << "one twice";
        EXPECT_TRUE(dgmf_vtk::PolygonsCloseTheMesh(volume, patchesApart(none, none)))
          << "closed apart";
        EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(volume, patchesApart(17, none)))
          << "one missing apart";
        EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(volume, patchesApart(none, 17)))
          << "one twice apart";
      });
  }
  // An empty cell among the patches (a polydata after DeleteCell) has no face, as in one grid.
  auto withEmpty = patchesApart(none, none);
  withEmpty->InsertNextCell(VTK_EMPTY_CELL, 0, nullptr);
  EXPECT_TRUE(dgmf_vtk::PolygonsCloseTheMesh(volume, withEmpty)) << "an empty cell apart";
  // The boundary facets with the patches apart are those of the one grid, in the same order.
  const dgmf_vtk::BoundaryFacets one = dgmf_vtk::FindBoundaryFacets(withPatches(none, 17), 3);
  const dgmf_vtk::BoundaryFacets apart =
    dgmf_vtk::FindBoundaryFacets(volume, patchesApart(none, 17), 3, false);
  EXPECT_EQ(one.Size(), 2 * facets.Size() + 1); // each face, as a face and as its triangle(s)
  EXPECT_EQ(apart.Ids, one.Ids);
  EXPECT_EQ(apart.Offsets, one.Offsets);
  // Ghost cells (a piece of a distributed mesh): their outer faces are not the boundary.
  auto ghosted = withPatches(none, none);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(ghosted->GetNumberOfCells());
  ghosts->FillValue(0);
  ghosted->GetCellData()->AddArray(ghosts);
  EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(ghosted));
  // A quadratic cell's faces have mid-edge nodes: not read here.
  auto quadratic = withPatches(none, none);
  const vtkIdType ten[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  quadratic->InsertNextCell(VTK_QUADRATIC_TETRA, 10, ten);
  EXPECT_FALSE(dgmf_vtk::PolygonsCloseTheMesh(quadratic));
}

TEST(BoundaryDetection, RunsOfHexahedraGiveTheAnswerOfTheCellByCellReading)
{
  // 26^3 = 17,576 cells (two blocks of the parity's pass) in VTK's 64-bit storage, read in runs
  // of one shape (FaceCells::GetCornerRun): hexahedra, every seventh cell a voxel instead (its
  // corners in VTK's voxel order: a run stops there), and one hexahedron given a ninth point id
  // (a run stops there too; the cell is read as its first 8). The same grid in 32-bit storage is
  // read cell by cell: the answers must agree. The box's boundary quads are the patches.
  const int n = 26;
  const auto id = [n](int i, int j, int k)
  { return static_cast<vtkIdType>(i + (n + 1) * (j + (n + 1) * k)); };
  vtkNew<vtkPoints> points;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        points->InsertNextPoint(i, j, k);
  const auto boxWithPatches = [&](int skippedPatch)
  {
    auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
    mesh->SetPoints(points);
    int cell = 0;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i, ++cell)
        {
          const vtkIdType c[9] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
            id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
            id(i, j + 1, k + 1), id(i, j, k) };
          if (cell % 7 == 3)
          {
            const vtkIdType voxel[8] = { c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6] };
            mesh->InsertNextCell(VTK_VOXEL, 8, voxel);
          }
          else
          {
            mesh->InsertNextCell(VTK_HEXAHEDRON, cell == 9001 ? 9 : 8, c);
          }
        }
    // The six sides' quads.
    int patch = 0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (const int side : { 0, n })
        {
          const vtkIdType quads[3][4] = { { id(side, a, b), id(side, a + 1, b),
                                            id(side, a + 1, b + 1), id(side, a, b + 1) },
            { id(a, side, b), id(a + 1, side, b), id(a + 1, side, b + 1), id(a, side, b + 1) },
            { id(a, b, side), id(a + 1, b, side), id(a + 1, b + 1, side), id(a, b + 1, side) } };
          for (const auto& quad : quads)
          {
            if (patch++ != skippedPatch)
            {
              mesh->InsertNextCell(VTK_QUAD, 4, quad);
            }
          }
        }
    return mesh;
  };
  for (const int skipped : { -1, 1234 }) // no patch left out, or one of the 4,056
  {
    auto mesh = boxWithPatches(skipped);
    ASSERT_TRUE(mesh->GetCells()->IsStorage64Bit());
    auto narrow = vtkSmartPointer<vtkUnstructuredGrid>::New();
    narrow->DeepCopy(mesh);
    ASSERT_TRUE(narrow->GetCells()->ConvertTo32BitStorage());
    for (int threads : { 1, 2 })
    {
      dgmf_vtk::RunWithThreads(threads,
        [&]()
        {
          EXPECT_EQ(dgmf_vtk::PolygonsCloseTheMesh(mesh), skipped < 0) << "skipped " << skipped;
          EXPECT_EQ(dgmf_vtk::PolygonsCloseTheMesh(narrow), skipped < 0) << "skipped " << skipped;
        });
    }
  }
}
