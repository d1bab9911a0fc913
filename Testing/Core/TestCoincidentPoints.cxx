// The first point at each place (dgmf::FirstCoincidentPoints): the merge of a composite input's
// blocks at their shared nodes and the coincident nodes of a mesh, found on several threads.
#include "dgmf/CoincidentPoints.h"

#include "TwoThreadFor.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

namespace
{
/// The values of a result, to compare with a std::vector.
std::vector<std::int64_t> Values(const dgmf::UninitializedVector<std::int64_t>& first)
{
  return std::vector<std::int64_t>(first.begin(), first.end());
}

/// The first index at each place, by a std::map of the coordinates (-0 as +0).
std::vector<std::int64_t> Reference(const std::vector<double>& xyz)
{
  std::map<std::array<double, 3>, std::int64_t> firstAt;
  std::vector<std::int64_t> first;
  for (std::size_t i = 0; i < xyz.size() / 3; ++i)
  {
    std::array<double, 3> key;
    for (int c = 0; c < 3; ++c)
    {
      key[c] = xyz[3 * i + c] == 0.0 ? 0.0 : xyz[3 * i + c];
    }
    first.push_back(firstAt.emplace(key, static_cast<std::int64_t>(i)).first->second);
  }
  return first;
}
} // namespace

TEST(CoincidentPoints, SameCoordinatesGiveTheFirstIndexOthersTheirOwn)
{
  // Repeats, -0 against +0, neighbours one ulp apart, the same values in another order.
  const std::vector<double> xyz = { 0.0, 1.0, 2.0, /**/ -0.0, 1.0, 2.0, /**/ 0.0, 1.0,
    std::nextafter(2.0, 3.0), /**/ 1.0, 0.0, 2.0, /**/ 0.0, 1.0, 2.0 };
  const std::vector<std::int64_t> expected = { 0, 0, 2, 3, 0 };
  EXPECT_EQ(Values(dgmf::FirstCoincidentPoints(xyz.data(), 5, dgmf::SerialFor)), expected);
  EXPECT_TRUE(Values(dgmf::FirstCoincidentPoints(xyz.data(), 0, dgmf::SerialFor)).empty());
}

TEST(CoincidentPoints, PiecesAreNumberedOneAfterTheOtherAndMergedAcross)
{
  // A grid of 8,000 points, then the same grid again in another piece (a block's own copy of
  // shared nodes), then a piece of new points: each repeat finds its first copy in piece 0.
  std::vector<double> grid, other;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 20; ++k)
      {
        grid.insert(grid.end(), { 0.1 * i, 0.1 * j, 0.1 * k });
        other.insert(other.end(), { 0.1 * i + 5.0, 0.1 * j, 0.1 * k });
      }
  dgmf::PointPieces pieces;
  pieces.Points = { grid.data(), grid.data(), other.data() };
  pieces.Counts = { 8000, 8000, 8000 };
  const std::vector<std::int64_t> first =
    Values(dgmf::FirstCoincidentPoints(pieces, dgmf::SerialFor));
  ASSERT_EQ(first.size(), 24000u);
  for (std::int64_t i = 0; i < 24000; ++i)
  {
    ASSERT_EQ(first[i], i < 16000 ? i % 8000 : i) << "point " << i;
  }
}

TEST(CoincidentPoints, ManyPointsInManyPartsWithOneAndTwoThreads)
{
  // 200,000 points (16 parts) drawn from 60,000 places, -0 for some zeros.
  std::mt19937 random(11);
  std::uniform_int_distribution<int> pick(0, 59999);
  std::vector<double> places;
  for (int s = 0; s < 60000; ++s)
  {
    places.insert(places.end(), { 0.5 * (s % 40), 0.25 * (s / 40 % 40), s / 1600 - 10.0 });
  }
  std::vector<double> points;
  const std::size_t count = 200000;
  for (std::size_t i = 0; i < count; ++i)
  {
    const int s = pick(random);
    const double sign = i % 2 ? -1.0 : 1.0; // -0.0 and +0.0: one place
    points.insert(points.end(),
      { places[3 * s] == 0.0 ? sign * 0.0 : places[3 * s], places[3 * s + 1], places[3 * s + 2] });
  }
  const std::vector<std::int64_t> expected = Reference(points);
  EXPECT_EQ(Values(dgmf::FirstCoincidentPoints(points.data(), count, dgmf::SerialFor)), expected);
  EXPECT_EQ(
    Values(dgmf::FirstCoincidentPoints(points.data(), count, dgmf_test::TwoThreadFor)), expected);
  // The same points in three pieces of odd sizes.
  dgmf::PointPieces pieces;
  pieces.Points = { points.data(), points.data() + 3 * 70001, points.data() + 3 * 70002 };
  pieces.Counts = { 70001, 1, count - 70002 };
  EXPECT_EQ(Values(dgmf::FirstCoincidentPoints(pieces, dgmf_test::TwoThreadFor)), expected);
}
