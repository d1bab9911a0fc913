/**
 * @file Simd.h
 * @brief The core's only platform-specific code: a two-lane double vector (two nodes or two cells
 * processed together) and memory prefetch, each with a portable scalar fallback.
 *
 * - `simd::Double2` is GCC's and Clang's vector extension (`vector_size(16)`: SSE2 on x86-64,
 *   NEON on ARM64) when the compiler has it, and otherwise (MSVC, other compilers, or the CMake
 *   option DGMF_FORCE_SCALAR_SIMD) a plain struct of two doubles with the same operators. Both
 *   do the same IEEE operations lane by lane in the same order, so they give the same bits: the
 *   tests check it by building the core both ways (scripts/run-portability-tests.sh).
 * - `simd::Prefetch` and `simd::PrefetchForWrite` ask the processor to start loading a cache line;
 *   they do nothing where the compiler has no way to say so. They never change a result.
 *
 * Nothing else in the project may use compiler extensions: code that wants two lanes or a
 * prefetch includes this header.
 */
#ifndef dgmf_Simd_h
#define dgmf_Simd_h

#if !defined(DGMF_FORCE_SCALAR_SIMD) && (defined(__GNUC__) || defined(__clang__))
#define DGMF_SIMD_VECTOR_EXTENSION 1
#else
#define DGMF_SIMD_VECTOR_EXTENSION 0
#endif

#if !defined(__GNUC__) && !defined(__clang__) && defined(_MSC_VER) &&                              \
  (defined(_M_X64) || defined(_M_IX86))
#include <xmmintrin.h> // _mm_prefetch
#define DGMF_SIMD_MSVC_PREFETCH 1
#else
#define DGMF_SIMD_MSVC_PREFETCH 0
#endif

namespace dgmf
{
namespace simd
{

#if DGMF_SIMD_VECTOR_EXTENSION

/// Two doubles processed together: `Double2{ a, b }`, lane access `v[0]`, `v[1]`, the arithmetic
/// operators lane by lane, and a double on either side of an operator used in both lanes.
typedef double Double2 __attribute__((vector_size(16)));

/// True when Double2 is the compiler's vector type (false: the scalar fallback).
constexpr bool IsVectorized = true;

#else

/// The portable Double2: the same interface and the same results as the vector type.
struct Double2
{
  double Lane[2];

  double& operator[](int l) { return this->Lane[l]; }
  double operator[](int l) const { return this->Lane[l]; }
  Double2& operator+=(const Double2& b)
  {
    this->Lane[0] += b.Lane[0];
    this->Lane[1] += b.Lane[1];
    return *this;
  }
};

constexpr bool IsVectorized = false;

inline Double2 Splat(double a)
{
  return Double2{ { a, a } };
}
inline Double2 operator+(const Double2& a, const Double2& b)
{
  return Double2{ { a.Lane[0] + b.Lane[0], a.Lane[1] + b.Lane[1] } };
}
inline Double2 operator-(const Double2& a, const Double2& b)
{
  return Double2{ { a.Lane[0] - b.Lane[0], a.Lane[1] - b.Lane[1] } };
}
inline Double2 operator*(const Double2& a, const Double2& b)
{
  return Double2{ { a.Lane[0] * b.Lane[0], a.Lane[1] * b.Lane[1] } };
}
inline Double2 operator/(const Double2& a, const Double2& b)
{
  return Double2{ { a.Lane[0] / b.Lane[0], a.Lane[1] / b.Lane[1] } };
}
inline Double2 operator-(const Double2& a)
{
  return Double2{ { -a.Lane[0], -a.Lane[1] } };
}
inline Double2 operator+(double a, const Double2& b)
{
  return Splat(a) + b;
}
inline Double2 operator+(const Double2& a, double b)
{
  return a + Splat(b);
}
inline Double2 operator-(double a, const Double2& b)
{
  return Splat(a) - b;
}
inline Double2 operator-(const Double2& a, double b)
{
  return a - Splat(b);
}
inline Double2 operator*(double a, const Double2& b)
{
  return Splat(a) * b;
}
inline Double2 operator*(const Double2& a, double b)
{
  return a * Splat(b);
}

#endif

/// Asks the processor to start loading the cache line at `address` for reading.
inline void Prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#elif DGMF_SIMD_MSVC_PREFETCH
  _mm_prefetch(static_cast<const char*>(address), _MM_HINT_T0);
#else
  (void)address;
#endif
}

/// Asks the processor to start loading the cache line at `address`, which is about to be written.
inline void PrefetchForWrite(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address, 1);
#elif DGMF_SIMD_MSVC_PREFETCH
  _mm_prefetch(static_cast<const char*>(address), _MM_HINT_T0);
#else
  (void)address;
#endif
}

} // namespace simd
} // namespace dgmf

#endif
