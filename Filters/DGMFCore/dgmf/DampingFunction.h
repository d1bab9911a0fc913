/**
 * @file DampingFunction.h
 * @brief The damping functions u1..u7 of the DGMF paper (Table 1).
 */
#ifndef dgmf_DampingFunction_h
#define dgmf_DampingFunction_h

#include "dgmf/Wendland.h"

#include <type_traits>

namespace dgmf
{

/**
 * The candidate functions u(r) of the paper's Table 1. Every one has u(0) = 1 and u(1) = 0.
 * U3 uses the Wendland C4 constant "+3" (the paper prints "+1", which would give u(0) = 1/3).
 */
enum class DampingFunction : int
{
  U1 = 1, ///< (1-r)^2 (r+1), the paper's choice (default)
  U2 = 2, ///< (1-r)^4 (4r+1), Wendland C2
  U3 = 3, ///< (1-r)^6 (35r^2+18r+3)/3, Wendland C4
  U4 = 4, ///< (1-r)^8 (32r^3+25r^2+8r+1), Wendland C6
  U5 = 5, ///< (1-r)^3 (r+1)
  U6 = 6, ///< (1-r)^2, Wendland C0
  U7 = 7  ///< 1-r, linear
};

/// True when `value` is one of the enumerators (1..7).
bool IsValidDampingFunction(int value);

/**
 * The damping factor f(r) of paper Eq. 2: u(r) for 0 <= r <= 1, 0 for r > 1.
 * r below 0 (round-off only: r is a convex combination of non-negative values) counts as 0.
 */
double EvaluateDamping(DampingFunction u, double r);

/// EvaluateDamping for the function `U` fixed at compile time (the same operations).
template <DampingFunction U>
inline double EvaluateDampingOf(double r)
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
  if constexpr (U == DampingFunction::U1)
  {
    return s2 * (r + 1.0);
  }
  else if constexpr (U == DampingFunction::U2)
  {
    return WendlandC2(r);
  }
  else if constexpr (U == DampingFunction::U3)
  {
    return s2 * s2 * s2 * ((35.0 * r + 18.0) * r + 3.0) / 3.0;
  }
  else if constexpr (U == DampingFunction::U4)
  {
    const double s4 = s2 * s2;
    return s4 * s4 * (((32.0 * r + 25.0) * r + 8.0) * r + 1.0);
  }
  else if constexpr (U == DampingFunction::U5)
  {
    return s2 * s * (r + 1.0);
  }
  else if constexpr (U == DampingFunction::U6)
  {
    return s2;
  }
  else
  {
    static_assert(U == DampingFunction::U7, "one of the seven functions");
    return s;
  }
}

/**
 * Calls `body(std::integral_constant<DampingFunction, U>())` for the function `u`, so that a loop
 * over many nodes evaluates EvaluateDampingOf<U> inline instead of choosing the function at every
 * node. Nothing is called for a value outside the enumerators.
 */
template <typename Body>
void WithDampingFunction(DampingFunction u, Body&& body)
{
  switch (u)
  {
    case DampingFunction::U1:
      return body(std::integral_constant<DampingFunction, DampingFunction::U1>());
    case DampingFunction::U2:
      return body(std::integral_constant<DampingFunction, DampingFunction::U2>());
    case DampingFunction::U3:
      return body(std::integral_constant<DampingFunction, DampingFunction::U3>());
    case DampingFunction::U4:
      return body(std::integral_constant<DampingFunction, DampingFunction::U4>());
    case DampingFunction::U5:
      return body(std::integral_constant<DampingFunction, DampingFunction::U5>());
    case DampingFunction::U6:
      return body(std::integral_constant<DampingFunction, DampingFunction::U6>());
    case DampingFunction::U7:
      return body(std::integral_constant<DampingFunction, DampingFunction::U7>());
  }
}

} // namespace dgmf

#endif
