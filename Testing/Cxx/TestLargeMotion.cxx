// Large motions through the filter: sub-steps and the quality guard on the thin slab (issue 10).
#include "vtkDGMFDeformFilter.h"

#include "FieldValue.h"
#include "ShippedMesh.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr vtkIdType SlabPoints = 2810;
constexpr vtkIdType SlabCells = 13781;

/// The slab rotated by `degrees` about the z axis through the origin, with the given options.
vtkSmartPointer<vtkUnstructuredGrid> Rotate(
  vtkUnstructuredGrid* mesh, double degrees, int subSteps, double repairThreshold)
{
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetDisplacementArrayName("Displacement");
  filter->SetRotationAngles(0.0, 0.0, degrees);
  filter->SetSubSteps(subSteps);
  filter->SetRepairThreshold(repairThreshold);
  filter->Update();
  auto output = vtkSmartPointer<vtkUnstructuredGrid>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}

using dgmf_test::Field;

/// Boundary exactness: moving nodes at their rotated positions, static nodes where they were.
void ExpectBoundaryExact(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, double degrees)
{
  vtkDataArray* marker = input->GetPointData()->GetArray("BoundaryMarker");
  const double a = degrees * Pi / 180.0;
  vtkIdType moving = 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const double* x = input->GetPoint(i);
    double y[3];
    output->GetPoint(i, y);
    const int kind = static_cast<int>(marker->GetTuple1(i));
    if (kind == 1)
    {
      ASSERT_TRUE(y[0] == x[0] && y[1] == x[1] && y[2] == x[2]) << "static node " << i << " moved";
    }
    else if (kind == 2)
    {
      ++moving;
      const double expected[3] = { std::cos(a) * x[0] - std::sin(a) * x[1],
        std::sin(a) * x[0] + std::cos(a) * x[1], x[2] };
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_NEAR(y[c], expected[c], 1e-12) << "moving node " << i << " off its position";
      }
    }
  }
  EXPECT_EQ(moving, 890);
}
} // namespace

// Premise of the tests below: in one step, the paper's method inverts cells on this mesh at 90
// degrees and leaves very bad cells at 60.
TEST(LargeMotion, OneStepInvertsCellsAtNinetyDegrees)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkSmartPointer<vtkUnstructuredGrid> out90 = Rotate(slab, 90.0, 1, 0.0);
  EXPECT_GT(Field(out90, "InvertedCellCount"), 0.0);
  vtkSmartPointer<vtkUnstructuredGrid> out60 = Rotate(slab, 60.0, 1, 0.0);
  EXPECT_LT(Field(out60, "SizeSkewMinimum"), 0.2);
  // Off by default: no large-motion report in the field data.
  EXPECT_EQ(out90->GetFieldData()->GetArray("SubStepsUsed"), nullptr);
  // Sub-steps without the guard: the steps, no guard's count (until 2026-11-30 fixed steps said
  // 0 bad cells left with cells inverted, automatic ones the last step's inverted cells).
  for (const int steps : { 0, 4 })
  {
    vtkSmartPointer<vtkUnstructuredGrid> stepped = Rotate(slab, 120.0, steps, 0.0);
    EXPECT_GE(Field(stepped, "SubStepsUsed"), 1.0) << steps;
    EXPECT_EQ(stepped->GetFieldData()->GetArray("RepairedCellCount"), nullptr) << steps;
    EXPECT_EQ(stepped->GetFieldData()->GetArray("UnrepairedCellCount"), nullptr) << steps;
  }
}

TEST(LargeMotion, GuardGivesNoInvertedCellAndMinimumAboveThresholdAtNinetyDegrees)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  for (const double threshold : { 0.2, 0.3 })
  {
    vtkSmartPointer<vtkUnstructuredGrid> out = Rotate(slab, 90.0, 0, threshold);
    ASSERT_EQ(out->GetNumberOfPoints(), SlabPoints);
    EXPECT_EQ(Field(out, "InvertedCellCount"), 0.0) << threshold;
    EXPECT_GE(Field(out, "SizeSkewMinimum"), threshold);
    EXPECT_GE(Field(out, "SubStepsUsed"), 1.0);
    EXPECT_GT(Field(out, "RepairedCellCount"), 0.0);
    EXPECT_EQ(Field(out, "UnrepairedCellCount"), 0.0);
    ExpectBoundaryExact(slab, out, 90.0);
    // Every input array reaches the output.
    EXPECT_NE(out->GetPointData()->GetArray("Displacement"), nullptr);
    EXPECT_NE(out->GetPointData()->GetArray("f"), nullptr);
  }
}

TEST(LargeMotion, GuardReachesThresholdAtSixtyDegrees)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkSmartPointer<vtkUnstructuredGrid> out = Rotate(slab, 60.0, 0, 0.3);
  EXPECT_EQ(Field(out, "InvertedCellCount"), 0.0);
  EXPECT_GE(Field(out, "SizeSkewMinimum"), 0.3);
  ExpectBoundaryExact(slab, out, 60.0);
}

// The guard moves only interior nodes near bad cells: most of the mesh is bit for bit the
// single-step result.
TEST(LargeMotion, GuardIsLocal)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkSmartPointer<vtkUnstructuredGrid> single = Rotate(slab, 90.0, 1, 0.0);
  vtkSmartPointer<vtkUnstructuredGrid> guarded = Rotate(slab, 90.0, 1, 0.2);
  EXPECT_EQ(Field(guarded, "SubStepsUsed"), 1.0);
  vtkDataArray* marker = slab->GetPointData()->GetArray("BoundaryMarker");
  vtkIdType changed = 0;
  for (vtkIdType i = 0; i < SlabPoints; ++i)
  {
    double a[3], b[3];
    single->GetPoint(i, a);
    guarded->GetPoint(i, b);
    if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
    {
      ++changed;
      EXPECT_EQ(marker->GetTuple1(i), 0.0) << "boundary node " << i << " moved by the guard";
    }
  }
  EXPECT_GT(changed, 0);
  EXPECT_LT(changed, SlabPoints / 5) << "the guard moved a large part of the mesh";
}

// Fixed sub-steps: the number asked for, the boundary on its path, the input unchanged.
TEST(LargeMotion, FixedSubStepsFollowThePath)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkNew<vtkUnstructuredGrid> before;
  before->DeepCopy(slab);
  vtkSmartPointer<vtkUnstructuredGrid> out = Rotate(slab, 90.0, 4, 0.2);
  EXPECT_EQ(Field(out, "SubStepsUsed"), 4.0);
  EXPECT_EQ(Field(out, "RejectedSubSteps"), 0.0);
  EXPECT_EQ(Field(out, "InvertedCellCount"), 0.0);
  EXPECT_GE(Field(out, "SizeSkewMinimum"), 0.2);
  ExpectBoundaryExact(slab, out, 90.0);
  for (vtkIdType i = 0; i < SlabPoints; ++i)
  {
    double a[3], b[3];
    before->GetPoint(i, a);
    slab->GetPoint(i, b);
    ASSERT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << "input modified at " << i;
  }
}

// The option off (SubSteps 1, RepairThreshold 0, the defaults) is exactly the paper's single step:
// the same filter with the properties set explicitly gives the same bits as a filter left at its
// defaults, and a one-step run with a zero threshold takes the single-step path.
TEST(LargeMotion, OptionOffIsExactlyTheSingleStep)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkNew<vtkDGMFDeformFilter> defaults;
  defaults->SetInputData(slab);
  defaults->SetBoundaryMarkerArrayName("BoundaryMarker");
  defaults->SetDisplacementArrayName("Displacement");
  defaults->SetRotationAngles(0.0, 0.0, 90.0);
  defaults->Update();
  EXPECT_EQ(defaults->GetSubSteps(), 1);
  EXPECT_EQ(defaults->GetRepairThreshold(), 0.0);
  vtkSmartPointer<vtkUnstructuredGrid> explicitOff = Rotate(slab, 90.0, 1, 0.0);
  vtkUnstructuredGrid* a = defaults->GetOutput();
  ASSERT_EQ(a->GetNumberOfPoints(), SlabPoints);
  for (vtkIdType i = 0; i < SlabPoints; ++i)
  {
    double x[3], y[3];
    a->GetPoint(i, x);
    explicitOff->GetPoint(i, y);
    ASSERT_TRUE(x[0] == y[0] && x[1] == y[1] && x[2] == y[2]) << i;
  }
  EXPECT_EQ(a->GetFieldData()->GetArray("SubStepsUsed"), nullptr);
}

// One sub-step without repair through the sub-step code equals the single step up to round-off
// at interior nodes (same graph, same f, same motion): automatic mode with nothing to reject.
TEST(LargeMotion, AutomaticModeWithoutBadCellsIsOneStep)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkSmartPointer<vtkUnstructuredGrid> single = Rotate(slab, 10.0, 1, 0.0);
  ASSERT_EQ(Field(single, "InvertedCellCount"), 0.0);
  vtkSmartPointer<vtkUnstructuredGrid> automatic = Rotate(slab, 10.0, 0, 0.0);
  EXPECT_EQ(Field(automatic, "SubStepsUsed"), 1.0);
  EXPECT_EQ(Field(automatic, "RejectedSubSteps"), 0.0);
  for (vtkIdType i = 0; i < SlabPoints; ++i)
  {
    double x[3], y[3];
    single->GetPoint(i, x);
    automatic->GetPoint(i, y);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_NEAR(x[c], y[c], 1e-12) << i;
    }
  }
}

TEST(LargeMotion, RefusedWithBodiesOrExtractedMotion)
{
  vtkSmartPointer<vtkUnstructuredGrid> slab =
    dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints, SlabCells);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(slab);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetDisplacementArrayName("Displacement");
  filter->SetRigidMotionModeToExtracted();
  filter->SetRepairThreshold(0.2);
  std::string errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&errors);
  onError->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData)
    { *static_cast<std::string*>(clientData) += static_cast<const char*>(callData); });
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(errors.find("Sub-steps and the quality guard"), std::string::npos) << errors;
}

// Progress reaches ParaView through the sub-steps and the repairs (not only four updates), and
// ParaView's abort stops the run at the next report: an empty output, a warning, and a filter that
// gives the same points as a fresh one when run again.
TEST(LargeMotion, ProgressMovesDuringSubStepsAndAbortStopsTheRun)
{
  auto slab = dgmf_test::ReadShippedMesh("thin_slab.vtu", SlabPoints);
  struct Watch
  {
    std::vector<double> Fractions;
    double AbortAt = 2.0; // never
    std::string Warnings;
  } watch;
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(slab);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetDisplacementArrayName("Displacement");
  filter->SetRotationAngles(0.0, 0.0, 90.0);
  filter->SetSubSteps(8);
  filter->SetRepairThreshold(0.2);
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&watch);
  onProgress->SetCallback(
    [](vtkObject* caller, unsigned long, void* data, void* callData)
    {
      auto* w = static_cast<Watch*>(data);
      const double fraction = *static_cast<double*>(callData);
      w->Fractions.push_back(fraction);
      if (fraction >= w->AbortAt)
      {
        static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      }
    });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  vtkNew<vtkCallbackCommand> onWarning;
  onWarning->SetClientData(&watch);
  onWarning->SetCallback([](vtkObject*, unsigned long, void* data, void* callData)
    { static_cast<Watch*>(data)->Warnings += static_cast<const char*>(callData); });
  filter->AddObserver(vtkCommand::WarningEvent, onWarning);

  filter->Update();
  ASSERT_EQ(filter->GetOutput()->GetNumberOfPoints(), SlabPoints);
  // One report per step and per repair pass, in order, between the graph (0.45) and 0.8.
  std::size_t during = 0;
  for (std::size_t k = 0; k < watch.Fractions.size(); ++k)
  {
    during += watch.Fractions[k] > 0.45 && watch.Fractions[k] < 0.8 ? 1 : 0;
    if (k > 0)
    {
      EXPECT_GE(watch.Fractions[k], watch.Fractions[k - 1]);
    }
  }
  EXPECT_GE(during, 8u);
  auto complete = vtkSmartPointer<vtkUnstructuredGrid>::New();
  complete->DeepCopy(filter->GetOutput());

  // Abort in the middle of the steps.
  watch.Fractions.clear();
  watch.AbortAt = 0.6;
  filter->SetRotationAngles(0.0, 0.0, 89.0);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(watch.Warnings.find("aborted"), std::string::npos) << watch.Warnings;
  for (double fraction : watch.Fractions) // the executive ends every run with 1
  {
    EXPECT_TRUE(fraction < 0.8 || fraction == 1.0) << fraction << ": not stopped";
  }

  // The next run is whole and the same as a run that was never aborted.
  watch.AbortAt = 2.0;
  filter->AbortExecuteOff();
  filter->SetRotationAngles(0.0, 0.0, 90.0);
  filter->Update();
  ASSERT_EQ(filter->GetOutput()->GetNumberOfPoints(), SlabPoints);
  for (vtkIdType i = 0; i < SlabPoints; ++i)
  {
    double a[3], b[3];
    complete->GetPoint(i, a);
    filter->GetOutput()->GetPoint(i, b);
    ASSERT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << "node " << i;
  }
}
