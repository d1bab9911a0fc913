#include "dgmf/RigidMotion.h"

#include <cmath>

namespace dgmf
{
namespace
{
constexpr double DegreesToRadians = 3.14159265358979323846 / 180.0;

/// Left-multiplies R by the rotation of `angle` radians about coordinate axis `axis`.
void RotateAbout(int axis, double angle, double R[3][3])
{
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  for (int col = 0; col < 3; ++col)
  {
    const double ri = R[i][col];
    const double rj = R[j][col];
    R[i][col] = c * ri - s * rj;
    R[j][col] = s * ri + c * rj;
  }
}
} // namespace

bool RigidMotion::HasRotation() const
{
  return this->AnglesDegrees[0] != 0.0 || this->AnglesDegrees[1] != 0.0 ||
    this->AnglesDegrees[2] != 0.0;
}

bool RigidMotion::IsIdentity() const
{
  return !this->HasRotation() && this->Translation[0] == 0.0 && this->Translation[1] == 0.0 &&
    this->Translation[2] == 0.0;
}

void RigidMotion::GetRotationMatrix(double fraction, double R[3][3]) const
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      R[i][j] = i == j ? 1.0 : 0.0;
    }
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (this->AnglesDegrees[axis] != 0.0)
    {
      RotateAbout(axis, fraction * this->AnglesDegrees[axis] * DegreesToRadians, R);
    }
  }
}

void RigidMotion::Apply(double f, const double x[3], const double* d, double out[3]) const
{
  double y[3] = { x[0], x[1], x[2] };
  if (f != 0.0 && this->HasRotation())
  {
    double R[3][3];
    this->GetRotationMatrix(f, R);
    const double r[3] = { x[0] - this->Center[0], x[1] - this->Center[1], x[2] - this->Center[2] };
    for (int i = 0; i < 3; ++i)
    {
      y[i] = this->Center[i] + R[i][0] * r[0] + R[i][1] * r[1] + R[i][2] * r[2];
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    out[i] = y[i] + f * this->Translation[i] + (d ? f * d[i] : 0.0);
  }
}

} // namespace dgmf
