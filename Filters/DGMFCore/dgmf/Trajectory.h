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
 * (slerp); the rotation is then about the given centre, as an axis and an angle (at most 180
 * degrees from the initial orientation).
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
  std::map<int, std::vector<TrajectoryRow>> Bodies;
};

} // namespace dgmf

#endif
