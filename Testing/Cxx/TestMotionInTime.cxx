// Motion in time (issue 19): rotation about an axis, harmonic and ramp laws reported as time
// steps, periodic motion without drift, trajectories from a table.
#include "vtkDGMFDeformFilter.h"

#include "ErrorMessages.h"
#include "FieldValue.h"
#include "ShippedMesh.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridAlgorithm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace
{
constexpr vtkIdType RectanglePoints = 768;
constexpr vtkIdType AirfoilPoints = 1417;
constexpr double Pi = 3.14159265358979323846;

vtkSmartPointer<vtkUnstructuredGrid> Rectangle()
{
  return dgmf_test::ReadShippedMesh("rotating_rectangle.vtu", RectanglePoints);
}

/// The points of the filter's current output, copied.
std::vector<double> PointsOf(vtkDGMFDeformFilter* filter)
{
  vtkUnstructuredGrid* output = filter->GetOutput();
  std::vector<double> points(3 * static_cast<std::size_t>(output->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    output->GetPoint(i, &points[3 * static_cast<std::size_t>(i)]);
  }
  return points;
}

double LargestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
  {
    largest = std::max(largest, std::abs(a[k] - b[k]));
  }
  return largest;
}

using Errors = dgmf_test::ErrorMessages;

/// A table of named columns of numbers.
vtkSmartPointer<vtkTable> Table(const std::map<std::string, std::vector<double>>& columns)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  for (const auto& column : columns)
  {
    vtkNew<vtkDoubleArray> values;
    values->SetName(column.first.c_str());
    for (double v : column.second)
    {
      values->InsertNextValue(v);
    }
    table->AddColumn(values);
  }
  return table;
}

/// A source of a grid with the given time steps (a reader of a case with time directories).
class TimedGridSource : public vtkUnstructuredGridAlgorithm
{
public:
  static TimedGridSource* New();
  vtkTypeMacro(TimedGridSource, vtkUnstructuredGridAlgorithm);
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::vector<double> Times;

protected:
  TimedGridSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->Times.data(),
      static_cast<int>(this->Times.size()));
    const double range[2] = { this->Times.front(), this->Times.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkUnstructuredGrid::GetData(out)->ShallowCopy(this->Grid);
    return 1;
  }
};
vtkStandardNewMacro(TimedGridSource);
} // namespace

TEST(MotionInTime, AnAxisAndAnAngleTurnAsTheEulerAnglesDo)
{
  auto mesh = Rectangle();
  vtkNew<vtkDGMFDeformFilter> euler;
  euler->SetInputData(mesh);
  euler->SetBoundaryMarkerArrayName("BoundaryMarker");
  euler->SetRotationCenter(0.3, 0.1, 0.0);
  euler->SetRotationAngles(0.0, 0.0, 30.0);
  euler->Update();
  const std::vector<double> expected = PointsOf(euler);
  for (const double sign : { 1.0, -1.0 })
  {
    vtkNew<vtkDGMFDeformFilter> axis;
    axis->SetInputData(mesh);
    axis->SetBoundaryMarkerArrayName("BoundaryMarker");
    axis->SetRotationCenter(0.3, 0.1, 0.0);
    axis->SetRotationAxis(
      0.0, 0.0, 2.0 * sign); // any length; the opposite axis, the opposite angle
    axis->SetRotationAngle(30.0 * sign);
    axis->Update();
    EXPECT_LT(LargestDifference(PointsOf(axis), expected), 1e-12);
    EXPECT_EQ(axis->GetOutput()->GetFieldData()->GetArray("MotionTime"), nullptr); // not in time
  }
  // Both forms at once: an error and no output.
  vtkNew<vtkDGMFDeformFilter> both;
  Errors errors(both);
  both->SetInputData(mesh);
  both->SetBoundaryMarkerArrayName("BoundaryMarker");
  both->SetRotationAngles(0.0, 0.0, 30.0);
  both->SetRotationAngle(10.0);
  both->Update();
  EXPECT_TRUE(errors.Contains("cannot be combined"));
  EXPECT_EQ(both->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(MotionInTime, AHarmonicLawReportsTimeStepsAndDeformsEachFrameFromTheInput)
{
  auto mesh = Rectangle();
  vtkNew<vtkDGMFDeformFilter> pitching;
  pitching->SetInputData(mesh);
  pitching->SetBoundaryMarkerArrayName("BoundaryMarker");
  pitching->SetRotationLaw(vtkDGMFDeformFilter::HARMONIC);
  pitching->SetRotationLawParameters(5.0, 20.0, 1.0, 0.0); // 5 + 20 sin(2 pi t) degrees
  pitching->SetTimeRange(0.0, 1.0);
  pitching->SetNumberOfTimeSteps(11);
  pitching->UpdateInformation();
  vtkInformation* info = pitching->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 11);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[10], 1.0);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE())[1], 1.0);

  for (const double t : { 0.0, 0.3, 0.75 })
  {
    pitching->UpdateTimeStep(t);
    EXPECT_EQ(dgmf_test::Field(pitching->GetOutput(), "MotionTime"), t);
    EXPECT_EQ(pitching->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), t);
    EXPECT_EQ(pitching->GetLastMotionTime(), t);
    if (t > 0.0)
    {
      EXPECT_TRUE(pitching->GetLastExecutionReusedGraph()) << "a frame rebuilt the graph";
    }
    vtkNew<vtkDGMFDeformFilter> still;
    still->SetInputData(mesh);
    still->SetBoundaryMarkerArrayName("BoundaryMarker");
    still->SetRotationAngle(5.0 + 20.0 * std::sin(2.0 * Pi * t));
    still->Update();
    EXPECT_LT(LargestDifference(PointsOf(pitching), PointsOf(still)), 1e-9) << "t = " << t;
  }
  EXPECT_EQ(mesh->GetPoint(0)[0], Rectangle()->GetPoint(0)[0]); // the input is unchanged

  // Back to a constant motion: no time steps any more, and no MotionTime.
  pitching->SetRotationLaw(vtkDGMFDeformFilter::CONSTANT);
  pitching->UpdateInformation();
  EXPECT_FALSE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  pitching->Update();
  EXPECT_EQ(pitching->GetOutput()->GetFieldData()->GetArray("MotionTime"), nullptr);

  // A ramp of the translation along Translation's direction: half-way at t = 0.5.
  vtkNew<vtkDGMFDeformFilter> ramp;
  ramp->SetInputData(mesh);
  ramp->SetBoundaryMarkerArrayName("BoundaryMarker");
  ramp->SetTranslation(2.0, 0.0, 0.0); // only its direction counts
  ramp->SetTranslationLaw(vtkDGMFDeformFilter::RAMP);
  ramp->SetTranslationLawParameters(0.0, 0.5, 0.0, 1.0);
  ramp->UpdateTimeStep(0.5);
  vtkNew<vtkDGMFDeformFilter> shifted;
  shifted->SetInputData(mesh);
  shifted->SetBoundaryMarkerArrayName("BoundaryMarker");
  shifted->SetTranslation(0.25, 0.0, 0.0);
  shifted->Update();
  EXPECT_LT(LargestDifference(PointsOf(ramp), PointsOf(shifted)), 1e-12);

  // A translation law needs a direction; a ramp must end after it starts.
  Errors errors(ramp);
  ramp->SetTranslation(0.0, 0.0, 0.0);
  ramp->UpdateTimeStep(0.5);
  EXPECT_TRUE(errors.Contains("Translation must not be zero"));
  EXPECT_EQ(ramp->GetOutput()->GetNumberOfPoints(), 0);
  ramp->SetTranslation(1.0, 0.0, 0.0);
  ramp->SetTranslationLawParameters(0.0, 0.5, 1.0, 1.0);
  ramp->UpdateTimeStep(0.5);
  EXPECT_TRUE(errors.Contains("end time"));
}

TEST(MotionInTime, AnInputWithOneTimeGetsTheMotionsTimesAndOneWithSeveralKeepsThem)
{
  // An OpenFOAM case with a "0" directory alone reports the one time 0: the animation had that
  // one frame until 2026-11-30. An input with two times or more keeps them.
  vtkNew<TimedGridSource> source;
  source->Grid = Rectangle();
  for (const std::vector<double>& times : { std::vector<double>{ 0.0 }, { 0.0, 2.0, 5.0 } })
  {
    source->Times = times;
    source->Modified();
    vtkNew<vtkDGMFDeformFilter> pitching;
    pitching->SetInputConnection(source->GetOutputPort());
    pitching->SetBoundaryMarkerArrayName("BoundaryMarker");
    pitching->SetRotationLaw(vtkDGMFDeformFilter::HARMONIC);
    pitching->SetRotationLawParameters(0.0, 10.0, 1.0, 0.0);
    pitching->SetNumberOfTimeSteps(5);
    pitching->UpdateInformation();
    vtkInformation* info = pitching->GetOutputInformation(0);
    const int reported = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    EXPECT_EQ(reported, times.size() > 1 ? 3 : 5) << times.size();
    pitching->UpdateTimeStep(0.25);
    EXPECT_EQ(dgmf_test::Field(pitching->GetOutput(), "MotionTime"), 0.25) << times.size();
  }
}

TEST(MotionInTime, APitchingAirfoilComesBackToTheSameBitsEveryPeriodWithoutInvertedCells)
{
  // NACA 0012 pitching +-20 degrees about its quarter chord, 50 frames a period, two periods,
  // with the quality guard: each frame maps from the input mesh, so frame k + 50 is frame k.
  auto airfoil = dgmf_test::ReadShippedMesh("pitching_airfoil.vtu", AirfoilPoints);
  vtkNew<vtkDGMFDeformFilter> pitching;
  pitching->SetInputData(airfoil);
  pitching->SetBoundaryMarkerArrayName("BoundaryMarker");
  pitching->SetRotationCenter(0.25, 0.0, 0.0);
  pitching->SetRotationLaw(vtkDGMFDeformFilter::HARMONIC);
  pitching->SetRotationLawParameters(0.0, 20.0, 1.0, 0.0);
  pitching->SetTimeRange(0.0, 2.0);
  pitching->SetNumberOfTimeSteps(101);
  pitching->SetSubSteps(0);
  pitching->SetRepairThreshold(0.2);
  pitching->UpdateInformation();
  vtkInformation* info = pitching->GetOutputInformation(0);
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 101);
  const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  std::vector<std::vector<double>> firstPeriod;
  double lowest = 1.0;
  for (int k = 0; k <= 100; ++k)
  {
    pitching->UpdateTimeStep(steps[k]);
    ASSERT_EQ(pitching->GetOutput()->GetNumberOfPoints(), AirfoilPoints) << "frame " << k;
    EXPECT_EQ(dgmf_test::Field(pitching->GetOutput(), "InvertedCellCount"), 0.0) << "frame " << k;
    lowest = std::min(lowest, dgmf_test::Field(pitching->GetOutput(), "SizeSkewMinimum"));
    std::vector<double> points = PointsOf(pitching);
    if (k < 50)
    {
      firstPeriod.push_back(points);
    }
    else
    {
      ASSERT_EQ(std::memcmp(points.data(), firstPeriod[static_cast<std::size_t>(k % 50)].data(),
                  points.size() * sizeof(double)),
        0)
        << "frame " << k << " differs from frame " << k % 50;
    }
  }
  EXPECT_GE(lowest, 0.2); // the guard's threshold held in every frame
  // The frame at 20 degrees is not the input: the law did move the airfoil.
  EXPECT_GT(LargestDifference(firstPeriod[12], firstPeriod[0]), 0.05);
}

TEST(MotionInTime, ATrajectoryTableMovesItsBodyBetweenRows)
{
  auto mesh = Rectangle();
  // Body 1: from rest to x + 1 and 30 degrees about z at t = 1, back to 0 degrees at t = 2.
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetTrajectoryData(Table({ { "time", { 0.0, 1.0, 2.0 } }, { "Body", { 1, 1, 1 } },
    { "TX", { 0.0, 1.0, 1.0 } }, { "RZ", { 0.0, 30.0, 0.0 } } }));
  filter->UpdateInformation();
  vtkInformation* info = filter->GetOutputInformation(0);
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 3);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[2], 2.0);
  filter->UpdateTimeStep(0.5);
  vtkNew<vtkDGMFDeformFilter> still;
  still->SetInputData(mesh);
  still->SetBoundaryMarkerArrayName("BoundaryMarker");
  still->SetTranslation(0.5, 0.0, 0.0);
  still->SetRotationAngle(15.0);
  still->Update();
  EXPECT_LT(LargestDifference(PointsOf(filter), PointsOf(still)), 1e-12);

  // Tables the filter refuses, with the row or the column named.
  const auto message = [&](vtkTable* table)
  {
    vtkNew<vtkDGMFDeformFilter> refused;
    Errors errors(refused);
    refused->SetInputData(mesh);
    refused->SetBoundaryMarkerArrayName("BoundaryMarker");
    refused->SetTrajectoryData(table);
    refused->UpdateTimeStep(0.5);
    EXPECT_EQ(refused->GetOutput()->GetNumberOfPoints(), 0);
    return errors.Messages.empty() ? std::string() : errors.Messages.front();
  };
  EXPECT_NE(message(Table({ { "Time", { 0.0, 2.0, 1.0 } }, { "TX", { 0, 1, 2 } } })).find("row 3"),
    std::string::npos);
  EXPECT_NE(message(Table({ { "T", { 0.0, 1.0 } } })).find("no column 'Time'"), std::string::npos);
  const std::string quaternion = message(Table({ { "Time", { 0.0, 1.0 } }, { "QW", { 1.0, 0.9 } },
    { "QX", { 0.0, 0.0 } }, { "QY", { 0.0, 0.0 } }, { "QZ", { 0.0, 0.0 } } }));
  EXPECT_NE(quaternion.find("row 2"), std::string::npos) << quaternion;
  EXPECT_NE(quaternion.find("length"), std::string::npos) << quaternion;
  EXPECT_NE(message(Table({ { "Time", { 0.0, 1.0 } }, { "QW", { 1.0, 1.0 } } })).find("all four"),
    std::string::npos);
  // Rows for a body the mesh does not have (one body here): refused, not ignored with the mesh
  // left where it is.
  const std::string body =
    message(Table({ { "Time", { 0.0, 1.0 } }, { "Body", { 3, 3 } }, { "TX", { 0.0, 1.0 } } }));
  EXPECT_NE(body.find("moves body 3, but the mesh has 1 moving body"), std::string::npos) << body;
  // A row cut short: VTK's CSV readers give a shorter column, which was read past its end (a
  // random rotation at that time, until 2026-11-30).
  vtkSmartPointer<vtkTable> cut = Table({ { "Time", { 0.0, 1.0, 2.0 } } });
  vtkNew<vtkDoubleArray> shorter;
  shorter->SetName("RZ");
  shorter->InsertNextValue(0.0);
  shorter->InsertNextValue(-10.0);
  cut->GetRowData()->AddArray(shorter);
  const std::string whole = message(cut);
  EXPECT_NE(whole.find("rows are not whole: its column 'RZ' has 2 values and the table 3 rows"),
    std::string::npos)
    << whole;
  // A column named twice (in another case, or with spaces: a table keeps both): which one?
  const std::string twice =
    message(Table({ { "Time", { 0.0, 1.0 } }, { "TX", { 0.0, 1.0 } }, { " tx", { 0.0, 2.0 } } }));
  EXPECT_NE(twice.find("has two columns 'TX'"), std::string::npos) << twice;
}
