#include "dgmf/DampingFunction.h"

#include "dgmf/Wendland.h"

namespace dgmf
{

bool IsValidDampingFunction(int value)
{
  return value >= static_cast<int>(DampingFunction::U1) &&
    value <= static_cast<int>(DampingFunction::U7);
}

double EvaluateDamping(DampingFunction u, double r)
{
  if (r >= 1.0)
  {
    return 0.0;
  }
  if (r <= 0.0)
  {
    return 1.0;
  }
  const double s = 1.0 - r;
  const double s2 = s * s;
  switch (u)
  {
    case DampingFunction::U1:
      return s2 * (r + 1.0);
    case DampingFunction::U2:
      return WendlandC2(r);
    case DampingFunction::U3:
      return s2 * s2 * s2 * ((35.0 * r + 18.0) * r + 3.0) / 3.0;
    case DampingFunction::U4:
    {
      const double s4 = s2 * s2;
      return s4 * s4 * (((32.0 * r + 25.0) * r + 8.0) * r + 1.0);
    }
    case DampingFunction::U5:
      return s2 * s * (r + 1.0);
    case DampingFunction::U6:
      return s2;
    case DampingFunction::U7:
      return s;
  }
  return 0.0;
}

} // namespace dgmf
