// The table that merges points at exactly the same coordinates (composite inputs' blocks, a
// mesh's coincident nodes).
#include "dgmf/ExactPointTable.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

TEST(ExactPointTable, SameCoordinatesGiveTheFirstIdOthersTheirOwn)
{
  // A stream with repeats, -0 against +0, and neighbours one ulp apart; grown from a tiny size.
  std::vector<double> kept;
  dgmf::ExactPointTable table(1);
  const auto add = [&](double x, double y, double z)
  {
    const double p[3] = { x, y, z };
    const auto next = static_cast<std::int64_t>(kept.size() / 3);
    const std::int64_t id = table.FindOrInsert(kept.data(), p, next);
    if (id == next)
    {
      kept.insert(kept.end(), p, p + 3);
    }
    return id;
  };
  EXPECT_EQ(add(0.0, 1.0, 2.0), 0);
  EXPECT_EQ(add(-0.0, 1.0, 2.0), 0); // -0 and +0: one node
  EXPECT_EQ(add(0.0, 1.0, std::nextafter(2.0, 3.0)), 1);
  EXPECT_EQ(add(1.0, 0.0, 2.0), 2); // the same values in another order: another point
  EXPECT_EQ(add(0.0, 1.0, 2.0), 0);

  // Many points on a grid, each twice (the second time from another "block"): every repeat finds
  // its first id, across the table's growth.
  std::vector<std::int64_t> first;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 20; ++k)
        first.push_back(add(0.1 * i, 0.1 * j, 0.1 * k));
  EXPECT_EQ(table.Size(), 3u + 8000u);
  std::size_t index = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 20; ++k)
        ASSERT_EQ(add(0.1 * i, 0.1 * j, 0.1 * k), first[index++]);
  EXPECT_EQ(table.Size(), 3u + 8000u);
  EXPECT_EQ(kept.size(), 3 * table.Size());
}

TEST(ExactPointTable, IdsCanBeTheCallersOwnPointsInPlace)
{
  // A mesh's points looked up in its own array: the canonical id of each is its first copy.
  std::mt19937 random(7);
  std::uniform_int_distribution<int> pick(0, 49);
  std::vector<double> points;
  std::vector<int> source;
  for (int i = 0; i < 500; ++i)
  {
    const int s = i < 50 ? i : pick(random);
    source.push_back(s);
    points.insert(points.end(), { 1.0 * s, 0.5 * s, -0.25 * s });
  }
  dgmf::ExactPointTable table(10);
  for (int i = 0; i < 500; ++i)
  {
    ASSERT_EQ(table.FindOrInsert(points.data(), points.data() + 3 * i, i), source[i]);
  }
  EXPECT_EQ(table.Size(), 50u);
}
