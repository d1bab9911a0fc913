// Location of a block of nodes with interleaved walks (NodeLocation) and the graph's seed grid.
#include "SyntheticNodes.h"

#include "dgmf/DelaunayGraph.h"
#include "dgmf/NodeLocation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace
{
struct Located
{
  std::vector<std::int32_t> Element;
  std::vector<double> Weights;
  dgmf::NodeLocationCounts Counts;
};

/// The graph of a node set's boundary nodes.
dgmf::DelaunayGraph GraphOf(const dgmf_test::NodeSet& set, std::vector<double>& boundary)
{
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (dgmf::IsBoundary(set.Kinds[i]))
    {
      boundary.insert(boundary.end(), set.Points.begin() + 3 * i, set.Points.begin() + 3 * i + 3);
    }
  }
  return dgmf::DelaunayGraph(set.Dimension, boundary.data(), boundary.size() / 3);
}

Located LocateAll(const dgmf::DelaunayGraph& graph, const std::vector<double>& points,
  const std::vector<dgmf::NodeKind>& kinds, std::size_t blockSize)
{
  const std::size_t nodes = kinds.size();
  Located result;
  result.Element.assign(nodes, -1);
  result.Weights.assign(4 * nodes, -1.0);
  for (std::size_t begin = 0; begin < nodes; begin += blockSize)
  {
    const dgmf::NodeLocationCounts counts = dgmf::LocateNodes(graph, points.data(), kinds.data(),
      begin, std::min(nodes, begin + blockSize), result.Element.data(), result.Weights.data());
    result.Counts.Outside += counts.Outside;
    result.Counts.Restarts += counts.Restarts;
  }
  return result;
}

/// Every interior node: an element whose weights are >= 0, sum to 1 and reproduce the node, the
/// element CGAL's exact location finds when the node is clearly inside one; boundary nodes
/// untouched.
void ExpectCorrect(const dgmf::DelaunayGraph& graph, const std::vector<double>& points,
  const std::vector<dgmf::NodeKind>& kinds, const Located& located, int dimension)
{
  const int n = dimension + 1;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < kinds.size(); ++i)
  {
    if (dgmf::IsBoundary(kinds[i]))
    {
      EXPECT_EQ(located.Element[i], -1) << "boundary node " << i << " was written";
      continue;
    }
    const std::int32_t e = located.Element[i];
    ASSERT_GE(e, 0) << "node " << i;
    ASSERT_LT(static_cast<std::size_t>(e), graph.GetNumberOfElements());
    const double* w = located.Weights.data() + n * i;
    const std::int32_t* vertices = graph.GetElement(e);
    double sum = 0.0, p[3] = { 0, 0, 0 }, smallest = 1.0;
    for (int k = 0; k < n; ++k)
    {
      ASSERT_GE(w[k], 0.0) << "node " << i;
      sum += w[k];
      smallest = std::min(smallest, w[k]);
      for (int c = 0; c < 3; ++c)
      {
        p[c] += w[k] * graph.GetVertexPosition(vertices[k])[c];
      }
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << "node " << i;
    for (int c = 0; c < dimension; ++c)
    {
      EXPECT_NEAR(p[c], points[3 * i + c], 1e-12) << "node " << i;
    }
    if (smallest > 1e-9)
    {
      EXPECT_EQ(e, graph.LocateExactly(points.data() + 3 * i, -1).Element) << "node " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, kinds.size() / 2);
}
} // namespace

TEST(NodeLocation, FindsTheElementOfEveryNodeIn3D)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(3000);
  std::vector<double> boundary;
  const dgmf::DelaunayGraph graph = GraphOf(set, boundary);
  const Located located = LocateAll(graph, set.Points, set.Kinds, 4096);
  ExpectCorrect(graph, set.Points, set.Kinds, located, 3);
  EXPECT_EQ(located.Counts.Outside, 0u);
}

TEST(NodeLocation, FindsTheElementOfEveryNodeIn2D)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  std::vector<double> boundary;
  const dgmf::DelaunayGraph graph = GraphOf(set, boundary);
  const Located located = LocateAll(graph, set.Points, set.Kinds, 4096);
  ExpectCorrect(graph, set.Points, set.Kinds, located, 2);
}

TEST(NodeLocation, ShuffledNumberingRestartsFromTheSeedGridAndStaysCorrect)
{
  // Random numbering: every node is a jump from the previous one, so short walks fail and the
  // lanes restart from the seed grid; small blocks give many lanes of one or two nodes.
  dgmf_test::NodeSet set = dgmf_test::SphereInBox(3000);
  std::vector<std::size_t> order(set.Size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  std::vector<double> points(3 * order.size());
  std::vector<dgmf::NodeKind> kinds(order.size());
  for (std::size_t j = 0; j < order.size(); ++j)
  {
    std::copy(set.Points.begin() + 3 * order[j], set.Points.begin() + 3 * order[j] + 3,
      points.begin() + 3 * j);
    kinds[j] = set.Kinds[order[j]];
  }
  std::vector<double> boundary;
  const dgmf::DelaunayGraph graph = GraphOf(set, boundary);
  for (std::size_t blockSize : { std::size_t(4096), std::size_t(13) })
  {
    const Located located = LocateAll(graph, points, kinds, blockSize);
    ExpectCorrect(graph, points, kinds, located, 3);
    EXPECT_GT(located.Counts.Restarts, 100u) << "block size " << blockSize;
  }
}

TEST(NodeLocation, NodesOutsideTheHullGetClampedWeightsAndAreCounted)
{
  const double square[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  const dgmf::DelaunayGraph graph(2, square, 4);
  const std::vector<double> points = { 0.25, 0.5, 0, 2.0, 0.5, 0, -3.0, -1.0, 0, 0.75, 0.25, 0 };
  const std::vector<dgmf::NodeKind> kinds(4, dgmf::NodeKind::Interior);
  const Located located = LocateAll(graph, points, kinds, 4096);
  EXPECT_EQ(located.Counts.Outside, 2u);
  for (std::size_t i = 0; i < 4; ++i)
  {
    ASSERT_GE(located.Element[i], 0);
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_GE(located.Weights[3 * i + k], 0.0);
      sum += located.Weights[3 * i + k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
}

TEST(NodeLocation, SeedElementIsAValidElementEverywhere)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(100);
  std::vector<double> boundary;
  const dgmf::DelaunayGraph graph = GraphOf(set, boundary);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-1e6, 1e6);
  for (int t = 0; t < 1000; ++t)
  {
    const double p[3] = { coordinate(random), coordinate(random), coordinate(random) };
    const std::int32_t e = graph.GetSeedElement(p);
    ASSERT_GE(e, 0);
    ASSERT_LT(static_cast<std::size_t>(e), graph.GetNumberOfElements());
  }
}
