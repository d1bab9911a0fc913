// Knupp's size-skew quality (Finite Elem. Anal. Des. 39, 2003) of a deformed cell relative to the
// same cell before deformation. The definitions, including the choices for wedges, pyramids,
// 2D cells in 3D space and degenerate cells, are in Documentation/quality.md.
#include "dgmf/SizeSkewQuality.h"

#include "dgmf/CellGeometry.h"
#include "dgmf/SizeSkewTerms.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace dgmf
{
namespace
{

using namespace sizeskew;

constexpr double kSqrt3 = 1.7320508075688772935;

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

} // namespace

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
      return sizeskew::HexSizeSkew(original, deformed);
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
