// Knupp's size-skew quality (Finite Elem. Anal. Des. 39, 2003) of a deformed cell relative to the
// same cell before deformation. The definitions, including the choices for wedges, pyramids,
// 2D cells in 3D space and degenerate cells, are in Documentation/quality.md.
#include "dgmf/SizeSkewQuality.h"

#include "dgmf/CellGeometry.h"
#include "dgmf/Simd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace dgmf
{
namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Below this size relative to (longest edge)^dimension, an original cell counts as degenerate.
constexpr double kDegenerateTolerance = 1e-12;
constexpr double kSqrt3 = 1.7320508075688772935;

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

/// Entries of lambda = A^T A for the edge matrix A = [a b c], and alpha = det A.
struct CornerMetric
{
  double L11, L22, L33, L12, L13, L23;
  double Alpha;
};

inline CornerMetric MakeCornerMetric(const Vec3& a, const Vec3& b, const Vec3& c, double alpha)
{
  return { Dot(a, a), Dot(b, b), Dot(c, c), Dot(a, b), Dot(a, c), Dot(b, c), alpha };
}

// Reciprocal corner qualities of the 3D shapes, written as factor * cbrt(numerator / denominator)
// so that the cube roots can be batched without divisions. Each cell's shape/skew factor is
// (number of corners) / (sum of these), the harmonic mean Knupp uses for quads and hexahedra.

/// Tet (Knupp): 1 / f_shape = (1.5 (l11+l22+l33) - (l12+l13+l23)) / (3 (sqrt(2) alpha)^(2/3)).
inline ScaledCubeRoot TetraInverseShape(const CornerMetric& m)
{
  const double frobenius = 1.5 * (m.L11 + m.L22 + m.L33) - (m.L12 + m.L13 + m.L23);
  return { frobenius / 3.0, 1.0, 2.0 * m.Alpha * m.Alpha };
}

/// Wedge: the hex term scaled by the ideal corner's sine product sqrt(3)/2 (60 and 90 degree
/// angles): ((sqrt(3)/2) sqrt(l11 l22 l33) / alpha)^(2/3).
inline ScaledCubeRoot WedgeInverseSkew(const CornerMetric& m)
{
  return { 1.0, 0.75 * m.L11 * m.L22 * m.L33, m.Alpha * m.Alpha };
}

/// Pyramid base corner: Knupp's mean ratio 3 det(T)^(2/3) / |T|_F^2 of T = A W^-1, W the corner
/// of the pyramid with all eight edges equal. (W^T W)^-1 = [[1.5, .5, -1], [.5, 1.5, -1],
/// [-1, -1, 2]] and det W = 1/sqrt(2) give the reciprocal below.
inline ScaledCubeRoot PyramidInverseShape(const CornerMetric& m)
{
  const double frobenius = 1.5 * (m.L11 + m.L22) + 2.0 * m.L33 + m.L12 - 2.0 * (m.L13 + m.L23);
  return { frobenius / 3.0, 1.0, 2.0 * m.Alpha * m.Alpha };
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

/// Shared by all 3D shapes: orientation and size from the sum of the corner determinants of the
/// original cell, inversion and the skew/shape factor from the deformed cell's corners.
template <std::size_t N, typename InverseCornerQuality>
CellQuality Evaluate3D(const CornerEdges (&corners)[N], const double* original,
  const double* deformed, InverseCornerQuality inverseQuality)
{
  double originalSum = 0.0;
  double longestEdge2 = 0.0;
  double smallest = kInfinity, largest = -kInfinity; // the original corners' Jacobians
  for (const CornerEdges& corner : corners)
  {
    const Vec3 o = Load(original, corner.Origin);
    const Vec3 a = Load(original, corner.A) - o;
    const Vec3 b = Load(original, corner.B) - o;
    const Vec3 c = Load(original, corner.C) - o;
    const double alpha = Dot(Cross(a, b), c);
    originalSum += alpha;
    smallest = std::min(smallest, alpha);
    largest = std::max(largest, alpha);
    longestEdge2 = std::max({ longestEdge2, Dot(a, a), Dot(b, b), Dot(c, c) });
  }
  // Written as !(x > y) so that NaN coordinates also take this exit.
  const double scale = static_cast<double>(N) * longestEdge2 * std::sqrt(longestEdge2);
  if (!(std::abs(originalSum) > kDegenerateTolerance * scale))
  {
    return Degenerate();
  }
  const double orientation = originalSum > 0.0 ? 1.0 : -1.0;
  if (!((orientation > 0.0 ? smallest : -largest) > 0.0))
  {
    return Degenerate(); // non-convex (or partly inverted) before the motion
  }

  double deformedSum = 0.0;
  ScaledCubeRoot terms[N];
  for (std::size_t k = 0; k < N; ++k)
  {
    const CornerEdges& corner = corners[k];
    const Vec3 o = Load(deformed, corner.Origin);
    const Vec3 a = Load(deformed, corner.A) - o;
    const Vec3 b = Load(deformed, corner.B) - o;
    const Vec3 c = Load(deformed, corner.C) - o;
    const double alpha = orientation * Dot(Cross(a, b), c);
    if (!(alpha > 0.0))
    {
      return Inverted();
    }
    deformedSum += alpha;
    terms[k] = inverseQuality(MakeCornerMetric(a, b, c, alpha));
  }
  const double inverseSum = SumOfScaledCubeRoots(terms);
  const double tau = deformedSum / (orientation * originalSum);
  return Valid(SizeFactor(tau) * static_cast<double>(N) / inverseSum);
}

/**
 * The hexahedron (Knupp): skew = 8 / sum_k (sqrt(l11 l22 l33)_k / alpha_k)^(2/3) over the corners
 * of kHexCorners, computed from the 12 edge vectors once (each corner's three edges are three of
 * them, up to sign): the most common cell of large structured meshes, and about twice as fast as
 * the generic Evaluate3D this way.
 */
/// For each corner of kHexCorners: its edges to A, B and C, and the product of their signs.
constexpr int kHexCornerEdges[8][3] = { { 0, 3, 8 }, { 1, 0, 9 }, { 2, 1, 10 }, { 3, 2, 11 },
  { 7, 4, 8 }, { 4, 5, 9 }, { 5, 6, 10 }, { 6, 7, 11 } };
constexpr double kHexCornerSign[8] = { -1.0, -1.0, -1.0, -1.0, 1.0, 1.0, 1.0, 1.0 };

/// The 12 edge vectors of a hexahedron and their squared lengths (of one, or two at once).
template <typename T>
struct HexEdgesOf
{
  Vec3Of<T> Vector[12];
  T Length2[12];
};
using HexEdges = HexEdgesOf<double>;

/// `load(i)` gives corner i.
template <typename T, typename Loader>
inline void ComputeHexEdges(const Loader& load, HexEdgesOf<T>& edges)
{
  for (int e = 0; e < 12; ++e)
  {
    edges.Vector[e] = load(kHexEdges[e][1]) - load(kHexEdges[e][0]);
    edges.Length2[e] = Dot(edges.Vector[e], edges.Vector[e]);
  }
}

inline void ComputeHexEdges(const double* points, HexEdges& edges)
{
  ComputeHexEdges([points](int i) { return Load(points, i); }, edges);
}

template <typename T>
inline T HexCornerDeterminant(const HexEdgesOf<T>& edges, int corner)
{
  const int* e = kHexCornerEdges[corner];
  return kHexCornerSign[corner] *
    Dot(Cross(edges.Vector[e[0]], edges.Vector[e[1]]), edges.Vector[e[2]]);
}

/// Not a number: the reference size of a hexahedron without a corner metric.
constexpr double kNoReference = std::numeric_limits<double>::quiet_NaN();

/// The checks of ComputeHexReferenceSize on one cell: its corner Jacobians `alphas` (sum `sum`)
/// and the squared lengths of its 12 edges. Returns `sum`, or kNoReference.
inline double CheckedHexReference(
  double sum, const double (&alphas)[8], const double (&length2)[12])
{
  double smallest = kInfinity, largest = -kInfinity;
  for (int corner = 0; corner < 8; ++corner)
  {
    smallest = std::min(smallest, alphas[corner]);
    largest = std::max(largest, alphas[corner]);
  }
  double longestEdge2 = 0.0;
  for (int e = 0; e < 12; ++e)
  {
    longestEdge2 = std::max(longestEdge2, length2[e]);
  }
  const double scale = 8.0 * longestEdge2 * std::sqrt(longestEdge2);
  // Written as !(x > y) so that NaN coordinates also take these exits.
  if (!(std::abs(sum) > kDegenerateTolerance * scale))
  {
    return kNoReference; // degenerate
  }
  if (!((sum > 0.0 ? smallest : -largest) > 0.0))
  {
    return kNoReference; // non-convex (or partly inverted) before the motion
  }
  return sum;
}

double HexReferenceSize(const double* original)
{
  HexEdges edges;
  ComputeHexEdges(original, edges);
  double sum = 0.0;
  double alphas[8];
  for (int corner = 0; corner < 8; ++corner)
  {
    alphas[corner] = HexCornerDeterminant(edges, corner);
    sum += alphas[corner];
  }
  return CheckedHexReference(sum, alphas, edges.Length2);
}

/// The deformed half of the hexahedron's metric, from its reference size (HexReferenceSize).
CellQuality HexSizeSkewFromReference(double referenceSize, const double* deformed)
{
  if (std::isnan(referenceSize))
  {
    return Degenerate();
  }
  const double orientation = referenceSize > 0.0 ? 1.0 : -1.0;
  HexEdges edges;
  ComputeHexEdges(deformed, edges);
  double deformedSum = 0.0;
  ScaledCubeRoot terms[8];
  for (int corner = 0; corner < 8; ++corner)
  {
    const double alpha = orientation * HexCornerDeterminant(edges, corner);
    if (!(alpha > 0.0))
    {
      return Inverted();
    }
    deformedSum += alpha;
    const int* e = kHexCornerEdges[corner];
    terms[corner] = { 1.0, edges.Length2[e[0]] * edges.Length2[e[1]] * edges.Length2[e[2]],
      alpha * alpha };
  }
  const double inverseSum = SumOfScaledCubeRoots(terms);
  const double tau = deformedSum / (orientation * referenceSize);
  return Valid(SizeFactor(tau) * 8.0 / inverseSum);
}

CellQuality HexSizeSkew(const double* original, const double* deformed)
{
  return HexSizeSkewFromReference(HexReferenceSize(original), deformed);
}

/// Four doubles processed together (Simd.h): four hexahedra at once.
using Four = simd::Double4;

/// Vec3 of four hexahedra at once.
using FourVec3 = Vec3Of<Four>;

using FourHexEdges = HexEdgesOf<Four>;

/// The edges of the four hexahedra whose corners are at `points[0..3]`.
inline void ComputeHexEdges(const double* const* points, FourHexEdges& edges)
{
  const double* a = points[0];
  const double* b = points[1];
  const double* c = points[2];
  const double* d = points[3];
  ComputeHexEdges(
    [a, b, c, d](int i) -> FourVec3
    {
      return { Four{ a[3 * i], b[3 * i], c[3 * i], d[3 * i] },
        Four{ a[3 * i + 1], b[3 * i + 1], c[3 * i + 1], d[3 * i + 1] },
        Four{ a[3 * i + 2], b[3 * i + 2], c[3 * i + 2], d[3 * i + 2] } };
    },
    edges);
}

/// InverseCubeRootInRange of four values (the bit-level guess lane by lane, the Newton steps
/// together).
inline Four InverseCubeRootInRange(Four x)
{
  return InverseCubeRootNewton(x,
    Four{ InverseCubeRootGuess(x[0]), InverseCubeRootGuess(x[1]), InverseCubeRootGuess(x[2]),
      InverseCubeRootGuess(x[3]) });
}

/// The cells of the group of four starting at `first`, of `count`: the last group repeats its last
/// cell (its lanes are computed twice and written once).
inline void GroupOfFour(std::size_t first, std::size_t count, std::size_t (&cells)[4])
{
  for (std::size_t l = 0; l < 4; ++l)
  {
    cells[l] = std::min(first + l, count - 1);
  }
}

} // namespace

DGMF_SIMD_AVX2_CLONES
void ComputeHexReferenceSizes(
  std::size_t count, const double* const* original, double* referenceSizes)
{
  // The loop's body is written here, not in a lambda: the AVX2 clone compiles what it inlines.
  for (std::size_t first = 0; first < count; first += 4)
  {
    std::size_t cells[4];
    GroupOfFour(first, count, cells);
    {
      const double* const points[4] = { original[cells[0]], original[cells[1]], original[cells[2]],
        original[cells[3]] };
      FourHexEdges edges;
      ComputeHexEdges(points, edges);
      Four sum = { 0.0, 0.0, 0.0, 0.0 };
      Four alphas[8];
      for (int corner = 0; corner < 8; ++corner)
      {
        alphas[corner] = HexCornerDeterminant(edges, corner);
        sum += alphas[corner];
      }
      for (int l = 0; l < 4; ++l)
      {
        double laneAlphas[8], laneLength2[12];
        for (int corner = 0; corner < 8; ++corner)
        {
          laneAlphas[corner] = alphas[corner][l];
        }
        for (int e = 0; e < 12; ++e)
        {
          laneLength2[e] = edges.Length2[e][l];
        }
        referenceSizes[cells[l]] = CheckedHexReference(sum[l], laneAlphas, laneLength2);
      }
    }
  }
}

DGMF_SIMD_AVX2_CLONES
void ComputeHexSizeSkew(std::size_t count, const double* referenceSizes,
  const double* const* deformed, CellQuality* quality)
{
  for (std::size_t first = 0; first < count; first += 4)
  {
    std::size_t cells[4];
    GroupOfFour(first, count, cells);
    {
      const double* const points[4] = { deformed[cells[0]], deformed[cells[1]], deformed[cells[2]],
        deformed[cells[3]] };
      const Four reference = { referenceSizes[cells[0]], referenceSizes[cells[1]],
        referenceSizes[cells[2]], referenceSizes[cells[3]] };
      Four orientation;
      for (int l = 0; l < 4; ++l)
      {
        orientation[l] = reference[l] > 0.0 ? 1.0 : -1.0;
      }
      FourHexEdges edges;
      ComputeHexEdges(points, edges);
      Four deformedSum = { 0.0, 0.0, 0.0, 0.0 };
      Four numerator[8], argument[8];
      // The smallest Jacobian and the range of the cube roots' arguments, lane by lane: a NaN
      // that Min or Max drops leaves a NaN in deformedSum or inverseSum, checked below.
      Four smallestAlpha, smallestArgument, largestArgument;
      for (int corner = 0; corner < 8; ++corner)
      {
        const Four alpha = orientation * HexCornerDeterminant(edges, corner);
        deformedSum += alpha;
        const int* e = kHexCornerEdges[corner];
        numerator[corner] = edges.Length2[e[0]] * edges.Length2[e[1]] * edges.Length2[e[2]];
        argument[corner] = numerator[corner] * numerator[corner] * (alpha * alpha);
        smallestAlpha = corner == 0 ? alpha : simd::Min(smallestAlpha, alpha);
        smallestArgument =
          corner == 0 ? argument[0] : simd::Min(smallestArgument, argument[corner]);
        largestArgument = corner == 0 ? argument[0] : simd::Max(largestArgument, argument[corner]);
      }
      Four inverseSum = { 0.0, 0.0, 0.0, 0.0 };
      for (int corner = 0; corner < 8; ++corner)
      {
        inverseSum += 1.0 * numerator[corner] * InverseCubeRootInRange(argument[corner]);
      }
      const Four tau = deformedSum / (orientation * reference);
      for (int l = 0; l < 4; ++l)
      {
        // A lane out of the fast path (no reference, inverted, a cube root out of range) is
        // evaluated on its own: the same operations where both apply, so the same bits.
        const bool usable = smallestAlpha[l] > 0.0 && smallestArgument[l] >= kCubeRootLow &&
          largestArgument[l] <= kCubeRootHigh && !std::isnan(deformedSum[l]) &&
          !std::isnan(inverseSum[l]);
        quality[cells[l]] = usable && !std::isnan(reference[l])
          ? Valid(SizeFactor(tau[l]) * 8.0 / inverseSum[l])
          : HexSizeSkewFromReference(reference[l], points[l]);
      }
    }
  }
}

double ComputeHexReferenceSize(const double* original)
{
  return HexReferenceSize(original);
}

CellQuality ComputeHexSizeSkew(double referenceSize, const double* deformed)
{
  return HexSizeSkewFromReference(referenceSize, deformed);
}

namespace
{

/// Longest squared edge of a polygon with n corners.
inline double LongestEdge2(const Vec3* p, int n)
{
  double longest = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const Vec3 e = p[(i + 1) % n] - p[i];
    longest = std::max(longest, Dot(e, e));
  }
  return longest;
}

CellQuality TriangleSizeShape(const double* original, const double* deformed)
{
  const Vec3 p[3] = { Load(original, 0), Load(original, 1), Load(original, 2) };
  // The original's normal (twice its area) fixes the orientation.
  const Vec3 normal0 = Cross(p[1] - p[0], p[2] - p[0]);
  const double alpha0 = std::sqrt(Dot(normal0, normal0));
  if (!(alpha0 > kDegenerateTolerance * LongestEdge2(p, 3)))
  {
    return Degenerate();
  }

  const Vec3 q0 = Load(deformed, 0);
  const Vec3 a = Load(deformed, 1) - q0;
  const Vec3 b = Load(deformed, 2) - q0;
  const Vec3 normal = Cross(a, b);
  if (!(Dot(normal, normal0) > 0.0))
  {
    return Inverted(); // flipped over (or collapsed) against the original orientation
  }
  // alpha measured along the deformed cell's own unit normal: twice its area.
  const double alpha = std::sqrt(Dot(normal, normal));
  const double tau = alpha / alpha0;
  // lambda11 + lambda22 - lambda12 is half the sum of the squared edge lengths: the same at
  // every corner, as is alpha.
  const double shape = kSqrt3 * alpha / (Dot(a, a) + Dot(b, b) - Dot(a, b));
  return Valid(SizeFactor(tau) * shape);
}

CellQuality QuadSizeSkew(const double* original, const double* deformed)
{
  const Vec3 p[4] = { Load(original, 0), Load(original, 1), Load(original, 2), Load(original, 3) };
  // Cross product of the diagonals = Newell normal = twice the vector area.
  const Vec3 normal0 = Cross(p[2] - p[0], p[3] - p[1]);
  const double area2Original = std::sqrt(Dot(normal0, normal0));
  if (!(area2Original > kDegenerateTolerance * LongestEdge2(p, 4)))
  {
    return Degenerate();
  }
  for (int k = 0; k < 4; ++k)
  {
    if (!(Dot(Cross(p[(k + 1) & 3] - p[k], p[(k + 3) & 3] - p[k]), normal0) > 0.0))
    {
      return Degenerate(); // non-convex (or a bow tie) before the motion
    }
  }

  const Vec3 q[4] = { Load(deformed, 0), Load(deformed, 1), Load(deformed, 2), Load(deformed, 3) };
  const Vec3 normal = Cross(q[2] - q[0], q[3] - q[1]);
  if (!(Dot(normal, normal0) > 0.0))
  {
    return Inverted();
  }
  const double area2 = std::sqrt(Dot(normal, normal));
  const Vec3 unitNormal = { normal.X / area2, normal.Y / area2, normal.Z / area2 };

  double inverseSum = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    // Edges to the next and the previous corner: alpha_k > 0 for a counter-clockwise corner.
    const Vec3 a = q[(k + 1) & 3] - q[k];
    const Vec3 b = q[(k + 3) & 3] - q[k];
    const double alpha = Dot(Cross(a, b), unitNormal);
    if (!(alpha > 0.0))
    {
      return Inverted();
    }
    inverseSum += std::sqrt(Dot(a, a) * Dot(b, b)) / alpha; // 1 / sin(corner angle)
  }
  // sum_k alpha_k = 4 area and |normal| = 2 area, so mean alpha ratio = |normal| ratio.
  const double tau = area2 / area2Original;
  return Valid(SizeFactor(tau) * 4.0 / inverseSum);
}

} // namespace

int GetNumberOfCorners(CellShape shape)
{
  switch (shape)
  {
    case CellShape::Triangle:
      return 3;
    case CellShape::Quad:
      return 4;
    case CellShape::Tetra:
      return 4;
    case CellShape::Hexahedron:
      return 8;
    case CellShape::Wedge:
      return 6;
    case CellShape::Pyramid:
      return 5;
  }
  return 0;
}

CellQuality ComputeSizeSkew(CellShape shape, const double* original, const double* deformed)
{
  switch (shape)
  {
    case CellShape::Triangle:
      return TriangleSizeShape(original, deformed);
    case CellShape::Quad:
      return QuadSizeSkew(original, deformed);
    case CellShape::Tetra:
      return Evaluate3D(kTetraCorners, original, deformed,
        [](const CornerMetric& m)
        { return TetraInverseShape(m); }); // a lambda inlines, a function pointer does not
    case CellShape::Hexahedron:
      return HexSizeSkew(original, deformed);
    case CellShape::Wedge:
      return Evaluate3D(kWedgeCorners, original, deformed,
        [](const CornerMetric& m)
        { return WedgeInverseSkew(m); }); // a lambda inlines, a function pointer does not
    case CellShape::Pyramid:
      return Evaluate3D(kPyramidCorners, original, deformed,
        [](const CornerMetric& m)
        { return PyramidInverseShape(m); }); // a lambda inlines, a function pointer does not
  }
  // Not a listed shape (an out-of-range cast): not computed.
  return CellQuality{ std::numeric_limits<double>::quiet_NaN(), false };
}

CellQuality TetraSizeSkew(double alpha, double edgeSquares, double originalAlpha)
{
  if (!(alpha > 0.0))
  {
    return Inverted();
  }
  // Evaluate3D's single tetrahedron corner: shape = 3 (2 alpha^2)^(1/3) / F with F half the
  // squared edges, so SizeSkew = f_size * 6 / (edgeSquares * (2 alpha^2)^(-1/3)).
  const double argument = 2.0 * alpha * alpha;
  const double inverseRoot = argument >= kCubeRootLow && argument <= kCubeRootHigh
    ? InverseCubeRootInRange(argument)
    : 1.0 / std::cbrt(argument);
  return Valid(SizeFactor(alpha / originalAlpha) * 6.0 / (edgeSquares * inverseRoot));
}

} // namespace dgmf
