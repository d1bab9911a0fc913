// A seeded randomized search for failures: random meshes (Delaunay triangulations of random
// points), random markings and random motions; invariants: boundary exactness, 0 <= f <= 1,
// finite output, no crash.
#include "vtkDGMFDeformFilter.h"

#include "vtkCell.h"
#include "vtkDataArray.h"
#include "vtkDelaunay2D.h"
#include "vtkDelaunay3D.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Random points in the unit square (2D) or cube (3D), triangulated, plus a hull of points on
/// the bounding box. Nodes within `radius` of the centre are removed except those kept as a body.
vtkSmartPointer<vtkUnstructuredGrid> RandomMesh(int dimension, int count, std::mt19937& random)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  vtkNew<vtkPoints> points;
  // The outer boundary: a grid on the box.
  const int m = 6;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= m; ++j)
      for (int k = 0; k <= (dimension == 3 ? m : 0); ++k)
      {
        const bool onBox =
          i == 0 || i == m || j == 0 || j == m || (dimension == 3 && (k == 0 || k == m));
        if (onBox)
          points->InsertNextPoint(
            -2.0 + 4.0 * i / m, -2.0 + 4.0 * j / m, dimension == 3 ? -2.0 + 4.0 * k / m : 0.0);
      }
  for (int n = 0; n < count; ++n)
    points->InsertNextPoint(
      1.9 * u(random), 1.9 * u(random), dimension == 3 ? 1.9 * u(random) : 0.0);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  if (dimension == 2)
  {
    vtkNew<vtkDelaunay2D> delaunay;
    delaunay->SetInputData(cloud);
    delaunay->Update();
    vtkPolyData* triangles = delaunay->GetOutput();
    mesh->SetPoints(triangles->GetPoints());
    mesh->Allocate(triangles->GetNumberOfCells());
    for (vtkIdType c = 0; c < triangles->GetNumberOfCells(); ++c)
      mesh->InsertNextCell(VTK_TRIANGLE, triangles->GetCell(c)->GetPointIds());
  }
  else
  {
    vtkNew<vtkDelaunay3D> delaunay;
    delaunay->SetInputData(cloud);
    delaunay->Update();
    mesh->DeepCopy(delaunay->GetOutput());
  }
  return mesh;
}
} // namespace

TEST(Randomized, InvariantsHoldForRandomMeshesMarkingsAndMotions)
{
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial)
  {
    const int dimension = trial % 2 ? 3 : 2;
    auto mesh = RandomMesh(dimension, dimension == 2 ? 300 : 150, random);
    ASSERT_GT(mesh->GetNumberOfCells(), 0);
    // Marking: the box is static; the nodes inside a random ball are the moving "body".
    const double centre[3] = { 0.5 * u(random), 0.5 * u(random),
      dimension == 3 ? 0.5 * u(random) : 0.0 };
    const double radius = 0.3 + 0.3 * std::abs(u(random));
    vtkNew<vtkIntArray> marker;
    marker->SetName("BoundaryMarker");
    marker->SetNumberOfTuples(mesh->GetNumberOfPoints());
    int moving = 0;
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double p[3];
      mesh->GetPoint(i, p);
      const bool onBox =
        std::abs(p[0]) == 2.0 || std::abs(p[1]) == 2.0 || (dimension == 3 && std::abs(p[2]) == 2.0);
      const double d = std::sqrt((p[0] - centre[0]) * (p[0] - centre[0]) +
        (p[1] - centre[1]) * (p[1] - centre[1]) + (p[2] - centre[2]) * (p[2] - centre[2]));
      const int kind = onBox ? 1 : d < radius ? 2 : 0;
      moving += kind == 2 ? 1 : 0;
      marker->SetValue(i, kind);
    }
    mesh->GetPointData()->AddArray(marker);
    // A random rigid motion about the body's centre and a random shape deformation.
    vtkNew<vtkDoubleArray> displacement;
    displacement->SetName("Displacement");
    displacement->SetNumberOfComponents(3);
    displacement->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      const double d[3] = { 0.05 * u(random), 0.05 * u(random),
        dimension == 3 ? 0.05 * u(random) : 0.0 };
      displacement->SetTuple(i, d);
    }
    mesh->GetPointData()->AddArray(displacement);
    vtkNew<vtkDGMFDeformFilter> filter;
    filter->SetInputData(mesh);
    filter->SetBoundaryMarkerArrayName("BoundaryMarker");
    filter->SetDisplacementArrayName("Displacement");
    filter->SetDampingFunction(1 + static_cast<int>(random() % 7));
    filter->SetStaticBoundaryR0(1.0 + std::abs(u(random)));
    filter->SetDeformationMode(1 + static_cast<int>(random() % 2));
    filter->SetRotationCenter(centre[0], centre[1], centre[2]);
    const double angle = 180.0 * u(random);
    if (dimension == 2)
      filter->SetRotationAngles(0, 0, angle);
    else
      filter->SetRotationAngles(angle * u(random), angle * u(random), angle);
    filter->SetTranslation(
      0.2 * u(random), 0.2 * u(random), dimension == 3 ? 0.2 * u(random) : 0.0);
    filter->Update();
    vtkUnstructuredGrid* out = filter->GetOutput();
    if (moving == 0)
    {
      // Nothing moves: the output is the input (with a warning).
      ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints());
      continue;
    }
    ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << "trial " << trial;
    vtkDataArray* f = out->GetPointData()->GetArray("f");
    double R[3][3];
    {
      // The prescribed rigid motion, computed independently: Rz Ry Rx.
      const double* a = filter->GetRotationAngles();
      const double ax = a[0] * Pi / 180, ay = a[1] * Pi / 180, az = a[2] * Pi / 180;
      const double Rx[3][3] = { { 1, 0, 0 }, { 0, std::cos(ax), -std::sin(ax) },
        { 0, std::sin(ax), std::cos(ax) } };
      const double Ry[3][3] = { { std::cos(ay), 0, std::sin(ay) }, { 0, 1, 0 },
        { -std::sin(ay), 0, std::cos(ay) } };
      const double Rz[3][3] = { { std::cos(az), -std::sin(az), 0 },
        { std::sin(az), std::cos(az), 0 }, { 0, 0, 1 } };
      double T[3][3] = {};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            T[i][j] += Ry[i][k] * Rx[k][j];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
          R[i][j] = 0;
          for (int k = 0; k < 3; ++k)
            R[i][j] += Rz[i][k] * T[k][j];
        }
    }
    const double* t = filter->GetTranslation();
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double x[3], y[3], d[3];
      mesh->GetPoint(i, x);
      out->GetPoint(i, y);
      displacement->GetTuple(i, d);
      ASSERT_TRUE(std::isfinite(y[0]) && std::isfinite(y[1]) && std::isfinite(y[2]));
      ASSERT_GE(f->GetTuple1(i), 0.0);
      ASSERT_LE(f->GetTuple1(i), 1.0);
      const int kind = marker->GetValue(i);
      if (kind == 1)
      {
        ASSERT_EQ(x[0], y[0]);
        ASSERT_EQ(x[1], y[1]);
        ASSERT_EQ(x[2], y[2]);
      }
      else if (kind == 2)
      {
        for (int r = 0; r < 3; ++r)
        {
          const double expected = centre[r] + R[r][0] * (x[0] - centre[0]) +
            R[r][1] * (x[1] - centre[1]) + R[r][2] * (x[2] - centre[2]) + t[r] + d[r];
          ASSERT_NEAR(y[r], expected, 1e-12 * std::max(1.0, std::abs(expected)))
            << "trial " << trial;
        }
      }
    }
  }
}
