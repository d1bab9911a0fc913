/**
 * @file Finite.h
 * @brief The check for NaN, infinite and overflowing values in large arrays (points,
 * displacements).
 */
#ifndef dgmf_Finite_h
#define dgmf_Finite_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace dgmf
{

/**
 * The magnitude from which a coordinate or displacement is refused: 2^332 (8.7e99). Squared
 * distances of larger values overflow (1e155 squared is beyond the largest double), which CGAL's
 * insertion did not survive (a segmentation fault on a mesh with one node at 1e160); no mesh in
 * any unit comes near it.
 */
constexpr double kLargestMagnitude = 8.749002899132048e99; // 2^332
/// The largest magnitude as text, for messages.
constexpr const char* kLargestMagnitudeText = "8.7e99";

/**
 * Index of the first value among `count` that is NaN, infinite or of magnitude kLargestMagnitude
 * or more, or `count` if there is none. Tested on the exponent bits, without a branch per value
 * (the points of a large mesh are a few hundred megabytes).
 */
inline std::size_t FirstOutOfRange(const double* values, std::size_t count)
{
  constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
  constexpr std::uint64_t limit = std::uint64_t(1023 + 332) << 52; // the exponent of 2^332
  for (std::size_t i = 0; i < count;)
  {
    const std::size_t begin = i;
    const std::size_t end = std::min(count, i + 4096);
    std::uint64_t bad = 0;
    for (; i < end; ++i)
    {
      std::uint64_t bits;
      std::memcpy(&bits, values + i, sizeof(bits));
      bad |= (bits & exponent) >= limit ? 1 : 0;
    }
    if (bad)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        if (!(std::abs(values[k]) < kLargestMagnitude))
        {
          return k;
        }
      }
    }
  }
  return count;
}

} // namespace dgmf

#endif
