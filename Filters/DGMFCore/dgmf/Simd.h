/**
 * @file Simd.h
 * @brief The core's only platform-specific code: two- and four-lane double vectors (nodes or cells
 * processed together), AVX2 clones of a function, and memory prefetch, each with a portable
 * scalar fallback.
 *
 * - `simd::Double2` and `simd::Double4` are GCC's and Clang's vector extension (`vector_size(16)`
 *   and `(32)`: SSE2, or AVX2 in DGMF_SIMD_AVX2_CLONES functions, on x86-64; NEON on ARM64) when
 *   the compiler has it, and otherwise (MSVC, other compilers, or the CMake option
 *   DGMF_FORCE_SCALAR_SIMD) a plain struct of two or four doubles with the same operators. Both
 *   do the same IEEE operations lane by lane in the same order, so they give the same bits: the
 *   tests check it by building the core both ways (scripts/run-portability-tests.sh).
 * - `simd::UInt4`: four 64-bit unsigned integers (wrapping arithmetic, shifts, bitwise operations;
 *   comparisons through `Equal` and `AtLeast`, which give all-ones lanes), the vector extension
 *   or a plain struct, the same way: integer lanes give the same values either way.
 * - `simd::Prefetch` and `simd::PrefetchForWrite` ask the processor to start loading a cache line;
 *   they do nothing where the compiler has no way to say so. They never change a result.
 *
 * Nothing else in the project may use compiler extensions: code that wants lanes, AVX2 clones or
 * a prefetch includes this header.
 */
#ifndef dgmf_Simd_h
#define dgmf_Simd_h

#include <cstdint>
#include <cstring>

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

/**
 * DGMF_SIMD_INLINE instead of `inline` on a function that must be inlined into its callers (so
 * that an AVX2 clone compiles it for AVX2, not calls a baseline copy).
 */
#if defined(__GNUC__) || defined(__clang__)
#define DGMF_SIMD_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define DGMF_SIMD_INLINE __forceinline
#else
#define DGMF_SIMD_INLINE inline
#endif

namespace dgmf
{
namespace simd
{

#if DGMF_SIMD_VECTOR_EXTENSION

/// Two doubles processed together: `Double2{ a, b }`, lane access `v[0]`, `v[1]`, the arithmetic
/// operators lane by lane, and a double on either side of an operator used in both lanes.
typedef double Double2 __attribute__((vector_size(16)));

/// Four doubles processed together (four cells at once), with the same interface as Double2:
/// one AVX register in a function marked DGMF_SIMD_AVX2_CLONES on a processor that has AVX2, two
/// SSE2 registers otherwise.
typedef double Double4 __attribute__((vector_size(32)));

/// True when Double2 and Double4 are the compiler's vector types (false: the scalar fallback).
constexpr bool IsVectorized = true;

/// Four 64-bit unsigned integers processed together: `UInt4{ a, b, c, d }`, lane access `v[0]`,
/// `+ - * ^ | &` lane by lane (wrapping), `>>` and `<<` by a count, and an integer on either side
/// of an operator used in every lane.
typedef std::uint64_t UInt4 __attribute__((vector_size(32)));

/// `UInt4{ a, b, c, d }` in either form of UInt4.
DGMF_SIMD_INLINE UInt4 MakeUInt4(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d)
{
  return UInt4{ a, b, c, d };
}

/// All-ones lanes where `a` and `b` are equal, zero elsewhere.
DGMF_SIMD_INLINE UInt4 Equal(const UInt4& a, const UInt4& b)
{
  return (UInt4)(a == b);
}

/// All-ones lanes where `a` is at least `b` (unsigned), zero elsewhere.
DGMF_SIMD_INLINE UInt4 AtLeast(const UInt4& a, std::uint64_t b)
{
  return (UInt4)(a >= b);
}

/// Lane by lane `a < b ? a : b` (b where either is NaN).
template <typename T>
inline T Min(const T& a, const T& b)
{
  return a < b ? a : b;
}

/// Lane by lane `a > b ? a : b` (b where either is NaN).
template <typename T>
inline T Max(const T& a, const T& b)
{
  return a > b ? a : b;
}

#else

/// The portable Double2 and Double4: the same interface and the same results as the vector types.
template <int N>
struct DoubleN
{
  double Lane[N];

  double& operator[](int l) { return this->Lane[l]; }
  double operator[](int l) const { return this->Lane[l]; }
  DoubleN& operator+=(const DoubleN& b)
  {
    for (int l = 0; l < N; ++l)
    {
      this->Lane[l] += b.Lane[l];
    }
    return *this;
  }
};

using Double2 = DoubleN<2>;
using Double4 = DoubleN<4>;

constexpr bool IsVectorized = false;

/// Lane by lane `a < b ? a : b` (b where either is NaN).
template <int N>
inline DoubleN<N> Min(const DoubleN<N>& a, const DoubleN<N>& b)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a.Lane[l] < b.Lane[l] ? a.Lane[l] : b.Lane[l];
  }
  return r;
}

/// Lane by lane `a > b ? a : b` (b where either is NaN).
template <int N>
inline DoubleN<N> Max(const DoubleN<N>& a, const DoubleN<N>& b)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a.Lane[l] > b.Lane[l] ? a.Lane[l] : b.Lane[l];
  }
  return r;
}

template <int N>
inline DoubleN<N> Splat(double a)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a;
  }
  return r;
}

template <int N>
inline DoubleN<N> operator-(const DoubleN<N>& a)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = -a.Lane[l];
  }
  return r;
}

template <int N>
inline DoubleN<N> operator+(const DoubleN<N>& a, const DoubleN<N>& b)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a.Lane[l] + b.Lane[l];
  }
  return r;
}
template <int N>
inline DoubleN<N> operator+(double a, const DoubleN<N>& b)
{
  return Splat<N>(a) + b;
}
template <int N>
inline DoubleN<N> operator+(const DoubleN<N>& a, double b)
{
  return a + Splat<N>(b);
}
template <int N>
inline DoubleN<N> operator-(const DoubleN<N>& a, const DoubleN<N>& b)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a.Lane[l] - b.Lane[l];
  }
  return r;
}
template <int N>
inline DoubleN<N> operator-(double a, const DoubleN<N>& b)
{
  return Splat<N>(a) - b;
}
template <int N>
inline DoubleN<N> operator-(const DoubleN<N>& a, double b)
{
  return a - Splat<N>(b);
}
template <int N>
inline DoubleN<N> operator*(const DoubleN<N>& a, const DoubleN<N>& b)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a.Lane[l] * b.Lane[l];
  }
  return r;
}
template <int N>
inline DoubleN<N> operator*(double a, const DoubleN<N>& b)
{
  return Splat<N>(a) * b;
}
template <int N>
inline DoubleN<N> operator*(const DoubleN<N>& a, double b)
{
  return a * Splat<N>(b);
}
template <int N>
inline DoubleN<N> operator/(const DoubleN<N>& a, const DoubleN<N>& b)
{
  DoubleN<N> r;
  for (int l = 0; l < N; ++l)
  {
    r.Lane[l] = a.Lane[l] / b.Lane[l];
  }
  return r;
}
template <int N>
inline DoubleN<N> operator/(double a, const DoubleN<N>& b)
{
  return Splat<N>(a) / b;
}
template <int N>
inline DoubleN<N> operator/(const DoubleN<N>& a, double b)
{
  return a / Splat<N>(b);
}

/// The portable UInt4: the same interface and the same values as the vector type.
struct UInt4
{
  std::uint64_t Lane[4];

  std::uint64_t& operator[](int l) { return this->Lane[l]; }
  std::uint64_t operator[](int l) const { return this->Lane[l]; }
};

/// An integer in every lane.
inline UInt4 SplatUInt4(std::uint64_t v)
{
  return UInt4{ { v, v, v, v } };
}

/// UInt4's operators lane by lane, with an integer on either side used in every lane.
#define DGMF_SIMD_UINT4_OPERATOR(OP)                                                               \
  inline UInt4 operator OP(const UInt4& a, const UInt4& b)                                         \
  {                                                                                                \
    return UInt4{ { a.Lane[0] OP b.Lane[0], a.Lane[1] OP b.Lane[1], a.Lane[2] OP b.Lane[2],        \
      a.Lane[3] OP b.Lane[3] } };                                                                  \
  }                                                                                                \
  inline UInt4 operator OP(const UInt4& a, std::uint64_t b)                                        \
  {                                                                                                \
    return a OP SplatUInt4(b);                                                                     \
  }                                                                                                \
  inline UInt4 operator OP(std::uint64_t a, const UInt4& b)                                        \
  {                                                                                                \
    return SplatUInt4(a) OP b;                                                                     \
  }                                                                                                \
  inline UInt4& operator OP##=(UInt4& a, const UInt4& b)                                           \
  {                                                                                                \
    return a = a OP b;                                                                             \
  }                                                                                                \
  inline UInt4& operator OP##=(UInt4& a, std::uint64_t b)                                          \
  {                                                                                                \
    return a = a OP b;                                                                             \
  }
DGMF_SIMD_UINT4_OPERATOR(+)
DGMF_SIMD_UINT4_OPERATOR(-)
DGMF_SIMD_UINT4_OPERATOR(*)
DGMF_SIMD_UINT4_OPERATOR(^)
DGMF_SIMD_UINT4_OPERATOR(|)
DGMF_SIMD_UINT4_OPERATOR(&)
#undef DGMF_SIMD_UINT4_OPERATOR

inline UInt4 operator>>(const UInt4& a, int count)
{
  return UInt4{ { a.Lane[0] >> count, a.Lane[1] >> count, a.Lane[2] >> count,
    a.Lane[3] >> count } };
}

inline UInt4 operator<<(const UInt4& a, int count)
{
  return UInt4{ { a.Lane[0] << count, a.Lane[1] << count, a.Lane[2] << count,
    a.Lane[3] << count } };
}

DGMF_SIMD_INLINE UInt4 MakeUInt4(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d)
{
  return UInt4{ { a, b, c, d } };
}

inline UInt4 Equal(const UInt4& a, const UInt4& b)
{
  UInt4 r;
  for (int l = 0; l < 4; ++l)
  {
    r.Lane[l] = a.Lane[l] == b.Lane[l] ? ~std::uint64_t(0) : 0;
  }
  return r;
}

inline UInt4 AtLeast(const UInt4& a, std::uint64_t b)
{
  UInt4 r;
  for (int l = 0; l < 4; ++l)
  {
    r.Lane[l] = a.Lane[l] >= b ? ~std::uint64_t(0) : 0;
  }
  return r;
}

#endif

/**
 * DGMF_SIMD_AVX2_CLONES before a function's definition compiles it twice, for AVX2 and for the
 * baseline, and picks one when the program loads, by the processor (GCC's target_clones, on
 * x86-64 with the vector types): Double4 arithmetic then takes one instruction instead of two.
 * Both clones do the same IEEE operations (no fused multiply-add: AVX2 alone does not allow it),
 * so the same bits. Nothing elsewhere.
 */
#if DGMF_SIMD_VECTOR_EXTENSION && defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define DGMF_SIMD_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define DGMF_SIMD_AVX2_CLONES
#endif

/// Four consecutive doubles at `p` (no alignment needed) as one Double4: one vector load.
DGMF_SIMD_INLINE Double4 LoadDouble4(const double* p)
{
  Double4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

/// Four consecutive 64-bit integers at `p` (no alignment needed) as one UInt4.
DGMF_SIMD_INLINE UInt4 LoadUInt4(const void* p)
{
  UInt4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

/// Whether any lane of `v` is not zero.
DGMF_SIMD_INLINE bool AnyLane(const UInt4& v)
{
  return (v[0] | v[1] | v[2] | v[3]) != 0;
}

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
