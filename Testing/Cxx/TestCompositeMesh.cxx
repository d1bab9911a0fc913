// The merge of a composite input's blocks into one mesh (DGMFCompositeMesh, DGMFMergedCells) and
// its cache between executions (DGMFCompositeMeshCache).
#include "DGMFCompositeMesh.h"
#include "DGMFCompositeMeshCache.h"
#include "HexBoxBlocks.h"
#include "TwoSquares.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
/// The unit cube's corners (points numbered x fastest) in VTK's hexahedron order, and its six
/// faces as a polyhedron's face stream.
const vtkIdType CubeCorners[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
const vtkIdType CubeFaces[] = { 4, 0, 4, 6, 2, 4, 1, 3, 7, 5, 4, 0, 1, 5, 4, 4, 2, 6, 7, 3, 4, 0, 2,
  3, 1, 4, 4, 5, 7, 6 };

/// A grid of the unit cube's 8 points and one cell: the cube as a polyhedron.
vtkSmartPointer<vtkUnstructuredGrid> UnitCubePolyhedron()
{
  auto cube = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        points->InsertNextPoint(i, j, k);
      }
    }
  }
  cube->SetPoints(points);
  cube->InsertNextCell(VTK_POLYHEDRON, 8, CubeCorners, 6, CubeFaces);
  return cube;
}

} // namespace

TEST(CompositeMesh, BlocksMergeAtSharedNodesAndScatterBack)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, TwoSquares(0.0)); // x in [0, 2]
  auto right = TwoSquares(2.0);         // x in [2, 4]: its left edge is the first's right edge
  right->GetPointData()->GetArray("BoundaryMarker")->SetTuple1(0, 1);
  blocks->SetBlock(1, right);
  const dgmf_vtk::CompositeMesh composite(blocks, "", "BoundaryMarker");
  vtkUnstructuredGrid* merged = composite.GetMergedMesh();
  EXPECT_EQ(merged->GetNumberOfPoints(), 10); // 12 block nodes, 2 shared
  EXPECT_EQ(merged->GetNumberOfCells(), 4);
  vtkDataArray* marker = merged->GetPointData()->GetArray("BoundaryMarker");
  ASSERT_TRUE(marker);
  EXPECT_EQ(marker->GetTuple1(2), 2.0); // moving in one block, static in the other: moving

  vtkNew<vtkUnstructuredGrid> deformed;
  deformed->DeepCopy(merged);
  for (vtkIdType i = 0; i < deformed->GetNumberOfPoints(); ++i)
  {
    double p[3];
    deformed->GetPoint(i, p);
    p[1] += 10.0;
    deformed->GetPoints()->SetPoint(i, p);
  }
  vtkNew<vtkMultiBlockDataSet> output;
  composite.ScatterResult(deformed, nullptr, output);
  auto* second = vtkUnstructuredGrid::SafeDownCast(output->GetBlock(1));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->GetNumberOfPoints(), 6);
  EXPECT_EQ(second->GetPoint(5)[0], 4.0);
  EXPECT_EQ(second->GetPoint(5)[1], 11.0);
  EXPECT_TRUE(second->GetPointData()->GetArray("BoundaryMarker")); // the block's own arrays
}

TEST(CompositeMesh, EveryKindOfBlockKeepsItsCellsOnTheMergedNodes)
{
  // A grid with 64-bit cell storage, the same shifted with 32-bit storage and a float
  // displacement, a polydata patch, and a grid with a polyhedron: each block's cells must come
  // out in order, of the same types, on merged nodes at the same places.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, TwoSquares(0.0));
  auto narrow = TwoSquares(2.0);
  vtkNew<vtkCellArray> cells32;
  cells32->Use32BitStorage();
  for (vtkIdType c = 0; c < narrow->GetNumberOfCells(); ++c)
  {
    vtkNew<vtkIdList> ids;
    narrow->GetCellPoints(c, ids);
    cells32->InsertNextCell(ids);
  }
  ASSERT_FALSE(cells32->IsStorage64Bit());
  narrow->SetCells(VTK_QUAD, cells32);
  vtkNew<vtkFloatArray> displacement;
  displacement->SetName("Displacement");
  displacement->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < narrow->GetNumberOfPoints(); ++i)
  {
    displacement->InsertNextTuple3(0.5f * static_cast<float>(i), 0.0f, 0.25f);
  }
  narrow->GetPointData()->AddArray(displacement);
  blocks->SetBlock(1, narrow);
  vtkNew<vtkPolyData> patch; // the line y = 0 of the first block, as two segments
  vtkNew<vtkPoints> patchPoints;
  for (int i = 0; i < 3; ++i)
  {
    patchPoints->InsertNextPoint(i, 0.0, 0.0);
  }
  patch->SetPoints(patchPoints);
  vtkNew<vtkCellArray> lines;
  const vtkIdType segments[2][2] = { { 0, 1 }, { 1, 2 } };
  lines->InsertNextCell(2, segments[0]);
  lines->InsertNextCell(2, segments[1]);
  patch->SetLines(lines);
  blocks->SetBlock(2, patch);
  // A hexahedron (no faces of its own in VTK's arrays) between two polyhedra: each polyhedron's
  // faces must follow it.
  const vtkSmartPointer<vtkUnstructuredGrid> cube = UnitCubePolyhedron();
  cube->InsertNextCell(VTK_HEXAHEDRON, 8, CubeCorners);
  const vtkIdType lowerCorners[4] = { 0, 1, 3, 2 };
  const vtkIdType pyramidFaces[] = { 4, 0, 1, 3, 2, 3, 0, 1, 4, 3, 1, 3, 4, 3, 3, 2, 4, 3, 2, 0,
    4 };
  const vtkIdType pyramidCorners[5] = { lowerCorners[0], lowerCorners[1], lowerCorners[2],
    lowerCorners[3], 4 };
  cube->InsertNextCell(VTK_POLYHEDRON, 5, pyramidCorners, 5, pyramidFaces);
  blocks->SetBlock(3, cube);

  const dgmf_vtk::CompositeMesh composite(blocks, "Displacement", "BoundaryMarker");
  vtkUnstructuredGrid* merged = composite.GetMergedMesh();
  EXPECT_FALSE(composite.GetPatches()) << "lines among the patches: every cell merged";
  // 6 + 6 - 2 shared + 0 new on the patch + 8 - 4 shared with the first block.
  EXPECT_EQ(merged->GetNumberOfPoints(), 14);
  ASSERT_EQ(merged->GetNumberOfCells(), 2 + 2 + 2 + 3);
  vtkIdType first = 0;
  for (unsigned int b = 0; b < blocks->GetNumberOfBlocks(); ++b)
  {
    auto* block = vtkDataSet::SafeDownCast(blocks->GetBlock(b));
    for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c)
    {
      vtkNew<vtkIdList> own, ids;
      block->GetCellPoints(c, own);
      merged->GetCellPoints(first + c, ids);
      EXPECT_EQ(merged->GetCellType(first + c), block->GetCellType(c)) << "block " << b;
      ASSERT_EQ(ids->GetNumberOfIds(), own->GetNumberOfIds()) << "block " << b << " cell " << c;
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        double p[3], q[3];
        block->GetPoint(own->GetId(k), p);
        merged->GetPoint(ids->GetId(k), q);
        EXPECT_EQ(p[0], q[0]);
        EXPECT_EQ(p[1], q[1]);
        EXPECT_EQ(p[2], q[2]);
      }
    }
    first += block->GetNumberOfCells();
  }
  // The polyhedra kept their faces, on merged nodes at the same places.
  for (const vtkIdType c : { 0, 2 })
  {
    vtkNew<vtkIdList> own, stream;
    cube->GetFaceStream(c, own);
    merged->GetFaceStream(6 + c, stream);
    ASSERT_EQ(stream->GetNumberOfIds(), own->GetNumberOfIds()) << "cell " << c;
    EXPECT_EQ(stream->GetId(0), c == 0 ? 6 : 5);
    for (vtkIdType at = 1; at < own->GetNumberOfIds();)
    {
      const vtkIdType count = own->GetId(at);
      EXPECT_EQ(stream->GetId(at++), count);
      for (vtkIdType m = 0; m < count; ++m, ++at)
      {
        double p[3], q[3];
        cube->GetPoint(own->GetId(at), p);
        merged->GetPoint(stream->GetId(at), q);
        EXPECT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "cell " << c;
      }
    }
  }
  EXPECT_EQ(merged->GetFaceLocations()->GetValue(7), -1); // the hexahedron
  // The float displacement as doubles at its block's nodes; zeros where no block has one.
  vtkDataArray* merges = merged->GetPointData()->GetArray("Displacement");
  ASSERT_TRUE(merges);
  EXPECT_TRUE(vtkDoubleArray::SafeDownCast(merges));
  double shared[3], own[3];
  merges->GetTuple(2, shared); // (2, 0, 0): the first block's, then the second's node 0
  EXPECT_EQ(shared[0], 0.0);
  EXPECT_EQ(shared[2], 0.25);
  bool found = false;
  for (vtkIdType i = 0; i < merged->GetNumberOfPoints(); ++i)
  {
    double p[3];
    merged->GetPoint(i, p);
    if (p[0] == 4.0 && p[1] == 1.0)
    {
      merges->GetTuple(i, own);
      EXPECT_EQ(own[0], 2.5); // node 5 of the second block
      found = true;
    }
  }
  EXPECT_TRUE(found);
}

TEST(CompositeMesh, APolyhedronWhoseFacesRunPastTheFaceArrayIsRefusedWithItsCellNamed)
{
  // VTK's face arrays as a broken writer might leave them: the second cell's faces start past
  // the end. The merge reads the arrays in place; it must stop with the cell named, not read on.
  const vtkSmartPointer<vtkUnstructuredGrid> grid = UnitCubePolyhedron();
  grid->InsertNextCell(VTK_POLYHEDRON, 8, CubeCorners, 6, CubeFaces);
  grid->GetFaceLocations()->SetValue(1, grid->GetFaces()->GetNumberOfValues() - 3);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, grid);
  try
  {
    const dgmf_vtk::CompositeMesh composite(blocks, "", "BoundaryMarker");
    ADD_FAILURE() << "the broken face array was read";
  }
  catch (const std::runtime_error& error)
  {
    EXPECT_NE(std::string(error.what()).find("Cell 1 is a polyhedron"), std::string::npos)
      << error.what();
  }
}

TEST(CompositeMesh, APolyhedralVolumeLendsItsCellsWithTheirFaces)
{
  // Two polyhedra (a cube, and the pyramid on its lower face) and a patch of the cube's upper
  // face: the merged grid takes the volume's cells and VTK's face arrays as they are.
  const vtkSmartPointer<vtkUnstructuredGrid> cube = UnitCubePolyhedron();
  cube->GetPoints()->InsertNextPoint(0.5, 0.5, -1.0);
  const vtkIdType pyramidCorners[5] = { 0, 1, 3, 2, 8 };
  const vtkIdType pyramidFaces[] = { 4, 0, 1, 3, 2, 3, 0, 1, 8, 3, 1, 3, 8, 3, 3, 2, 8, 3, 2, 0,
    8 };
  cube->InsertNextCell(VTK_POLYHEDRON, 5, pyramidCorners, 5, pyramidFaces);
  vtkNew<vtkPolyData> top;
  vtkNew<vtkPoints> topPoints;
  for (const double* p :
    { cube->GetPoint(4), cube->GetPoint(5), cube->GetPoint(7), cube->GetPoint(6) })
  {
    topPoints->InsertNextPoint(p);
  }
  top->SetPoints(topPoints);
  vtkNew<vtkCellArray> quad;
  const vtkIdType corners[4] = { 0, 1, 2, 3 };
  quad->InsertNextCell(4, corners);
  top->SetPolys(quad);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, cube);
  blocks->SetBlock(1, top);
  const dgmf_vtk::CompositeMesh composite(blocks, "", "");
  vtkUnstructuredGrid* merged = composite.GetMergedMesh();
  EXPECT_TRUE(composite.SharesInputCells());
  EXPECT_EQ(merged->GetCells(), cube->GetCells());
  EXPECT_EQ(merged->GetFaces(), cube->GetFaces());
  EXPECT_EQ(merged->GetFaceLocations(), cube->GetFaceLocations());
  vtkNew<vtkIdList> stream;
  merged->GetFaceStream(1, stream);
  EXPECT_EQ(stream->GetId(0), 5); // the pyramid's five faces
  ASSERT_TRUE(composite.GetPatches());
  EXPECT_EQ(composite.GetPatches()->GetNumberOfCells(), 1);
}

TEST(CompositeMesh, TheMergeIsKeptWhileTheBlocksAreUnchangedAndRedoneWhenOneChanges)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, TwoSquares(0.0));
  auto right = TwoSquares(2.0);
  blocks->SetBlock(1, right);
  dgmf_vtk::CompositeMeshCache cache;
  const dgmf_vtk::CompositeMesh* first = &cache.Get(blocks, "", "BoundaryMarker");
  EXPECT_FALSE(cache.WasReused());
  vtkUnstructuredGrid* merged = first->GetMergedMesh();
  EXPECT_EQ(merged->GetNumberOfPoints(), 10);
  EXPECT_GT(cache.GetMemorySize(), 10 * 3 * sizeof(double));

  // A new motion of the same input: the same merged grid (the caches keyed on it match).
  EXPECT_EQ(cache.Get(blocks, "", "BoundaryMarker").GetMergedMesh(), merged);
  EXPECT_TRUE(cache.WasReused());

  // A point moved in place in a block: merged again, with the new coordinates.
  right->GetPoints()->SetPoint(5, 4.0, 1.5, 0.0);
  right->GetPoints()->Modified();
  const dgmf_vtk::CompositeMesh& moved = cache.Get(blocks, "", "BoundaryMarker");
  EXPECT_FALSE(cache.WasReused());
  const vtkIdType node = moved.GetLeaves()[1].Node(5);
  EXPECT_EQ(moved.GetMergedMesh()->GetPoint(node)[1], 1.5);

  // A marker value changed in place, another selected array, a block replaced: merged again.
  cache.Get(blocks, "", "BoundaryMarker");
  EXPECT_TRUE(cache.WasReused());
  right->GetPointData()->GetArray("BoundaryMarker")->SetTuple1(0, 1);
  right->GetPointData()->GetArray("BoundaryMarker")->Modified();
  cache.Get(blocks, "", "BoundaryMarker");
  EXPECT_FALSE(cache.WasReused());
  cache.Get(blocks, "", "");
  EXPECT_FALSE(cache.WasReused());
  blocks->SetBlock(1, TwoSquares(2.0));
  cache.Get(blocks, "", "");
  EXPECT_FALSE(cache.WasReused());
}

TEST(CompositeMesh, AVolumeLendsItsCellsAndItsPatchesKeepTheirPolygonsApart)
{
  // A CFD reader's volume (64-bit cells, every node in order) and its six sides as patches with
  // points of their own: the merged grid has the volume's cells themselves, not a copy; the
  // patches' polygons are in a grid of their own on the merged points; the cache holds neither
  // the volume's points nor its cells.
  const int n = 24;
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(n, "");
  auto* volume = vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0));
  ASSERT_TRUE(volume->GetCells()->IsStorage64Bit());
  dgmf_vtk::CompositeMeshCache cache;
  const dgmf_vtk::CompositeMesh& composite = cache.Get(blocks, "", "");
  vtkUnstructuredGrid* merged = composite.GetMergedMesh();
  EXPECT_TRUE(composite.SharesInputCells());
  EXPECT_EQ(merged->GetCells(), volume->GetCells());
  EXPECT_EQ(merged->GetNumberOfPoints(), volume->GetNumberOfPoints());
  vtkUnstructuredGrid* patches = composite.GetPatches();
  ASSERT_TRUE(patches);
  EXPECT_EQ(patches->GetPoints(), merged->GetPoints());
  EXPECT_EQ(patches->GetNumberOfCells(), 6 * n * n);
  const auto& leaves = composite.GetLeaves();
  ASSERT_EQ(leaves.size(), 7u);
  EXPECT_FALSE(leaves[0].InPatches);
  auto* sides = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  for (unsigned int b = 0; b < 6; ++b)
  {
    const dgmf_vtk::CompositeMesh::Leaf& leaf = leaves[b + 1];
    auto* side = vtkPolyData::SafeDownCast(sides->GetBlock(b));
    EXPECT_TRUE(leaf.InPatches);
    EXPECT_EQ(leaf.FirstCell, b * n * n);
    ASSERT_EQ(leaf.Cells, side->GetNumberOfCells());
    for (vtkIdType c = 0; c < leaf.Cells; ++c)
    {
      vtkNew<vtkIdList> own, ids;
      side->GetCellPoints(c, own);
      patches->GetCellPoints(leaf.FirstCell + c, ids);
      EXPECT_EQ(patches->GetCellType(leaf.FirstCell + c), VTK_QUAD);
      ASSERT_EQ(ids->GetNumberOfIds(), 4);
      for (vtkIdType k = 0; k < 4; ++k)
      {
        const double* p = side->GetPoint(own->GetId(k));
        const double* q = merged->GetPoint(ids->GetId(k));
        ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "side " << b << " cell " << c;
      }
    }
  }
  // What a copy of the volume's cells would take: the cache holds far less (the patches).
  const std::size_t volumeCells = 1024 *
    static_cast<std::size_t>(volume->GetCells()->GetActualMemorySize() +
      volume->GetCellTypesArray()->GetActualMemorySize());
  EXPECT_LT(cache.GetMemorySize(), volumeCells / 2);

  // The same volume in 32-bit cells is copied (the face matching's fast path reads 64 bits).
  vtkNew<vtkCellArray> cells32;
  cells32->Use32BitStorage();
  for (vtkIdType c = 0; c < volume->GetNumberOfCells(); ++c)
  {
    vtkNew<vtkIdList> ids;
    volume->GetCellPoints(c, ids);
    cells32->InsertNextCell(ids);
  }
  volume->SetCells(VTK_HEXAHEDRON, cells32);
  const dgmf_vtk::CompositeMesh copied(blocks, "", "");
  EXPECT_FALSE(copied.SharesInputCells());
  ASSERT_TRUE(copied.GetPatches());
  ASSERT_EQ(copied.GetMergedMesh()->GetNumberOfCells(), volume->GetNumberOfCells());
  for (vtkIdType c = 0; c < volume->GetNumberOfCells(); c += 97)
  {
    vtkNew<vtkIdList> own, ids;
    volume->GetCellPoints(c, own);
    copied.GetMergedMesh()->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 8);
    for (vtkIdType k = 0; k < 8; ++k)
    {
      EXPECT_EQ(ids->GetId(k), own->GetId(k)) << "cell " << c;
    }
  }
}

TEST(CompositeMesh, NodesAreNumberedInTheOrderTheyAreFirstMetOverManyBlocksOfPoints)
{
  // More points than the numbering's blocks of 65,536: a first leaf of distinct points but one
  // repeat near its end (so that the leading run of first points ends inside a block), then a
  // leaf with some of the first leaf's points (in another order) and new ones. Each leaf's node
  // map against a std::map of the coordinates, in the order met.
  const auto leafOf = [](const std::vector<double>& xs)
  {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const double x : xs)
    {
      points->InsertNextPoint(x, 0.5 * x, 0.0);
    }
    grid->SetPoints(points);
    const vtkIdType vertex[1] = { 0 };
    grid->InsertNextCell(VTK_VERTEX, 1, vertex);
    return grid;
  };
  std::vector<double> first(150'000);
  for (std::size_t i = 0; i < first.size(); ++i)
  {
    first[i] = static_cast<double>(i);
  }
  first[140'000] = 7.0; // a repeat inside the first leaf
  std::vector<double> second;
  for (int k = 0; k < 50; ++k)
  {
    second.push_back(1049.0 - k); // the first leaf's points 1000 - 1049, reversed
    second.push_back(-1.0 - k);   // new points
  }
  second.push_back(149'999.0); // the first leaf's last point
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, leafOf(first));
  blocks->SetBlock(1, leafOf(second));
  const dgmf_vtk::CompositeMesh composite(blocks, "", "");

  std::map<double, vtkIdType> nodeAt;
  std::vector<std::vector<vtkIdType>> expected(2);
  for (int l = 0; l < 2; ++l)
  {
    for (const double x : l == 0 ? first : second)
    {
      const auto found = nodeAt.emplace(x, static_cast<vtkIdType>(nodeAt.size())).first;
      expected[static_cast<std::size_t>(l)].push_back(found->second);
    }
  }
  vtkUnstructuredGrid* merged = composite.GetMergedMesh();
  ASSERT_EQ(merged->GetNumberOfPoints(), static_cast<vtkIdType>(nodeAt.size()));
  ASSERT_EQ(composite.GetLeaves().size(), 2u);
  for (std::size_t l = 0; l < 2; ++l)
  {
    const auto& leaf = composite.GetLeaves()[l];
    EXPECT_FALSE(leaf.SameNumbering) << "leaf " << l;
    const std::vector<double>& xs = l == 0 ? first : second;
    for (std::size_t i = 0; i < xs.size(); ++i)
    {
      const vtkIdType node = leaf.Node(static_cast<vtkIdType>(i));
      ASSERT_EQ(node, expected[l][i]) << "leaf " << l << ", point " << i;
      ASSERT_EQ(merged->GetPoint(node)[0], xs[i]) << "leaf " << l << ", point " << i;
    }
  }
}

TEST(CompositeMesh, AFirstLeafOfDistinctPointsIsItsOwnNumbering)
{
  // A CFD reader's volume first (its points all distinct, more than one block of the numbering),
  // then a patch on some of them: the volume needs no node map, the patch maps onto its nodes.
  auto volume = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 70'000; ++i)
  {
    points->InsertNextPoint(i, 0.0, 0.0);
  }
  volume->SetPoints(points);
  const vtkIdType vertex[1] = { 0 };
  volume->InsertNextCell(VTK_VERTEX, 1, vertex);
  auto patch = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> patchPoints;
  patchPoints->InsertNextPoint(69'999.0, 0.0, 0.0);
  patchPoints->InsertNextPoint(3.0, 0.0, 0.0);
  patch->SetPoints(patchPoints);
  patch->InsertNextCell(VTK_VERTEX, 1, vertex);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, volume);
  blocks->SetBlock(1, patch);
  const dgmf_vtk::CompositeMesh composite(blocks, "", "");
  EXPECT_EQ(composite.GetMergedMesh()->GetNumberOfPoints(), 70'000);
  EXPECT_TRUE(composite.GetLeaves()[0].SameNumbering);
  EXPECT_FALSE(composite.GetLeaves()[1].SameNumbering);
  EXPECT_EQ(composite.GetLeaves()[1].Node(0), 69'999);
  EXPECT_EQ(composite.GetLeaves()[1].Node(1), 3);
}
