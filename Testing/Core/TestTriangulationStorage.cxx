// CGAL's storage for the graph's triangulation, reserved before the insertion
// (DelaunayGraph::ReserveTriangulation): the same triangulation, whether the storage was enough or
// had to grow. (CGAL's iteration order does change with it; the graph's element order does not:
// core.DelaunayGraph.TheElementsNumberingDoesNotDependOnThePointsOrder, speed.md.) That storage
// is in the huge-page arena, and goes back to it with the graph.
#include "dgmf/DelaunayGraph.h"
#include "dgmf/DelaunayGraphCgal.h"
#include "dgmf/HugePageArena.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace
{
// The graph's own types.
using dgmf::graph_cgal::Delaunay3;
using Point = dgmf::graph_cgal::Kernel::Point_3;

/// Points of the degenerate kind the graph meets: a sphere's nodes and a box's surface grid,
/// moved by a little noise (as the graph's perturbation does).
std::vector<std::pair<Point, std::int32_t>> SphereInBox()
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-1e-9, 1e-9);
  std::vector<std::pair<Point, std::int32_t>> points;
  const auto add = [&](double x, double y, double z)
  {
    points.emplace_back(Point(x + noise(random), y + noise(random), z + noise(random)),
      static_cast<std::int32_t>(points.size()));
  };
  const int n = 24;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double theta = 3.14159265358979 * (i + 0.5) / n, phi = 6.28318530717959 * j / n;
      add(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      // Two opposite faces of the box [-4, 4]^3 (the others are enough for the test's size).
      add(-4.0 + 8.0 * i / (n - 1), -4.0 + 8.0 * j / (n - 1), -4.0);
      add(-4.0 + 8.0 * i / (n - 1), -4.0 + 8.0 * j / (n - 1), 4.0);
    }
  }
  return points;
}

/// The finite cells: each cell's vertex infos sorted, and the parity of the permutation that
/// sorts them (its orientation), the list sorted.
std::vector<std::array<std::int32_t, 5>> Cells(const Delaunay3& t)
{
  std::vector<std::array<std::int32_t, 5>> cells;
  for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c)
  {
    std::array<std::int32_t, 5> v = { c->vertex(0)->info(), c->vertex(1)->info(),
      c->vertex(2)->info(), c->vertex(3)->info(), 0 };
    for (int a = 0; a < 4; ++a)
    {
      for (int b = a + 1; b < 4; ++b)
      {
        v[4] ^= v[a] > v[b] ? 1 : 0; // inversions
      }
    }
    std::sort(v.begin(), v.begin() + 4);
    cells.push_back(v);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}
} // namespace

TEST(TriangulationStorage, ReservedStorageGivesTheSameTriangulation)
{
  const std::vector<std::pair<Point, std::int32_t>> points = SphereInBox();
  Delaunay3 grown;
  grown.insert(points.begin(), points.end());
  const std::vector<std::array<std::int32_t, 5>> expected = Cells(grown);
  ASSERT_GT(expected.size(), 4 * points.size()); // a real tetrahedralisation
  // Enough storage, and too little (the rest grown during the insertion, as without reserving).
  for (const double perPoint : { 6.5, 2.0 })
  {
    Delaunay3 reserved;
    reserved.tds().cells().reserve(static_cast<std::size_t>(perPoint * points.size()) + 16);
    reserved.tds().vertices().reserve(points.size() + 1);
    reserved.insert(points.begin(), points.end());
    EXPECT_TRUE(reserved.is_valid());
    EXPECT_EQ(Cells(reserved), expected) << perPoint << " cells per point reserved";
  }
}

TEST(TriangulationStorage, TheGraphsCellsAndVerticesAreInTheHugePageArena)
{
  const std::vector<std::pair<Point, std::int32_t>> points = SphereInBox();
  const std::size_t before = dgmf::HugePageArenaBytes();
  {
    Delaunay3 t;
    t.insert(points.begin(), points.end());
    // CGAL's containers allocate through std::allocator of the element type, which the graph's
    // cell and vertex types specialise (DelaunayGraphCgal.h): without it, the arena is empty.
    const std::size_t cells = t.tds().cells().capacity() * sizeof(Delaunay3::Cell);
    const std::size_t vertices = t.tds().vertices().capacity() * sizeof(Delaunay3::Vertex);
    EXPECT_GE(dgmf::HugePageArenaBytes() - before, cells + vertices);
  }
  EXPECT_EQ(dgmf::HugePageArenaBytes(), before);
  // The same through the graph itself.
  std::vector<double> xyz;
  for (const auto& point : points)
  {
    xyz.insert(xyz.end(), { point.first.x(), point.first.y(), point.first.z() });
  }
  {
    const dgmf::DelaunayGraph graph(3, xyz.data(), points.size());
    EXPECT_GE(dgmf::HugePageArenaBytes() - before, 6 * points.size() * sizeof(Delaunay3::Cell));
  }
  EXPECT_EQ(dgmf::HugePageArenaBytes(), before);
}
