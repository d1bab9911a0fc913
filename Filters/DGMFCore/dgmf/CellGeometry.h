/**
 * @file CellGeometry.h
 * @brief What the quality metric and the quality guard share about cells: 3-vectors, and the
 * corner and edge tables of every shape, in VTK's corner order.
 */
#ifndef dgmf_CellGeometry_h
#define dgmf_CellGeometry_h

#include "dgmf/SizeSkewQuality.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace dgmf
{

/// A 3-vector of doubles, or of two-lane vectors (two cells at once: simd::Double2).
template <typename T>
struct Vec3Of
{
  T X, Y, Z;
};
using Vec3 = Vec3Of<double>;

/// Point `i` of an array of 3 doubles per point.
inline Vec3 Load(const double* points, std::int64_t i)
{
  return { points[3 * i], points[3 * i + 1], points[3 * i + 2] };
}

/// Writes `v` as point `i` of an array of 3 doubles per point.
inline void Store(const Vec3& v, double* points, std::int64_t i)
{
  points[3 * i] = v.X;
  points[3 * i + 1] = v.Y;
  points[3 * i + 2] = v.Z;
}

template <typename T>
inline Vec3Of<T> operator+(const Vec3Of<T>& a, const Vec3Of<T>& b)
{
  return { a.X + b.X, a.Y + b.Y, a.Z + b.Z };
}

template <typename T>
inline Vec3Of<T> operator-(const Vec3Of<T>& a, const Vec3Of<T>& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}

inline Vec3 operator*(double s, const Vec3& a)
{
  return { s * a.X, s * a.Y, s * a.Z };
}

template <typename T>
inline T Dot(const Vec3Of<T>& a, const Vec3Of<T>& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}

template <typename T>
inline Vec3Of<T> Cross(const Vec3Of<T>& a, const Vec3Of<T>& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}

inline double Norm(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}

inline bool IsFinite(const Vec3& a)
{
  return std::isfinite(a.X) && std::isfinite(a.Y) && std::isfinite(a.Z);
}

/**
 * The edges leaving one corner of a cell: Origin -> A, Origin -> B and, in 3D, Origin -> C (C < 0
 * for 2D shapes), ordered so that det[A-O, B-O, C-O] > 0 at every corner of a valid cell in VTK's
 * orientation (the size-skew metric's corner Jacobians).
 */
struct CornerEdges
{
  int Origin, A, B, C;
};

constexpr CornerEdges kTriangleCorners[] = { { 0, 1, 2, -1 } };
constexpr CornerEdges kQuadCorners[] = { { 0, 1, 3, -1 }, { 1, 2, 0, -1 }, { 2, 3, 1, -1 },
  { 3, 0, 2, -1 } };
constexpr CornerEdges kTetraCorners[] = { { 0, 1, 2, 3 } };
// Bottom 0-3 counter-clockwise seen from the top 4-7, 4 above 0.
constexpr CornerEdges kHexCorners[] = { { 0, 1, 3, 4 }, { 1, 2, 0, 5 }, { 2, 3, 1, 6 },
  { 3, 0, 2, 7 }, { 4, 7, 5, 0 }, { 5, 4, 6, 1 }, { 6, 5, 7, 2 }, { 7, 6, 4, 3 } };
// VTK: the normal (1-0)x(2-0) of the bottom triangle points away from the top triangle 3,4,5, so
// the in-triangle edges are taken as (previous, next) to make the determinants positive.
constexpr CornerEdges kWedgeCorners[] = { { 0, 2, 1, 3 }, { 1, 0, 2, 4 }, { 2, 1, 0, 5 },
  { 3, 4, 5, 0 }, { 4, 5, 3, 1 }, { 5, 3, 4, 2 } };
// Base 0-3 counter-clockwise seen from the apex 4. Only the base corners are used: each one sees
// the apex, and the apex has four edges (no single 3x3 edge matrix).
constexpr CornerEdges kPyramidCorners[] = { { 0, 1, 3, 4 }, { 1, 2, 0, 4 }, { 2, 3, 1, 4 },
  { 3, 0, 2, 4 } };

constexpr int kTriangleEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 } };
constexpr int kQuadEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
constexpr int kTetraEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
constexpr int kHexEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 },
  { 6, 7 }, { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
constexpr int kWedgeEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 4 }, { 4, 5 }, { 5, 3 },
  { 0, 3 }, { 1, 4 }, { 2, 5 } };
constexpr int kPyramidEdges[][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 4 }, { 1, 4 },
  { 2, 4 }, { 3, 4 } };

/// Largest number of corners of a covered shape (the hexahedron).
constexpr int kMaximumCorners = 8;

/// Corner and edge tables of a shape.
struct ShapeTables
{
  const CornerEdges* Corners;
  int NumberOfCorners;
  const int (*Edges)[2];
  int NumberOfEdges;
  int Dimension;
};

/// The tables of `shape`.
ShapeTables GetShapeTables(CellShape shape);

} // namespace dgmf

#endif
