// The comparison methods through the filter: same inputs and outputs as DGMF, boundary
// reproduction, exact translation, the paper's ordering on the rotating rectangle, robustness on
// 10,000 boundary nodes, and the standalone quality filter.
#include "vtkDGMFDeformFilter.h"
#include "vtkSizeSkewQualityFilter.h"

#include "FieldValue.h"
#include "HexahedraOfGrid.h"
#include "ShippedMesh.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;
const int AllMethods[] = { vtkDGMFDeformFilter::DGMF, vtkDGMFDeformFilter::DGM,
  vtkDGMFDeformFilter::DGRBF, vtkDGMFDeformFilter::RBF, vtkDGMFDeformFilter::IDW };
const char* const MethodNames[] = { "DGMF", "DGM", "DGRBF", "RBF", "IDW" };

using dgmf_test::Field;

vtkSmartPointer<vtkUnstructuredGrid> Deform(
  vtkUnstructuredGrid* mesh, int method, const double angles[3], const double translation[3])
{
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetMethod(method);
  filter->SetRotationAngles(angles[0], angles[1], angles[2]);
  filter->SetTranslation(translation[0], translation[1], translation[2]);
  filter->Update();
  return filter->GetOutput();
}
} // namespace

TEST(Methods, EveryMethodReproducesTheBoundaryMotion)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_rectangle.vtu", 768);
  const double angles[3] = { 0, 0, 30 };
  const double translation[3] = { 0.2, -0.1, 0 };
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  const double a = 30.0 * Pi / 180.0;
  for (int method : AllMethods)
  {
    auto out = Deform(mesh, method, angles, translation);
    ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << MethodNames[method];
    auto* name = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("Method"));
    ASSERT_NE(name, nullptr);
    EXPECT_EQ(name->GetValue(0), MethodNames[method]);
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double x[3], y[3];
      mesh->GetPoint(i, x);
      out->GetPoint(i, y);
      const int kind = static_cast<int>(marker->GetTuple1(i));
      if (kind == 0)
        continue;
      double expected[2] = { x[0], x[1] };
      if (kind == 2)
      {
        expected[0] = std::cos(a) * x[0] - std::sin(a) * x[1] + translation[0];
        expected[1] = std::sin(a) * x[0] + std::cos(a) * x[1] + translation[1];
      }
      const double scale = std::max(1.0, std::hypot(expected[0], expected[1]));
      EXPECT_NEAR(y[0], expected[0], 1e-10 * scale) << MethodNames[method] << " node " << i;
      EXPECT_NEAR(y[1], expected[1], 1e-10 * scale) << MethodNames[method] << " node " << i;
    }
    EXPECT_NE(out->GetCellData()->GetArray("SizeSkew"), nullptr);
  }
}

TEST(Methods, PureTranslationIsExactEverywhere)
{
  auto mesh = dgmf_test::ReadShippedMesh("sphere_in_box.vtu", 3200);
  // Every boundary node moves: mark the box as moving too.
  vtkNew<vtkUnstructuredGrid> allMoving;
  allMoving->DeepCopy(mesh);
  vtkDataArray* marker = allMoving->GetPointData()->GetArray("BoundaryMarker");
  for (vtkIdType i = 0; i < allMoving->GetNumberOfPoints(); ++i)
  {
    if (marker->GetTuple1(i) == 1)
      marker->SetTuple1(i, 2);
  }
  const double angles[3] = { 0, 0, 0 };
  const double translation[3] = { 0.3, -0.2, 0.1 };
  for (int method : AllMethods)
  {
    if (method == vtkDGMFDeformFilter::DGMF)
      continue; // DGMF scales the translation by f, which is 1 everywhere only with no static node
    auto out = Deform(allMoving, method, angles, translation);
    ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    double largest = 0.0;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double x[3], y[3];
      mesh->GetPoint(i, x);
      out->GetPoint(i, y);
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(y[c] - x[c] - translation[c]));
    }
    EXPECT_LT(largest, 1e-12) << MethodNames[method];
    EXPECT_EQ(Field(out, "InvertedCellCount"), 0.0) << MethodNames[method];
  }
}

TEST(Methods, DGMFKeepsTheRotatingRectangleBetterThanDGMAt60Degrees)
{
  // The paper's Fig. 4: DGM degrades quickly with the rotation angle, DGMF does not.
  auto mesh = dgmf_test::ReadShippedMesh("rotating_rectangle.vtu", 768);
  const double angles[3] = { 0, 0, 60 };
  const double none[3] = { 0, 0, 0 };
  auto dgmf = Deform(mesh, vtkDGMFDeformFilter::DGMF, angles, none);
  auto dgm = Deform(mesh, vtkDGMFDeformFilter::DGM, angles, none);
  const double dgmfMean = Field(dgmf, "SizeSkewMean");
  const double dgmMean = Field(dgm, "SizeSkewMean");
  std::cout << "rotating rectangle, 60 degrees: SizeSkew mean DGMF " << dgmfMean << " (minimum "
            << Field(dgmf, "SizeSkewMinimum") << "), DGM " << dgmMean << " (minimum "
            << Field(dgm, "SizeSkewMinimum") << ")" << std::endl;
  EXPECT_GE(dgmfMean, dgmMean);
}

TEST(Methods, DGMCountsInvertedGraphElements)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  const double angles[3] = { 0, 0, 90 };
  const double none[3] = { 0, 0, 0 };
  auto out = Deform(mesh, vtkDGMFDeformFilter::DGM, angles, none);
  ASSERT_GT(out->GetNumberOfPoints(), 0); // the result is produced even so
  EXPECT_GT(Field(out, "InvertedGraphElementCount"), 0.0);
}

TEST(Methods, GreedyRBFMeetsItsToleranceQuickly)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetMethodToRBF();
  filter->RBFGreedyOn();
  filter->SetRBFGreedyTolerance(1e-3);
  filter->SetRotationAngles(0, 0, 45);
  filter->Update();
  vtkUnstructuredGrid* out = filter->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  EXPECT_LE(Field(out, "RBFBoundaryError"), 1e-3);
  EXPECT_LT(Field(out, "RBFCentreCount"), 115.0); // fewer centres than the 115 boundary nodes
}

namespace
{
/// A structured hexahedral box [0, 1]^3 of (n+1)^3 nodes: the outer faces are static, and every
/// node of the block [0.4, 0.6]^3 is moving (a rigid body meshed through).
vtkSmartPointer<vtkUnstructuredGrid> MarkedBox(int n)
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  const int m = n + 1;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
      {
        points->InsertNextPoint(i / double(n), j / double(n), k / double(n));
        const bool outer = i == 0 || j == 0 || k == 0 || i == n || j == n || k == n;
        auto inBody = [n](int c) { return c >= 0.4 * n && c <= 0.6 * n; };
        const bool body = inBody(i) && inBody(j) && inBody(k);
        marker->InsertNextValue(outer ? 1 : body ? 2 : 0);
      }
  mesh->SetPoints(points);
  mesh->GetPointData()->AddArray(marker);
  mesh->Allocate(n * n * n);
  dgmf_test::AddHexahedraOfGrid(mesh, n);
  return mesh;
}
} // namespace

TEST(Methods, TenThousandBoundaryNodesNeitherCrashNorHang)
{
  // 42^3 nodes: 6 * 41^2 + 2 = 10,088 outer boundary nodes plus the body's 9^3. RBF without greedy
  // selection would need a dense solve of that size: it runs with greedy selection here.
  auto mesh = MarkedBox(41);
  const double translation[3] = { 0.01, 0.005, 0.0 };
  const double angles[3] = { 0, 0, 3 };
  for (int method : AllMethods)
  {
    const auto start = std::chrono::steady_clock::now();
    vtkNew<vtkDGMFDeformFilter> filter;
    filter->SetInputData(mesh);
    filter->SetBoundaryMarkerArrayName("BoundaryMarker");
    filter->SetMethod(method);
    filter->SetRotationCenter(0.5, 0.5, 0.5);
    filter->SetRotationAngles(angles[0], angles[1], angles[2]);
    filter->SetTranslation(translation[0], translation[1], translation[2]);
    if (method == vtkDGMFDeformFilter::RBF)
    {
      filter->RBFGreedyOn();
      filter->SetRBFGreedyTolerance(1e-2);
    }
    filter->Update();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << MethodNames[method] << " on " << mesh->GetNumberOfPoints() << " nodes: " << seconds
              << " s" << std::endl;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints())
      << MethodNames[method];
    EXPECT_EQ(Field(filter->GetOutput(), "InvertedCellCount"), 0.0) << MethodNames[method];
  }
}

TEST(Methods, QualityFilterMeasuresAnyPairOfMeshes)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  const double angles[3] = { 0, 0, 45 };
  const double none[3] = { 0, 0, 0 };
  auto deformed = Deform(mesh, vtkDGMFDeformFilter::RBF, angles, none);
  vtkNew<vtkSizeSkewQualityFilter> quality;
  quality->SetInputData(deformed);
  quality->SetReferenceData(mesh);
  quality->Update();
  vtkUnstructuredGrid* out = quality->GetOutput();
  ASSERT_EQ(out->GetNumberOfCells(), mesh->GetNumberOfCells());
  vtkDataArray* ours = out->GetCellData()->GetArray("SizeSkew");
  vtkDataArray* filters = deformed->GetCellData()->GetArray("SizeSkew");
  ASSERT_TRUE(ours && filters);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    ASSERT_EQ(ours->GetTuple1(c), filters->GetTuple1(c));
  EXPECT_EQ(Field(out, "SizeSkewMean"), Field(deformed, "SizeSkewMean"));

  // The mesh against itself: every cell keeps its size, the score is the shape alone (<= 1).
  vtkNew<vtkSizeSkewQualityFilter> identity;
  identity->SetInputData(mesh);
  identity->SetReferenceData(mesh);
  identity->Update();
  EXPECT_EQ(Field(identity->GetOutput(), "InvertedCellCount"), 0.0);

  // Different meshes: a clear error and no output.
  auto other = dgmf_test::ReadShippedMesh("rotating_rectangle.vtu", 768);
  vtkNew<vtkSizeSkewQualityFilter> mismatch;
  mismatch->SetInputData(mesh);
  mismatch->SetReferenceData(other);
  mismatch->Update();
  EXPECT_EQ(mismatch->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(Methods, TheMethodTableNamesEveryMethodTheFilterRuns)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  int count = 0;
  for (int method = 0; vtkDGMFDeformFilter::GetMethodName(method); ++method, ++count)
  {
    const std::string key = vtkDGMFDeformFilter::GetMethodKey(method);
    ASSERT_EQ(vtkDGMFDeformFilter::GetMethodFromName(key.c_str()), method) << key;
    ASSERT_EQ(
      vtkDGMFDeformFilter::GetMethodFromName(vtkDGMFDeformFilter::GetMethodName(method)), method);
    vtkNew<vtkDGMFDeformFilter> filter;
    filter->SetInputData(mesh);
    filter->SetBoundaryMarkerArrayName("BoundaryMarker");
    filter->SetMethod(vtkDGMFDeformFilter::GetMethodFromName(key.c_str()));
    filter->SetRotationAngles(0, 0, 10);
    filter->Update();
    auto* name =
      vtkStringArray::SafeDownCast(filter->GetOutput()->GetFieldData()->GetAbstractArray("Method"));
    ASSERT_TRUE(name) << key;
    EXPECT_EQ(name->GetValue(0), vtkDGMFDeformFilter::GetMethodName(method));
  }
  EXPECT_EQ(count, 5);
  EXPECT_EQ(vtkDGMFDeformFilter::GetMethodFromName("NoSuchMethod"), -1);
  EXPECT_EQ(vtkDGMFDeformFilter::GetMethodKeys(" | "), "dgmf | dgm | dgrbf | rbf | idw");
}
