// The VTK adapter's parts, each on its own (Documentation/architecture.md): the content key, the
// output buffers, the memory guard, the mesh conversions, the output arrays, the composite merge
// and the input gathering (the boundary detection: TestBoundaryDetection.cxx). Built from the
// module's sources (they are private to it).
#include "DGMFCompositeMesh.h"
#include "DGMFCompositeMeshCache.h"
#include "DGMFContentKey.h"
#include "DGMFInputNodes.h"
#include "DGMFMemoryGuard.h"
#include "DGMFMeshConversion.h"
#include "DGMFOutputArrays.h"
#include "DGMFOutputBuffers.h"
#include "DGMFSMPTools.h"
#include "TwoSquares.h"

#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace
{

void SetEnvironment(const char* name, const char* value)
{
#ifdef _WIN32
  _putenv_s(name, value ? value : "");
#else
  if (value)
  {
    setenv(name, value, 1);
  }
  else
  {
    unsetenv(name);
  }
#endif
}

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

TEST(ContentKey, MatchesTheSameContentInAnyObjectAndNothingElse)
{
  vtkNew<vtkDoubleArray> a;
  a->SetNumberOfTuples(1000);
  for (vtkIdType i = 0; i < 1000; ++i)
  {
    a->SetValue(i, 0.5 * i);
  }
  const auto hashOf = [](vtkDataArray* array)
  { return [array]() { return dgmf_vtk::HashArray(array); }; };
  dgmf_vtk::ContentKey key;
  EXPECT_FALSE(key.Matches(a, hashOf(a)));
  key.Set(a, hashOf(a));
  EXPECT_TRUE(key.Matches(a, hashOf(a)));
  a->Modified(); // touched, same content
  EXPECT_TRUE(key.Matches(a, hashOf(a)));
  vtkNew<vtkDoubleArray> copy; // a new object with the same values (a reader's next time step)
  copy->DeepCopy(a);
  EXPECT_TRUE(key.Matches(copy, hashOf(copy)));
  copy->SetValue(999, -1.0);
  copy->Modified();
  EXPECT_FALSE(key.Matches(copy, hashOf(copy)));
  key.Reset();
  EXPECT_FALSE(key.Matches(a, hashOf(a)));
  const double x[3] = { 1, 2, 3 }, y[3] = { 1, 2, 4 };
  EXPECT_NE(dgmf_vtk::HashBytes(x, sizeof x), dgmf_vtk::HashBytes(y, sizeof y));
  EXPECT_EQ(dgmf_vtk::HashBytes(x, sizeof x), dgmf_vtk::HashBytes(x, sizeof x));
}

TEST(ContentKey, ALargeHashIsTheSameOnAnyNumberOfThreadsAndSeesEveryByte)
{
  // 10 MB: three blocks of the hash, the last one partial.
  std::vector<std::uint8_t> bytes(10'000'003);
  for (std::size_t i = 0; i < bytes.size(); ++i)
  {
    bytes[i] = static_cast<std::uint8_t>((i * 0x9e3779b97f4a7c15ull) >> 56);
  }
  const auto hash = [&](int threads)
  {
    std::uint64_t h = 0;
    dgmf_vtk::RunWithThreads(
      threads, [&]() { h = dgmf_vtk::HashBytes(bytes.data(), bytes.size()); });
    return h;
  };
  const std::uint64_t one = hash(1);
  EXPECT_EQ(hash(2), one);
  for (const std::size_t changed : { std::size_t(0), std::size_t(5'000'000), bytes.size() - 1 })
  {
    bytes[changed] ^= 1;
    EXPECT_NE(hash(2), one) << "byte " << changed;
    bytes[changed] ^= 1;
  }
  // Two blocks swapped: a different hash.
  std::swap_ranges(bytes.begin(), bytes.begin() + (1 << 22), bytes.begin() + (1 << 22));
  EXPECT_NE(hash(2), one);
}

TEST(ContentKey, AnObjectOnlyKeyMatchesThatObjectUnmodifiedWithoutHashing)
{
  vtkNew<vtkDoubleArray> a;
  a->SetNumberOfTuples(10);
  a->FillValue(1.0);
  int hashes = 0;
  const auto hashOf = [&hashes](vtkDataArray* array)
  {
    return [&hashes, array]()
    {
      ++hashes;
      return dgmf_vtk::HashArray(array);
    };
  };
  dgmf_vtk::ContentKey key;
  key.SetObjectOnly(a);
  EXPECT_TRUE(key.Matches(a, hashOf(a)));
  EXPECT_TRUE(key.MatchesObject(a));
  vtkNew<vtkDoubleArray> copy; // the same values in another object: not known without a hash
  copy->DeepCopy(a);
  EXPECT_FALSE(key.Matches(copy, hashOf(copy)));
  a->Modified(); // possibly changed in place
  EXPECT_FALSE(key.Matches(a, hashOf(a)));
  EXPECT_FALSE(key.MatchesObject(a));
  EXPECT_EQ(hashes, 0);
  key.Set(a, hashOf(a)); // a full key again compares content
  EXPECT_TRUE(key.Matches(copy, hashOf(copy)));
}

TEST(OutputBuffers, PointsAreReusedOnlyWhenNobodyElseHoldsThem)
{
  auto input = TwoSquares();
  vtkNew<vtkUnstructuredGrid> output;
  vtkSmartPointer<vtkPoints> last;
  vtkPoints* first = dgmf_vtk::ReuseOutputPoints(last, input, output, 6);
  output->SetPoints(first);
  EXPECT_EQ(dgmf_vtk::ReuseOutputPoints(last, input, output, 6).GetPointer(), first);
  vtkSmartPointer<vtkDataArray> heldByUser = first->GetData(); // e.g. a Python variable
  vtkPoints* second = dgmf_vtk::ReuseOutputPoints(last, input, output, 6);
  EXPECT_NE(second, first);
  EXPECT_EQ(second->GetNumberOfPoints(), 6);
  EXPECT_NE(dgmf_vtk::ReuseOutputPoints(last, input, output, 7).GetPointer(), second);
}

TEST(OutputBuffers, FieldArraysKeepTheirValuesAndNeverOverwriteAHeldArray)
{
  dgmf_vtk::FieldArrays fields;
  fields.Reset(4);
  const dgmf::FieldKey key{ 1.0, 0 }, other{ 2.0, 0 };
  EXPECT_EQ(fields.Find(dgmf::names::R, key), nullptr);
  double* r = fields.Store(dgmf::names::R, key);
  r[0] = 42.0;
  EXPECT_EQ(fields.Find(dgmf::names::R, key), r);
  EXPECT_EQ(fields.Find(dgmf::names::R, other), nullptr);
  EXPECT_STREQ(fields.GetArray(dgmf::names::R)->GetName(), "r");
  vtkSmartPointer<vtkDoubleArray> inAnOutput = fields.GetArray(dgmf::names::R);
  double* again = fields.Store(dgmf::names::R, other);
  EXPECT_NE(again, r); // a new array: the held one is left alone
  EXPECT_EQ(inAnOutput->GetValue(0), 42.0);
  EXPECT_EQ(fields.Store(dgmf::names::F, key), fields.Store(dgmf::names::F, other)); // not held
  fields.Reset(4);
  EXPECT_EQ(fields.Find(dgmf::names::R, other), nullptr); // a new mapping forgets every key
  EXPECT_EQ(fields.Prepare(true, false).size(), 1u);
  EXPECT_THROW(fields.Store("q", key), std::invalid_argument);
}

TEST(MemoryGuard, RefusesWhatCannotFitAndSaysSo)
{
  EXPECT_DOUBLE_EQ(dgmf_vtk::EstimateDeformationBytes(1000.0, 500.0), 1000.0 * 277 + 500.0 * 9);
  SetEnvironment("DGMF_PROCESS_MEMORY_KIB", nullptr);
  EXPECT_GT(dgmf_vtk::AvailableBytes(), 1e6);
  EXPECT_EQ(dgmf_vtk::CheckDeformationMemory(1000.0, 1000.0), "");
  SetEnvironment("DGMF_PROCESS_MEMORY_KIB", "1"); // a process limit of 1 KiB
  const std::string refused = dgmf_vtk::CheckDeformationMemory(1e6, 1e6);
  SetEnvironment("DGMF_PROCESS_MEMORY_KIB", nullptr);
  EXPECT_NE(refused.find("Deforming 1000000 points needs about"), std::string::npos) << refused;
  EXPECT_NE(refused.find("on a machine with more memory"), std::string::npos) << refused;
}

TEST(MeshConversion, CellShapesDimensionAndGrids)
{
  dgmf::CellShape shape;
  const int* order = nullptr;
  ASSERT_TRUE(dgmf_vtk::CellShapeOf(VTK_PIXEL, shape, order));
  EXPECT_EQ(shape, dgmf::CellShape::Quad);
  EXPECT_EQ(order[2], 3); // pixel corners 2 and 3 swap
  ASSERT_TRUE(dgmf_vtk::CellShapeOf(VTK_VOXEL, shape, order));
  EXPECT_EQ(shape, dgmf::CellShape::Hexahedron);
  EXPECT_EQ(order[6], 7);
  EXPECT_FALSE(dgmf_vtk::CellShapeOf(VTK_POLYHEDRON, shape, order));
  EXPECT_FALSE(dgmf_vtk::CellShapeOf(VTK_QUADRATIC_TETRA, shape, order));

  auto grid = TwoSquares();
  std::vector<double> copy;
  const double* xyz = dgmf_vtk::PointsAsDouble(grid->GetPoints(), copy);
  EXPECT_TRUE(copy.empty()); // doubles are used in place
  EXPECT_EQ(dgmf_vtk::DetectDimension(grid, xyz, 6), 2);
  grid->GetPoints()->SetPoint(5, 2.0, 1.0, 0.5);
  EXPECT_EQ(dgmf_vtk::DetectDimension(grid, xyz, 6), -1); // 2D cells off a plane z = constant
  const dgmf::CellMesh cells = dgmf_vtk::ToCellMesh(grid);
  ASSERT_EQ(cells.GetNumberOfCells(), 2u);
  EXPECT_EQ(cells.Connectivity[4], 1);

  vtkNew<vtkPolyData> patch; // a boundary patch, as the OpenFOAM reader gives it
  patch->SetPoints(grid->GetPoints());
  vtkNew<vtkCellArray> polygons;
  const vtkIdType triangle[3] = { 0, 1, 4 };
  polygons->InsertNextCell(3, triangle);
  patch->SetPolys(polygons);
  const vtkSmartPointer<vtkUnstructuredGrid> asGrid = dgmf_vtk::AsUnstructuredGrid(patch);
  ASSERT_EQ(asGrid->GetNumberOfCells(), 1);
  EXPECT_EQ(asGrid->GetCellType(0), VTK_TRIANGLE);
  EXPECT_EQ(asGrid->GetPoints(), grid->GetPoints());
  EXPECT_EQ(dgmf_vtk::AsUnstructuredGrid(grid).GetPointer(), grid.GetPointer());
}

TEST(OutputArrays, ReportsSummariesAndLocalNodesUnderTheSharedNames)
{
  vtkNew<vtkFieldData> fieldData;
  dgmf::DeformationReport report;
  report.AddCount(dgmf::names::RBFCentreCount, 12);
  report.Values.push_back({ dgmf::names::FittedTranslation, false, 3, { 1, 2, 3, 4, 5, 6 } });
  dgmf_vtk::AddReport(fieldData, report);
  ASSERT_TRUE(vtkIdTypeArray::SafeDownCast(fieldData->GetArray("RBFCentreCount")));
  EXPECT_EQ(dgmf_vtk::GetFieldValue(fieldData, "RBFCentreCount"), 12.0);
  vtkDataArray* fitted = fieldData->GetArray("FittedTranslation");
  ASSERT_TRUE(fitted);
  EXPECT_EQ(fitted->GetNumberOfTuples(), 2); // one tuple per body
  EXPECT_EQ(fitted->GetComponent(1, 2), 6.0);
  dgmf::QualitySummary summary;
  summary.Mean = 0.75;
  summary.Minimum = 0.5;
  summary.Inverted = 3;
  summary.Evaluated = 8;
  dgmf_vtk::SetQualitySummary(fieldData, summary);
  EXPECT_EQ(dgmf_vtk::GetFieldValue(fieldData, "SizeSkewMean"), 0.75);
  EXPECT_EQ(dgmf_vtk::GetFieldValue(fieldData, "InvertedCellCount"), 3.0);
  EXPECT_EQ(dgmf_vtk::GetFieldValue(fieldData, "SizeSkewEvaluatedCells"), 8.0);

  // A distributed run deformed 6 nodes, 4 of them its own: r and f keep the 4.
  auto grid = TwoSquares();
  dgmf_vtk::FieldArrays fields;
  fields.Reset(6);
  fields.Store(dgmf::names::F, dgmf::FieldKey{ 1.0, 1 })[3] = 0.25;
  dgmf_vtk::AddMethodResults(grid, nullptr, fields.GetArray(dgmf::names::F),
    dgmf::DeformationReport(), true, true, "DGMF", 4);
  vtkDataArray* f = grid->GetPointData()->GetArray("f");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->GetNumberOfTuples(), 4);
  EXPECT_EQ(f->GetTuple1(3), 0.25);
  EXPECT_FALSE(grid->GetPointData()->GetArray("r"));
  EXPECT_EQ(dgmf_vtk::GetFieldValue(grid->GetFieldData(), "GraphReused"), 1.0);
  auto* method = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("Method"));
  ASSERT_TRUE(method);
  EXPECT_EQ(method->GetValue(0), "DGMF");
}

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
  composite.ScatterResult(deformed, output);
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
