// Bad input, large motion and data safety (issue 8): a clear error or a correct result, never a
// crash or a silent loss.
#include "vtkDGMFDeformFilter.h"

#include "FieldValue.h"
#include "ShippedMesh.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
/// Runs the filter and collects its error and warning messages.
struct FilterRun
{
  vtkNew<vtkDGMFDeformFilter> Filter;
  std::vector<std::string> Errors, Warnings;
  vtkNew<vtkCallbackCommand> OnError, OnWarning;

  FilterRun()
  {
    this->OnError->SetClientData(&this->Errors);
    this->OnError->SetCallback(Collect);
    this->OnWarning->SetClientData(&this->Warnings);
    this->OnWarning->SetCallback(Collect);
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->OnError);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->OnWarning);
    this->Filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  }
  static void Collect(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    static_cast<std::vector<std::string>*>(clientData)
      ->emplace_back(callData ? static_cast<const char*>(callData) : "");
  }
  vtkUnstructuredGrid* Execute(vtkUnstructuredGrid* mesh)
  {
    this->Filter->SetInputData(mesh);
    this->Filter->Update();
    return this->Filter->GetOutput();
  }
  static bool Has(const std::vector<std::string>& messages, const std::string& text)
  {
    for (const std::string& m : messages)
      if (m.find(text) != std::string::npos)
        return true;
    return false;
  }
};

using dgmf_test::Field;
} // namespace

TEST(BadInput, NonFiniteCoordinatesOrDisplacements)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  double p[3];
  mesh->GetPoint(100, p);
  p[1] = std::numeric_limits<double>::quiet_NaN();
  mesh->GetPoints()->SetPoint(100, p);
  FilterRun nanPoint;
  EXPECT_EQ(nanPoint.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(nanPoint.Errors, "NaN or infinite point coordinates"));

  // Finite but huge: a boundary node at 1e160 (its squared distances overflow) crashed CGAL's
  // insertion or corrupted the heap until 2026-11-30; an interior node at -1e300 too.
  for (const double huge : { 1e160, -1e300 })
  {
    auto far = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
    vtkDataArray* marker = far->GetPointData()->GetArray("BoundaryMarker");
    vtkIdType node = 0;
    while (marker->GetTuple1(node) != (huge > 0.0 ? 2.0 : 0.0))
    {
      ++node;
    }
    far->GetPoint(node, p);
    p[0] = huge;
    far->GetPoints()->SetPoint(node, p);
    FilterRun hugePoint;
    hugePoint.Filter->SetRotationAngles(0, 0, 10);
    EXPECT_EQ(hugePoint.Execute(far)->GetNumberOfPoints(), 0) << huge;
    EXPECT_TRUE(FilterRun::Has(hugePoint.Errors, "of magnitude 8.7e99 or more")) << huge;
  }

  auto clean = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* d = clean->GetPointData()->GetArray("Displacement");
  d->SetComponent(5, 0, std::numeric_limits<double>::infinity());
  FilterRun infDisplacement;
  infDisplacement.Filter->SetDisplacementArrayName("Displacement");
  EXPECT_EQ(infDisplacement.Execute(clean)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(infDisplacement.Errors, "NaN or infinite values"));
}

TEST(BadInput, NoBoundaryNodeAndNoMovingNode)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  std::vector<double> saved(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    saved[i] = marker->GetTuple1(i);
    marker->SetTuple1(i, 0);
  }
  FilterRun none;
  EXPECT_EQ(none.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(none.Errors, "No node is a boundary node"));
  // The words agree with the behaviour: an error and no output, not "the output has the input's
  // points".
  EXPECT_FALSE(FilterRun::Has(none.Warnings, "the output has the input's points"));

  // Only static nodes: the output has the input's points, with a warning.
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    marker->SetTuple1(i, saved[i] == 2 ? 1 : saved[i]);
  marker->Modified();
  FilterRun still;
  still.Filter->SetRotationAngles(0, 0, 45);
  vtkUnstructuredGrid* out = still.Execute(mesh);
  ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_TRUE(FilterRun::Has(still.Warnings, "No node is marked as moving"));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    mesh->GetPoint(i, a);
    out->GetPoint(i, b);
    ASSERT_EQ(std::memcmp(a, b, sizeof(a)), 0) << "node " << i;
  }
}

TEST(BadInput, DisplacementOnNodesNotMovingIsReportedAsIgnored)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("Contradicting");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(mesh->GetNumberOfPoints());
  vtkIdType staticNodes = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const bool isStatic = marker->GetTuple1(i) == 1;
    staticNodes += isStatic ? 1 : 0;
    displacement->SetTuple3(i, isStatic ? 0.01 : 0.0, 0.0, 0.0);
  }
  mesh->GetPointData()->AddArray(displacement);
  FilterRun run;
  run.Filter->SetDisplacementArrayName("Contradicting");
  ASSERT_EQ(run.Execute(mesh)->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_TRUE(FilterRun::Has(run.Warnings,
    std::to_string(staticNodes) + " nodes not marked as moving have a non-zero displacement"));
  // DGMF1 reads every node's value (a known field), but static nodes never move: they are the ones
  // counted. An interior node's value is used: no warning (until 2026-11-30 DGMF1 counted them as
  // "ignored" while they moved the nodes).
  FilterRun dgmf1;
  dgmf1.Filter->SetDisplacementArrayName("Contradicting");
  dgmf1.Filter->SetDeformationModeToDGMF1();
  ASSERT_EQ(dgmf1.Execute(mesh)->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_TRUE(FilterRun::Has(
    dgmf1.Warnings, std::to_string(staticNodes) + " static nodes have a non-zero displacement"));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    displacement->SetTuple3(i, marker->GetTuple1(i) == 0 ? 0.01 : 0.0, 0.0, 0.0);
  }
  displacement->Modified();
  FilterRun interior;
  interior.Filter->SetDisplacementArrayName("Contradicting");
  interior.Filter->SetDeformationModeToDGMF1();
  ASSERT_EQ(interior.Execute(mesh)->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_FALSE(FilterRun::Has(interior.Warnings, "have a non-zero displacement"));
}

TEST(BadInput, CoplanarBoundaryOf3DMeshIsRejected)
{
  // A 3D mesh whose marked boundary nodes all lie in the plane z = -5.
  auto mesh = dgmf_test::ReadShippedMesh("sphere_in_box.vtu", 3200);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    marker->SetTuple1(i, p[2] == -5.0 ? (p[0] < 0 ? 2 : 1) : 0);
  }
  FilterRun run;
  EXPECT_EQ(run.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(run.Errors, "coplanar"));
}

TEST(BadInput, ASlipBoundaryOfA2DMeshThatIsNotStraightIsRejected)
{
  // The whole outer square of the 2D circle mesh as slip (marker 3): four lines, not one. It lies
  // in the mesh's plane z = 0, so it passed as a plane before, and its nodes left their sides.
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (marker->GetTuple1(i) == 1)
    {
      marker->SetTuple1(i, 3);
    }
  }
  FilterRun run;
  run.Filter->SetRotationAngles(0, 0, 5);
  EXPECT_EQ(run.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(run.Errors, "is not straight"));
}

TEST(BadInput, PlanarMeshOffZeroAndTiltedMesh)
{
  // z = 3.5 everywhere: still 2D, and z is kept.
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    p[2] = 3.5;
    mesh->GetPoints()->SetPoint(i, p);
  }
  FilterRun lifted;
  lifted.Filter->SetRotationAngles(0, 0, 60);
  vtkUnstructuredGrid* out = lifted.Execute(mesh);
  ASSERT_EQ(out->GetNumberOfPoints(), 822);
  EXPECT_EQ(Field(out, "InvertedCellCount"), 0.0);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    ASSERT_EQ(out->GetPoint(i)[2], 3.5);

  // z with round-off (a mesh turned into the plane by a transform: 1e-15; single precision:
  // 1e-7): still 2D, the same x and y bit for bit, each z kept (refused until 2026-11-30).
  auto rounded = vtkSmartPointer<vtkUnstructuredGrid>::New();
  rounded->DeepCopy(mesh);
  for (vtkIdType i = 0; i < rounded->GetNumberOfPoints(); ++i)
  {
    double p[3];
    rounded->GetPoint(i, p);
    p[2] = 3.5 + (i % 3 - 1) * 4e-7;
    rounded->GetPoints()->SetPoint(i, p);
  }
  FilterRun roundOff;
  roundOff.Filter->SetRotationAngles(0, 0, 60);
  vtkUnstructuredGrid* nearly = roundOff.Execute(rounded);
  ASSERT_EQ(nearly->GetNumberOfPoints(), 822);
  for (vtkIdType i = 0; i < nearly->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(nearly->GetPoint(i)[0], out->GetPoint(i)[0]) << "point " << i;
    ASSERT_EQ(nearly->GetPoint(i)[1], out->GetPoint(i)[1]) << "point " << i;
    ASSERT_EQ(nearly->GetPoint(i)[2], rounded->GetPoint(i)[2]) << "point " << i;
  }

  // Tilted plane: a clear error.
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    p[2] = 0.1 * p[0];
    mesh->GetPoints()->SetPoint(i, p);
  }
  FilterRun tilted;
  EXPECT_EQ(tilted.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(tilted.Errors, "plane z = constant"));
  EXPECT_TRUE(FilterRun::Has(tilted.Errors, "a surface mesh"));
}

TEST(BadInput, AnotherKindOfDataSetIsSaidByName)
{
  // A vtkPolyData (a surface from pvpython's Sphere()): one error naming it and what is taken
  // (until 2026-11-30 VTK's "is of type vtkPolyData, but a vtkUnstructuredGrid is required", seven
  // times per update, and nothing from the filter).
  vtkNew<vtkPolyData> surface;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 1);
  surface->SetPoints(points);
  FilterRun run;
  run.Filter->SetInputData(surface);
  run.Filter->Update();
  ASSERT_EQ(run.Errors.size(), 1u);
  EXPECT_TRUE(FilterRun::Has(run.Errors,
    "The input is a vtkPolyData: the filter deforms meshes "
    "given as a vtkUnstructuredGrid"));
  EXPECT_EQ(vtkPolyData::SafeDownCast(run.Filter->GetOutputDataObject(0))->GetNumberOfPoints(), 0);
}

TEST(BadInput, CoincidentBoundaryNodes)
{
  // Two extra nodes on top of a circle node: one moving (a duplicate), one static (a conflict).
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  vtkIdType circleNode = 0;
  while (marker->GetTuple1(circleNode) != 2)
    ++circleNode;
  double p[3];
  mesh->GetPoint(circleNode, p);
  const vtkIdType duplicate = mesh->GetPoints()->InsertNextPoint(p);
  const vtkIdType conflicting = mesh->GetPoints()->InsertNextPoint(p);
  for (int k = 0; k < mesh->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* a = mesh->GetPointData()->GetArray(k);
    a->InsertTuple(duplicate, a->GetTuple(circleNode));
    a->InsertTuple(conflicting, a->GetTuple(circleNode));
  }
  marker->SetTuple1(conflicting, 1);
  FilterRun run;
  run.Filter->SetRotationAngles(0, 0, 30);
  vtkUnstructuredGrid* out = run.Execute(mesh);
  ASSERT_EQ(out->GetNumberOfPoints(), 824);
  EXPECT_TRUE(FilterRun::Has(run.Warnings, "coincide with moving ones"));
  double moved[3], copy[3], kept[3];
  out->GetPoint(circleNode, moved);
  out->GetPoint(duplicate, copy);
  out->GetPoint(conflicting, kept);
  EXPECT_EQ(std::memcmp(moved, copy, sizeof(moved)), 0) << "a duplicate moves with its twin";
  EXPECT_EQ(std::memcmp(kept, p, sizeof(p)), 0) << "a static node stays, even on a moving one";
  EXPECT_GT(std::hypot(moved[0] - p[0], moved[1] - p[1]), 0.1);
}

TEST(BadInput, NodesOutsideTheGraphUseTheNearestElementAndAreCounted)
{
  // The boundary nodes above y = 4 (the top side and the top of the other two) are not marked:
  // the graph's hull ends below y = 4, and the mesh nodes above it fall outside the graph.
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (p[1] > 4.0)
      marker->SetTuple1(i, 0);
  }
  FilterRun run;
  run.Filter->SetRotationAngles(0, 0, 20);
  vtkUnstructuredGrid* out = run.Execute(mesh);
  ASSERT_EQ(out->GetNumberOfPoints(), 822);
  EXPECT_GT(Field(out, "OutsideNodeCount"), 0.0);
  EXPECT_TRUE(FilterRun::Has(run.Warnings, "outside the Delaunay graph"));
  vtkDataArray* f = out->GetPointData()->GetArray("f");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    ASSERT_GE(f->GetTuple1(i), 0.0);
    ASSERT_LE(f->GetTuple1(i), 1.0);
    ASSERT_TRUE(std::isfinite(out->GetPoint(i)[0]));
  }
}

TEST(BadInput, MixedHigherOrderAndPolygonCellsAreDeformed)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
  // A quadratic triangle on the corners of cell 0 with three new mid-edge nodes, and a polygon.
  vtkIdType npts;
  const vtkIdType* pts;
  mesh->GetCells()->GetCellAtId(0, npts, pts);
  vtkIdType quadratic[6] = { pts[0], pts[1], pts[2], 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
  {
    double a[3], b[3];
    mesh->GetPoint(pts[k], a);
    mesh->GetPoint(pts[(k + 1) % 3], b);
    const double mid[3] = { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.0 };
    quadratic[3 + k] = mesh->GetPoints()->InsertNextPoint(mid);
  }
  const vtkIdType polygon[5] = { pts[0], pts[1], quadratic[4], pts[2], quadratic[5] };
  for (int k = 0; k < mesh->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* a = mesh->GetPointData()->GetArray(k);
    for (int m = 0; m < 3; ++m)
      a->InsertTuple(quadratic[3 + m], a->GetTuple(pts[0]));
  }
  for (int m = 0; m < 3; ++m)
    marker->SetTuple1(quadratic[3 + m], 0);
  const vtkIdType before = mesh->GetNumberOfCells();
  mesh->InsertNextCell(VTK_QUADRATIC_TRIANGLE, 6, quadratic);
  mesh->InsertNextCell(VTK_POLYGON, 5, polygon);
  FilterRun run;
  run.Filter->SetRotationAngles(0, 0, 30);
  vtkUnstructuredGrid* out = run.Execute(mesh);
  ASSERT_EQ(out->GetNumberOfPoints(), 825);
  vtkDataArray* sizeSkew = out->GetCellData()->GetArray("SizeSkew");
  ASSERT_NE(sizeSkew, nullptr);
  EXPECT_TRUE(std::isnan(sizeSkew->GetTuple1(before))); // quadratic triangle: not computed
  // A polygon is judged through its triangles about its centre (DecomposedSizeSkew).
  EXPECT_GE(sizeSkew->GetTuple1(before + 1), 0.0);
  EXPECT_LE(sizeSkew->GetTuple1(before + 1), 1.0);
  EXPECT_FALSE(std::isnan(sizeSkew->GetTuple1(0)));
  EXPECT_FALSE(std::isnan(Field(out, "SizeSkewMean")));
  // The new mid-edge nodes moved like their neighbours (nodes are nodes).
  double a[3], b[3];
  mesh->GetPoint(quadratic[3], a);
  out->GetPoint(quadratic[3], b);
  EXPECT_GT(std::hypot(a[0] - b[0], a[1] - b[1]), 0.0);
}

TEST(BadInput, InvertingMotionIsFlaggedOrRefused)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  FilterRun produce;
  produce.Filter->SetMethodToDGM();
  produce.Filter->SetRotationAngles(0, 0, 90);
  vtkUnstructuredGrid* out = produce.Execute(mesh);
  ASSERT_EQ(out->GetNumberOfPoints(), 822);
  const double inverted = Field(out, "InvertedCellCount");
  EXPECT_GT(inverted, 0.0);
  vtkDataArray* flags = out->GetCellData()->GetArray("Inverted");
  ASSERT_NE(flags, nullptr);
  double flagged = 0;
  for (vtkIdType c = 0; c < flags->GetNumberOfTuples(); ++c)
    flagged += flags->GetTuple1(c);
  EXPECT_EQ(flagged, inverted);

  FilterRun tooFar;
  tooFar.Filter->SetRotationAngles(0, 0, 1000);
  EXPECT_EQ(tooFar.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(tooFar.Errors, "within [-720, 720]"));

  // A rotation law that goes beyond two turns later is refused at its first frame, where its
  // angle is still 0 (until 2026-11-30 at the first frame beyond, a series half written).
  FilterRun later;
  later.Filter->SetRotationLaw(vtkDGMFDeformFilter::RAMP);
  later.Filter->SetRotationLawParameters(0.0, 1000.0, 1.0, 2.0);
  later.Filter->SetInputData(mesh);
  later.Filter->UpdateTimeStep(0.0);
  EXPECT_EQ(later.Filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(later.Errors, "reaches 1000 degrees")) << later.Errors.size();

  FilterRun refuse;
  refuse.Filter->SetMethodToDGM();
  refuse.Filter->SetRotationAngles(0, 0, 90);
  refuse.Filter->FailOnInvertedCellsOn();
  EXPECT_EQ(refuse.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(refuse.Errors, "inverts"));

  // Without the quality metric nothing counts the inverted cells: the combination is refused
  // (until 2026-11-30 it produced the inverted mesh without a word).
  FilterRun blind;
  blind.Filter->SetMethodToDGM();
  blind.Filter->SetRotationAngles(0, 0, 90);
  blind.Filter->FailOnInvertedCellsOn();
  blind.Filter->ComputeQualityOff();
  EXPECT_EQ(blind.Execute(mesh)->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(blind.Errors, "Fail On Inverted Cells needs Compute Quality"));

  // Sub-steps and the quality guard are DGMF's: another method says it ignores them.
  FilterRun ignored;
  ignored.Filter->SetMethodToDGM();
  ignored.Filter->SetRotationAngles(0, 0, 30);
  ignored.Filter->SetRepairThreshold(0.3);
  EXPECT_EQ(ignored.Execute(mesh)->GetNumberOfPoints(), 822);
  EXPECT_TRUE(FilterRun::Has(ignored.Warnings, "Sub Steps and Repair Threshold are DGMF's"));
  EXPECT_TRUE(FilterRun::Has(ignored.Warnings, "ignored by DGM"));
}

TEST(DataSafety, PropertyChangesInAnyOrderGiveTheFreshResult)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_rectangle.vtu", 768);
  std::mt19937 random(7);
  vtkNew<vtkDGMFDeformFilter> reused;
  reused->SetInputData(mesh);
  reused->SetBoundaryMarkerArrayName("BoundaryMarker");
  for (int step = 0; step < 25; ++step)
  {
    // Change one or two properties at random, then compare with a fresh filter.
    const int method = static_cast<int>(random() % 5);
    const int damping = 1 + static_cast<int>(random() % 7);
    const double angle = static_cast<double>(random() % 120) - 60.0;
    const double r0s = 1.0 + (random() % 3) * 0.5;
    switch (random() % 4)
    {
      case 0:
        reused->SetMethod(method);
        break;
      case 1:
        reused->SetDampingFunction(damping);
        break;
      case 2:
        reused->SetRotationAngles(0, 0, angle);
        break;
      default:
        reused->SetStaticBoundaryR0(r0s);
        break;
    }
    reused->Update();
    vtkNew<vtkDGMFDeformFilter> fresh;
    fresh->SetInputData(mesh);
    fresh->SetBoundaryMarkerArrayName("BoundaryMarker");
    fresh->SetMethod(reused->GetMethod());
    fresh->SetDampingFunction(reused->GetDampingFunction());
    fresh->SetRotationAngles(reused->GetRotationAngles());
    fresh->SetStaticBoundaryR0(reused->GetStaticBoundaryR0());
    fresh->Update();
    vtkDataArray* a = reused->GetOutput()->GetPoints()->GetData();
    vtkDataArray* b = fresh->GetOutput()->GetPoints()->GetData();
    ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues()) << "step " << step;
    for (vtkIdType k = 0; k < a->GetNumberOfValues(); ++k)
      ASSERT_EQ(a->GetComponent(k / 3, k % 3), b->GetComponent(k / 3, k % 3)) << "step " << step;
  }
}

TEST(BadInput, ADeformationThatCannotFitInMemoryIsRefusedBeforeItStarts)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
#ifdef _WIN32
  _putenv_s("DGMF_PROCESS_MEMORY_KIB", "1");
#else
  setenv("DGMF_PROCESS_MEMORY_KIB", "1", 1); // a process limit of 1 KiB
#endif
  FilterRun refused;
  vtkUnstructuredGrid* out = refused.Execute(mesh);
#ifdef _WIN32
  _putenv_s("DGMF_PROCESS_MEMORY_KIB", "");
#else
  unsetenv("DGMF_PROCESS_MEMORY_KIB");
#endif
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_TRUE(FilterRun::Has(refused.Errors, "Deforming 822 points needs about"));
  FilterRun allowed;
  EXPECT_EQ(allowed.Execute(mesh)->GetNumberOfPoints(), 822);
}

TEST(BadInput, ASlipFaceMarkedEdgesIncludedIsSaidAsSuch)
{
  // The box's lowest face marked slip (3), its edges included: the slip nodes lie outside the
  // graph of the static and moving nodes and barely move. The warning asked "is the whole outer
  // boundary marked?" (it is) until 2026-11-30; it now says what to mark. With the edges static,
  // no slip node is outside.
  for (const bool edges : { true, false })
  {
    auto mesh = dgmf_test::ReadShippedMesh("sphere_in_box.vtu", 3200);
    vtkDataArray* marker = mesh->GetPointData()->GetArray("BoundaryMarker");
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double p[3];
      mesh->GetPoint(i, p);
      const bool inner = std::abs(p[0]) < 5.0 && std::abs(p[1]) < 5.0;
      if (marker->GetTuple1(i) == 1 && p[2] == -5.0 && (edges || inner))
      {
        marker->SetTuple1(i, 3);
      }
    }
    FilterRun run;
    run.Filter->SetTranslation(2.0, 0.0, 0.0);
    ASSERT_EQ(run.Execute(mesh)->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << edges;
    EXPECT_EQ(FilterRun::Has(run.Warnings,
                "of them are slip nodes: where a slip boundary meets the static boundary, mark "
                "the nodes of their common edges static (1)"),
      edges);
  }
}
