#include "dgmf/Trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

std::string RowName(const TrajectoryRow& row)
{
  return "trajectory row " + std::to_string(row.Row) + " (time " + std::to_string(row.Time) +
    ", body " + std::to_string(row.Body) + ")";
}

/// q = a * b (Hamilton product, w first).
void Multiply(const double a[4], const double b[4], double q[4])
{
  q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  q[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  q[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  q[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/// The axis (unit, or zero for no rotation) and angle in degrees (0 to 180) of unit quaternion q.
double AxisAngleOf(const double q[4], double axis[3])
{
  const double sign = q[0] < 0.0 ? -1.0 : 1.0; // the same rotation, by at most 180 degrees
  const double sinHalf = std::sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 3; ++k)
  {
    axis[k] = sinHalf > 0.0 ? sign * q[1 + k] / sinHalf : 0.0;
  }
  return sinHalf > 0.0 ? 2.0 * std::atan2(sinHalf, sign * q[0]) * 180.0 / Pi : 0.0;
}

/// The shortest-arc interpolation of unit quaternions a and b at s in [0, 1].
void Slerp(const double a[4], const double b[4], double s, double q[4])
{
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const double sign = d < 0.0 ? -1.0 : 1.0; // q and -q are the same rotation
  d *= sign;
  double wa = 1.0 - s, wb = s;
  if (d < 0.9995)
  {
    const double theta = std::acos(std::min(d, 1.0));
    wa = std::sin((1.0 - s) * theta) / std::sin(theta);
    wb = std::sin(s * theta) / std::sin(theta);
  }
  double norm = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    q[k] = wa * a[k] + wb * sign * b[k];
    norm += q[k] * q[k];
  }
  norm = std::sqrt(norm);
  for (int k = 0; k < 4; ++k)
  {
    q[k] /= norm;
  }
}
} // namespace

void EulerAnglesToQuaternion(const double anglesDegrees[3], double q[4])
{
  // R = Rz Ry Rx: q = qz * qy * qx.
  double axes[3][4];
  for (int c = 0; c < 3; ++c)
  {
    const double half = 0.5 * anglesDegrees[c] * Pi / 180.0;
    axes[c][0] = std::cos(half);
    for (int k = 0; k < 3; ++k)
    {
      axes[c][1 + k] = k == c ? std::sin(half) : 0.0;
    }
  }
  double zy[4];
  Multiply(axes[2], axes[1], zy);
  Multiply(zy, axes[0], q);
}

Trajectory::Trajectory(const std::vector<TrajectoryRow>& rows)
{
  for (const TrajectoryRow& row : rows)
  {
    bool finite = std::isfinite(row.Time);
    for (double v : row.Translation)
      finite = finite && std::isfinite(v);
    double norm = 0.0;
    for (double v : row.Quaternion)
    {
      finite = finite && std::isfinite(v);
      norm += v * v;
    }
    if (!finite)
    {
      throw std::invalid_argument(RowName(row) + ": a value is not finite.");
    }
    if (row.Body < 1)
    {
      throw std::invalid_argument(RowName(row) + ": body ids start at 1.");
    }
    if (std::abs(std::sqrt(norm) - 1.0) > 1e-6)
    {
      throw std::invalid_argument(RowName(row) + ": the quaternion's length is " +
        std::to_string(std::sqrt(norm)) + ", not 1.");
    }
    std::vector<TrajectoryRow>& body = this->Bodies[row.Body];
    if (!body.empty() && !(row.Time > body.back().Time))
    {
      throw std::invalid_argument(RowName(row) +
        ": the times of a body must increase (the row "
        "before it has time " +
        std::to_string(body.back().Time) + ").");
    }
    body.push_back(row);
  }
  if (this->Bodies.empty())
  {
    throw std::invalid_argument("the trajectory table has no rows");
  }
  for (const auto& [id, rows] : this->Bodies)
  {
    std::vector<RowRotation>& path = this->Rotations[id];
    path.resize(rows.size());
    // Angles about one coordinate axis in every row: that axis, the angles as given.
    int axis = TrajectoryRow::NoAxis;
    bool oneAxis = true;
    for (const TrajectoryRow& row : rows)
    {
      const bool fits = row.AngleAxis == TrajectoryRow::NoAxis ||
        (row.AngleAxis >= 0 && (axis == TrajectoryRow::NoAxis || axis == row.AngleAxis));
      oneAxis = oneAxis && fits;
      axis = row.AngleAxis >= 0 ? row.AngleAxis : axis;
    }
    if (oneAxis)
    {
      for (std::size_t k = 0; k < rows.size(); ++k)
      {
        path[k].Axis[axis >= 0 ? axis : 2] = 1.0;
        path[k].Degrees = rows[k].AngleAxis >= 0 ? rows[k].AngleDegrees : 0.0;
        path[k].AxisToNext = true;
        path[k].AsGiven = true;
      }
      continue;
    }
    // Otherwise the orientations: each step's own rotation (the shorter way) adds to the angle
    // while it turns about the axis turned about so far.
    path[0].Degrees = AxisAngleOf(rows[0].Quaternion, path[0].Axis);
    for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    {
      const double* a = rows[k].Quaternion;
      const double inverse[4] = { a[0], -a[1], -a[2], -a[3] };
      double step[4], stepAxis[3];
      Multiply(rows[k + 1].Quaternion, inverse, step);
      const double stepDegrees = AxisAngleOf(step, stepAxis);
      RowRotation& here = path[k];
      RowRotation& next = path[k + 1];
      const double along =
        here.Axis[0] * stepAxis[0] + here.Axis[1] * stepAxis[1] + here.Axis[2] * stepAxis[2];
      const bool still = here.Axis[0] == 0.0 && here.Axis[1] == 0.0 && here.Axis[2] == 0.0;
      // About one axis within 0.01 radian (rounded tables); At() keeps the exact orientation.
      if (stepDegrees == 0.0 || still || std::abs(along) >= std::cos(0.01))
      {
        const double sign = still || stepDegrees == 0.0 ? 1.0 : (along < 0.0 ? -1.0 : 1.0);
        for (int c = 0; c < 3; ++c)
        {
          next.Axis[c] = still ? stepAxis[c] : here.Axis[c];
          here.Axis[c] = next.Axis[c]; // a body at rest turns about the step's axis
        }
        next.Degrees = here.Degrees + sign * stepDegrees;
        here.AxisToNext = true;
      }
      else
      {
        next.Degrees = AxisAngleOf(rows[k + 1].Quaternion, next.Axis);
      }
    }
  }
}

std::vector<double> Trajectory::GetTimes() const
{
  std::vector<double> times;
  for (const auto& body : this->Bodies)
  {
    for (const TrajectoryRow& row : body.second)
    {
      times.push_back(row.Time);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

int Trajectory::GetLargestBody() const
{
  return this->Bodies.rbegin()->first;
}

RigidMotion Trajectory::At(int body, double t, const double center[3]) const
{
  const auto found = this->Bodies.find(body);
  if (found == this->Bodies.end())
  {
    throw std::invalid_argument("the trajectory table has no row for body " + std::to_string(body));
  }
  const std::vector<TrajectoryRow>& rows = found->second;
  // The rows around t: [k - 1, k], or the first or last row alone.
  const auto after = std::upper_bound(rows.begin(), rows.end(), t,
    [](double time, const TrajectoryRow& row) { return time < row.Time; });
  const TrajectoryRow& a = after == rows.begin() ? rows.front() : *(after - 1);
  const TrajectoryRow& b = after == rows.end() ? rows.back() : *after;
  const double s = &a == &b ? 0.0 : (t - a.Time) / (b.Time - a.Time);
  RigidMotion motion;
  for (int c = 0; c < 3; ++c)
  {
    motion.Translation[c] = a.Translation[c] + s * (b.Translation[c] - a.Translation[c]);
    motion.Center[c] = center[c];
  }
  const std::vector<RowRotation>& path = this->Rotations.at(body);
  const RowRotation& from = path[static_cast<std::size_t>(&a - rows.data())];
  const RowRotation& to = path[static_cast<std::size_t>(&b - rows.data())];
  const double estimate = from.Degrees + s * (to.Degrees - from.Degrees);
  if ((&a == &b || from.AxisToNext) && from.AsGiven)
  {
    // The rows' angles about one coordinate axis: exact, continuous beyond 180 degrees.
    if (estimate != 0.0)
    {
      motion.AxisAngleDegrees = estimate;
      std::copy(from.Axis, from.Axis + 3, motion.Axis);
    }
    return motion;
  }
  double q[4], axis[3];
  Slerp(a.Quaternion, b.Quaternion, s, q);
  double degrees = AxisAngleOf(q, axis);
  if (&a == &b || from.AxisToNext)
  {
    // About one axis: the orientation's angle, turned by the multiple of 360 degrees nearest to
    // the sum of the steps (continuous beyond 180 degrees; the orientation stays the table's).
    const double* along = from.Axis;
    const double sign =
      degrees == 0.0 || axis[0] * along[0] + axis[1] * along[1] + axis[2] * along[2] >= 0.0 ? 1.0
                                                                                            : -1.0;
    for (int c = 0; c < 3; ++c)
    {
      axis[c] = degrees == 0.0 ? along[c] : sign * axis[c];
    }
    degrees *= sign;
    degrees += 360.0 * std::round((estimate - degrees) / 360.0);
  }
  if (degrees != 0.0)
  {
    motion.AxisAngleDegrees = degrees;
    std::copy(axis, axis + 3, motion.Axis);
  }
  return motion;
}

} // namespace dgmf
