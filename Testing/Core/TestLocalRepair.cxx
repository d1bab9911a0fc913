// The quality guard (Documentation/repair.md): inverted and poor cells of small 2D and 3D grids
// are repaired by moving nearby interior nodes only; boundary nodes, nodes outside the region and
// meshes without bad cells are left bit for bit; results do not depend on the ParallelFor. The
// give-up rules: TestLocalRepairGiveUp.cxx; the grids: RepairGrids.h.
#include "RepairGrids.h"
#include "TwoThreadFor.h"
#include "dgmf/LocalRepair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace dgmf_test;

namespace
{

/**
 * Layer of every node around the bad cells: 0 for their nodes, l for the nodes of cells that
 * share a node of layer l - 1; -1 beyond.
 */
std::vector<int> NodeLayers(
  const TestMesh& grid, const std::vector<double>& points, double threshold)
{
  const CellMesh& mesh = grid.Mesh;
  const std::vector<CellQuality> qualities = Qualities(grid, points);
  std::vector<int> layer(mesh.NumberOfPoints, -1);
  for (std::size_t c = 0; c < qualities.size(); ++c)
  {
    if (dgmf::IsBadCell(qualities[c], threshold))
    {
      for (std::int64_t k = mesh.Offsets[c]; k < mesh.Offsets[c + 1]; ++k)
      {
        layer[static_cast<std::size_t>(mesh.Connectivity[static_cast<std::size_t>(k)])] = 0;
      }
    }
  }
  for (int l = 1; l < 100; ++l)
  {
    std::vector<int> next = layer;
    for (std::size_t c = 0; c < qualities.size(); ++c)
    {
      bool touches = false;
      for (std::int64_t k = mesh.Offsets[c]; k < mesh.Offsets[c + 1]; ++k)
      {
        const int value =
          layer[static_cast<std::size_t>(mesh.Connectivity[static_cast<std::size_t>(k)])];
        touches = touches || value == l - 1;
      }
      for (std::int64_t k = mesh.Offsets[c]; touches && k < mesh.Offsets[c + 1]; ++k)
      {
        int& value = next[static_cast<std::size_t>(mesh.Connectivity[static_cast<std::size_t>(k)])];
        value = value < 0 ? l : value;
      }
    }
    layer = next;
  }
  return layer;
}

bool SameBits(const double* a, const double* b)
{
  return std::memcmp(a, b, 3 * sizeof(double)) == 0;
}

/**
 * The common checks of a repaired inversion: no inverted cell and no cell below the threshold,
 * the report matches a recount, boundary nodes and nodes outside the region are bit for bit
 * unchanged, and everything is finite.
 */
void CheckRepaired(const TestMesh& grid, const std::vector<double>& deformed,
  const RepairReport& report, const RepairParameters& parameters)
{
  const Stats before = Summarize(grid, deformed, parameters.Threshold);
  const Stats after = Summarize(grid, grid.Points, parameters.Threshold);
  EXPECT_GT(before.Inverted, 0u);
  EXPECT_EQ(report.InvertedBefore, before.Inverted);
  EXPECT_EQ(report.BadCellsBefore, before.Bad);
  EXPECT_EQ(report.InvertedAfter, 0u);
  EXPECT_EQ(after.Inverted, 0u);
  EXPECT_EQ(report.BadCellsAfter, 0u);
  EXPECT_EQ(after.Bad, 0u);
  EXPECT_GE(after.Minimum, parameters.Threshold);
  EXPECT_EQ(report.MinimumAfter, after.Minimum);
  EXPECT_EQ(report.MinimumBefore, 0.0);
  EXPECT_GT(report.MovedNodes, 0u);
  EXPECT_LE(report.MovedNodes, report.FreeNodes);
  EXPECT_GE(report.Passes, 1u);
  EXPECT_LE(report.Passes, static_cast<std::size_t>(parameters.MaximumPasses));

  const std::vector<int> layer = NodeLayers(grid, deformed, parameters.Threshold);
  std::size_t moved = 0;
  for (std::size_t n = 0; n < grid.Kinds.size(); ++n)
  {
    const double* p = grid.Points.data() + 3 * n;
    const double* q = deformed.data() + 3 * n;
    EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    if (grid.Kinds[n] != NodeKind::Interior)
    {
      EXPECT_TRUE(SameBits(p, q)) << "boundary node " << n << " moved";
    }
    if (layer[n] < 0 || layer[n] > parameters.Layers)
    {
      EXPECT_TRUE(SameBits(p, q)) << "node " << n << " of layer " << layer[n] << " moved";
    }
    moved += SameBits(p, q) ? 0 : 1;
  }
  EXPECT_EQ(moved, report.MovedNodes);
}

void PrintReport(const char* name, const RepairReport& report, double seconds)
{
  std::cout << "[ repair   ] " << name << ": bad " << report.BadCellsBefore << " -> "
            << report.BadCellsAfter << ", inverted " << report.InvertedBefore << " -> "
            << report.InvertedAfter << ", minimum " << report.MinimumBefore << " -> "
            << report.MinimumAfter << ", free " << report.FreeNodes << ", moved "
            << report.MovedNodes << ", passes " << report.Passes << ", "
            << 1e6 * seconds /
      static_cast<double>(std::max<std::size_t>(1, report.FreeNodes * report.Passes))
            << " us per node and pass\n";
}

RepairReport TimedRepair(const char* name, TestMesh& grid, const RepairParameters& parameters)
{
  const auto start = std::chrono::steady_clock::now();
  const RepairReport report = Repair(grid, parameters);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  PrintReport(name, report, seconds);
  return report;
}

} // namespace

TEST(LocalRepair, Untangles2DTriangles)
{
  const int n = 11;
  TestMesh grid = Grid2D(n, true);
  // The centre node pushed past its upper-right neighbour: several triangles turn over.
  Displace(grid, NodeIndex2D(n, 5, 5), 0.17, 0.13, 0.0);
  const std::vector<double> deformed = grid.Points;
  const RepairParameters parameters;
  const RepairReport report = TimedRepair("2D triangles", grid, parameters);
  CheckRepaired(grid, deformed, report, parameters);
  for (std::size_t node = 0; node < grid.Kinds.size(); ++node)
  {
    EXPECT_EQ(grid.Points[3 * node + 2], 0.25); // in the plane, bit for bit
  }
}

TEST(LocalRepair, Untangles2DQuads)
{
  const int n = 11;
  TestMesh grid = Grid2D(n, false);
  Displace(grid, NodeIndex2D(n, 4, 6), -0.16, 0.14, 0.0);
  Displace(grid, NodeIndex2D(n, 6, 3), 0.12, 0.0, 0.0);
  const std::vector<double> deformed = grid.Points;
  const RepairParameters parameters;
  const RepairReport report = TimedRepair("2D quads", grid, parameters);
  CheckRepaired(grid, deformed, report, parameters);
  for (std::size_t node = 0; node < grid.Kinds.size(); ++node)
  {
    EXPECT_EQ(grid.Points[3 * node + 2], 0.25);
  }
}

TEST(LocalRepair, Untangles2DCellsInATiltedPlane)
{
  const int n = 11;
  TestMesh grid = Grid2D(n, true, true, 0.0);
  Displace(grid, NodeIndex2D(n, 5, 5), 0.17, 0.13, 0.0);
  // Rotate everything (original and deformed) into a plane that is not normal to an axis.
  const double c = std::cos(0.7), s = std::sin(0.7), ct = std::cos(0.4), st = std::sin(0.4);
  for (std::vector<double>* points : { &grid.Original, &grid.Points })
  {
    for (std::size_t node = 0; node < grid.Kinds.size(); ++node)
    {
      double* p = points->data() + 3 * node;
      const double x = c * p[0] - s * p[1], y = s * p[0] + c * p[1];
      p[0] = x;
      p[1] = ct * y;
      p[2] = st * y + 0.3;
    }
  }
  const std::vector<double> deformed = grid.Points;
  const RepairParameters parameters;
  const RepairReport report = Repair(grid, parameters);
  CheckRepaired(grid, deformed, report, parameters);
  for (std::size_t node = 0; node < grid.Kinds.size(); ++node)
  {
    const double* p = grid.Points.data() + 3 * node;
    EXPECT_NEAR(-st * p[1] + ct * (p[2] - 0.3), 0.0, 1e-14); // distance to the plane
  }
}

TEST(LocalRepair, Untangles3DTetrahedra)
{
  const int n = 7;
  TestMesh grid = Grid3D(n, true);
  const double h = 1.0 / (n - 1);
  Displace(grid, NodeIndex3D(n, 3, 3, 3), 1.3 * h, 1.2 * h, 1.1 * h);
  const std::vector<double> deformed = grid.Points;
  const RepairParameters parameters;
  const RepairReport report = TimedRepair("3D tetrahedra", grid, parameters);
  CheckRepaired(grid, deformed, report, parameters);
}

TEST(LocalRepair, Untangles3DHexahedra)
{
  const int n = 7;
  TestMesh grid = Grid3D(n, false);
  const double h = 1.0 / (n - 1);
  Displace(grid, NodeIndex3D(n, 3, 3, 3), 1.3 * h, -1.2 * h, 0.9 * h);
  Displace(grid, NodeIndex3D(n, 2, 4, 2), -0.7 * h, 0.0, 0.0);
  const std::vector<double> deformed = grid.Points;
  const RepairParameters parameters;
  const RepairReport report = TimedRepair("3D hexahedra", grid, parameters);
  CheckRepaired(grid, deformed, report, parameters);
}

TEST(LocalRepair, Untangles3DWedgesAndPyramids)
{
  const int n = 6;
  TestMesh grid = WedgePyramidGrid(n);
  const double h = 1.0 / (n - 1);
  Displace(grid, NodeIndex3D(n, 2, 2, 2), 1.2 * h, 0.9 * h, -1.1 * h);
  const std::vector<double> deformed = grid.Points;
  const RepairParameters parameters;
  const RepairReport report = TimedRepair("3D wedges and pyramids", grid, parameters);
  CheckRepaired(grid, deformed, report, parameters);
}

TEST(LocalRepair, RecoversNonFiniteNode)
{
  const int n = 6;
  TestMesh grid = Grid3D(n, true);
  grid.Points[3 * NodeIndex3D(n, 2, 3, 2)] = std::numeric_limits<double>::quiet_NaN();
  const RepairParameters parameters;
  const RepairReport report = Repair(grid, parameters);
  EXPECT_GT(report.InvertedBefore, 0u);
  EXPECT_EQ(report.InvertedAfter, 0u);
  EXPECT_EQ(report.BadCellsAfter, 0u);
  for (double value : grid.Points)
  {
    EXPECT_TRUE(std::isfinite(value));
  }

  // 2D: the lost node comes back into the plane z = 0.25, exactly.
  TestMesh flat = Grid2D(n, false);
  flat.Points[3 * NodeIndex2D(n, 2, 3)] = std::numeric_limits<double>::infinity();
  const RepairReport flatReport = Repair(flat, parameters);
  EXPECT_EQ(flatReport.InvertedAfter, 0u);
  EXPECT_EQ(flatReport.BadCellsAfter, 0u);
  for (std::size_t node = 0; node < flat.Kinds.size(); ++node)
  {
    EXPECT_TRUE(std::isfinite(flat.Points[3 * node]) && std::isfinite(flat.Points[3 * node + 1]));
    EXPECT_EQ(flat.Points[3 * node + 2], 0.25);
  }
}

TEST(LocalRepair, NothingToRepairLeavesMeshUntouched)
{
  const int n = 9;
  for (int dimension = 2; dimension <= 3; ++dimension)
  {
    TestMesh grid = dimension == 2 ? Grid2D(n, true) : Grid3D(n, true);
    Jitter(grid, 0.05 / (n - 1), dimension == 2, 7);
    const std::vector<double> deformed = grid.Points;
    const RepairParameters parameters;
    ASSERT_EQ(Summarize(grid, deformed, parameters.Threshold).Bad, 0u);
    const RepairReport report = Repair(grid, parameters);
    EXPECT_EQ(
      std::memcmp(grid.Points.data(), deformed.data(), deformed.size() * sizeof(double)), 0);
    EXPECT_EQ(report.BadCellsBefore, 0u);
    EXPECT_EQ(report.BadCellsAfter, 0u);
    EXPECT_EQ(report.InvertedBefore, 0u);
    EXPECT_EQ(report.FreeNodes, 0u);
    EXPECT_EQ(report.MovedNodes, 0u);
    EXPECT_EQ(report.Passes, 0u);
    EXPECT_EQ(report.MinimumBefore, report.MinimumAfter);
    EXPECT_GT(report.MinimumBefore, parameters.Threshold);
  }
}

TEST(LocalRepair, CellOfBoundaryNodesCannotBeRepaired)
{
  // A single triangle, all of its nodes on the boundary, squashed.
  TestMesh single;
  single.Mesh.NumberOfPoints = 3;
  AddCell(single.Mesh, CellShape::Triangle, { 0, 1, 2 });
  single.Original = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  single.Points = { 0, 0, 0, 1, 0, 0, 0.5, 0.01, 0 };
  single.Kinds.assign(3, NodeKind::MovingBoundary);
  const std::vector<double> squashed = single.Points;
  const RepairReport one = Repair(single, RepairParameters());
  EXPECT_EQ(one.BadCellsBefore, 1u);
  EXPECT_EQ(one.BadCellsAfter, 1u);
  EXPECT_EQ(one.InvertedAfter, 0u);
  EXPECT_EQ(one.MovedNodes, 0u);
  EXPECT_EQ(one.FreeNodes, 0u);
  EXPECT_LT(one.MinimumAfter, 0.2);
  EXPECT_EQ(single.Points, squashed);

  // In a grid: the corner triangle (three boundary nodes) turned over by its corner node, and
  // an interior node pushed over its neighbours. Only the latter can be repaired.
  const int n = 11;
  TestMesh grid = Grid2D(n, true, false);
  grid.Points[0] = 0.08;
  grid.Points[1] = 0.08;
  Displace(grid, NodeIndex2D(n, 5, 5), 0.15, -0.12, 0.0);
  const std::vector<double> deformed = grid.Points;
  const std::vector<CellQuality> qualitiesBefore = Qualities(grid, deformed);
  const RepairParameters parameters;
  const RepairReport report = Repair(grid, parameters);
  const std::vector<CellQuality> qualitiesAfter = Qualities(grid, grid.Points);
  EXPECT_TRUE(qualitiesBefore[0].Inverted); // the corner cell is cell 0: nodes 0, 1, n
  EXPECT_TRUE(qualitiesAfter[0].Inverted);
  EXPECT_EQ(report.BadCellsAfter, 1u);
  EXPECT_EQ(report.InvertedAfter, 1u);
  EXPECT_GT(report.InvertedBefore, 1u);
  EXPECT_EQ(report.MinimumAfter, 0.0);
  for (std::size_t c = 1; c < qualitiesAfter.size(); ++c)
  {
    EXPECT_FALSE(dgmf::IsBadCell(qualitiesAfter[c], parameters.Threshold)) << "cell " << c;
  }
  for (std::size_t node = 0; node < grid.Kinds.size(); ++node)
  {
    if (grid.Kinds[node] != NodeKind::Interior)
    {
      EXPECT_TRUE(SameBits(grid.Points.data() + 3 * node, deformed.data() + 3 * node));
    }
  }
}

TEST(LocalRepair, NodesOfUncoveredCellsStayFixed)
{
  const int n = 9;
  TestMesh grid = Grid2D(n, false);
  const std::size_t centre = NodeIndex2D(n, 4, 4);
  Displace(grid, centre, 0.15, 0.13, 0.0);
  // The quad to the lower left of the centre node is "not covered" (as a polygon would be).
  grid.Mesh.Covered.assign(grid.Mesh.Shapes.size(), 1);
  const std::size_t uncovered = 3 * (n - 1) + 3;
  grid.Mesh.Covered[uncovered] = 0;
  const std::vector<double> deformed = grid.Points;
  const RepairReport report = Repair(grid, RepairParameters());
  for (std::int64_t k = grid.Mesh.Offsets[uncovered]; k < grid.Mesh.Offsets[uncovered + 1]; ++k)
  {
    const auto node = static_cast<std::size_t>(grid.Mesh.Connectivity[static_cast<std::size_t>(k)]);
    EXPECT_TRUE(SameBits(grid.Points.data() + 3 * node, deformed.data() + 3 * node));
  }
  // The centre node is fixed, so its cells stay bad; but the report counts covered cells only.
  EXPECT_GT(report.BadCellsBefore, 0u);
  EXPECT_LE(report.BadCellsAfter, report.BadCellsBefore);
}

TEST(LocalRepair, SameResultForAnyParallelFor)
{
  const int n = 9; // 3072 tetrahedra: two blocks of the quality evaluation
  TestMesh serial = Grid3D(n, true);
  Jitter(serial, 0.25 / (n - 1), false, 11);
  Displace(serial, NodeIndex3D(n, 4, 4, 4), 1.2 / (n - 1), 0.0, -1.1 / (n - 1));
  TestMesh threaded = serial;
  const RepairParameters parameters;
  const RepairReport a = Repair(serial, parameters, dgmf::SerialFor);
  const RepairReport b = Repair(threaded, parameters, TwoThreadFor);
  EXPECT_GT(a.MovedNodes, 0u);
  EXPECT_EQ(std::memcmp(
              serial.Points.data(), threaded.Points.data(), serial.Points.size() * sizeof(double)),
    0);
  EXPECT_EQ(a.BadCellsAfter, b.BadCellsAfter);
  EXPECT_EQ(a.MovedNodes, b.MovedNodes);
  EXPECT_EQ(a.Passes, b.Passes);
  EXPECT_EQ(a.MinimumAfter, b.MinimumAfter);
}

TEST(LocalRepair, MinimumNeverDecreases)
{
  struct Case
  {
    const char* Name;
    TestMesh Grid;
    bool Planar;
    double Amplitude; // in grid spacings: poor cells, none inverted
    double Threshold;
  };
  Case cases[] = { { "2D triangles", Grid2D(13, true), true, 0.3, 0.6 },
    { "2D quads", Grid2D(13, false), true, 0.3, 0.6 },
    { "3D tetrahedra", Grid3D(7, true), false, 0.3, 0.6 },
    { "3D hexahedra", Grid3D(7, false), false, 0.22, 0.75 } };
  for (Case& test : cases)
  {
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      TestMesh grid = test.Grid;
      const double h = grid.Original[3]; // spacing: node 1 is at (h, 0, 0)
      Jitter(grid, test.Amplitude * h, test.Planar, seed);
      RepairParameters parameters;
      parameters.Threshold = test.Threshold;
      const std::vector<double> deformed = grid.Points;
      const Stats before = Summarize(grid, deformed, parameters.Threshold);
      ASSERT_EQ(before.Inverted, 0u) << test.Name;
      ASSERT_GT(before.Bad, 0u) << test.Name;
      const RepairReport report = Repair(grid, parameters);
      const Stats after = Summarize(grid, grid.Points, parameters.Threshold);
      EXPECT_GE(after.Minimum, before.Minimum) << test.Name << " seed " << seed;
      EXPECT_GT(after.Minimum, before.Minimum) << test.Name << " seed " << seed;
      EXPECT_EQ(report.MinimumBefore, before.Minimum);
      EXPECT_EQ(report.MinimumAfter, after.Minimum);
      EXPECT_EQ(report.BadCellsAfter, after.Bad);
      EXPECT_LE(after.Bad, before.Bad) << test.Name << " seed " << seed;
      EXPECT_EQ(after.Inverted, 0u);
      if (seed == 1)
      {
        std::cout << "[ repair   ] jittered " << test.Name << ": minimum " << before.Minimum
                  << " -> " << after.Minimum << ", cells below " << test.Threshold << " "
                  << before.Bad << " -> " << after.Bad << ", passes " << report.Passes << "\n";
      }
    }
  }
}

TEST(LocalRepair, LayersBoundTheRegion)
{
  const int n = 13;
  for (int layers = 0; layers <= 3; ++layers)
  {
    TestMesh grid = Grid2D(n, true);
    Displace(grid, NodeIndex2D(n, 6, 6), 0.11, 0.09, 0.0);
    const std::vector<double> deformed = grid.Points;
    RepairParameters parameters;
    parameters.Layers = layers;
    const RepairReport report = Repair(grid, parameters);
    const std::vector<int> layer = NodeLayers(grid, deformed, parameters.Threshold);
    for (std::size_t node = 0; node < grid.Kinds.size(); ++node)
    {
      if (layer[node] < 0 || layer[node] > layers)
      {
        EXPECT_TRUE(SameBits(grid.Points.data() + 3 * node, deformed.data() + 3 * node));
      }
    }
    EXPECT_EQ(report.InvertedAfter, 0u) << "layers " << layers;
  }
}

TEST(LocalRepair, ZeroPassesOnlyCounts)
{
  TestMesh grid = Grid2D(7, true);
  Displace(grid, NodeIndex2D(7, 3, 3), 0.3, 0.2, 0.0);
  const std::vector<double> deformed = grid.Points;
  RepairParameters parameters;
  parameters.MaximumPasses = 0;
  const RepairReport report = Repair(grid, parameters);
  EXPECT_GT(report.BadCellsBefore, 0u);
  EXPECT_EQ(report.BadCellsAfter, report.BadCellsBefore);
  EXPECT_EQ(report.Passes, 0u);
  EXPECT_EQ(grid.Points, deformed);
}

TEST(LocalRepair, RejectsInvalidInput)
{
  TestMesh grid = Grid2D(4, true);
  RepairParameters parameters;
  parameters.Threshold = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Repair(grid, parameters), std::invalid_argument);
  parameters = RepairParameters();
  parameters.Layers = -1;
  EXPECT_THROW(Repair(grid, parameters), std::invalid_argument);

  TestMesh badIndex = grid;
  badIndex.Mesh.Connectivity[4] = 99;
  EXPECT_THROW(Repair(badIndex, RepairParameters()), std::invalid_argument);
  TestMesh badShape = grid;
  badShape.Mesh.Shapes[0] = CellShape::Quad;
  EXPECT_THROW(Repair(badShape, RepairParameters()), std::invalid_argument);
  TestMesh badOffsets = grid;
  badOffsets.Mesh.Offsets.back() += 3;
  EXPECT_THROW(Repair(badOffsets, RepairParameters()), std::invalid_argument);

  TestMesh empty;
  const RepairReport report = Repair(empty, RepairParameters());
  EXPECT_EQ(report.BadCellsBefore, 0u);
}
