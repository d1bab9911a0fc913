/**
 * @file DampingFunction.h
 * @brief The damping functions u1..u7 of the DGMF paper (Table 1).
 */
#ifndef dgmf_DampingFunction_h
#define dgmf_DampingFunction_h

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

} // namespace dgmf

#endif
