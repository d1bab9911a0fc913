// Meshes numbered without spatial coherence: the start grid gives every walk a start a few
// elements from its node; the nodes are located right, in 2D and 3D, the same for any number of
// threads.
#include "LayeredMeshes.h"

#include "dgmf/DelaunayMapping.h"
#include "dgmf/LocationStartGrid.h"
#include "dgmf/NodeLocation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace
{
using dgmftest::LayeredMesh;
using dgmftest::MakeLayeredMesh;
using dgmftest::TwoThreads;

/// A mesh's points and kinds, renumbered at random (as a mesh reassembled from pieces is).
struct Shuffled
{
  std::vector<double> Points;
  std::vector<dgmf::NodeKind> Kinds;
};

Shuffled Shuffle(const std::vector<double>& points, const std::vector<dgmf::NodeKind>& kinds)
{
  const std::size_t n = kinds.size();
  std::vector<std::size_t> oldOf(n);
  std::iota(oldOf.begin(), oldOf.end(), std::size_t{ 0 });
  std::shuffle(oldOf.begin(), oldOf.end(), std::mt19937(11));
  Shuffled shuffled;
  shuffled.Points.resize(3 * n);
  shuffled.Kinds.resize(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    std::copy_n(points.data() + 3 * oldOf[k], 3, shuffled.Points.data() + 3 * k);
    shuffled.Kinds[k] = kinds[oldOf[k]];
  }
  return shuffled;
}

std::size_t CountInterior(const std::vector<dgmf::NodeKind>& kinds)
{
  return static_cast<std::size_t>(std::count(kinds.begin(), kinds.end(), dgmf::NodeKind::Interior));
}

/// The walk steps of locating every node from the given start elements (-1 for boundary nodes).
std::size_t StepsFrom(
  const dgmf::DelaunayGraph& graph, const Shuffled& mesh, const std::vector<std::int32_t>& starts)
{
  const std::size_t n = mesh.Kinds.size();
  std::vector<std::int32_t> element(n, dgmf::DelaunayMapping::NotLocated);
  std::vector<double> weights(4 * n);
  return dgmf::LocateNodes(graph, mesh.Points.data(), mesh.Kinds.data(), 0, n, element.data(),
    weights.data(), 0, 0, starts.data())
    .Steps;
}
} // namespace

TEST(LocationStartGrid, AShuffledNumberingIsLocatedFromItRightAndThreadIndependent)
{
  // IsNumberingCoherent says a shuffled numbering is not coherent, and every walk then starts from
  // the start grid's element near its node instead of the previous node's (anywhere).
  const LayeredMesh layered = MakeLayeredMesh(40, 12);
  const Shuffled mesh = Shuffle(layered.Points, layered.Kinds);
  const std::size_t n = mesh.Kinds.size();
  const dgmf::DelaunayMapping ordered(
    3, layered.Points.data(), n, layered.Kinds.data(), dgmf::SerialFor);
  const dgmf::DelaunayMapping one(3, mesh.Points.data(), n, mesh.Kinds.data(), dgmf::SerialFor);
  const dgmf::DelaunayMapping two(3, mesh.Points.data(), n, mesh.Kinds.data(), TwoThreads());
  EXPECT_FALSE(ordered.GetLocatedFromStartGrid());
  EXPECT_TRUE(one.GetLocatedFromStartGrid());
  EXPECT_EQ(one.GetNumberOfOutsideNodes(), 0u);
  dgmftest::ExpectSameAndRightLocations(one, two, mesh.Points.data());
  EXPECT_EQ(one.GetNumberOfWalkSteps(), two.GetNumberOfWalkSteps());
}

TEST(LocationStartGrid, ItsStartsAreMuchNearerThanTheSeedGridsAndDoNotDependOnThreads)
{
  // About 200 nodes per boundary node, as in the benchmark's mesh: many nodes per seed cell, so
  // the cells are cut into sub-cells. The graph's elements are long slivers from the body to the
  // far field, so a walk from the seed grid's element (one per cell, by the elements' centroids)
  // is many steps; from the start grid's, about one (about 2.6 with uncut cells).
  const LayeredMesh layered = MakeLayeredMesh(12, 400);
  const Shuffled mesh = Shuffle(layered.Points, layered.Kinds);
  const std::size_t n = mesh.Kinds.size();
  const dgmf::DelaunayMapping mapping(3, mesh.Points.data(), n, mesh.Kinds.data(), dgmf::SerialFor);
  const dgmf::DelaunayGraph& graph = mapping.GetGraph();
  const dgmf::LocationStartGrid one(
    graph, mesh.Points.data(), mesh.Kinds.data(), n, dgmf::SerialFor);
  const dgmf::LocationStartGrid two(graph, mesh.Points.data(), mesh.Kinds.data(), n, TwoThreads());

  // The sub-cells follow the nodes: about NodesPerSubCell interior nodes each where there are
  // nodes, one per empty seed cell.
  const auto& cells = graph.GetSeedGridGeometry().Cells;
  const auto seedCells = static_cast<std::size_t>(cells[0] * cells[1] * cells[2]);
  const std::size_t interior = CountInterior(mesh.Kinds);
  EXPECT_EQ(one.GetNumberOfSubCells(), two.GetNumberOfSubCells());
  EXPECT_GT(one.GetNumberOfSubCells(), seedCells + interior / 256);
  EXPECT_LT(one.GetNumberOfSubCells(), seedCells + 8 * interior / 32);

  std::vector<std::int32_t> fromGrid(n, -1), fromGridTwo(n, -1), fromSeed(n, -1);
  one.GetStartElements(mesh.Points.data(), mesh.Kinds.data(), 0, n, fromGrid.data());
  two.GetStartElements(mesh.Points.data(), mesh.Kinds.data(), 0, n, fromGridTwo.data());
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* p = mesh.Points.data() + 3 * i;
    if (dgmf::IsBoundary(mesh.Kinds[i]))
    {
      ASSERT_EQ(fromGrid[i], -1) << "boundary node " << i;
      continue;
    }
    ASSERT_GE(fromGrid[i], 0);
    ASSERT_LT(static_cast<std::size_t>(fromGrid[i]), graph.GetNumberOfElements());
    ASSERT_EQ(fromGrid[i], one.GetStartElement(p)) << "node " << i;
    ASSERT_EQ(fromGrid[i], fromGridTwo[i]) << "node " << i;
    fromSeed[i] = graph.GetSeedElement(p);
  }
  const std::size_t gridSteps = StepsFrom(graph, mesh, fromGrid);
  const std::size_t seedSteps = StepsFrom(graph, mesh, fromSeed);
  EXPECT_LT(static_cast<double>(gridSteps) / static_cast<double>(interior), 2.0);
  EXPECT_LT(4 * gridSteps, seedSteps);
}

TEST(LocationStartGrid, AShuffled2DMeshIsLocatedRight)
{
  // A circle of radius 1 (moving) in a square of side 20 (static), nodes in rings between them
  // (150 per boundary node), renumbered at random.
  std::vector<double> points;
  std::vector<dgmf::NodeKind> kinds;
  const int around = 100, rings = 300;
  const double pi = std::acos(-1.0);
  for (int r = 0; r < rings; ++r)
  {
    const double t = static_cast<double>(r) / (rings - 1);
    for (int k = 0; k < around; ++k)
    {
      const double angle = 2.0 * pi * k / around;
      const double c = std::cos(angle), s = std::sin(angle);
      const double square = 10.0 / std::max(std::abs(c), std::abs(s));
      const double radius = (1.0 - t) * 1.0 + t * square;
      points.insert(points.end(), { radius * c, radius * s, 0.0 });
      kinds.push_back(r == 0 ? dgmf::NodeKind::MovingBoundary
          : r == rings - 1   ? dgmf::NodeKind::StaticBoundary
                             : dgmf::NodeKind::Interior);
    }
  }
  const Shuffled mesh = Shuffle(points, kinds);
  const std::size_t n = mesh.Kinds.size();
  const dgmf::DelaunayMapping one(2, mesh.Points.data(), n, mesh.Kinds.data(), dgmf::SerialFor);
  const dgmf::DelaunayMapping two(2, mesh.Points.data(), n, mesh.Kinds.data(), TwoThreads());
  EXPECT_TRUE(one.GetLocatedFromStartGrid());
  EXPECT_EQ(one.GetNumberOfOutsideNodes(), 0u);
  dgmftest::ExpectSameAndRightLocations(one, two, mesh.Points.data());
  EXPECT_LT(static_cast<double>(one.GetNumberOfWalkSteps()) /
      static_cast<double>(CountInterior(mesh.Kinds)),
    2.0); // about one step a node; 3.4 with uncut seed cells
}
