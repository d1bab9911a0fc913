// A tetrahedron seen from one moving corner (RepairTetraForm.h).
#include "dgmf/RepairTetraForm.h"

#include "dgmf/Simd.h"
#include "dgmf/SizeSkewTerms.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dgmf
{
namespace repair
{

TetraForm MakeTetraForm(const double* corners, int corner, double orientation, double originalAlpha)
{
  Vec3 others[3];
  for (int c = 0, k = 0; c < 4; ++c)
  {
    if (c != corner)
    {
      others[k++] = Load(corners, c);
    }
  }
  return MakeTetraForm(others[0], others[1], others[2], corner, orientation, originalAlpha);
}

namespace
{
/// The fields of a form in its group (kFormGroupFields).
enum FormField : std::size_t
{
  NormalX = 0,
  OtherX = 3, // other k's coordinate c at OtherX + 3 k + c
  OppositeEdges = 12,
  InverseOriginalAlpha = 13,
  OriginalAlpha = 14
};

using Four = simd::Double4;

DGMF_SIMD_INLINE Four Field(const double* group, std::size_t field)
{
  return simd::LoadDouble4(group + 4 * field);
}

/// TetraForm::Measure of a group's four forms at `y`: the same operations in each lane.
DGMF_SIMD_INLINE void MeasureGroup(
  const double* group, const Vec3& y, Four& alpha, Four& edgeSquares)
{
  Four d[3][3];
  for (std::size_t k = 0; k < 3; ++k)
  {
    d[k][0] = y.X - Field(group, OtherX + 3 * k);
    d[k][1] = y.Y - Field(group, OtherX + 3 * k + 1);
    d[k][2] = y.Z - Field(group, OtherX + 3 * k + 2);
  }
  alpha = Field(group, NormalX) * d[0][0] + Field(group, NormalX + 1) * d[0][1] +
    Field(group, NormalX + 2) * d[0][2];
  edgeSquares = (d[0][0] * d[0][0] + d[0][1] * d[0][1] + d[0][2] * d[0][2]) +
    (d[1][0] * d[1][0] + d[1][1] * d[1][1] + d[1][2] * d[1][2]) +
    (d[2][0] * d[2][0] + d[2][1] * d[2][1] + d[2][2] * d[2][2]) + Field(group, OppositeEdges);
}
} // namespace

void StoreFormInGroup(const TetraForm& form, std::size_t index, double* groups)
{
  double* group = groups + index / 4 * kFormGroupDoubles;
  const std::size_t lane = index % 4;
  const auto put = [group, lane](std::size_t field, double value)
  { group[4 * field + lane] = value; };
  put(NormalX, form.Normal.X);
  put(NormalX + 1, form.Normal.Y);
  put(NormalX + 2, form.Normal.Z);
  for (std::size_t k = 0; k < 3; ++k)
  {
    put(OtherX + 3 * k, form.Others[k].X);
    put(OtherX + 3 * k + 1, form.Others[k].Y);
    put(OtherX + 3 * k + 2, form.Others[k].Z);
  }
  put(OppositeEdges, form.OppositeEdges);
  put(InverseOriginalAlpha, form.InverseOriginalAlpha);
  put(OriginalAlpha, form.OriginalAlpha);
}

void StoreFormsInGroups(
  const TetraForm* forms, std::size_t count, std::size_t first, std::vector<double>& groups)
{
  const std::size_t padded = (count + 3) / 4 * 4;
  groups.resize(padded / 4 * kFormGroupDoubles);
  for (std::size_t j = 0; j < padded; ++j)
  {
    const std::size_t k = std::min(j, count - 1);
    StoreFormInGroup(forms[WrappedOffset(k, first, count)], j, groups.data());
  }
}

DGMF_SIMD_AVX2_CLONES
double MinimumCubedSizeSkew(
  const double* groups, std::size_t count, const Vec3& y, double cutoffCube, bool& inverted)
{
  // TetraForm::Measure and CubedSizeSkew, the same operations in the same order in each lane;
  // `smaller ? tau3 : 1` is Min(tau3, 1) and `smaller ? 1 : tau3` Max(tau3, 1), since tau3 < 1
  // exactly when tau < 1. Tau is a number wherever alpha > 0, since a usable form's
  // InverseOriginalAlpha is positive (infinite only for a subnormal original Jacobian); the other
  // lanes are inverted, value 0.
  double minimum = std::numeric_limits<double>::infinity();
  inverted = false;
  for (std::size_t first = 0; first < count; first += 4)
  {
    const double* group = groups + first / 4 * kFormGroupDoubles;
    Four alpha, edgeSquares;
    MeasureGroup(group, y, alpha, edgeSquares);
    const Four ratio = alpha / edgeSquares;
    const Four tau = alpha * Field(group, InverseOriginalAlpha);
    const Four tau3 = tau * tau * tau;
    const Four one = { 1.0, 1.0, 1.0, 1.0 };
    const Four zero = { 0.0, 0.0, 0.0, 0.0 };
    const Four cube =
      (432.0 * ratio * ratio * simd::Min(tau3, one)) / (edgeSquares * simd::Max(tau3, one));
    // `cube > 0 ? min(cube, 1) : 0` (+0 for NaN and -0 too); it is also the inverted lanes' 0:
    // where alpha is not > 0, tau3 is not > 0 (NaN only where alpha is +-0 and the inverse
    // infinite, and then ratio^2 is 0 or NaN) and edgeSquares not < 0, so cube is not > 0.
    const Four value = simd::Min(simd::Max(cube, zero), one);
    const bool upright = alpha[0] > 0.0 && alpha[1] > 0.0 && alpha[2] > 0.0 && alpha[3] > 0.0;
    inverted = inverted || !upright;
    // The values are numbers, so the order of the minima does not matter.
    minimum =
      std::min(minimum, std::min(std::min(value[0], value[1]), std::min(value[2], value[3])));
    if (minimum <= cutoffCube)
    {
      break;
    }
  }
  return minimum;
}

DGMF_SIMD_AVX2_CLONES
void EvaluateFormGroups(
  const double* groups, std::size_t count, const Vec3& y, CellQuality* qualities)
{
  // TetraSizeSkew's operations in each lane: the size factor std::min(tau, 1 / tau) is
  // Min(1 / tau, tau) (`1 / tau < tau ? 1 / tau : tau`), the value
  // f_size * 6 / (edgeSquares * (2 alpha^2)^(-1/3)). Lanes whose alpha is not > 0 or whose root's
  // argument is out of the fast range take the cell-by-cell function (what the lanes computed
  // there is not used).
  for (std::size_t first = 0; first < count; first += 4)
  {
    const double* group = groups + first / 4 * kFormGroupDoubles;
    Four alpha, edgeSquares;
    MeasureGroup(group, y, alpha, edgeSquares);
    const Four argument = 2.0 * alpha * alpha;
    const Four inverseRoot = sizeskew::InverseCubeRootInRange(argument);
    const Four originalAlpha = Field(group, OriginalAlpha);
    const Four tau = alpha / originalAlpha;
    const Four value = simd::Min(1.0 / tau, tau) * 6.0 / (edgeSquares * inverseRoot);
    const std::size_t lanes = std::min<std::size_t>(4, count - first);
    for (std::size_t l = 0; l < lanes; ++l)
    {
      const int lane = static_cast<int>(l);
      const bool fast = alpha[lane] > 0.0 && argument[lane] >= sizeskew::kCubeRootLow &&
        argument[lane] <= sizeskew::kCubeRootHigh;
      qualities[first + l] = fast
        ? sizeskew::Valid(value[lane])
        : TetraSizeSkew(alpha[lane], edgeSquares[lane], originalAlpha[lane]);
    }
  }
}

} // namespace repair
} // namespace dgmf
