// The VTK adapter's parts, each on its own (Documentation/architecture.md): the content key, the
// output buffers, the memory guard, the mesh conversions, the output arrays, the composite merge
// and the input gathering (the boundary detection: TestBoundaryDetection.cxx). Built from the
// module's sources (they are private to it).
#include "DGMFContentKey.h"
#include "DGMFInputNodes.h"
#include "DGMFMemoryGuard.h"
#include "DGMFMeshConversion.h"
#include "DGMFOutputArrays.h"
#include "DGMFOutputBuffers.h"
#include "DGMFSMPTools.h"
#include "HexahedraOfGrid.h"
#include "TwoSquares.h"

#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

TEST(ContentKey, ThePatchesKeyTellsNoneTheSameCellsAndNewCellsApart)
{
  dgmf_vtk::PatchesKey key;
  EXPECT_FALSE(key.Matches(nullptr)) << "never set";
  key.Set(nullptr);
  EXPECT_TRUE(key.Matches(nullptr));
  auto patches = TwoSquares();
  EXPECT_FALSE(key.Matches(patches));
  key.Set(patches);
  EXPECT_TRUE(key.Matches(patches));
  EXPECT_FALSE(key.Matches(nullptr));
  vtkNew<vtkUnstructuredGrid> again; // a new merge of the same blocks
  again->DeepCopy(patches);
  EXPECT_TRUE(key.Matches(again));
  vtkNew<vtkUnstructuredGrid> more; // patches with one more polygon
  more->DeepCopy(patches);
  const vtkIdType other[4] = { 0, 1, 4, 3 };
  more->InsertNextCell(VTK_QUAD, 4, other);
  EXPECT_FALSE(key.Matches(more));
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
  // A composite input's patches kept apart: the guard's cells are the grid's, then theirs.
  const dgmf::CellMesh both = dgmf_vtk::ToCellMesh(grid, asGrid);
  ASSERT_EQ(both.GetNumberOfCells(), 3u);
  EXPECT_EQ(both.Shapes[2], dgmf::CellShape::Triangle);
  EXPECT_EQ(both.Connectivity[static_cast<std::size_t>(both.Offsets[2]) + 2], 4);
  // The hint stride samples the patches' cells after the grid's, as in one grid holding both:
  // a 4^3 box (stride 25, a layer) and many quads of its side z = 0 (whose edges make it 5).
  const vtkSmartPointer<vtkUnstructuredGrid> box = dgmf_test::HexahedralBox(4);
  vtkNew<vtkUnstructuredGrid> sides;
  sides->SetPoints(box->GetPoints());
  vtkNew<vtkUnstructuredGrid> one;
  one->DeepCopy(box);
  for (int copy = 0; copy < 40; ++copy)
  {
    for (vtkIdType j = 0; j < 4; ++j)
    {
      for (vtkIdType i = 0; i < 4; ++i)
      {
        const vtkIdType quad[4] = { i + 5 * j, i + 1 + 5 * j, i + 1 + 5 * (j + 1),
          i + 5 * (j + 1) };
        sides->InsertNextCell(VTK_QUAD, 4, quad);
        one->InsertNextCell(VTK_QUAD, 4, quad);
      }
    }
  }
  EXPECT_EQ(dgmf_vtk::HintStrideOf(box), 25u);
  EXPECT_EQ(dgmf_vtk::HintStrideOf(one), 5u);
  EXPECT_EQ(dgmf_vtk::HintStrideOf(box, sides), dgmf_vtk::HintStrideOf(one));
  // The dimension of a block's cells, and whether they are all polygons (what may be a patch).
  bool polygonsOnly = false;
  EXPECT_EQ(dgmf_vtk::CellDimensionOf(dgmf_vtk::CellTypesOf(patch), polygonsOnly), 2);
  EXPECT_TRUE(polygonsOnly);
  vtkNew<vtkCellArray> lines;
  const vtkIdType segment[2] = { 0, 1 };
  lines->InsertNextCell(2, segment);
  patch->SetLines(lines);
  EXPECT_EQ(dgmf_vtk::CellDimensionOf(dgmf_vtk::CellTypesOf(patch), polygonsOnly), 2);
  EXPECT_FALSE(polygonsOnly) << "a line";
}

TEST(MeshConversion, CellTypesAreFoundWhereverTheyAreInLongRuns)
{
  // 600,003 cells over three of the passes' blocks: hexahedra, and other types alone or in short
  // runs at places that are not multiples of 8 (the runs are skipped 8 bytes at a time).
  const vtkIdType n = 600'003;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(n);
  types->FillValue(VTK_HEXAHEDRON);
  types->SetValue(5, VTK_TRIANGLE);
  types->SetValue(262'150, VTK_TRIANGLE);
  for (vtkIdType c = 300'001; c < 300'014; ++c)
  {
    types->SetValue(c, VTK_TETRA);
  }
  types->SetValue(n - 1, VTK_QUAD);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  connectivity->FillValue(0);
  for (vtkIdType c = 0; c <= n; ++c)
  {
    offsets->SetValue(c, c);
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetCells(types, cells, nullptr, nullptr);
  std::array<bool, 256> present{};
  dgmf_vtk::RunWithThreads(2, [&]() { present = dgmf_vtk::CellTypesPresent(grid); });
  for (int type = 0; type < 256; ++type)
  {
    const bool expected =
      type == VTK_HEXAHEDRON || type == VTK_TRIANGLE || type == VTK_TETRA || type == VTK_QUAD;
    EXPECT_EQ(present[static_cast<std::size_t>(type)], expected) << "type " << type;
  }
  std::array<bool, 256> polygons{};
  polygons[VTK_TRIANGLE] = polygons[VTK_QUAD] = true;
  EXPECT_EQ(dgmf_vtk::CellsOfTypes(grid, polygons), (std::vector<vtkIdType>{ 5, 262'150, n - 1 }));
  EXPECT_TRUE(dgmf_vtk::CellsOfTypes(grid, std::array<bool, 256>{}).empty());
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
