// The hexahedron's size-skew metric (SizeSkewQuality.h): one cell, its original half kept apart
// (the reference size), and four cells at a time in four-lane vectors. Definitions:
// Documentation/quality.md; speed: Documentation/speed.md, "The quality metric on a new motion".
#include "dgmf/CellGeometry.h"
#include "dgmf/Simd.h"
#include "dgmf/SizeSkewQuality.h"
#include "dgmf/SizeSkewTerms.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dgmf
{
namespace sizeskew
{
namespace
{

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

/// The checks of ComputeHexReferenceSize on one cell, from the sum of its corner Jacobians, the
/// smallest and largest of them, and the longest squared edge. Returns `sum`, or kNoReference.
inline double CheckedHexReference(
  double sum, double smallestAlpha, double largestAlpha, double longestEdge2)
{
  const double scale = 8.0 * longestEdge2 * std::sqrt(longestEdge2);
  // Written as !(x > y) so that NaN coordinates also take these exits.
  if (!(std::abs(sum) > kDegenerateTolerance * scale))
  {
    return kNoReference; // degenerate
  }
  if (!((sum > 0.0 ? smallestAlpha : -largestAlpha) > 0.0))
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
  double smallest = kInfinity, largest = -kInfinity;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double alpha = HexCornerDeterminant(edges, corner);
    sum += alpha;
    smallest = std::min(smallest, alpha);
    largest = std::max(largest, alpha);
  }
  double longestEdge2 = 0.0;
  for (int e = 0; e < 12; ++e)
  {
    longestEdge2 = std::max(longestEdge2, edges.Length2[e]);
  }
  return CheckedHexReference(sum, smallest, largest, longestEdge2);
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

/// Four doubles processed together (Simd.h): four hexahedra at once.
using Four = simd::Double4;

/// Vec3 of four hexahedra at once.
using FourVec3 = Vec3Of<Four>;

using FourHexEdges = HexEdgesOf<Four>;

/// The edges of the four hexahedra of `group` (SizeSkewQuality.h's layout): one vector load per
/// coordinate of a corner.
inline void ComputeHexEdges(const double* group, FourHexEdges& edges)
{
  ComputeHexEdges(
    [group](int i) -> FourVec3
    {
      return { simd::LoadDouble4(group + HexGroupIndex(i, 0, 0)),
        simd::LoadDouble4(group + HexGroupIndex(i, 1, 0)),
        simd::LoadDouble4(group + HexGroupIndex(i, 2, 0)) };
    },
    edges);
}

/**
 * The group of cells `first` .. `first` + 3 (a multiple of 4) of `count`: the last group's missing
 * lanes are filled with its last cell in `scratch` (their results are computed and not written).
 */
inline const double* CompleteGroup(
  const double* groups, std::size_t first, std::size_t count, double (&scratch)[kHexGroupDoubles])
{
  const double* group = groups + first / 4 * kHexGroupDoubles;
  const std::size_t lanes = std::min<std::size_t>(4, count - first);
  if (lanes == 4)
  {
    return group;
  }
  for (std::size_t v = 0; v < kHexGroupDoubles / 4; ++v)
  {
    for (std::size_t l = 0; l < 4; ++l)
    {
      scratch[4 * v + l] = group[4 * v + std::min(l, lanes - 1)];
    }
  }
  return scratch;
}

/// Cells given by pointers (8 x 3 coordinates each) into groups, 64 at a time, for `evaluate`.
template <typename Evaluate>
inline void InGroupsOf64(std::size_t count, const double* const* cells, Evaluate evaluate)
{
  constexpr std::size_t kBlock = 64;
  alignas(64) double groups[kBlock / 4 * kHexGroupDoubles];
  for (std::size_t first = 0; first < count; first += kBlock)
  {
    const std::size_t n = std::min(kBlock, count - first);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int k = 0; k < 8; ++k)
      {
        StoreHexGroupCorner(groups, i, k, cells[first + i] + 3 * k);
      }
    }
    evaluate(first, n, groups);
  }
}

} // namespace

CellQuality HexSizeSkew(const double* original, const double* deformed)
{
  return HexSizeSkewFromReference(HexReferenceSize(original), deformed);
}

} // namespace sizeskew

using namespace sizeskew;

DGMF_SIMD_AVX2_CLONES
void ComputeHexReferenceSizesInGroups(
  std::size_t count, const double* originalGroups, double* referenceSizes)
{
  // The loop's body is written here, not in a function of its own: the AVX2 clone compiles what
  // it inlines.
  alignas(64) double scratch[kHexGroupDoubles];
  for (std::size_t first = 0; first < count; first += 4)
  {
    const double* group = CompleteGroup(originalGroups, first, count, scratch);
    FourHexEdges edges;
    ComputeHexEdges(group, edges);
    Four sum = { 0.0, 0.0, 0.0, 0.0 };
    // The extremes lane by lane (minima and maxima are exact: the one-cell path's values).
    Four smallest, largest;
    for (int corner = 0; corner < 8; ++corner)
    {
      const Four alpha = HexCornerDeterminant(edges, corner);
      sum += alpha;
      smallest = corner == 0 ? alpha : simd::Min(smallest, alpha);
      largest = corner == 0 ? alpha : simd::Max(largest, alpha);
    }
    Four longestEdge2 = edges.Length2[0];
    for (int e = 1; e < 12; ++e)
    {
      longestEdge2 = simd::Max(longestEdge2, edges.Length2[e]);
    }
    const std::size_t lanes = std::min<std::size_t>(4, count - first);
    for (std::size_t l = 0; l < lanes; ++l)
    {
      referenceSizes[first + l] =
        CheckedHexReference(sum[l], smallest[l], largest[l], longestEdge2[l]);
    }
  }
}

DGMF_SIMD_AVX2_CLONES
void ComputeHexSizeSkewInGroups(std::size_t count, const double* referenceSizes,
  const double* deformedGroups, CellQuality* quality)
{
  alignas(64) double scratch[kHexGroupDoubles];
  for (std::size_t first = 0; first < count; first += 4)
  {
    const double* group = CompleteGroup(deformedGroups, first, count, scratch);
    const std::size_t lanes = std::min<std::size_t>(4, count - first);
    Four reference;
    for (std::size_t l = 0; l < 4; ++l)
    {
      reference[l] = referenceSizes[first + std::min(l, lanes - 1)];
    }
    Four orientation;
    for (int l = 0; l < 4; ++l)
    {
      orientation[l] = reference[l] > 0.0 ? 1.0 : -1.0;
    }
    FourHexEdges edges;
    ComputeHexEdges(group, edges);
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
      smallestArgument = corner == 0 ? argument[0] : simd::Min(smallestArgument, argument[corner]);
      largestArgument = corner == 0 ? argument[0] : simd::Max(largestArgument, argument[corner]);
    }
    Four inverseSum = { 0.0, 0.0, 0.0, 0.0 };
    for (int corner = 0; corner < 8; ++corner)
    {
      inverseSum += 1.0 * numerator[corner] * InverseCubeRootInRange(argument[corner]);
    }
    const Four tau = deformedSum / (orientation * reference);
    for (std::size_t l = 0; l < lanes; ++l)
    {
      // A lane out of the fast path (no reference, inverted, a cube root out of range) is
      // evaluated on its own: the same operations where both apply, so the same bits.
      const bool usable = smallestAlpha[l] > 0.0 && smallestArgument[l] >= kCubeRootLow &&
        largestArgument[l] <= kCubeRootHigh && !std::isnan(deformedSum[l]) &&
        !std::isnan(inverseSum[l]) && !std::isnan(reference[l]);
      if (usable)
      {
        quality[first + l] = Valid(SizeFactor(tau[l]) * 8.0 / inverseSum[l]);
      }
      else
      {
        double corners[24];
        LoadHexGroupCell(group, l, corners);
        quality[first + l] = HexSizeSkewFromReference(reference[l], corners);
      }
    }
  }
}

void ComputeHexReferenceSizes(
  std::size_t count, const double* const* original, double* referenceSizes)
{
  InGroupsOf64(count, original,
    [referenceSizes](std::size_t first, std::size_t n, const double* groups)
    { ComputeHexReferenceSizesInGroups(n, groups, referenceSizes + first); });
}

void ComputeHexSizeSkew(std::size_t count, const double* referenceSizes,
  const double* const* deformed, CellQuality* quality)
{
  InGroupsOf64(count, deformed,
    [referenceSizes, quality](std::size_t first, std::size_t n, const double* groups)
    { ComputeHexSizeSkewInGroups(n, referenceSizes + first, groups, quality + first); });
}

double ComputeHexReferenceSize(const double* original)
{
  return HexReferenceSize(original);
}

CellQuality ComputeHexSizeSkew(double referenceSize, const double* deformed)
{
  return HexSizeSkewFromReference(referenceSize, deformed);
}

} // namespace dgmf
