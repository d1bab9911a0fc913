/**
 * @file RepairTetraForm.h
 * @brief The quality guard's view of a tetrahedron while one of its corners moves (private to the
 * core: NodeRepairer uses it): its SizeSkew, the cube of it and its gradient as functions of that
 * corner's position, without the cell's other corners or connectivity.
 */
#ifndef dgmf_RepairTetraForm_h
#define dgmf_RepairTetraForm_h

#include "dgmf/CellGeometry.h"
#include "dgmf/SizeSkewQuality.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace dgmf
{
namespace repair
{

/**
 * A tetrahedron seen from one of its corners while the others stay: its corner Jacobian is
 * affine and its squared edges quadratic in that corner's position y, so its SizeSkew at y
 * (TetraSizeSkew) needs neither the cell's corners nor its connectivity.
 */
struct TetraForm
{
  bool Usable = false;          ///< a non-degenerate tetrahedron (the others are evaluated in full)
  Vec3 Normal{ 0.0, 0.0, 0.0 }; ///< alpha(y) = Normal . (y - Others[0]), original orientation
  Vec3 Others[3];               ///< the three corners that stay
  double OppositeEdges = 0.0;   ///< squared lengths of the three edges between them
  double OriginalAlpha = 0.0;   ///< the original cell's corner Jacobian (> 0)
  double InverseOriginalAlpha = 0.0; ///< 1 / OriginalAlpha

  /// The corner Jacobian and the sum of the squared edges with the corner at `y`.
  void Measure(const Vec3& y, double& alpha, double& edgeSquares) const
  {
    const Vec3 d0 = y - this->Others[0];
    const Vec3 d1 = y - this->Others[1];
    const Vec3 d2 = y - this->Others[2];
    alpha = Dot(this->Normal, d0);
    edgeSquares = Dot(d0, d0) + Dot(d1, d1) + Dot(d2, d2) + this->OppositeEdges;
  }

  /// The cell's SizeSkew with the corner at `y` (equal to ComputeSizeSkew up to round-off).
  CellQuality Evaluate(const Vec3& y) const
  {
    double alpha, edgeSquares;
    this->Measure(y, alpha, edgeSquares);
    return TetraSizeSkew(alpha, edgeSquares, this->OriginalAlpha);
  }

  /**
   * The cube of the cell's SizeSkew with the corner at `y`, without a cube root:
   * 432 f_size^3 alpha^2 / edgeSquares^3 (TetraSizeSkew), in [0, 1], 0 for values that are not
   * numbers; 0 with `inverted` set for an inverted cell. Cubes order cells as their values do.
   */
  double CubedSizeSkew(const Vec3& y, bool& inverted) const
  {
    double alpha, edgeSquares;
    this->Measure(y, alpha, edgeSquares);
    if (!(alpha > 0.0))
    {
      inverted = true;
      return 0.0;
    }
    // 432 (alpha / edgeSquares)^2 / edgeSquares times tau^3 (smaller than the original) or
    // divided by it (larger), with two divisions; alpha / edgeSquares keeps the powers in range.
    const double ratio = alpha / edgeSquares;
    const double tau = alpha * this->InverseOriginalAlpha;
    const double tau3 = tau * tau * tau;
    const bool smaller = tau < 1.0;
    const double cube =
      (432.0 * ratio * ratio * (smaller ? tau3 : 1.0)) / (edgeSquares * (smaller ? 1.0 : tau3));
    return cube > 0.0 ? std::min(cube, 1.0) : 0.0;
  }

  /**
   * The gradient of the cell's SizeSkew with respect to the corner at `y`, where it is `quality`
   * (> 0): quality ((+-1 + 2/3) grad alpha / alpha - grad edgeSquares / edgeSquares), +1 while
   * the cell is smaller than the original (f_size = tau), -1 once larger (f_size = 1 / tau).
   */
  Vec3 Gradient(const Vec3& y, double quality) const
  {
    double alpha, edgeSquares;
    this->Measure(y, alpha, edgeSquares);
    if (!(alpha > 0.0 && edgeSquares > 0.0))
    {
      return Vec3{ 0.0, 0.0, 0.0 };
    }
    const double sizeSign = alpha < this->OriginalAlpha ? 1.0 : -1.0;
    const Vec3 edgeGradient =
      2.0 * ((y - this->Others[0]) + (y - this->Others[1]) + (y - this->Others[2]));
    return quality *
      (((sizeSign + 2.0 / 3.0) / alpha) * this->Normal - (1.0 / edgeSquares) * edgeGradient);
  }
};

/// Forms stored four to a group for MinimumCubedSizeSkew and EvaluateFormGroups: per group, each
/// of kFormGroupFields fields (the normal's 3 coordinates, the other corners' 9, OppositeEdges,
/// InverseOriginalAlpha, OriginalAlpha) as four consecutive doubles, one per form (the lanes of
/// simd::Double4).
constexpr std::size_t kFormGroupFields = 15;
constexpr std::size_t kFormGroupDoubles = 4 * kFormGroupFields;

/// The cell offset visited j-th when a node's `count` cells are visited from offset `first`
/// (< count) on, wrapping around: (first + j) % count, for j < count.
inline std::size_t WrappedOffset(std::size_t j, std::size_t first, std::size_t count)
{
  return j + first < count ? j + first : j + first - count;
}

/// The inverse of WrappedOffset: the visit index j of cell offset `offset` (< count).
inline std::size_t VisitOfOffset(std::size_t offset, std::size_t first, std::size_t count)
{
  return offset >= first ? offset - first : offset + count - first;
}

/// Writes usable `form` as form `index` of `groups` (group index / 4, lane index % 4).
void StoreFormInGroup(const TetraForm& form, std::size_t index, double* groups);

/**
 * `groups` sized for the `count` (> 0) usable `forms` and filled from form `first` (< count) on,
 * wrapping around: form (first + j) % count at index j; the last group's missing lanes repeat
 * its last form (the same minimum, the same verdict in MinimumCubedSizeSkew).
 */
void StoreFormsInGroups(
  const TetraForm* forms, std::size_t count, std::size_t first, std::vector<double>& groups);

/**
 * The smallest TetraForm::CubedSizeSkew at `y` over forms 0 .. `count` - 1 of `groups`
 * (StoreFormInGroup; the lanes of the last group past `count` repeat one of its forms), four at a
 * time: each form's value has the bits of CubedSizeSkew. Stops after the first group whose
 * minimum is at or below `cutoffCube`; `inverted` tells if a form evaluated is inverted. The
 * forms' divisions overlap, where one form at a time waits for each (the guard's trial
 * positions, speed.md "Large rotations").
 */
double MinimumCubedSizeSkew(
  const double* groups, std::size_t count, const Vec3& y, double cutoffCube, bool& inverted);

/**
 * TetraForm::Evaluate at `y` of forms 0 .. `count` - 1 of `groups` (StoreFormInGroup), to
 * `qualities` (`count` values), four at a time with each value's bits: the cube roots of the
 * lanes in range (TetraSizeSkew's fast path) together, the other lanes (inverted, or a root out
 * of range) cell by cell. The guard's accepted moves (NodeRepairer::Accept).
 */
void EvaluateFormGroups(
  const double* groups, std::size_t count, const Vec3& y, CellQuality* qualities);

/**
 * The form of a tetrahedron seen from corner `corner` (0 to 3, VTK order), whose three other
 * corners are now at `o0`, `o1`, `o2` (in their order): `orientation` is the sign of the original
 * cell's corner Jacobian and `originalAlpha` its absolute value. Not usable if that is not
 * positive and finite or the others' coordinates are not finite. Inline, so that the guard's
 * visits build their forms in place from the points (a form returned through memory and copied
 * waited on its own stores: speed.md, "Loads that waited for their own stores, in the guard").
 */
inline TetraForm MakeTetraForm(const Vec3& o0, const Vec3& o1, const Vec3& o2, int corner,
  double orientation, double originalAlpha)
{
  TetraForm form;
  form.Others[0] = o0;
  form.Others[1] = o1;
  form.Others[2] = o2;
  // The corner Jacobian det(p1 - p0, p2 - p0, p3 - p0) changes sign with each transposition:
  // with the moving corner taken from its place to the last, (-1)^(3 - corner) times
  // (o1 - o0) x (o2 - o0) . (y - o0), o the others in their order.
  const double sign = ((3 - corner) % 2 == 0 ? 1.0 : -1.0) * orientation;
  const Vec3 e01 = o1 - o0;
  const Vec3 e02 = o2 - o0;
  const Vec3 e12 = o2 - o1;
  form.Normal = sign * Cross(e01, e02);
  form.OppositeEdges = Dot(e01, e01) + Dot(e02, e02) + Dot(e12, e12);
  form.OriginalAlpha = originalAlpha;
  form.InverseOriginalAlpha = 1.0 / originalAlpha;
  // A finite original Jacobian: an infinite one would make tau = alpha * 0 not a number where
  // alpha overflows, a case MinimumCubedSizeSkew does not reproduce (such cells are degenerate
  // for the guard anyway).
  form.Usable = originalAlpha > 0.0 && std::isfinite(originalAlpha) && IsFinite(form.Normal) &&
    std::isfinite(form.OppositeEdges);
  return form;
}

/// The same form from the tetrahedron's current `corners` (12 coordinates, VTK order; the
/// moving corner's are not read).
TetraForm MakeTetraForm(
  const double* corners, int corner, double orientation, double originalAlpha);

} // namespace repair
} // namespace dgmf

#endif
