/**
 * @file Trajectory.h
 * @brief Rigid motions of bodies given at times (a table, e.g. from a six-degrees-of-freedom
 * solver), interpolated in between: translation linearly, rotation by slerp.
 */
#ifndef dgmf_Trajectory_h
#define dgmf_Trajectory_h

#include "dgmf/RigidMotion.h"

#include <cstddef>
#include <map>
#include <vector>

namespace dgmf
{

/// One row of a trajectory table: the motion of one body at one time.
struct TrajectoryRow
{
  double Time = 0.0;
  int Body = 1;                                  ///< body id, >= 1
  double Translation[3] = { 0.0, 0.0, 0.0 };     ///< from the body's initial position
  double Quaternion[4] = { 1.0, 0.0, 0.0, 0.0 }; ///< rotation (w, x, y, z), unit length
  std::size_t Row = 0;                           ///< the row's number in the table, for messages
  /// The rotation given as an angle about one coordinate axis (a table of angles RX, RY, RZ with
  /// at most one of them non-zero in the row): 0, 1 or 2; NoAxis for a row with no rotation;
  /// -1 otherwise (a quaternion, or angles about several axes).
  int AngleAxis = -1;
  double AngleDegrees = 0.0; ///< that angle, as given (beyond 180 degrees too)
  static constexpr int NoAxis = -2;
};

/**
 * The unit quaternion (w, x, y, z) of Euler angles in degrees about x, y and z applied in that
 * order (R = Rz Ry Rx, RigidMotion's convention).
 */
void EulerAnglesToQuaternion(const double anglesDegrees[3], double q[4]);

/**
 * @brief The trajectories of one or more bodies.
 *
 * Each body's rows must have strictly increasing times (in table order). Before a body's first
 * time its first row holds, after its last time its last row. Between two rows the translation is
 * interpolated linearly and the rotation along the shortest arc between the two quaternions
 * (slerp); the rotation is then about the given centre, as an axis and an angle.
 *
 * The angle is continuous in time where the rotation keeps one axis, beyond 180 degrees: a body
 * whose rows all turn it about one coordinate axis by angles (RX, RY or RZ alone) turns by the
 * angle interpolated linearly between its rows, as given (0, 90, ..., 450 degrees: up to 450);
 * otherwise, over each run of rows whose steps turn about one axis (within 0.01 radian: rows
 * written with a few digits), the steps' angles add up, and the orientation slerp gives is
 * turned by the multiple of 360 degrees nearest to that sum (so the body is exactly where the
 * table puts it). Elsewhere the angle is that of the orientation, at most 180 degrees. Angles
 * beyond +-720 degrees are refused by the filter (RigidMotion::CheckRotation). DGMF damps the angle
 * (a node turns by f times it), so an angle that wrapped from 180 to -180 degrees would make the
 * mesh jump between two times.
 */
class Trajectory
{
public:
  /**
   * Takes the rows (any order of bodies). Throws std::invalid_argument naming the table row for a
   * time, translation or quaternion that is not finite, a body id below 1, a quaternion whose
   * length differs from 1 by more than 1e-6, or a time not after the body's previous one.
   */
  explicit Trajectory(const std::vector<TrajectoryRow>& rows);

  /// Every time of the table, sorted, each once.
  std::vector<double> GetTimes() const;

  /// The largest body id.
  int GetLargestBody() const;

  /// True when the table has rows for `body`.
  bool HasBody(int body) const { return this->Bodies.count(body) > 0; }

  /**
   * The motion of `body` at time `t` about `center` (translation, and rotation as an axis and an
   * angle). Throws std::invalid_argument for a body without rows.
   */
  RigidMotion At(int body, double t, const double center[3]) const;

private:
  /// A row's rotation as an axis and an angle, continuous along the body's rows where it can be.
  struct RowRotation
  {
    double Axis[3] = { 0.0, 0.0, 0.0 }; ///< zero while the body has not turned
    double Degrees = 0.0;
    bool AxisToNext = false; ///< the step to the next row turns about Axis: angles interpolate
    bool AsGiven = false;    ///< the rows' own angles about one coordinate axis (exact)
  };

  std::map<int, std::vector<TrajectoryRow>> Bodies;
  std::map<int, std::vector<RowRotation>> Rotations; ///< per body, one per row
};

} // namespace dgmf

#endif
