// The quality OpenFOAM users act on, through the VTK filters: polyhedra get a SizeSkew, cells
// invalid in the input are counted apart, and the face non-orthogonality is checkMesh's.
#include "vtkDGMFDeformFilter.h"
#include "vtkSizeSkewQualityFilter.h"

#include "FieldValue.h"
#include "HexahedraOfGrid.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <array>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using dgmf_test::Field;

namespace
{
/// Two unit cubes along x sharing the face x = 1: the first a hexahedron, the second a
/// hexahedron or the same cell as a polyhedron (OpenFOAM's cells, as its reader gives them).
vtkSmartPointer<vtkUnstructuredGrid> TwoCubes(bool polyhedron)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (double x : { 0.0, 1.0, 2.0 })
  {
    for (double z : { 0.0, 1.0 })
    {
      for (double y : { 0.0, 1.0 })
      {
        points->InsertNextPoint(x, y, z);
      }
    }
  }
  const auto id = [](int i, int y, int z) { return static_cast<vtkIdType>(4 * i + 2 * z + y); };
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->SetPoints(points);
  for (int i = 0; i < 2; ++i)
  {
    const vtkIdType hex[8] = { id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0),
      id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1) };
    if (i == 1 && polyhedron)
    {
      const int faces[6][4] = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 },
        { 0, 3, 2, 1 }, { 4, 5, 6, 7 } };
      vtkNew<vtkIdList> stream;
      stream->InsertNextId(6);
      for (const auto& face : faces)
      {
        stream->InsertNextId(4);
        for (int k : face)
        {
          stream->InsertNextId(hex[k]);
        }
      }
      mesh->InsertNextCell(VTK_POLYHEDRON, stream);
    }
    else
    {
      mesh->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
    }
  }
  return mesh;
}

/// `mesh` with the points of the face x = 2 moved by `dy` along y.
vtkSmartPointer<vtkUnstructuredGrid> Sheared(vtkUnstructuredGrid* mesh, double dy)
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->DeepCopy(mesh);
  for (vtkIdType p = 8; p < 12; ++p)
  {
    double x[3];
    out->GetPoint(p, x);
    x[1] += dy;
    out->GetPoints()->SetPoint(p, x);
  }
  return out;
}

vtkUnstructuredGrid* Measure(
  vtkSizeSkewQualityFilter* quality, vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* reference)
{
  quality->SetInputData(mesh);
  quality->SetReferenceData(reference);
  quality->ComputeNonOrthogonalityOn();
  quality->Update();
  return quality->GetOutput();
}
} // namespace

TEST(FaceQualityFilters, APolyhedronGetsASizeSkewAndTheSameNonOrthogonalityAsAHexahedron)
{
  for (bool polyhedron : { false, true })
  {
    SCOPED_TRACE(polyhedron ? "polyhedron" : "hexahedron");
    const vtkSmartPointer<vtkUnstructuredGrid> mesh = TwoCubes(polyhedron);
    vtkNew<vtkSizeSkewQualityFilter> quality;
    vtkUnstructuredGrid* same = Measure(quality, mesh, mesh);
    EXPECT_EQ(Field(same, "SizeSkewEvaluatedCells"), 2.0);
    EXPECT_NEAR(same->GetCellData()->GetArray("SizeSkew")->GetTuple1(1), 1.0, 1e-12);
    EXPECT_EQ(Field(same, "MaximumNonOrthogonality"), 0.0);
    // Sheared by 2: the neighbour's centre moves by 1 along y, 45 degrees.
    vtkUnstructuredGrid* sheared = Measure(quality, Sheared(mesh, 2.0), mesh);
    EXPECT_EQ(Field(sheared, "SizeSkewEvaluatedCells"), 2.0);
    const double sizeSkew = sheared->GetCellData()->GetArray("SizeSkew")->GetTuple1(1);
    EXPECT_GT(sizeSkew, 0.0);
    EXPECT_LT(sizeSkew, 1.0);
    EXPECT_NEAR(Field(sheared, "MaximumNonOrthogonality"), 45.0, 1e-10);
    EXPECT_NEAR(Field(sheared, "InputMaximumNonOrthogonality"), 0.0, 1e-12);
    EXPECT_NEAR(sheared->GetCellData()->GetArray("NonOrthogonality")->GetTuple1(0), 45.0, 1e-10);
    EXPECT_EQ(Field(sheared, "InvertedCellCount"), 0.0);
  }
}

namespace
{
/**
 * Cell `cell` of `mesh` dented by moving point `dent` inside it (`inside`: OpenFOAM accepts the
 * cell, the corner metric calls it inverted) is counted invalid in the input, not inverted, with
 * the size-skew of an unchanged cell; the dent pushed through the cell's bottom (`through`)
 * inverts it, and it stays counted invalid in the input.
 */
void ExpectDentedCellJudgedThroughItsFaces(vtkUnstructuredGrid* mesh, vtkIdType cell,
  vtkIdType dent, const std::array<double, 3>& inside, const std::array<double, 3>& through)
{
  vtkNew<vtkUnstructuredGrid> dented;
  dented->DeepCopy(mesh);
  dented->GetPoints()->SetPoint(dent, inside.data());
  vtkNew<vtkSizeSkewQualityFilter> quality;
  vtkUnstructuredGrid* same = Measure(quality, dented, dented);
  EXPECT_EQ(Field(same, "InputInvalidCellCount"), 1.0);
  EXPECT_EQ(Field(same, "InvertedCellCount"), 0.0);
  EXPECT_EQ(same->GetCellData()->GetArray("InputInvalid")->GetTuple1(cell), 1.0);
  EXPECT_NEAR(same->GetCellData()->GetArray("SizeSkew")->GetTuple1(cell), 1.0, 1e-12);
  vtkNew<vtkUnstructuredGrid> pushed;
  pushed->DeepCopy(dented);
  pushed->GetPoints()->SetPoint(dent, through.data());
  vtkUnstructuredGrid* inverted = Measure(quality, pushed, dented);
  EXPECT_EQ(Field(inverted, "InvertedCellCount"), 1.0);
  EXPECT_EQ(inverted->GetCellData()->GetArray("Inverted")->GetTuple1(cell), 1.0);
  EXPECT_EQ(Field(inverted, "InputInvalidCellCount"), 1.0);
}
} // namespace

TEST(FaceQualityFilters, CellsInvalidInTheInputAreCountedApartFromCellsTheMotionInverts)
{
  // The second cube dented (corner 6 below its mid-plane).
  ExpectDentedCellJudgedThroughItsFaces(
    TwoCubes(false), 1, 10, { 1.6, 0.6, 0.3 }, { 1.6, 0.6, -0.5 });
}

TEST(FaceQualityFilters, ADentedCellPastTheFirstGroupOfFourIsJudgedThroughItsFaces)
{
  // 7 separate unit cubes, the sixth (cell 5: the second lane of the second group of four that the
  // metric evaluates together) dented the same way: the deformed corners of that lane are taken
  // out of the group for the faces' judgement.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkUnstructuredGrid> cubes;
  cubes->SetPoints(points);
  constexpr double corner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  for (int i = 0; i < 7; ++i)
  {
    vtkIdType hex[8];
    for (int k = 0; k < 8; ++k)
    {
      hex[k] = points->InsertNextPoint(2.0 * i + corner[k][0], corner[k][1], corner[k][2]);
    }
    cubes->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  }
  // Corner 5 of cube 5 (x = 11, y = 0, z = 1), as the dent of TwoCubes.
  ExpectDentedCellJudgedThroughItsFaces(
    cubes, 5, 8 * 5 + 5, { 10.6, 0.6, 0.3 }, { 10.6, 0.6, -0.5 });
}

namespace
{
/// A box of n^3 hexahedra, its points jittered (every cell different), with a BoundaryMarker:
/// 2 (moving) on the face x = 0, 1 (static) on the rest of the boundary.
vtkSmartPointer<vtkUnstructuredGrid> JitteredBox(int n)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        const bool boundary = i == 0 || j == 0 || k == 0 || i == n || j == n || k == n;
        points->InsertNextPoint(i + (boundary ? 0.0 : jitter(random)),
          j + (boundary ? 0.0 : jitter(random)), k + (boundary ? 0.0 : jitter(random)));
        marker->InsertNextValue(i == 0 ? 2 : boundary ? 1 : 0);
      }
  auto box = vtkSmartPointer<vtkUnstructuredGrid>::New();
  box->SetPoints(points);
  box->GetPointData()->AddArray(marker);
  dgmf_test::AddHexahedraOfGrid(box, n);
  return box;
}

/// True when the SizeSkew arrays of `a` and `b` hold the same bits.
bool SameSizeSkew(vtkUnstructuredGrid* a, vtkUnstructuredGrid* b)
{
  auto* x = vtkDoubleArray::SafeDownCast(a->GetCellData()->GetArray("SizeSkew"));
  auto* y = vtkDoubleArray::SafeDownCast(b->GetCellData()->GetArray("SizeSkew"));
  return x && y && x->GetNumberOfTuples() == a->GetNumberOfCells() &&
    y->GetNumberOfTuples() == x->GetNumberOfTuples() &&
    std::memcmp(x->GetPointer(0), y->GetPointer(0),
      sizeof(double) * static_cast<std::size_t>(x->GetNumberOfTuples())) == 0;
}

/// The SizeSkew of `mesh` against `reference` by a new quality filter (nothing kept).
vtkSmartPointer<vtkUnstructuredGrid> FreshQuality(
  vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* reference)
{
  vtkNew<vtkSizeSkewQualityFilter> quality;
  quality->SetInputData(mesh);
  quality->SetReferenceData(reference);
  quality->Update();
  return quality->GetOutput();
}
} // namespace

TEST(FaceQualityFilters, ANewMotionReusesTheHexahedraOriginalHalfAndFollowsAChangedInput)
{
  const int n = 8; // 512 hexahedra
  const vtkSmartPointer<vtkUnstructuredGrid> box = JitteredBox(n);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(box);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetTranslation(-0.3, 0.1, 0.0);
  filter->ComputeQualityOff();
  filter->Update();
  const std::size_t withoutQuality = filter->GetCacheMemorySize();
  // Frame after frame, the quality equals a fresh filter's, bit for bit.
  filter->ComputeQualityOn();
  for (double angle : { 5.0, 20.0, 35.0 })
  {
    SCOPED_TRACE(angle);
    filter->SetRotationAngles(0.0, 0.0, angle);
    filter->Update();
    EXPECT_TRUE(filter->GetLastExecutionReusedGraph());
    EXPECT_TRUE(SameSizeSkew(filter->GetOutput(), FreshQuality(filter->GetOutput(), box)));
    EXPECT_GT(filter->GetLastQualitySeconds(), 0.0);
  }
  // The reference sizes are kept: 8 bytes per cell.
  EXPECT_EQ(filter->GetCacheMemorySize(), withoutQuality + 8 * box->GetNumberOfCells());
  // The input's interior points moved in place (the same object, modified): the original half
  // must follow them, not the kept one.
  for (vtkIdType p = 0; p < box->GetNumberOfPoints(); ++p)
  {
    if (vtkArrayDownCast<vtkIntArray>(box->GetPointData()->GetArray("BoundaryMarker"))
          ->GetValue(p) == 0)
    {
      double x[3];
      box->GetPoint(p, x);
      box->GetPoints()->SetPoint(p, x[0] + 0.1, 0.9 * x[1] + 0.05, x[2]);
    }
  }
  box->GetPoints()->Modified();
  filter->Update();
  EXPECT_TRUE(SameSizeSkew(filter->GetOutput(), FreshQuality(filter->GetOutput(), box)));
  // The quality filter keeps the same half for a mesh measured again against one reference.
  vtkNew<vtkSizeSkewQualityFilter> quality;
  quality->SetReferenceData(box);
  for (double angle : { 10.0, 40.0 })
  {
    filter->SetRotationAngles(0.0, 0.0, angle);
    filter->Update();
    vtkNew<vtkUnstructuredGrid> deformed;
    deformed->ShallowCopy(filter->GetOutput());
    quality->SetInputData(deformed);
    quality->Update();
    EXPECT_TRUE(SameSizeSkew(quality->GetOutput(), FreshQuality(deformed, box)));
  }
}

TEST(FaceQualityFilters, TheQualityArraysAreReusedOnlyWhenNobodyElseHoldsThem)
{
  const vtkSmartPointer<vtkUnstructuredGrid> box = JitteredBox(6);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(box);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetRotationAngles(0.0, 0.0, 10.0);
  filter->Update();
  vtkDataArray* first = filter->GetOutput()->GetCellData()->GetArray("SizeSkew");
  ASSERT_NE(first, nullptr);
  // A new motion writes into the same memory when only the filter holds it.
  filter->SetRotationAngles(0.0, 0.0, 20.0);
  filter->Update();
  vtkDataArray* second = filter->GetOutput()->GetCellData()->GetArray("SizeSkew");
  EXPECT_EQ(second, first);
  EXPECT_TRUE(SameSizeSkew(filter->GetOutput(), FreshQuality(filter->GetOutput(), box)));
  // Held by the user (a Python variable, a downstream filter): never written again.
  vtkSmartPointer<vtkDataArray> held = second;
  std::vector<double> before(static_cast<std::size_t>(held->GetNumberOfTuples()));
  for (vtkIdType c = 0; c < held->GetNumberOfTuples(); ++c)
    before[static_cast<std::size_t>(c)] = held->GetTuple1(c);
  filter->SetRotationAngles(0.0, 0.0, 40.0);
  filter->Update();
  EXPECT_NE(filter->GetOutput()->GetCellData()->GetArray("SizeSkew"), held.GetPointer());
  for (vtkIdType c = 0; c < held->GetNumberOfTuples(); ++c)
    ASSERT_EQ(held->GetTuple1(c), before[static_cast<std::size_t>(c)]);
  EXPECT_TRUE(SameSizeSkew(filter->GetOutput(), FreshQuality(filter->GetOutput(), box)));
}
