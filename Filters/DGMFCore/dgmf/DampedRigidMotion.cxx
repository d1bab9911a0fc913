#include "dgmf/DampedRigidMotion.h"

#include <cmath>
#include <stdexcept>

namespace dgmf
{
namespace
{
/// Fills the sin/cos table of an angle given in degrees.
void Tabulate(double angleDegrees, int steps, std::vector<double>& sines,
  std::vector<double>& cosines, double& angle, double& anglePerStep)
{
  constexpr double degreesToRadians = 3.14159265358979323846 / 180.0;
  angle = angleDegrees * degreesToRadians;
  anglePerStep = angle / steps;
  sines.resize(static_cast<std::size_t>(steps) + 1);
  cosines.resize(static_cast<std::size_t>(steps) + 1);
  for (int k = 0; k <= steps; ++k)
  {
    const double a = k == steps ? angle : angle * k / steps;
    sines[static_cast<std::size_t>(k)] = std::sin(a);
    cosines[static_cast<std::size_t>(k)] = std::cos(a);
  }
}
} // namespace

DampedRigidMotion::DampedRigidMotion(const RigidMotion& motion)
  : Motion(motion)
{
  motion.CheckRotation();
  if (motion.HasAxisRotation())
  {
    this->HasAxisRotation = true;
    motion.GetUnitAxis(this->UnitAxis);
    Axis& a = this->AxisRotation;
    Tabulate(motion.AxisAngleDegrees, Steps, a.Sin, a.Cos, a.Angle, a.AnglePerStep);
    a.ShortSeries = std::abs(a.AnglePerStep) <= ShortSeriesLimit;
    return;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (motion.AnglesDegrees[axis] == 0.0)
    {
      continue;
    }
    Axis& a = this->Axes[this->NumberOfAxes++];
    a.I = (axis + 1) % 3;
    a.J = (axis + 2) % 3;
    Tabulate(motion.AnglesDegrees[axis], Steps, a.Sin, a.Cos, a.Angle, a.AnglePerStep);
    a.ShortSeries = std::abs(a.AnglePerStep) <= ShortSeriesLimit;
  }
}

} // namespace dgmf
