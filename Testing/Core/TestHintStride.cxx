// The hint stride: found from a layered mesh's cells, none for a shuffled numbering, and used by
// the location (correct results, the same bits with 1 and 2 threads, most nodes found from it).
#include "LayeredMeshes.h"

#include "dgmf/DelaunayMapping.h"
#include "dgmf/HintStride.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

using dgmftest::ExpectSameAndRightLocations;
using dgmftest::LayeredMesh;
using dgmftest::MakeLayeredMesh;
using dgmftest::TwoThreads;

TEST(HintStride, LayeredMeshGivesTheLayerSize)
{
  const LayeredMesh mesh = MakeLayeredMesh(8, 6);
  EXPECT_EQ(dgmf::FindHintStride(mesh.Cells), mesh.NodesPerLayer);
}

TEST(HintStride, ShuffledNumberingGivesNone)
{
  LayeredMesh mesh = MakeLayeredMesh(8, 6);
  std::vector<std::int64_t> renumber(mesh.Kinds.size());
  std::iota(renumber.begin(), renumber.end(), 0);
  std::shuffle(renumber.begin(), renumber.end(), std::mt19937(3));
  for (auto& cell : mesh.Cells)
    for (auto& id : cell)
      id = renumber[static_cast<std::size_t>(id)];
  EXPECT_EQ(dgmf::FindHintStride(mesh.Cells), 0u);
  EXPECT_EQ(dgmf::FindHintStride({}), 0u);
}

TEST(HintStride, LocationWithTheStrideIsRightUsesItAndDoesNotDependOnThreads)
{
  // 30 layers of 484 nodes: the stride is longer than a run but shorter than a block (ranges
  // within a block); 12 layers of 9,128 nodes: longer than a block (waves of blocks).
  for (const int a : { 12, 40 })
  {
    const LayeredMesh mesh = MakeLayeredMesh(a, a == 12 ? 30 : 12);
    const std::size_t n = mesh.Kinds.size();
    const std::size_t stride = dgmf::FindHintStride(mesh.Cells);
    ASSERT_EQ(stride, mesh.NodesPerLayer);
    const dgmf::DelaunayMapping plain(3, mesh.Points.data(), n, mesh.Kinds.data(), dgmf::SerialFor);
    const dgmf::DelaunayMapping one(
      3, mesh.Points.data(), n, mesh.Kinds.data(), dgmf::SerialFor, stride);
    const dgmf::DelaunayMapping two(
      3, mesh.Points.data(), n, mesh.Kinds.data(), TwoThreads(), stride);
    const std::size_t interior = static_cast<std::size_t>(
      std::count(mesh.Kinds.begin(), mesh.Kinds.end(), dgmf::NodeKind::Interior));
    EXPECT_EQ(plain.GetNumberOfStrideHits(), 0u);
    // The walks count the elements they cross, whichever start they take.
    EXPECT_GT(plain.GetNumberOfWalkSteps(), 0u);
    EXPECT_EQ(one.GetNumberOfWalkSteps(), two.GetNumberOfWalkSteps());
    EXPECT_GT(one.GetNumberOfStrideHits(), interior / 2) << "a = " << a;
    ExpectSameAndRightLocations(one, two, mesh.Points.data());
  }
}
