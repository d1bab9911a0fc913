// Rigid motions extracted from displacements, and several moving bodies, through the filter.
#include "vtkDGMFDeformFilter.h"

#include "ErrorMessages.h"
#include "FieldValue.h"
#include "ShippedMesh.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Displacement of a rotation by `degrees` about (cx, cy) at the nodes where `select` holds.
template <typename Select>
void SetRotationDisplacement(
  vtkUnstructuredGrid* mesh, double degrees, double cx, double cy, Select select)
{
  vtkDataArray* d = mesh->GetPointData()->GetArray("Displacement");
  const double a = degrees * Pi / 180.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (!select(i))
      continue;
    const double* x = mesh->GetPoint(i);
    const double dx = x[0] - cx, dy = x[1] - cy;
    const double value[3] = { cx + std::cos(a) * dx - std::sin(a) * dy - x[0],
      cy + std::sin(a) * dx + std::cos(a) * dy - x[1], 0.0 };
    d->SetTuple(i, value);
  }
  d->Modified();
}

using dgmf_test::Field;
} // namespace

TEST(Bodies, RotationGivenOnlyAsDisplacementMatchesTheExplicitRotation)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822, 1529);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  SetRotationDisplacement(
    mesh, 90.0, 0.0, 0.0, [&](vtkIdType i) { return marker->GetTuple1(i) == 2; });

  vtkNew<vtkDGMFDeformFilter> extracted;
  extracted->SetInputData(mesh);
  extracted->SetBoundaryMarkerArrayName("BoundaryMarker");
  extracted->SetDisplacementArrayName("Displacement");
  extracted->SetRigidMotionModeToExtracted();
  extracted->Update();
  vtkUnstructuredGrid* a = extracted->GetOutput();
  ASSERT_EQ(a->GetNumberOfPoints(), 822);
  EXPECT_NEAR(Field(a, "FittedRotationAngle"), 90.0, 1e-9);
  EXPECT_NEAR(Field(a, "FittedRotationAxis", 2), 1.0, 1e-12);
  EXPECT_LT(Field(a, "FittedResidualRMS"), 1e-12);

  auto still = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822, 1529);
  vtkNew<vtkDGMFDeformFilter> explicitRotation;
  explicitRotation->SetInputData(still);
  explicitRotation->SetBoundaryMarkerArrayName("BoundaryMarker");
  explicitRotation->SetRotationAngles(0, 0, 90);
  explicitRotation->Update();
  vtkUnstructuredGrid* b = explicitRotation->GetOutput();
  for (vtkIdType i = 0; i < 822; ++i)
  {
    const double* p = a->GetPoint(i);
    const double* q = b->GetPoint(i);
    const double scale = std::max(1.0, std::hypot(q[0], q[1]));
    ASSERT_NEAR(p[0], q[0], 1e-9 * scale) << "node " << i;
    ASSERT_NEAR(p[1], q[1], 1e-9 * scale) << "node " << i;
  }
}

TEST(Bodies, TwoCirclesTurningInOppositeDirections)
{
  auto mesh = dgmf_test::ReadShippedMesh("two_circles.vtu", 1118, 2054);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetBodyIdArrayName("BodyId");
  filter->SetBodyMotion(1, 0, 0, 0, -2.5, 0, 0, 0, 0, 45);
  filter->SetBodyMotion(2, 0, 0, 0, 2.5, 0, 0, 0, 0, -45);
  filter->Update();
  vtkUnstructuredGrid* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 1118);
  EXPECT_EQ(Field(out, "InvertedCellCount"), 0.0);
  std::cout << "two circles, +-45 degrees: SizeSkew mean " << Field(out, "SizeSkewMean")
            << ", minimum " << Field(out, "SizeSkewMinimum") << std::endl;

  // Each body turned about its own centre by its own angle.
  vtkDataArray* body = mesh->GetPointData()->GetArray("BodyId");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const int id = static_cast<int>(body->GetTuple1(i));
    if (id == 0)
      continue;
    const double cx = id == 1 ? -2.5 : 2.5;
    const double a = (id == 1 ? 45.0 : -45.0) * Pi / 180.0;
    const double* x = mesh->GetPoint(i);
    const double* y = out->GetPoint(i);
    EXPECT_NEAR(y[0], cx + std::cos(a) * (x[0] - cx) - std::sin(a) * x[1], 1e-12);
    EXPECT_NEAR(y[1], std::sin(a) * (x[0] - cx) + std::cos(a) * x[1], 1e-12);
  }

  // The cells touching each body turn rigidly with it: their SizeSkew stays close to the original.
  vtkNew<vtkDGMFDeformFilter> still;
  still->SetInputData(mesh);
  still->SetBoundaryMarkerArrayName("BoundaryMarker");
  still->SetBodyIdArrayName("BodyId");
  still->Update();
  vtkDataArray* before = still->GetOutput()->GetCellData()->GetArray("SizeSkew");
  vtkDataArray* after = out->GetCellData()->GetArray("SizeSkew");
  int adjacent = 0;
  double largestChange = 0.0, totalChange = 0.0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    mesh->GetCells()->GetCellAtId(c, npts, pts);
    bool touches = false;
    for (vtkIdType k = 0; k < npts; ++k)
      touches = touches || body->GetTuple1(pts[k]) > 0;
    if (!touches)
      continue;
    ++adjacent;
    const double change = std::abs(after->GetTuple1(c) - before->GetTuple1(c));
    largestChange = std::max(largestChange, change);
    totalChange += change;
  }
  std::cout << adjacent << " cells touch a body: SizeSkew change mean " << totalChange / adjacent
            << ", largest " << largestChange << std::endl;
  EXPECT_GT(adjacent, 100);
  EXPECT_LT(totalChange / adjacent, 0.1);
  EXPECT_LT(largestChange, 0.2);

  // The same motions extracted from displacements give the same mesh.
  auto displaced = dgmf_test::ReadShippedMesh("two_circles.vtu", 1118, 2054);
  vtkDataArray* ids = displaced->GetPointData()->GetArray("BodyId");
  SetRotationDisplacement(
    displaced, 45.0, -2.5, 0.0, [&](vtkIdType i) { return ids->GetTuple1(i) == 1; });
  SetRotationDisplacement(
    displaced, -45.0, 2.5, 0.0, [&](vtkIdType i) { return ids->GetTuple1(i) == 2; });
  vtkNew<vtkDGMFDeformFilter> extracted;
  extracted->SetInputData(displaced);
  extracted->SetBoundaryMarkerArrayName("BoundaryMarker");
  extracted->SetBodyIdArrayName("BodyId");
  extracted->SetDisplacementArrayName("Displacement");
  extracted->SetRigidMotionModeToExtracted();
  extracted->Update();
  vtkDataArray* angles = extracted->GetOutput()->GetFieldData()->GetArray("FittedRotationAngle");
  ASSERT_NE(angles, nullptr);
  ASSERT_EQ(angles->GetNumberOfTuples(), 2);
  EXPECT_NEAR(angles->GetTuple1(0), 45.0, 1e-9);
  EXPECT_NEAR(angles->GetTuple1(1), 45.0, 1e-9); // about -z
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    // The fitted centres are the circles' node centroids: equal to the explicit ones up to
    // round-off on these symmetric circles.
    ASSERT_NEAR(extracted->GetOutput()->GetPoint(i)[0], out->GetPoint(i)[0], 1e-9);
    ASSERT_NEAR(extracted->GetOutput()->GetPoint(i)[1], out->GetPoint(i)[1], 1e-9);
  }
}

TEST(Bodies, BadBodyIdsGetAClearError)
{
  auto mesh = dgmf_test::ReadShippedMesh("two_circles.vtu", 1118, 2054);
  vtkDataArray* ids = mesh->GetPointData()->GetArray("BodyId");
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  vtkIdType interior = 0;
  while (marker->GetTuple1(interior) != 0)
    ++interior;
  ids->SetTuple1(interior, 1);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetBodyIdArrayName("BodyId");
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(Bodies, BodyMotionRowsForBodiesTheMeshLacksAreErrors)
{
  // Until 2026-11-30 a row for a body the mesh does not have was ignored, and one with a bad id
  // was dropped after a message at set time: either way the mesh came out unmoved.
  auto mesh = dgmf_test::ReadShippedMesh("two_circles.vtu", 1118, 2054);
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_test::ErrorMessages errors(filter);
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetBodyIdArrayName("BodyId");
  filter->SetBodyMotion(3, 0, 0, 0, 0, 0, 0, 0, 0, 10);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.Contains("Body Motions moves body 3, but the mesh has 2 moving bodies"));

  filter->RemoveAllBodyMotions();
  filter->SetBodyMotion(1.5, 0, 0, 0, 0, 0, 0, 0, 0, 10);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.Contains("Body Motions has a row for the body id 1.5"));

  filter->RemoveAllBodyMotions(); // the bad row is gone with the others
  filter->SetBodyMotion(1, 0, 0, 0, -2.5, 0, 0, 0, 0, 10);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 1118);
}

TEST(Bodies, ARowForABodyIdNoNodeHasIsAnError)
{
  // Bodies numbered 1 and 3: a row for body 2 moved nothing, and body 3 (meant) stayed still,
  // without a word, until 2026-11-30. Rows for the bodies the mesh has still work.
  auto mesh = dgmf_test::ReadShippedMesh("two_circles.vtu", 1118, 2054);
  vtkDataArray* ids = mesh->GetPointData()->GetArray("BodyId");
  for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
  {
    if (ids->GetTuple1(i) == 2)
    {
      ids->SetTuple1(i, 3);
    }
  }
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_test::ErrorMessages errors(filter);
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetBodyIdArrayName("BodyId");
  filter->SetBodyMotion(2, 0, 0, 0, 2.5, 0, 0, 0, 0, -10);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.Contains(
    "Body Motions moves body 2, but no moving node has that body id (the mesh's bodies: 1, 3)."));
  filter->RemoveAllBodyMotions();
  filter->SetBodyMotion(3, 0, 0, 0, 2.5, 0, 0, 0, 0, -10);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 1118);
}
