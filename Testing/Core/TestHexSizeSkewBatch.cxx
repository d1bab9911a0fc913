// The hexahedra's size-skew four at a time (ComputeHexReferenceSizes, ComputeHexSizeSkew): the
// same bits as the one-cell metric, whatever the cells (inverted, degenerate, non-convex,
// mirrored, tiny enough to leave the fast cube root) and however many (not a multiple of four).
#include "dgmf/SizeSkewQuality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace
{
using dgmf::CellQuality;
using dgmf::CellShape;

constexpr double kCube[24] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1,
  1 };

bool SameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

/// Perturbed cubes, original and deformed, with every kind of cell the batch must hand over.
struct Cells
{
  std::vector<std::vector<double>> Original, Deformed;

  explicit Cells(std::size_t count)
  {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    for (std::size_t t = 0; t < count; ++t)
    {
      const double amplitude = t % 5 == 0 ? 2.0 : 0.15; // strong: some corners invert
      const double scale = t % 61 == 0 ? 1e-20 : 3.0;   // tiny: cube roots out of range
      std::vector<double> original(24), deformed(24);
      for (int k = 0; k < 24; ++k)
      {
        original[k] = scale * (kCube[k] + 0.02 * jitter(random));
        deformed[k] = original[k] + scale * amplitude * 0.3 * jitter(random);
      }
      if (t % 97 == 0)
      {
        for (int k = 12; k < 24; ++k)
          original[k] = original[k - 12]; // top face on the bottom one: degenerate
      }
      if (t % 89 == 0)
      {
        original[20] = -0.5 * scale; // corner 6 pushed below the bottom face: non-convex
      }
      if (t % 7 == 0)
      {
        for (int k = 0; k < 24; k += 3)
        {
          original[k] = -original[k]; // mirrored: negative orientation
          deformed[k] = -deformed[k];
        }
      }
      this->Original.push_back(original);
      this->Deformed.push_back(deformed);
    }
  }

  std::vector<const double*> Pointers(const std::vector<std::vector<double>>& points) const
  {
    std::vector<const double*> pointers;
    for (const std::vector<double>& p : points)
      pointers.push_back(p.data());
    return pointers;
  }
};
} // namespace

TEST(HexSizeSkewBatch, FourAtATimeGiveTheBitsOfOneAtATime)
{
  for (std::size_t count : { std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(4003) })
  {
    const Cells cells(count);
    std::vector<double> references(count);
    dgmf::ComputeHexReferenceSizes(count, cells.Pointers(cells.Original).data(), references.data());
    std::vector<CellQuality> batch(count);
    dgmf::ComputeHexSizeSkew(
      count, references.data(), cells.Pointers(cells.Deformed).data(), batch.data());
    std::size_t inverted = 0, invalid = 0, tiny = 0, valid = 0;
    for (std::size_t t = 0; t < count; ++t)
    {
      const double* original = cells.Original[t].data();
      const double* deformed = cells.Deformed[t].data();
      const double reference = dgmf::ComputeHexReferenceSize(original);
      ASSERT_TRUE(
        SameBits(references[t], reference) || (std::isnan(references[t]) && std::isnan(reference)))
        << "cell " << t << " of " << count;
      const CellQuality single = dgmf::ComputeSizeSkew(CellShape::Hexahedron, original, deformed);
      ASSERT_TRUE(SameBits(batch[t].SizeSkew, single.SizeSkew)) << "cell " << t << " of " << count;
      ASSERT_EQ(batch[t].Inverted, single.Inverted) << "cell " << t;
      ASSERT_EQ(batch[t].InputInvalid, single.InputInvalid) << "cell " << t;
      const CellQuality fromReference = dgmf::ComputeHexSizeSkew(reference, deformed);
      ASSERT_TRUE(SameBits(fromReference.SizeSkew, single.SizeSkew)) << "cell " << t;
      inverted += single.Inverted ? 1 : 0;
      invalid += single.InputInvalid ? 1 : 0;
      tiny += t % 61 == 0 && !single.Inverted && !single.InputInvalid ? 1 : 0;
      valid += !single.Inverted && !single.InputInvalid && single.SizeSkew > 0.0 ? 1 : 0;
    }
    if (count > 1000)
    {
      // The cases the batch hands to the one-cell path all occurred.
      EXPECT_GT(inverted, 50u);
      EXPECT_GT(invalid, 50u);
      EXPECT_GT(tiny, 20u);
      EXPECT_GT(valid, 2000u);
    }
  }
}

TEST(HexSizeSkewBatch, GroupsGiveTheBitsOfOneAtATimeAndReadOnlyTheirCells)
{
  // Cells in the vectors' layout, written by the literal formula (which pins the layout), every
  // lane past the cells NaN, the arrays of exactly the cells' size (AddressSanitizer sees an
  // over-read), sentinels after the outputs: partial last groups of 1, 2 and 3 lanes, with
  // inverted, non-convex and tiny cells at every lane (Cells' patterns by 5, 7, 61, 89, 97).
  for (std::size_t count : { std::size_t(1), std::size_t(2), std::size_t(3), std::size_t(5),
         std::size_t(6), std::size_t(7), std::size_t(63), std::size_t(65), std::size_t(4003) })
  {
    const Cells cells(count);
    const std::size_t groups = (count + 3) / 4;
    std::vector<double> original(groups * dgmf::kHexGroupDoubles, std::nan(""));
    std::vector<double> deformed(groups * dgmf::kHexGroupDoubles, std::nan(""));
    for (std::size_t t = 0; t < count; ++t)
    {
      for (int k = 0; k < 8; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          const std::size_t at = t / 4 * 96 + static_cast<std::size_t>(3 * k + c) * 4 + t % 4;
          ASSERT_EQ(at, t / 4 * dgmf::kHexGroupDoubles + dgmf::HexGroupIndex(k, c, t % 4));
          original[at] = cells.Original[t][3 * k + c];
          deformed[at] = cells.Deformed[t][3 * k + c];
        }
      }
    }
    constexpr double kSentinel = 12345.0;
    std::vector<double> references(count + 4, kSentinel);
    dgmf::ComputeHexReferenceSizesInGroups(count, original.data(), references.data());
    const std::vector<double> exactReferences(references.begin(), references.begin() + count);
    std::vector<CellQuality> quality(count + 4, CellQuality{ kSentinel, true, true });
    dgmf::ComputeHexSizeSkewInGroups(
      count, exactReferences.data(), deformed.data(), quality.data());
    for (std::size_t t = 0; t < count; ++t)
    {
      const double reference = dgmf::ComputeHexReferenceSize(cells.Original[t].data());
      ASSERT_TRUE(
        SameBits(references[t], reference) || (std::isnan(references[t]) && std::isnan(reference)))
        << "cell " << t << " of " << count;
      const CellQuality single = dgmf::ComputeSizeSkew(
        CellShape::Hexahedron, cells.Original[t].data(), cells.Deformed[t].data());
      ASSERT_TRUE(SameBits(quality[t].SizeSkew, single.SizeSkew))
        << "cell " << t << " of " << count;
      ASSERT_EQ(quality[t].Inverted, single.Inverted) << "cell " << t << " of " << count;
      ASSERT_EQ(quality[t].InputInvalid, single.InputInvalid) << "cell " << t << " of " << count;
    }
    for (std::size_t t = count; t < count + 4; ++t)
    {
      EXPECT_EQ(references[t], kSentinel) << "written past the cells, " << count;
      EXPECT_EQ(quality[t].SizeSkew, kSentinel) << "written past the cells, " << count;
    }
  }
}

TEST(HexSizeSkewBatch, TheReferenceSizeIsTheSignedSumOfTheCornerJacobians)
{
  // A 2 x 3 x 4 box: every corner Jacobian is 24, so the size is 8 x 24, negative when mirrored.
  double box[24];
  for (int k = 0; k < 24; k += 3)
  {
    box[k] = 2.0 * kCube[k];
    box[k + 1] = 3.0 * kCube[k + 1];
    box[k + 2] = 4.0 * kCube[k + 2];
  }
  EXPECT_EQ(dgmf::ComputeHexReferenceSize(box), 192.0);
  for (int k = 0; k < 24; k += 3)
    box[k] = -box[k];
  EXPECT_EQ(dgmf::ComputeHexReferenceSize(box), -192.0);
  // The same box twice as large: a size-skew of 0.5 against the first one's reference.
  double larger[24];
  for (int k = 0; k < 24; ++k)
    larger[k] = std::cbrt(2.0) * box[k];
  EXPECT_NEAR(dgmf::ComputeHexSizeSkew(-192.0, larger).SizeSkew, 0.5, 1e-12);
  // A flat box has no reference: its quality is InputInvalid.
  for (int k = 14; k < 24; k += 3)
    box[k] = 0.0;
  EXPECT_TRUE(std::isnan(dgmf::ComputeHexReferenceSize(box)));
  EXPECT_TRUE(dgmf::ComputeHexSizeSkew(std::nan(""), box).InputInvalid);
}
