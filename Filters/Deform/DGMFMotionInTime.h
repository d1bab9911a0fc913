/**
 * @file DGMFMotionInTime.h
 * @brief vtkDGMFDeformFilter's motion at a time: the rotation about an axis, the motion laws, the
 * trajectory table, and the time steps the filter reports (private to the DGMF::Filters module).
 */
#ifndef DGMFMotionInTime_h
#define DGMFMotionInTime_h

#include "dgmf/MotionLaw.h"
#include "dgmf/RigidMotion.h"
#include "dgmf/Trajectory.h"

#include <memory>
#include <vector>

class vtkDGMFDeformFilter;
class vtkInformation;
class vtkTable;

namespace dgmf_vtk
{

/// True when the filter's motion depends on time: a law other than Constant, or a table connected.
bool IsMotionInTime(vtkDGMFDeformFilter* filter, bool hasTrajectoryTable);

/// One execution's motion in time.
struct MotionInTime
{
  bool TimeDependent = false; ///< a law other than Constant, or a trajectory table
  double Time = 0.0;          ///< the time the motion is taken at (0 when not time dependent)
  std::unique_ptr<dgmf::Trajectory> Trajectory; ///< the table's motions, when one is connected
};

/**
 * The motion in time of the execution about to run (RequestData): the time asked for downstream
 * (`outInfo`'s UPDATE_TIME_STEP), else the first of the motion's time steps, and the trajectory
 * `table` read (may be null). Throws std::invalid_argument for a table that cannot be read.
 */
MotionInTime MotionOfExecution(
  vtkDGMFDeformFilter* filter, vtkTable* table, vtkInformation* outInfo);

/**
 * RequestInformation's part: when the motion depends on time and the input (`inInfo`) has fewer
 * than two time steps, the motion's own (MotionTimeSteps, the table's when it can be read) and
 * their range are set in `outInfo`; an input with two or more keeps them (the pipeline copied
 * them already).
 */
void ReportMotionTimeSteps(
  vtkDGMFDeformFilter* filter, vtkTable* table, vtkInformation* inInfo, vtkInformation* outInfo);

/**
 * The motion the filter's properties give at time `t`: Translation (its direction times the
 * translation law's value, with a law), RotationCenter, and RotationAngles or RotationAngle about
 * RotationAxis (the rotation law's value, with a law). Throws std::invalid_argument, with the
 * message for the user, for RotationAngles together with a RotationAngle or a rotation law, a
 * translation law with a zero Translation, and bad law parameters. With `largest`, the laws'
 * largest magnitudes instead of their values at `t` (the motion a series' checks judge before
 * its first frame: an axis of length 0, a 2D mesh turned out of its plane).
 */
dgmf::RigidMotion PropertiesMotionAt(vtkDGMFDeformFilter* filter, double t, bool largest = false);

/**
 * The trajectories of a table (the filter's second input): a column "Time"; optionally "Body"
 * (ids >= 1; default 1), "TX", "TY", "TZ" (default 0), and the rotation as a unit quaternion
 * "QW", "QX", "QY", "QZ" or as angles in degrees "RX", "RY", "RZ" (RotationAngles' convention);
 * without either, no rotation. Column names are matched without regard to case. Throws
 * std::invalid_argument naming the column or the row (rows count from 1).
 */
dgmf::Trajectory ReadTrajectoryTable(vtkTable* table);

/**
 * The time steps the filter reports when the motion depends on time and the input has none: the
 * trajectory's times if there is one, else NumberOfTimeSteps equally spaced over TimeRange.
 */
std::vector<double> MotionTimeSteps(
  vtkDGMFDeformFilter* filter, const dgmf::Trajectory* trajectory);

/// MotionTimeSteps with the trajectory of `table` (read here; may be null: none). Throws
/// std::invalid_argument, as ReadTrajectoryTable does, for a table that cannot be read.
std::vector<double> MotionTimeSteps(vtkDGMFDeformFilter* filter, vtkTable* table);

} // namespace dgmf_vtk

#endif
