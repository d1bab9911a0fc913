// The quality guard's give-up rules (Documentation/repair.md): a repair that cannot remove the bad
// cells in the passes it has left, or whose first pass left more bad cells than it found, is given
// up (when the sub-steps can halve the step); repairs that can finish are never given up.
#include "RepairGrids.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <iostream>
#include <vector>

using namespace dgmf_test;

TEST(LocalRepair, GivesUpOnlyWhenThePassesLeftCannotRemoveTheBadCells)
{
  // Tetrahedral grids with every interior node jittered, repaired against thresholds 0.5 to 0.75.
  // Every repair that removes all bad cells in its 20 passes is not given up and gives the same
  // bits with the option; one that cannot (jitter 0.4 spacings, threshold 0.75: hundreds of bad
  // cells left after 20 passes) is given up within a few passes.
  const auto run = [](double amplitude, double threshold, bool giveUp, TestMesh& grid)
  {
    grid = Grid3D(7, true);
    Jitter(grid, amplitude * grid.Original[3], false, 1);
    RepairParameters parameters;
    parameters.Threshold = threshold;
    parameters.GiveUpWhenHopeless = giveUp;
    return Repair(grid, parameters);
  };
  for (double threshold : { 0.5, 0.6, 0.7 })
  {
    for (double amplitude : { 0.3, 0.4 })
    {
      TestMesh with, without;
      const RepairReport withReport = run(amplitude, threshold, true, with);
      const RepairReport withoutReport = run(amplitude, threshold, false, without);
      ASSERT_EQ(withoutReport.BadCellsAfter, 0u) << amplitude << " " << threshold;
      EXPECT_FALSE(withReport.GaveUp) << amplitude << " " << threshold;
      EXPECT_EQ(withReport.Passes, withoutReport.Passes);
      EXPECT_EQ(
        std::memcmp(with.Points.data(), without.Points.data(), with.Points.size() * sizeof(double)),
        0);
    }
  }

  TestMesh hopeless, hopelessAllPasses;
  const RepairReport givenUp = run(0.4, 0.75, true, hopeless);
  const RepairReport allPasses = run(0.4, 0.75, false, hopelessAllPasses);
  EXPECT_TRUE(givenUp.GaveUp);
  EXPECT_GT(givenUp.BadCellsAfter, 0u);
  EXPECT_LT(givenUp.Passes, 10u);
  EXPECT_FALSE(allPasses.GaveUp);
  EXPECT_EQ(allPasses.Passes, 20u);
  EXPECT_GT(allPasses.BadCellsAfter, 100u); // it was indeed hopeless
  std::cout << "[ repair   ] hopeless: bad " << givenUp.BadCellsBefore << " -> "
            << givenUp.BadCellsAfter << ", given up after " << givenUp.Passes
            << " passes (all 20 passes: " << allPasses.BadCellsAfter << ")\n";
}

TEST(LocalRepair, GivesUpAfterTheFirstPassWhenItLeftMoreBadCells)
{
  // A 7^3 tetrahedral grid whose interior is twisted about the vertical axis through its centre
  // (the angle falling to 0 at the boundary), as a large rotation's step leaves a mesh, repaired
  // against thresholds 0.2 to 0.5. A repair that removes all bad cells within 15 of its 20 passes
  // is never given up, and gives the same bits with the option (the three that need 19 or 20
  // passes are given up: the give-up is a bet on halving the step, which those lose). The
  // 180-degree twist at 0.5, whose first pass leaves more bad cells than it found (and 20 passes
  // leave hundreds), is given up after that first pass.
  const auto run = [](double angle, double threshold, bool giveUp, TestMesh& grid)
  {
    grid = Grid3D(7, true);
    const double radians = angle * std::acos(-1.0) / 180.0;
    for (std::size_t k = 0; k < grid.Kinds.size(); ++k)
    {
      if (grid.Kinds[k] == NodeKind::Interior)
      {
        const double x = grid.Original[3 * k] - 0.5;
        const double y = grid.Original[3 * k + 1] - 0.5;
        const double turn = radians * (1.0 - 2.0 * std::max(std::abs(x), std::abs(y)));
        grid.Points[3 * k] = 0.5 + std::cos(turn) * x - std::sin(turn) * y;
        grid.Points[3 * k + 1] = 0.5 + std::sin(turn) * x + std::cos(turn) * y;
      }
    }
    RepairParameters parameters;
    parameters.Threshold = threshold;
    parameters.GiveUpWhenHopeless = giveUp;
    return Repair(grid, parameters);
  };
  int quick = 0;
  for (double angle : { 60.0, 90.0, 120.0, 150.0, 180.0 })
  {
    for (double threshold : { 0.2, 0.3, 0.5 })
    {
      TestMesh with, without;
      const RepairReport withReport = run(angle, threshold, true, with);
      const RepairReport withoutReport = run(angle, threshold, false, without);
      if (withoutReport.BadCellsAfter != 0 || withoutReport.Passes > 15)
      {
        continue;
      }
      ++quick;
      EXPECT_FALSE(withReport.GaveUp) << angle << " " << threshold;
      EXPECT_EQ(withReport.Passes, withoutReport.Passes) << angle << " " << threshold;
      EXPECT_EQ(
        std::memcmp(with.Points.data(), without.Points.data(), with.Points.size() * sizeof(double)),
        0)
        << angle << " " << threshold;
    }
  }
  EXPECT_GE(quick, 8);

  TestMesh hopeless, hopelessAllPasses;
  const RepairReport givenUp = run(180.0, 0.5, true, hopeless);
  const RepairReport allPasses = run(180.0, 0.5, false, hopelessAllPasses);
  EXPECT_TRUE(givenUp.GaveUp);
  EXPECT_EQ(givenUp.Passes, 1u);
  EXPECT_GT(givenUp.BadCellsAfter, givenUp.BadCellsBefore); // (more, not as many)
  EXPECT_GT(allPasses.BadCellsAfter, 100u);                 // it was indeed hopeless
}
