/**
 * @file Finite.h
 * @brief The check for NaN and infinite values in large arrays (points, displacements).
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
 * Index of the first value among `count` that is NaN or infinite, or `count` if all are finite.
 * A double is finite when its exponent bits are not all ones: tested without a branch per value
 * (the points of a large mesh are a few hundred megabytes).
 */
inline std::size_t FirstNonFinite(const double* values, std::size_t count)
{
  constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
  for (std::size_t i = 0; i < count;)
  {
    const std::size_t begin = i;
    const std::size_t end = std::min(count, i + 4096);
    std::uint64_t bad = 0;
    for (; i < end; ++i)
    {
      std::uint64_t bits;
      std::memcpy(&bits, values + i, sizeof(bits));
      bad |= (bits & exponent) == exponent ? 1 : 0;
    }
    if (bad)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        if (!std::isfinite(values[k]))
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
