// The Delaunay graph (CGAL) and point location: barycentric coordinates, hints, degenerate input.
#include "SyntheticNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/DelaunayGraph.h"
#include "dgmf/DelaunayMapping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
std::vector<double> BoundaryPoints(const dgmf_test::NodeSet& set)
{
  std::vector<double> xyz;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (dgmf::IsBoundary(set.Kinds[i]))
    {
      xyz.insert(xyz.end(), set.Points.begin() + 3 * i, set.Points.begin() + 3 * i + 3);
    }
  }
  return xyz;
}

/// Checks e_i >= 0, sum e_i = 1 and sum e_i x_i = p for every interior node.
void CheckWeights(const dgmf_test::NodeSet& set)
{
  dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  const dgmf::DelaunayGraph& graph = mapping.GetGraph();
  const int n = graph.GetVerticesPerElement();
  std::size_t checked = 0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (mapping.IsBoundaryNode(i))
    {
      continue;
    }
    const double* w = mapping.GetWeights(i);
    const std::int32_t* vertices = graph.GetElement(mapping.GetElementOfNode(i));
    double sum = 0.0;
    double p[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < n; ++k)
    {
      ASSERT_GE(w[k], 0.0) << "node " << i;
      sum += w[k];
      const double* x = graph.GetVertexPosition(vertices[k]);
      for (int c = 0; c < 3; ++c)
      {
        p[c] += w[k] * x[c];
      }
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << "node " << i;
    for (int c = 0; c < set.Dimension; ++c)
    {
      EXPECT_NEAR(p[c], set.Points[3 * i + c], 1e-12) << "node " << i << " coordinate " << c;
    }
    ++checked;
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_EQ(mapping.GetNumberOfOutsideNodes(), 0u);
}
} // namespace

TEST(DelaunayGraph, BarycentricCoordinatesReproducePositions2D)
{
  CheckWeights(dgmf_test::CircleInSquare());
}

TEST(DelaunayGraph, BarycentricCoordinatesReproducePositions3D)
{
  CheckWeights(dgmf_test::SphereInBox());
}

TEST(DelaunayGraph, ElementsArePositivelyOriented)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(10);
  const std::vector<double> xyz = BoundaryPoints(set);
  dgmf::DelaunayGraph graph(3, xyz.data(), xyz.size() / 3);
  EXPECT_GT(graph.GetNumberOfElements(), 100u);
  EXPECT_EQ(
    graph.CountInvertedElements(std::vector<double>(3 * graph.GetNumberOfVertices(), 0.0).data()),
    0u);
  // Mirroring every vertex (x -> -x) inverts every element that is not flat.
  std::vector<double> mirror(3 * graph.GetNumberOfVertices(), 0.0);
  for (std::size_t v = 0; v < graph.GetNumberOfVertices(); ++v)
  {
    const std::size_t point = static_cast<std::size_t>(graph.GetPointOfVertex()[v]);
    mirror[3 * v] = -2.0 * xyz[3 * point]; // displacement taking x to -x
  }
  EXPECT_EQ(graph.CountInvertedElements(mirror.data()),
    graph.GetNumberOfElements() - graph.GetNumberOfFlatElements());
  // The box faces are coplanar grids and the sphere's nodes cospherical: flat artefacts exist,
  // but they are a minority.
  EXPECT_LT(graph.GetNumberOfFlatElements(), graph.GetNumberOfElements() / 2);
}

TEST(DelaunayGraph, LocationDoesNotDependOnTheHint)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(500);
  const std::vector<double> xyz = BoundaryPoints(set);
  dgmf::DelaunayGraph graph(3, xyz.data(), xyz.size() / 3);
  const double p[3] = { 2.1234, -1.5678, 3.3141 };
  const dgmf::DelaunayGraph::Location fromScratch = graph.LocateExactly(p, -1);
  ASSERT_GE(fromScratch.Element, 0);
  EXPECT_FALSE(fromScratch.Outside);
  for (std::int32_t hint = 0; hint < static_cast<std::int32_t>(graph.GetNumberOfElements());
       hint += 37)
  {
    const dgmf::DelaunayGraph::Location fromHint = graph.LocateExactly(p, hint);
    EXPECT_EQ(fromHint.Element, fromScratch.Element) << "hint " << hint;
  }
}

TEST(DelaunayGraph, PointOutsideTheHullGetsTheNearestHullElement)
{
  const double square[] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  dgmf::DelaunayGraph graph(2, square, 4);
  ASSERT_EQ(graph.GetNumberOfElements(), 2u);
  const double p[3] = { 2.0, 0.5, 0.0 };
  const dgmf::DelaunayGraph::Location location = graph.LocateExactly(p, -1);
  EXPECT_TRUE(location.Outside);
  ASSERT_GE(location.Element, 0);
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_GE(location.Weights[k], 0.0);
    sum += location.Weights[k];
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

TEST(DelaunayGraph, CoincidentPointsShareAVertex)
{
  const double points[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0 };
  dgmf::DelaunayGraph graph(2, points, 5);
  EXPECT_EQ(graph.GetNumberOfVertices(), 4u);
  EXPECT_EQ(graph.GetVertexOfPoint()[1], graph.GetVertexOfPoint()[3]);
  EXPECT_EQ(graph.GetPointOfVertex()[graph.GetVertexOfPoint()[3]], 1);
}

TEST(DelaunayGraph, DegenerateInputIsRejected)
{
  const double collinear[] = { 0, 0, 0, 1, 1, 0, 2, 2, 0, 3, 3, 0 };
  EXPECT_THROW(dgmf::DelaunayGraph(2, collinear, 4), std::invalid_argument);
  const double coplanar[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0 };
  EXPECT_THROW(dgmf::DelaunayGraph(3, coplanar, 5), std::invalid_argument);
  const double notFinite[] = { 0, 0, 0, 1, 0, 0, NAN, 1, 0 };
  EXPECT_THROW(dgmf::DelaunayGraph(2, notFinite, 3), std::invalid_argument);
  EXPECT_THROW(dgmf::DelaunayGraph(4, collinear, 4), std::invalid_argument);
}

namespace
{
/// Points of a grid on a box's faces (coplanar, cocircular), a sphere's (cospherical) and random
/// ones inside, with some repeated: every kind of degeneracy the graph meets, in enough points
/// for many blocks of every loop.
std::vector<double> DegenerateCloud(int dimension)
{
  std::vector<double> xyz;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> inside(-0.9, 0.9);
  const int grid = dimension == 3 ? 13 : 200;
  for (int i = 0; i < grid; ++i)
  {
    for (int j = 0; j < grid; ++j)
    {
      const double u = -1.0 + 2.0 * i / (grid - 1), v = -1.0 + 2.0 * j / (grid - 1);
      if (dimension == 2)
      {
        if (i == 0 || j == 0 || i == grid - 1 || j == grid - 1)
        {
          xyz.insert(xyz.end(), { u, v, 0.0 });
        }
        continue;
      }
      for (const double side : { -1.0, 1.0 })
      {
        xyz.insert(xyz.end(), { side, u, v, u, side, v, u, v, side });
      }
    }
  }
  for (int k = 0; k < 3000; ++k)
  {
    const double angle = 0.01 * k, height = -0.5 + k / 3000.0;
    const double radius = dimension == 3 ? std::sqrt(0.25 - height * height) : 0.5;
    xyz.insert(xyz.end(),
      { radius * std::cos(angle), radius * std::sin(angle), dimension == 3 ? height : 0.0 });
    xyz.insert(
      xyz.end(), { inside(random), inside(random), dimension == 3 ? inside(random) : 0.0 });
  }
  xyz.insert(xyz.end(), xyz.begin() + 30, xyz.begin() + 60); // coincident with earlier points
  return xyz;
}
} // namespace

// The loops of the graph's construction run through the caller's ParallelFor: two threads must
// give the same graph, bit for bit, as one, and the caller's work must run once beside CGAL.
TEST(DelaunayGraph, TwoThreadsBuildTheSameGraphAsOne)
{
  for (const int dimension : { 2, 3 })
  {
    const std::vector<double> xyz = DegenerateCloud(dimension);
    const std::size_t count = xyz.size() / 3;
    const dgmf::DelaunayGraph serial(dimension, xyz.data(), count);
    int calls = 0;
    const dgmf::DelaunayGraph parallel(
      dimension, xyz.data(), count, dgmf_test::TwoThreadFor, { [&]() { ++calls; } });
    EXPECT_EQ(calls, 1);
    ASSERT_GT(serial.GetNumberOfElements(), 3u * 4096u) << "too few elements for several blocks";
    ASSERT_EQ(parallel.GetNumberOfVertices(), serial.GetNumberOfVertices());
    ASSERT_EQ(parallel.GetNumberOfElements(), serial.GetNumberOfElements());
    EXPECT_LT(serial.GetNumberOfVertices(), count) << "the coincident points share vertices";
    EXPECT_EQ(parallel.GetVertexOfPoint(), serial.GetVertexOfPoint());
    EXPECT_EQ(parallel.GetNumberOfFlatElements(), serial.GetNumberOfFlatElements());
    EXPECT_GT(serial.GetNumberOfFlatElements(), 0u) << "the cloud has degenerate elements";
    for (std::size_t v = 0; v < serial.GetNumberOfVertices(); ++v)
    {
      ASSERT_EQ(std::memcmp(parallel.GetVertexPosition(static_cast<std::int32_t>(v)),
                  serial.GetVertexPosition(static_cast<std::int32_t>(v)), 3 * sizeof(double)),
        0)
        << "vertex " << v;
    }
    for (std::int32_t e = 0; e < static_cast<std::int32_t>(serial.GetNumberOfElements()); ++e)
    {
      ASSERT_EQ(std::memcmp(parallel.GetElement(e), serial.GetElement(e),
                  static_cast<std::size_t>(dimension + 1) * sizeof(std::int32_t)),
        0)
        << "element " << e;
      const dgmf::WalkRecord& a = parallel.GetWalkRecord(e);
      const dgmf::WalkRecord& b = serial.GetWalkRecord(e);
      ASSERT_EQ(std::memcmp(a.Corners, b.Corners, sizeof(a.Corners)), 0) << "element " << e;
      ASSERT_EQ(std::memcmp(a.Neighbors, b.Neighbors, sizeof(a.Neighbors)), 0) << "element " << e;
    }
    // Folding the half x > 0 onto x < 0 inverts the elements there: both graphs count the same,
    // on one thread or two.
    std::vector<double> fold(3 * serial.GetNumberOfVertices(), 0.0);
    for (std::size_t v = 0; v < serial.GetNumberOfVertices(); ++v)
    {
      const std::size_t point = static_cast<std::size_t>(serial.GetPointOfVertex()[v]);
      fold[3 * v] = xyz[3 * point] > 0.0 ? -2.0 * xyz[3 * point] : 0.0;
    }
    const std::size_t inverted = serial.CountInvertedElements(fold.data());
    EXPECT_GT(inverted, serial.GetNumberOfElements() / 4);
    EXPECT_EQ(parallel.CountInvertedElements(fold.data(), dgmf_test::TwoThreadFor), inverted);
  }
}

namespace
{
/// Element `e` of `graph` (built from `xyz`) as the sorted coordinates of its corners' points.
std::vector<std::array<double, 3>> CornersOf(
  const dgmf::DelaunayGraph& graph, const std::vector<double>& xyz, std::int32_t e)
{
  std::vector<std::array<double, 3>> corners;
  for (int k = 0; k < graph.GetVerticesPerElement(); ++k)
  {
    const auto point = static_cast<std::size_t>(
      graph.GetPointOfVertex()[static_cast<std::size_t>(graph.GetElement(e)[k])]);
    corners.push_back({ xyz[3 * point], xyz[3 * point + 1], xyz[3 * point + 2] });
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}
} // namespace

// The elements' numbering is a function of the points, not of the order CGAL inserts and stores
// them (which follows the input's order, and the storage reserved): the same points in another
// order give element e the same corners, for every e.
TEST(DelaunayGraph, TheElementsNumberingDoesNotDependOnThePointsOrder)
{
  for (const int dimension : { 2, 3 })
  {
    const std::vector<double> xyz = DegenerateCloud(dimension);
    const std::size_t count = xyz.size() / 3;
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::shuffle(order.begin(), order.end(), std::mt19937(11));
    std::vector<double> shuffled(xyz.size());
    for (std::size_t i = 0; i < count; ++i)
    {
      std::copy(
        xyz.begin() + 3 * order[i], xyz.begin() + 3 * order[i] + 3, shuffled.begin() + 3 * i);
    }
    const dgmf::DelaunayGraph graph(dimension, xyz.data(), count);
    const dgmf::DelaunayGraph other(dimension, shuffled.data(), count);
    ASSERT_EQ(other.GetNumberOfElements(), graph.GetNumberOfElements());
    ASSERT_GT(graph.GetNumberOfElements(), 1000u);
    for (std::int32_t e = 0; e < static_cast<std::int32_t>(graph.GetNumberOfElements()); ++e)
    {
      ASSERT_EQ(CornersOf(other, shuffled, e), CornersOf(graph, xyz, e))
        << "element " << e << " in " << dimension << "D";
    }
  }
}

// The caller's work runs even when the graph rejects its input, and its exception (which may
// explain the graph's) is the one thrown.
TEST(DelaunayGraph, TheCallersFailureIsThrownInPreferenceToTheGraphs)
{
  const double coplanar[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0 };
  bool ran = false;
  EXPECT_THROW(
    dgmf::DelaunayGraph(3, coplanar, 5, dgmf_test::TwoThreadFor, { [&]() { ran = true; } }),
    std::invalid_argument);
  EXPECT_TRUE(ran);
  EXPECT_THROW(dgmf::DelaunayGraph(3, coplanar, 5, dgmf::SerialFor,
                 { []() { throw std::runtime_error("the caller's check"); } }),
    std::runtime_error);
  const std::vector<double> cloud = DegenerateCloud(3);
  EXPECT_THROW(dgmf::DelaunayGraph(3, cloud.data(), cloud.size() / 3, dgmf_test::TwoThreadFor,
                 { []() { throw std::runtime_error("the caller's check"); } }),
    std::runtime_error);
}

// The side jobs each run exactly once, on one thread or two, and the first failing job in the
// list's order is the one thrown.
TEST(DelaunayGraph, EverySideJobRunsOnceAndTheFirstFailureInOrderIsThrown)
{
  const std::vector<double> cloud = DegenerateCloud(3);
  const dgmf::ParallelFor serial = dgmf::SerialFor, twoThreads = dgmf_test::TwoThreadFor;
  for (const dgmf::ParallelFor* parallelFor : { &serial, &twoThreads })
  {
    std::vector<std::atomic<int>> runs(200);
    dgmf::DelaunayGraph::SideJobs jobs;
    for (std::size_t j = 0; j < runs.size(); ++j)
    {
      jobs.emplace_back([&runs, j]() { ++runs[j]; });
    }
    const dgmf::DelaunayGraph graph(3, cloud.data(), cloud.size() / 3, *parallelFor, jobs);
    EXPECT_GT(graph.GetNumberOfElements(), 0u);
    for (const std::atomic<int>& r : runs)
    {
      ASSERT_EQ(r.load(), 1);
    }
    jobs.clear();
    for (int j = 0; j < 50; ++j)
    {
      jobs.emplace_back(
        [j]()
        {
          if (j == 7 || j == 30)
            throw std::runtime_error("job " + std::to_string(j));
        });
    }
    try
    {
      dgmf::DelaunayGraph(3, cloud.data(), cloud.size() / 3, *parallelFor, jobs);
      ADD_FAILURE() << "no exception";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_STREQ(e.what(), "job 7");
    }
  }
}

TEST(DelaunayGraph, APointJustOutsideAFlatHullFaceGetsTheFacetUnderIt)
{
  // The boundary of a cube as a grid of points: its faces are flat, the graph's hull facets there
  // lie in one plane (up to the graph's perturbation). A point a hair outside a face (what
  // single-precision input or a tilted symmetry plane gives) must be interpolated in the facet it
  // projects onto: a linear field then comes out as at the projection. Grids of 7 and 13 points
  // a side, and the first scaled by 1/6: an element with two facets on the hull, walked from one
  // to the other, stopped the walk on 2026-11-30 (669 of 6,400 points wrong on the 13 grid, by up
  // to 7.4) until it kept the facets it had visited rather than their elements.
  for (const auto& [n, scale] :
    { std::pair{ 7, 1.0 }, std::pair{ 13, 1.0 }, std::pair{ 7, 1.0 / 6 } })
  {
    std::vector<double> xyz;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          if (i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1)
          {
            xyz.insert(xyz.end(), { scale * i, scale * j, scale * k });
          }
    dgmf::DelaunayGraph graph(3, xyz.data(), xyz.size() / 3);
    const auto field = [](const double* x) { return x[0] + 2.0 * x[1] + 3.0 * x[2]; };
    double worst = 0.0;
    int outside = 0;
    const int samples = 40 * (n - 1) / 6;
    for (int a = 0; a < samples; ++a)
    {
      for (int b = 0; b < samples; ++b)
      {
        const double p[3] = { scale * (0.1 + 0.15 * a), scale * (0.07 + 0.15 * b),
          -scale * 1e-9 * (1 + (a + b) % 3) };
        const dgmf::DelaunayGraph::Location location = graph.LocateExactly(p, -1);
        ASSERT_GE(location.Element, 0);
        outside += location.Outside ? 1 : 0;
        double value = 0.0;
        double sum = 0.0;
        for (int k = 0; k < 4; ++k)
        {
          ASSERT_GE(location.Weights[k], 0.0);
          sum += location.Weights[k];
          const std::int32_t v = graph.GetElement(location.Element)[k];
          value += location.Weights[k] * field(&xyz[3 * graph.GetPointOfVertex()[v]]);
        }
        EXPECT_NEAR(sum, 1.0, 1e-14);
        const double projected[3] = { p[0], p[1], 0.0 };
        worst = std::max(worst, std::abs(value - field(projected)));
      }
    }
    EXPECT_GT(outside, samples * samples * 2 / 3) << "the points are outside the hull";
    EXPECT_LT(worst, 1e-6 * scale)
      << "a linear field at the projection: grid " << n << ", scale " << scale;
  }
}

TEST(DelaunayGraph, APointJustOutsideAStraightHullEdgeGetsTheEdgeUnderIt)
{
  // The 2D case: the boundary of a square as a grid of points, points a hair below y = 0.
  const int n = 9;
  std::vector<double> xyz;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1)
      {
        xyz.insert(xyz.end(), { double(i), double(j), 0.0 });
      }
  dgmf::DelaunayGraph graph(2, xyz.data(), xyz.size() / 3);
  const auto field = [](const double* x) { return 3.0 * x[0] - x[1]; };
  double worst = 0.0;
  int outside = 0;
  for (int a = 0; a < 200; ++a)
  {
    const double p[3] = { 0.013 + 0.04 * a, -1e-9 * (1 + a % 3), 0.0 };
    const dgmf::DelaunayGraph::Location location = graph.LocateExactly(p, -1);
    ASSERT_GE(location.Element, 0);
    outside += location.Outside ? 1 : 0;
    double value = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_GE(location.Weights[k], 0.0);
      const std::int32_t v = graph.GetElement(location.Element)[k];
      value += location.Weights[k] * field(&xyz[3 * graph.GetPointOfVertex()[v]]);
    }
    const double projected[3] = { p[0], 0.0, 0.0 };
    worst = std::max(worst, std::abs(value - field(projected)));
  }
  EXPECT_GT(outside, 150);
  EXPECT_LT(worst, 1e-6);
}
