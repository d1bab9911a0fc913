#include "dgmf/DampingFunction.h"

namespace dgmf
{

bool IsValidDampingFunction(int value)
{
  return value >= static_cast<int>(DampingFunction::U1) &&
    value <= static_cast<int>(DampingFunction::U7);
}

double EvaluateDamping(DampingFunction u, double r)
{
  double f = 0.0; // a value outside the enumerators (never given: parameters are checked)
  WithDampingFunction(
    u, [&](auto function) { f = EvaluateDampingOf<decltype(function)::value>(r); });
  return f;
}

} // namespace dgmf
