/**
 * @file WalkRecord.h
 * @brief One graph element as the point-location walk reads it: corners and neighbours in one
 * 128-byte record, and the barycentric coordinates of a point in it.
 */
#ifndef dgmf_WalkRecord_h
#define dgmf_WalkRecord_h

#include "dgmf/Simd.h"

#include <cstdint>

namespace dgmf
{

/**
 * An element's corner coordinates (graph coordinates, z = 0 in 2D) and the elements across its
 * faces (neighbour k is opposite corner k, -1 on the hull). A walk step reads one record: two
 * adjacent cache lines, which the hardware fetches together.
 */
struct alignas(128) WalkRecord
{
  double Corners[4][3];
  std::int32_t Neighbors[4];
};
static_assert(sizeof(WalkRecord) == 128, "a walk record is two cache lines");

/**
 * A point whose barycentric coordinates are all >= -WeightTolerance is taken to be in the element:
 * points on a shared face (common in structured meshes, where nodes lie on the segments between
 * boundary nodes) come out a few ulps negative in one of the two elements, and must not send every
 * such node on a walk. Such weights are clamped to 0 afterwards.
 */
constexpr double WeightTolerance = 1e-12;

/**
 * Unnormalised barycentric coordinates of `p` in the element of `record`: the signed sub-element
 * volumes (areas in 2D) opposite each corner, `dimension` + 1 of them. Returns their sum, the
 * element's volume (positive for every element of the graph, up to round-off on flat ones).
 */
inline double SubVolumes(const WalkRecord& record, int dimension, const double p[3], double w[4])
{
  const double(*x)[3] = record.Corners;
  if (dimension == 2)
  {
    const double a[2] = { x[0][0] - p[0], x[0][1] - p[1] };
    const double b[2] = { x[1][0] - p[0], x[1][1] - p[1] };
    const double c[2] = { x[2][0] - p[0], x[2][1] - p[1] };
    // Twice the signed areas of the sub-triangles opposite each vertex.
    w[0] = b[0] * c[1] - b[1] * c[0];
    w[1] = c[0] * a[1] - c[1] * a[0];
    w[2] = a[0] * b[1] - a[1] * b[0];
    w[3] = 0.0;
    return w[0] + w[1] + w[2];
  }
  double a[3], b[3], c[3], d[3];
  for (int k = 0; k < 3; ++k)
  {
    a[k] = x[0][k] - p[k];
    b[k] = x[1][k] - p[k];
    c[k] = x[2][k] - p[k];
    d[k] = x[3][k] - p[k];
  }
  // Six times the signed volumes of the sub-tetrahedra opposite each vertex.
  const double cd[3] = { c[1] * d[2] - c[2] * d[1], c[2] * d[0] - c[0] * d[2],
    c[0] * d[1] - c[1] * d[0] };
  const double ab[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
    a[0] * b[1] - a[1] * b[0] };
  w[0] = b[0] * cd[0] + b[1] * cd[1] + b[2] * cd[2];
  w[1] = -(a[0] * cd[0] + a[1] * cd[1] + a[2] * cd[2]);
  w[2] = ab[0] * d[0] + ab[1] * d[1] + ab[2] * d[2];
  w[3] = -(ab[0] * c[0] + ab[1] * c[1] + ab[2] * c[2]);
  return w[0] + w[1] + w[2] + w[3];
}

/**
 * SubVolumes() of two points in two 3D elements at once, in the processor's two-lane
 * double-precision vectors (GCC and Clang vector extension): the same operations in the same
 * order, so the same bits, at about the cost of one.
 */
inline void SubVolumesPair3(const WalkRecord& r0, const WalkRecord& r1, const double p0[3],
  const double p1[3], double w0[4], double w1[4], double& total0, double& total1)
{
  using Pair = simd::Double2;
  Pair rel[4][3];
  for (int k = 0; k < 4; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      rel[k][c] = Pair{ r0.Corners[k][c], r1.Corners[k][c] } - Pair{ p0[c], p1[c] };
    }
  }
  const Pair(&a)[3] = rel[0];
  const Pair(&b)[3] = rel[1];
  const Pair(&c)[3] = rel[2];
  const Pair(&d)[3] = rel[3];
  const Pair cd[3] = { c[1] * d[2] - c[2] * d[1], c[2] * d[0] - c[0] * d[2],
    c[0] * d[1] - c[1] * d[0] };
  const Pair ab[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
    a[0] * b[1] - a[1] * b[0] };
  const Pair w[4] = { b[0] * cd[0] + b[1] * cd[1] + b[2] * cd[2],
    -(a[0] * cd[0] + a[1] * cd[1] + a[2] * cd[2]), ab[0] * d[0] + ab[1] * d[1] + ab[2] * d[2],
    -(ab[0] * c[0] + ab[1] * c[1] + ab[2] * c[2]) };
  const Pair total = w[0] + w[1] + w[2] + w[3];
  for (int k = 0; k < 4; ++k)
  {
    w0[k] = w[k][0];
    w1[k] = w[k][1];
  }
  total0 = total[0];
  total1 = total[1];
}

/**
 * True when the unnormalised coordinates `w` (with sum `total`) put the point in the element up to
 * round-off: total > 0 and every w[k] >= -WeightTolerance * total. Bitwise, without branches (the
 * walk interleaves several of these).
 */
inline bool IsInside(const double w[4], double total, int dimension)
{
  const double floor = -WeightTolerance * total;
  const bool inside3 = (w[0] >= floor) & (w[1] >= floor) & (w[2] >= floor);
  return (total > 0.0) & inside3 & ((dimension == 2) | (w[3] >= floor));
}

/**
 * Barycentric coordinates of `p` in the element of `record` (sub-element volumes over the element
 * volume; `dimension` + 1 of them). Returns true when all are >= -WeightTolerance, i.e. `p` is in
 * the element up to round-off. When the element has no positive volume the coordinates are left
 * unnormalised and false is returned.
 */
inline bool BarycentricWeights(
  const WalkRecord& record, int dimension, const double p[3], double w[4])
{
  const double total = SubVolumes(record, dimension, p, w);
  if (!(total > 0.0))
  {
    return false;
  }
  const double inv = 1.0 / total;
  for (int k = 0; k <= dimension; ++k)
  {
    w[k] *= inv;
  }
  return IsInside(w, 1.0, dimension);
}

/// The corner (0..dimension) with the most negative coordinate: the walk crosses the face opposite
/// it.
inline int MostNegativeWeight(const double w[4], int dimension)
{
  int most = 0;
  for (int k = 1; k <= dimension; ++k)
  {
    most = w[k] < w[most] ? k : most;
  }
  return most;
}

/// Makes weights non-negative and summing to 1 (points outside the hull, or round-off).
inline void ClampWeights(double* w, int n)
{
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    w[i] = w[i] > 0.0 ? w[i] : 0.0;
    sum += w[i];
  }
  for (int i = 0; i < n; ++i)
  {
    w[i] = sum > 0.0 ? w[i] / sum : 1.0 / n;
  }
}

/**
 * Copies a node's `n` (3 or 4) weights: written out, since a copy of a run-time length is a
 * memmove call per node (a fifth of the location's samples).
 */
inline void StoreWeights(const double* w, int n, double* out)
{
  out[0] = w[0];
  out[1] = w[1];
  out[2] = w[2];
  if (n == 4)
  {
    out[3] = w[3];
  }
}

} // namespace dgmf

#endif
