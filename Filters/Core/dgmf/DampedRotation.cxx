#include "dgmf/DampedRotation.h"

#include <cmath>
#include <stdexcept>

namespace dgmf
{

DampedRigidMotion::DampedRigidMotion(const RigidMotion& motion)
  : Motion(motion)
{
  constexpr double degreesToRadians = 3.14159265358979323846 / 180.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (motion.AnglesDegrees[axis] == 0.0)
    {
      continue;
    }
    if (!(std::abs(motion.AnglesDegrees[axis]) <= 720.0))
    {
      throw std::invalid_argument("rotation angles must be within [-720, 720] degrees");
    }
    Axis& a = this->Axes[this->NumberOfAxes++];
    a.I = (axis + 1) % 3;
    a.J = (axis + 2) % 3;
    a.Angle = motion.AnglesDegrees[axis] * degreesToRadians;
    a.AnglePerStep = a.Angle / Steps;
    a.Sin.resize(Steps + 1);
    a.Cos.resize(Steps + 1);
    for (int k = 0; k <= Steps; ++k)
    {
      const double angle = k == Steps ? a.Angle : a.Angle * k / Steps;
      a.Sin[static_cast<std::size_t>(k)] = std::sin(angle);
      a.Cos[static_cast<std::size_t>(k)] = std::cos(angle);
    }
  }
}

} // namespace dgmf
