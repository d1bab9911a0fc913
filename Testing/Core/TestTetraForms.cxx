// A tetrahedron's SizeSkew from three numbers (core TetraSizeSkew) and the quality guard's view of
// a tetrahedron while one corner moves (repair::TetraForm): both against the full metric.
#include "dgmf/RepairTetraForm.h"
#include "dgmf/SizeSkewQuality.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using dgmf::CellQuality;
using dgmf::CellShape;
using dgmf::ComputeSizeSkew;

namespace
{
/// A case of the four-at-a-time tests: forms, their groups and a point.
struct FormCase
{
  std::vector<dgmf::repair::TetraForm> Forms; ///< in the groups' order
  std::vector<double> Groups;
  dgmf::Vec3 Y;
};

/**
 * Case `t`: 1 + t % 13 random usable forms with coordinates `scale` times numbers in [-1, 1]
 * (original Jacobians 0.01 to 1 times scale^3), laid out in groups from form (t / 13) % count
 * on (as the guard starts at the node's worst cell), and a point within half the scale.
 */
FormCase MakeFormCase(int t, double scale, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const std::size_t count = 1 + static_cast<std::size_t>(t % 13);
  FormCase c;
  while (c.Forms.size() < count)
  {
    double corners[12];
    for (double& x : corners)
      x = scale * unit(random);
    const double originalAlpha = 0.1 * scale * scale * scale * std::pow(10.0, unit(random));
    const dgmf::repair::TetraForm form =
      dgmf::repair::MakeTetraForm(corners, t % 4, t % 2 == 0 ? 1.0 : -1.0, originalAlpha);
    if (form.Usable)
      c.Forms.push_back(form);
  }
  const std::size_t first = static_cast<std::size_t>(t / 13) % count;
  dgmf::repair::StoreFormsInGroups(c.Forms.data(), count, first, c.Groups);
  std::rotate(c.Forms.begin(), c.Forms.begin() + static_cast<std::ptrdiff_t>(first), c.Forms.end());
  c.Y = dgmf::Vec3{ 0.5 * scale * unit(random), 0.5 * scale * unit(random),
    0.5 * scale * unit(random) };
  return c;
}
} // namespace

TEST(SizeSkewQuality, TetraFromThreeNumbersIsTheTetrahedronsSizeSkew)
{
  // Random tetrahedra of both orientations and of sizes 1e-3 to 1e3, moved by up to twice their
  // size (some inverted): TetraSizeSkew from (alpha, squared edges, original alpha) is
  // ComputeSizeSkew up to round-off, and inverted exactly when ComputeSizeSkew says so.
  std::mt19937 random(23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t inverted = 0, valid = 0;
  for (int t = 0; t < 4000; ++t)
  {
    const double scale = std::pow(10.0, 3.0 * unit(random));
    const double amplitude = t % 3 == 0 ? 2.0 : 0.3;
    double original[12], deformed[12];
    for (int k = 0; k < 12; ++k)
    {
      original[k] = scale * unit(random);
      deformed[k] = original[k] + amplitude * scale * unit(random);
    }
    const auto alphaOf = [](const double* p)
    {
      double e[3][3];
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
          e[c][d] = p[3 * (c + 1) + d] - p[d];
      return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
        e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
        e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    };
    const double alpha0 = alphaOf(original);
    if (std::abs(alpha0) < 1e-3 * scale * scale * scale)
      continue; // nearly flat originals: their inversion is decided at round-off
    const double orientation = alpha0 > 0.0 ? 1.0 : -1.0;
    const double alpha = orientation * alphaOf(deformed);
    double edgeSquares = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        for (int d = 0; d < 3; ++d)
          edgeSquares += std::pow(deformed[3 * b + d] - deformed[3 * a + d], 2);
    const CellQuality full = ComputeSizeSkew(CellShape::Tetra, original, deformed);
    const CellQuality fromNumbers = dgmf::TetraSizeSkew(alpha, edgeSquares, orientation * alpha0);
    if (std::abs(alpha) < 1e-9 * scale * scale * scale)
      continue; // flat after the motion: either verdict is round-off
    ASSERT_EQ(full.Inverted, fromNumbers.Inverted) << "case " << t;
    EXPECT_NEAR(fromNumbers.SizeSkew, full.SizeSkew, 1e-13) << "case " << t;
    (full.Inverted ? inverted : valid) += 1;
  }
  EXPECT_GT(inverted, 100u);
  EXPECT_GT(valid, 1000u);
  // Not numbers score 0 (inverted), never NaN.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(dgmf::TetraSizeSkew(nan, 1.0, 1.0).Inverted);
  EXPECT_EQ(dgmf::TetraSizeSkew(1.0, nan, 1.0).SizeSkew, 0.0);
}

TEST(LocalRepair, TetrahedronSeenFromOneCornerIsTheFullMetric)
{
  // The guard judges a moving node's tetrahedra through forms affine (the Jacobian) and quadratic
  // (the squared edges) in the node's position. For every corner of random tetrahedra of both
  // orientations, the form at random positions equals ComputeSizeSkew of the cell with that
  // corner moved, its cube (no cube root) is the value's cube, and its gradient is the full
  // metric's by central differences.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t checked = 0, inverted = 0, gradients = 0;
  const auto alphaOf = [](const double* p) // the corner Jacobian det(p1 - p0, p2 - p0, p3 - p0)
  {
    const dgmf::Vec3 o = dgmf::Load(p, 0);
    return dgmf::Dot(dgmf::Cross(dgmf::Load(p, 1) - o, dgmf::Load(p, 2) - o), dgmf::Load(p, 3) - o);
  };
  for (int t = 0; t < 500; ++t)
  {
    double original[12];
    for (int k = 0; k < 12; ++k)
      original[k] = unit(random);
    for (int corner = 0; corner < 4; ++corner)
    {
      double deformed[12];
      for (int k = 0; k < 12; ++k)
        deformed[k] = original[k] + 0.2 * unit(random);
      const double alpha0 = alphaOf(original);
      const dgmf::repair::TetraForm form =
        dgmf::repair::MakeTetraForm(deformed, corner, alpha0 < 0.0 ? -1.0 : 1.0, std::abs(alpha0));
      if (!form.Usable)
        continue; // a degenerate original
      for (int trial = 0; trial < 4; ++trial)
      {
        const dgmf::Vec3 y{ 1.5 * unit(random), 1.5 * unit(random), 1.5 * unit(random) };
        double moved[12];
        std::copy(deformed, deformed + 12, moved);
        dgmf::Store(y, moved, corner);
        const CellQuality full = dgmf::ComputeSizeSkew(CellShape::Tetra, original, moved);
        const CellQuality viaForm = form.Evaluate(y);
        ASSERT_EQ(full.Inverted, viaForm.Inverted) << "case " << t << " corner " << corner;
        ASSERT_NEAR(viaForm.SizeSkew, full.SizeSkew, 1e-12) << "case " << t;
        bool cubeInverted = false;
        const double cube = form.CubedSizeSkew(y, cubeInverted);
        ASSERT_EQ(cubeInverted, full.Inverted) << "case " << t;
        ASSERT_NEAR(cube, std::pow(full.SizeSkew, 3.0), 1e-12) << "case " << t;
        if (!full.Inverted && full.SizeSkew > 1e-3 && full.SizeSkew < 1.0)
        {
          // The gradient against central differences of the full metric.
          const double step = 1e-6;
          const dgmf::Vec3 gradient = form.Gradient(y, full.SizeSkew);
          for (int d = 0; d < 3; ++d)
          {
            double ahead[12], behind[12];
            std::copy(moved, moved + 12, ahead);
            std::copy(moved, moved + 12, behind);
            ahead[3 * corner + d] += step;
            behind[3 * corner + d] -= step;
            const double slope =
              (dgmf::ComputeSizeSkew(CellShape::Tetra, original, ahead).SizeSkew -
                dgmf::ComputeSizeSkew(CellShape::Tetra, original, behind).SizeSkew) /
              (2.0 * step);
            const double component = d == 0 ? gradient.X : d == 1 ? gradient.Y : gradient.Z;
            // The size term has a kink where the volume equals the original's (tau = 1).
            if (std::abs(alphaOf(moved) / alpha0 - 1.0) > 1e-3)
            {
              ASSERT_NEAR(component, slope, 1e-5 * (1.0 + std::abs(slope))) << "case " << t;
              ++gradients;
            }
          }
        }
        ++checked;
        inverted += full.Inverted ? 1 : 0;
      }
    }
  }
  EXPECT_GT(checked, 7000u);
  EXPECT_GT(inverted, 1000u);
  EXPECT_GT(gradients, 5000u);
}

TEST(LocalRepair, FormsFourAtATimeGiveTheCellByCellMinimumAndDecision)
{
  // The guard's trial positions evaluate a node's tetrahedra four at a time
  // (StoreFormsInGroups, MinimumCubedSizeSkew). Over random forms of every count from 1 to 13,
  // laid out from any first form (the last group padded with a repeated form), some inverted at the
  // trial point, some larger and some smaller than the original: without a cutoff, the same minimum
  // (bit for bit) and the same inverted flag as CubedSizeSkew cell by cell; with a cutoff, the same
  // verdict (at or below it, or the same value above it).
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t compared = 0, withInverted = 0, rejected = 0, accepted = 0, larger = 0, smaller = 0;
  for (int t = 0; t < 3000; ++t)
  {
    const FormCase c = MakeFormCase(t, 1.0, random);
    const std::vector<dgmf::repair::TetraForm>& forms = c.Forms;
    const std::vector<double>& groups = c.Groups;
    const std::size_t count = forms.size();
    const dgmf::Vec3 y = c.Y;

    double minimum = std::numeric_limits<double>::infinity();
    bool inverted = false;
    for (const dgmf::repair::TetraForm& form : forms)
    {
      double alpha, edgeSquares;
      form.Measure(y, alpha, edgeSquares);
      (alpha * form.InverseOriginalAlpha < 1.0 ? smaller : larger) += alpha > 0.0 ? 1 : 0;
      minimum = std::min(minimum, form.CubedSizeSkew(y, inverted));
    }
    bool groupedInverted = false;
    const double grouped =
      dgmf::repair::MinimumCubedSizeSkew(groups.data(), count, y, -1.0, groupedInverted);
    ASSERT_EQ(std::memcmp(&grouped, &minimum, sizeof grouped), 0) << "case " << t;
    ASSERT_EQ(groupedInverted, inverted) << "case " << t;
    withInverted += inverted ? 1 : 0;

    // With a cutoff: rejected by both, or the same value above it.
    const double cutoff = minimum * (1.0 + 0.5 * unit(random));
    bool cellInverted = false;
    double stopped = std::numeric_limits<double>::infinity();
    for (const dgmf::repair::TetraForm& form : forms)
    {
      stopped = std::min(stopped, form.CubedSizeSkew(y, cellInverted));
      if (stopped <= cutoff)
        break;
    }
    bool cutInverted = false;
    const double cut =
      dgmf::repair::MinimumCubedSizeSkew(groups.data(), count, y, cutoff, cutInverted);
    ASSERT_EQ(cut <= cutoff, stopped <= cutoff) << "case " << t;
    if (stopped > cutoff)
    {
      ASSERT_EQ(cut, stopped) << "case " << t;
      ASSERT_EQ(cutInverted, cellInverted) << "case " << t;
    }
    if (minimum > 0.0) // no cell inverted: rejected or not by the cutoff alone
    {
      (stopped <= cutoff ? rejected : accepted) += 1;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 3000u);
  EXPECT_GT(withInverted, 300u);
  EXPECT_GT(rejected, 100u);
  EXPECT_GT(accepted, 100u);
  // An infinite original Jacobian has no form: tau would be inf * 0 where alpha overflows, which
  // the lanes would not score as the cell-by-cell function does.
  const double corners[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  EXPECT_FALSE(
    dgmf::repair::MakeTetraForm(corners, 3, 1.0, std::numeric_limits<double>::infinity()).Usable);
  EXPECT_TRUE(dgmf::repair::MakeTetraForm(corners, 3, 1.0, 1.0).Usable);
  EXPECT_GT(larger, 1000u);
  EXPECT_GT(smaller, 1000u);
}

TEST(LocalRepair, FormsFourAtATimeGiveEachCellsSizeSkew)
{
  // The guard's accepted moves take their tetrahedra's values four at a time
  // (EvaluateFormGroups). Over random forms of every count from 1 to 13, laid out from any first
  // form, at points where some are inverted, some larger and some smaller than the original, and
  // at scales whose cube roots leave the fast range (tiny and huge coordinates): every value and
  // inverted flag as TetraForm::Evaluate gives it, bit for bit.
  std::mt19937 random(12);
  const double scales[] = { 1.0, 1e-80, 1e60 };
  std::size_t compared = 0, inverted = 0, outOfRange = 0, larger = 0, smaller = 0;
  for (int t = 0; t < 3000; ++t)
  {
    const FormCase c = MakeFormCase(t, scales[t % 3], random);
    const std::vector<dgmf::repair::TetraForm>& forms = c.Forms;
    const std::size_t count = forms.size();
    const dgmf::Vec3 y = c.Y;
    std::vector<dgmf::CellQuality> grouped(count);
    dgmf::repair::EvaluateFormGroups(c.Groups.data(), count, y, grouped.data());
    for (std::size_t j = 0; j < count; ++j)
    {
      const dgmf::CellQuality single = forms[j].Evaluate(y);
      ASSERT_EQ(std::memcmp(&grouped[j].SizeSkew, &single.SizeSkew, sizeof(double)), 0)
        << "case " << t << ", form " << j;
      ASSERT_EQ(grouped[j].Inverted, single.Inverted) << "case " << t << ", form " << j;
      double alpha, edgeSquares;
      forms[j].Measure(y, alpha, edgeSquares);
      const double argument = 2.0 * alpha * alpha;
      inverted += single.Inverted ? 1 : 0;
      outOfRange += alpha > 0.0 && !(argument >= 1e-300 && argument <= 1e300) ? 1 : 0;
      (alpha < forms[j].OriginalAlpha ? smaller : larger) += alpha > 0.0 ? 1 : 0;
      ++compared;
    }
  }
  EXPECT_GT(compared, 20000u);
  EXPECT_GT(inverted, 3000u);
  EXPECT_GT(outOfRange, 3000u);
  EXPECT_GT(larger, 3000u);
  EXPECT_GT(smaller, 3000u);
}
