#include "dgmf/RigidMotion.h"

#include "dgmf/NumberText.h"

#include <cmath>
#include <stdexcept>
#include <string>

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

bool RigidMotion::HasEulerAngles() const
{
  return this->AnglesDegrees[0] != 0.0 || this->AnglesDegrees[1] != 0.0 ||
    this->AnglesDegrees[2] != 0.0;
}

bool RigidMotion::HasAxisRotation() const
{
  return this->AxisAngleDegrees != 0.0;
}

bool RigidMotion::HasRotation() const
{
  return this->HasEulerAngles() || this->HasAxisRotation();
}

void RigidMotion::GetUnitAxis(double axis[3]) const
{
  const double norm = std::sqrt(
    this->Axis[0] * this->Axis[0] + this->Axis[1] * this->Axis[1] + this->Axis[2] * this->Axis[2]);
  if (!(norm > 0.0) || !std::isfinite(norm))
  {
    throw std::invalid_argument("the rotation axis must be a finite, non-zero vector");
  }
  for (int c = 0; c < 3; ++c)
  {
    axis[c] = this->Axis[c] / norm;
  }
}

void RigidMotion::CheckRotation() const
{
  for (double angle : { this->AnglesDegrees[0], this->AnglesDegrees[1], this->AnglesDegrees[2],
         this->AxisAngleDegrees })
  {
    if (!(std::abs(angle) <= MaximumAngleDegrees))
    {
      throw std::invalid_argument(
        "rotation angles must be within [-720, 720] degrees (got " + NumberText(angle) + ")");
    }
  }
  if (!this->HasAxisRotation())
  {
    return;
  }
  if (this->HasEulerAngles())
  {
    throw std::invalid_argument(
      "a rigid motion has either Euler angles or an axis rotation, not both");
  }
  double axis[3];
  this->GetUnitAxis(axis);
}

void RigidMotion::Check() const
{
  for (int c = 0; c < 3; ++c)
  {
    if (!std::isfinite(this->Translation[c]) || !std::isfinite(this->Center[c]))
    {
      throw std::invalid_argument("the translation and the rotation centre must be finite");
    }
  }
  this->CheckRotation();
}

bool RigidMotion::KeepsPlane() const
{
  if (this->HasAxisRotation() && (this->Axis[0] != 0.0 || this->Axis[1] != 0.0))
  {
    return false;
  }
  return this->AnglesDegrees[0] == 0.0 && this->AnglesDegrees[1] == 0.0 &&
    this->Translation[2] == 0.0;
}

bool RigidMotion::IsIdentity() const
{
  return !this->HasRotation() && this->Translation[0] == 0.0 && this->Translation[1] == 0.0 &&
    this->Translation[2] == 0.0;
}

void RigidMotion::GetRotationMatrix(double fraction, double R[3][3]) const
{
  this->CheckRotation();
  if (this->HasAxisRotation())
  {
    // Rodrigues: R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T.
    double k[3];
    this->GetUnitAxis(k);
    const double angle = fraction * this->AxisAngleDegrees * DegreesToRadians;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    const double v = 1.0 - c;
    R[0][0] = c + v * k[0] * k[0];
    R[0][1] = v * k[0] * k[1] - s * k[2];
    R[0][2] = v * k[0] * k[2] + s * k[1];
    R[1][0] = v * k[1] * k[0] + s * k[2];
    R[1][1] = c + v * k[1] * k[1];
    R[1][2] = v * k[1] * k[2] - s * k[0];
    R[2][0] = v * k[2] * k[0] - s * k[1];
    R[2][1] = v * k[2] * k[1] + s * k[0];
    R[2][2] = c + v * k[2] * k[2];
    return;
  }
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
  this->CheckRotation();
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
