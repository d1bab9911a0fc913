#include "DGMFMotionInTime.h"

#include "vtkDGMFDeformFilter.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dgmf_vtk
{
namespace
{
dgmf::MotionLaw LawOf(int kind, const double parameters[4])
{
  dgmf::MotionLaw law;
  law.Kind = static_cast<dgmf::MotionLawKind>(kind);
  std::copy_n(parameters, 4, law.Parameters);
  return law;
}

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// `text` without the spaces and tabs around it (a CSV header's " Time ").
std::string Trimmed(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t");
  return first == std::string::npos ? ""
                                    : text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// The column `name` of `table` (any case, spaces around ignored), or null; std::invalid_argument
/// if not numeric.
vtkDataArray* Column(vtkTable* table, const char* name)
{
  vtkAbstractArray* found = nullptr;
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    vtkAbstractArray* column = table->GetColumn(c);
    if (column && column->GetName() && Trimmed(Lower(column->GetName())) == Lower(name))
    {
      if (found)
      {
        // "Time,TX,TX": which one was meant? (the first was taken until 2026-11-30)
        throw std::invalid_argument(std::string("The trajectory table has two columns '") + name +
          "': name each column once.");
      }
      found = column;
    }
  }
  if (!found)
  {
    return nullptr;
  }
  auto* numbers = vtkDataArray::SafeDownCast(found);
  if (!numbers || numbers->GetNumberOfComponents() != 1)
  {
    throw std::invalid_argument(std::string("The trajectory table's column '") + found->GetName() +
      "' is not a column of numbers.");
  }
  return numbers;
}

std::string ColumnNames(vtkTable* table)
{
  std::string names;
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    const char* name = table->GetColumn(c) ? table->GetColumn(c)->GetName() : nullptr;
    names += (names.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
  }
  return names.empty() ? "none" : names;
}
} // namespace

bool IsMotionInTime(vtkDGMFDeformFilter* filter, bool hasTrajectoryTable)
{
  return hasTrajectoryTable || filter->GetRotationLaw() != vtkDGMFDeformFilter::CONSTANT ||
    filter->GetTranslationLaw() != vtkDGMFDeformFilter::CONSTANT;
}

MotionInTime MotionOfExecution(
  vtkDGMFDeformFilter* filter, vtkTable* table, vtkInformation* outInfo)
{
  MotionInTime motion;
  motion.TimeDependent = IsMotionInTime(filter, table != nullptr);
  if (!motion.TimeDependent)
  {
    return motion;
  }
  if (table)
  {
    motion.Trajectory = std::make_unique<dgmf::Trajectory>(ReadTrajectoryTable(table));
  }
  motion.Time = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    : MotionTimeSteps(filter, motion.Trajectory.get()).front();
  return motion;
}

void ReportMotionTimeSteps(
  vtkDGMFDeformFilter* filter, vtkTable* table, vtkInformation* inInfo, vtkInformation* outInfo)
{
  // An input whose data change in time (two time steps or more) keeps its steps; one time step
  // (an OpenFOAM case's "0": until 2026-11-30 the animation had that one frame) does not.
  if (!IsMotionInTime(filter, table != nullptr) ||
    inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) > 1)
  {
    return;
  }
  std::vector<double> steps;
  try
  {
    steps = MotionTimeSteps(filter, table && table->GetNumberOfRows() > 0 ? table : nullptr);
  }
  catch (const std::exception&)
  {
    steps = MotionTimeSteps(filter, static_cast<const dgmf::Trajectory*>(nullptr));
    // the table's error is reported by RequestData
  }
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), static_cast<int>(steps.size()));
  const double range[2] = { steps.front(), steps.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
}

dgmf::RigidMotion PropertiesMotionAt(vtkDGMFDeformFilter* filter, double t, bool largest)
{
  dgmf::RigidMotion motion;
  filter->GetTranslation(motion.Translation);
  filter->GetRotationCenter(motion.Center);
  filter->GetRotationAngles(motion.AnglesDegrees);
  filter->GetRotationAxis(motion.Axis);
  motion.AxisAngleDegrees = filter->GetRotationAngle();
  const dgmf::MotionLaw rotation =
    LawOf(filter->GetRotationLaw(), filter->GetRotationLawParameters());
  const dgmf::MotionLaw translation =
    LawOf(filter->GetTranslationLaw(), filter->GetTranslationLawParameters());
  rotation.Check("the rotation law");
  translation.Check("the translation law");
  if (rotation.LargestMagnitude() > dgmf::RigidMotion::MaximumAngleDegrees)
  {
    // Said before the first frame, not at the first time beyond (a series half written).
    std::ostringstream message;
    message << "The rotation law reaches " << rotation.LargestMagnitude()
            << " degrees (mean + amplitude, or the ramp's ends): at most "
            << dgmf::RigidMotion::MaximumAngleDegrees
            << " (two turns) can be damped; deform a longer motion in parts.";
    throw std::invalid_argument(message.str());
  }
  if (motion.HasEulerAngles() && (motion.HasAxisRotation() || rotation.IsTimeDependent()))
  {
    throw std::invalid_argument(
      "Rotation Angles (about x, y, z) cannot be combined with a Rotation Angle about the Rotation "
      "Axis or with a rotation law (which turns about the Rotation Axis): set Rotation Angles to "
      "0 0 0, or the other to 0 and the law to Constant.");
  }
  if (rotation.IsTimeDependent())
  {
    motion.AxisAngleDegrees = largest ? rotation.LargestMagnitude() : rotation.Evaluate(t);
  }
  if (translation.IsTimeDependent())
  {
    const double* d = motion.Translation;
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(length > 0.0) || !std::isfinite(length))
    {
      throw std::invalid_argument("A translation law moves along the Translation's direction: "
                                  "Translation must not be zero.");
    }
    const double distance = largest ? translation.LargestMagnitude() : translation.Evaluate(t);
    for (double& component : motion.Translation)
    {
      component = component / length * distance;
    }
  }
  return motion;
}

dgmf::Trajectory ReadTrajectoryTable(vtkTable* table)
{
  // Columns of unequal length (a CSV reader's answer to a row cut short) would be read past
  // their ends.
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    vtkAbstractArray* column = table->GetColumn(c);
    if (column && column->GetNumberOfTuples() != table->GetNumberOfRows())
    {
      throw std::invalid_argument("The trajectory table's rows are not whole: its column '" +
        std::string(column->GetName() ? column->GetName() : "(unnamed)") + "' has " +
        std::to_string(column->GetNumberOfTuples()) + " values and the table " +
        std::to_string(table->GetNumberOfRows()) +
        " rows (a row cut short, or a table still being written?).");
    }
  }
  vtkDataArray* time = Column(table, "Time");
  if (!time)
  {
    throw std::invalid_argument(
      "The trajectory table has no column 'Time' (its columns: " + ColumnNames(table) + ").");
  }
  vtkDataArray* body = Column(table, "Body");
  vtkDataArray* translation[3] = { Column(table, "TX"), Column(table, "TY"), Column(table, "TZ") };
  vtkDataArray* quaternion[4] = { Column(table, "QW"), Column(table, "QX"), Column(table, "QY"),
    Column(table, "QZ") };
  vtkDataArray* angles[3] = { Column(table, "RX"), Column(table, "RY"), Column(table, "RZ") };
  const int quaternionColumns = static_cast<int>(std::count_if(
    quaternion, quaternion + 4, [](vtkDataArray* column) { return column != nullptr; }));
  const bool anyAngle = angles[0] || angles[1] || angles[2];
  if (quaternionColumns != 0 && quaternionColumns != 4)
  {
    throw std::invalid_argument(
      "The trajectory table has some of the quaternion columns QW, QX, QY, QZ but not all four "
      "(its columns: " +
      ColumnNames(table) + ").");
  }
  if (quaternionColumns == 4 && anyAngle)
  {
    throw std::invalid_argument("The trajectory table gives the rotation twice: as a quaternion "
                                "(QW, QX, QY, QZ) and as angles (RX, RY, RZ). Keep one.");
  }
  std::vector<dgmf::TrajectoryRow> rows;
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    dgmf::TrajectoryRow row;
    row.Row = static_cast<std::size_t>(r + 1);
    row.Time = time->GetTuple1(r);
    const double id = body ? body->GetTuple1(r) : 1.0;
    if (!(id >= 1.0 && id <= 1e6 && id == std::floor(id)))
    {
      throw std::invalid_argument("Trajectory row " + std::to_string(r + 1) + ": the body id " +
        std::to_string(id) + " is not a whole number from 1 on.");
    }
    row.Body = static_cast<int>(id);
    for (int c = 0; c < 3; ++c)
    {
      row.Translation[c] = translation[c] ? translation[c]->GetTuple1(r) : 0.0;
    }
    if (quaternionColumns == 4)
    {
      for (int k = 0; k < 4; ++k)
      {
        row.Quaternion[k] = quaternion[k]->GetTuple1(r);
      }
    }
    else if (anyAngle)
    {
      double degrees[3];
      for (int c = 0; c < 3; ++c)
      {
        degrees[c] = angles[c] ? angles[c]->GetTuple1(r) : 0.0;
      }
      // An angle that is not finite makes the quaternion so: dgmf::Trajectory names the row.
      dgmf::EulerAnglesToQuaternion(degrees, row.Quaternion);
      // An angle about one axis is kept as given (beyond 180 degrees: Trajectory).
      const int turned =
        static_cast<int>(std::count_if(degrees, degrees + 3, [](double d) { return d != 0.0; }));
      row.AngleAxis = turned == 0 ? dgmf::TrajectoryRow::NoAxis : -1;
      for (int c = 0; c < 3 && turned == 1; ++c)
      {
        row.AngleAxis = degrees[c] != 0.0 ? c : row.AngleAxis;
        row.AngleDegrees = degrees[c] != 0.0 ? degrees[c] : row.AngleDegrees;
      }
    }
    rows.push_back(row);
  }
  return dgmf::Trajectory(rows); // checks times, finiteness and unit quaternions, naming the row
}

std::vector<double> MotionTimeSteps(vtkDGMFDeformFilter* filter, const dgmf::Trajectory* trajectory)
{
  if (trajectory)
  {
    return trajectory->GetTimes();
  }
  // Increasing and distinct, as a pipeline's times must be: a range given end first is taken
  // from its low end, and an empty range (or one step) is one time.
  const double* range = filter->GetTimeRange();
  const double low = std::min(range[0], range[1]), high = std::max(range[0], range[1]);
  const int count = low < high ? filter->GetNumberOfTimeSteps() : 1;
  std::vector<double> steps;
  for (int k = 0; k < count; ++k)
  {
    steps.push_back(count == 1 ? low : low + (high - low) * k / (count - 1));
  }
  // Steps finer than the doubles around the range give equal times: each once.
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

std::vector<double> MotionTimeSteps(vtkDGMFDeformFilter* filter, vtkTable* table)
{
  if (!table)
  {
    return MotionTimeSteps(filter, static_cast<const dgmf::Trajectory*>(nullptr));
  }
  const dgmf::Trajectory trajectory = ReadTrajectoryTable(table);
  return MotionTimeSteps(filter, &trajectory);
}

} // namespace dgmf_vtk
