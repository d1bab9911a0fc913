/**
 * @file SizeSkewTerms.h
 * @brief What the size-skew metric's files share (private to the core): the cube roots without
 * divisions, the final value's clamping, and the hexahedron evaluated alone. Not part of the
 * core's interface: SizeSkewQuality.h is.
 */
#ifndef dgmf_SizeSkewTerms_h
#define dgmf_SizeSkewTerms_h

#include "dgmf/Simd.h"
#include "dgmf/SizeSkewQuality.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace dgmf
{
namespace sizeskew
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Below this size relative to (longest edge)^dimension, an original cell counts as degenerate.
constexpr double kDegenerateTolerance = 1e-12;

constexpr double kCubeRootLow = 1e-300;
constexpr double kCubeRootHigh = 1e300;

/**
 * x^(-1/3) for x in [kCubeRootLow, kCubeRootHigh], to a few ulp, without a division: a
 * bit-level first guess (a few per cent off) and four Newton steps y <- y (4 - x y^3) / 3
 * (quadratic convergence). Plain arithmetic: it does not depend on the platform's math library,
 * and the eight corners of a hexahedron pipeline through it (divisions would dominate the metric).
 */
inline double InverseCubeRootGuess(double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = 0x553EF0FF289DD796ull - bits / 3;
  double y;
  std::memcpy(&y, &bits, sizeof y);
  return y;
}

/// The Newton steps from the guess `y`, for one value (T = double) or two (a two-lane vector).
template <typename T>
inline T InverseCubeRootNewton(T x, T y)
{
  const T third = x * (1.0 / 3.0);
  for (int step = 0; step < 4; ++step)
  {
    y = y * (4.0 / 3.0 - third * (y * y * y));
  }
  return y;
}

inline double InverseCubeRootInRange(double x)
{
  return InverseCubeRootNewton(x, InverseCubeRootGuess(x));
}

/// InverseCubeRootInRange of four values (the bit-level guess lane by lane, the Newton steps
/// together): each lane has the one-value function's bits.
DGMF_SIMD_INLINE simd::Double4 InverseCubeRootInRange(simd::Double4 x)
{
  return InverseCubeRootNewton(x,
    simd::Double4{ InverseCubeRootGuess(x[0]), InverseCubeRootGuess(x[1]),
      InverseCubeRootGuess(x[2]), InverseCubeRootGuess(x[3]) });
}

/// factor * cbrt(numerator / denominator), as factor * n * (n^2 d)^(-1/3).
struct ScaledCubeRoot
{
  double Factor, Numerator, Denominator;
};

/**
 * sum_k factor_k * cbrt(numerator_k / denominator_k). The roots are independent iterations, so
 * they overlap; arguments out of range (inf, NaN, extreme values) fall back to std::cbrt.
 */
template <std::size_t N>
inline double SumOfScaledCubeRoots(const ScaledCubeRoot (&terms)[N])
{
  double argument[N];
  bool inRange = true;
  for (std::size_t k = 0; k < N; ++k)
  {
    argument[k] = terms[k].Numerator * terms[k].Numerator * terms[k].Denominator;
    inRange &= argument[k] >= kCubeRootLow && argument[k] <= kCubeRootHigh;
  }
  double sum = 0.0;
  if (inRange)
  {
    for (std::size_t k = 0; k < N; ++k)
    {
      sum += terms[k].Factor * terms[k].Numerator * InverseCubeRootInRange(argument[k]);
    }
  }
  else
  {
    for (std::size_t k = 0; k < N; ++k)
    {
      sum += terms[k].Factor * std::cbrt(terms[k].Numerator / terms[k].Denominator);
    }
  }
  return sum;
}

/// f_size = min(tau, 1/tau).
inline double SizeFactor(double tau)
{
  return std::min(tau, 1.0 / tau);
}

/// Final value in [0, 1]; round-off above 1 is clamped, and anything not a number (overflow of
/// absurd coordinates) becomes 0 so that an evaluated cell never reads as "not computed".
inline CellQuality Valid(double value)
{
  CellQuality quality;
  quality.SizeSkew = value > 0.0 ? std::min(value, 1.0) : 0.0;
  quality.Inverted = false;
  return quality;
}

/// An original cell without a corner metric: degenerate, or a corner not positive (non-convex).
inline CellQuality Degenerate()
{
  return CellQuality{ 0.0, false, true };
}

inline CellQuality Inverted()
{
  return CellQuality{ 0.0, true };
}

/// ComputeSizeSkew of a hexahedron, one cell from its corners (HexSizeSkew.cxx).
CellQuality HexSizeSkew(const double* original, const double* deformed);

} // namespace sizeskew
} // namespace dgmf

#endif
