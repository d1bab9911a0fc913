// The quality guard (Documentation/repair.md): inverted and poor cells of small 2D and 3D grids
// are repaired by moving nearby interior nodes only; boundary nodes, nodes outside the region and
// meshes without bad cells are left bit for bit; results do not depend on the ParallelFor.
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
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

using dgmf::CellMesh;
using dgmf::CellQuality;
using dgmf::CellShape;
using dgmf::NodeKind;
using dgmf::RepairCells;
using dgmf::RepairParameters;
using dgmf::RepairReport;

namespace
{

/// A mesh, its original points, a deformed copy and the node kinds.
struct TestMesh
{
  CellMesh Mesh;
  std::vector<double> Original;
  std::vector<double> Points;
  std::vector<NodeKind> Kinds;
};

void AddCell(CellMesh& mesh, CellShape shape, std::initializer_list<std::int64_t> nodes)
{
  if (mesh.Offsets.empty())
  {
    mesh.Offsets.push_back(0);
  }
  mesh.Connectivity.insert(mesh.Connectivity.end(), nodes.begin(), nodes.end());
  mesh.Offsets.push_back(static_cast<std::int64_t>(mesh.Connectivity.size()));
  mesh.Shapes.push_back(shape);
}

/**
 * Unit square at height z, n x n nodes, boundary ring static. Each square is a quad, or two
 * triangles split along the diagonal (i, j)-(i+1, j+1) (rising) or (i+1, j)-(i, j+1).
 */
TestMesh Grid2D(int n, bool triangles, bool rising = true, double z = 0.25)
{
  TestMesh grid;
  const double h = 1.0 / (n - 1);
  grid.Mesh.NumberOfPoints = static_cast<std::size_t>(n * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      grid.Original.insert(grid.Original.end(), { i * h, j * h, z });
      const bool boundary = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      grid.Kinds.push_back(boundary ? NodeKind::StaticBoundary : NodeKind::Interior);
    }
  }
  const auto id = [n](int i, int j) { return static_cast<std::int64_t>(j * n + i); };
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const std::int64_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!triangles)
      {
        AddCell(grid.Mesh, CellShape::Quad, { a, b, c, d });
      }
      else if (rising)
      {
        AddCell(grid.Mesh, CellShape::Triangle, { a, b, c });
        AddCell(grid.Mesh, CellShape::Triangle, { a, c, d });
      }
      else
      {
        AddCell(grid.Mesh, CellShape::Triangle, { a, b, d });
        AddCell(grid.Mesh, CellShape::Triangle, { b, c, d });
      }
    }
  }
  grid.Points = grid.Original;
  return grid;
}

/// Unit cube, n^3 nodes, boundary static; hexahedra, or six tetrahedra per cube (Kuhn).
TestMesh Grid3D(int n, bool tetrahedra)
{
  TestMesh grid;
  const double h = 1.0 / (n - 1);
  grid.Mesh.NumberOfPoints = static_cast<std::size_t>(n * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        grid.Original.insert(grid.Original.end(), { i * h, j * h, k * h });
        const bool boundary = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
        grid.Kinds.push_back(boundary ? NodeKind::StaticBoundary : NodeKind::Interior);
      }
    }
  }
  const auto id = [n](int i, int j, int k)
  { return static_cast<std::int64_t>((k * n + j) * n + i); };
  for (int k = 0; k + 1 < n; ++k)
  {
    for (int j = 0; j + 1 < n; ++j)
    {
      for (int i = 0; i + 1 < n; ++i)
      {
        const std::int64_t v[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        if (!tetrahedra)
        {
          AddCell(
            grid.Mesh, CellShape::Hexahedron, { v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7] });
        }
        else
        {
          // Around the diagonal 0-6; the orientation of each tet is judged against itself.
          const int ring[7] = { 1, 2, 3, 7, 4, 5, 1 };
          for (int t = 0; t < 6; ++t)
          {
            AddCell(grid.Mesh, CellShape::Tetra, { v[0], v[ring[t]], v[ring[t + 1]], v[6] });
          }
        }
      }
    }
  }
  grid.Points = grid.Original;
  return grid;
}

/**
 * Unit cube, n^3 grid nodes, boundary static; the cubes alternate (checkerboard) between two
 * wedges and six pyramids around an extra centre node.
 */
TestMesh WedgePyramidGrid(int n)
{
  TestMesh grid = Grid3D(n, false);
  const CellMesh hexahedra = grid.Mesh;
  grid.Mesh = CellMesh();
  const double h = 1.0 / (n - 1);
  std::size_t points = static_cast<std::size_t>(n * n * n);
  for (std::size_t c = 0; c + 1 < hexahedra.Offsets.size(); ++c)
  {
    const std::int64_t* v = hexahedra.Connectivity.data() + hexahedra.Offsets[c];
    const double* p0 = grid.Original.data() + 3 * v[0];
    const bool even = (static_cast<int>(std::lround(p0[0] / h + p0[1] / h + p0[2] / h)) & 1) == 0;
    if (even)
    {
      AddCell(grid.Mesh, CellShape::Wedge, { v[0], v[1], v[3], v[4], v[5], v[7] });
      AddCell(grid.Mesh, CellShape::Wedge, { v[1], v[2], v[3], v[5], v[6], v[7] });
      continue;
    }
    const auto centre = static_cast<std::int64_t>(points++);
    grid.Original.insert(grid.Original.end(), { p0[0] + h / 2, p0[1] + h / 2, p0[2] + h / 2 });
    grid.Kinds.push_back(NodeKind::Interior);
    const int faces[6][4] = { { 0, 1, 2, 3 }, { 4, 7, 6, 5 }, { 0, 4, 5, 1 }, { 1, 5, 6, 2 },
      { 2, 6, 7, 3 }, { 3, 7, 4, 0 } };
    for (const auto& f : faces)
    {
      AddCell(grid.Mesh, CellShape::Pyramid, { v[f[0]], v[f[1]], v[f[2]], v[f[3]], centre });
    }
  }
  grid.Mesh.NumberOfPoints = points;
  grid.Points = grid.Original;
  return grid;
}

std::size_t NodeIndex2D(int n, int i, int j)
{
  return static_cast<std::size_t>(j * n + i);
}

std::size_t NodeIndex3D(int n, int i, int j, int k)
{
  return static_cast<std::size_t>((k * n + j) * n + i);
}

void Displace(TestMesh& grid, std::size_t node, double dx, double dy, double dz)
{
  grid.Points[3 * node] += dx;
  grid.Points[3 * node + 1] += dy;
  grid.Points[3 * node + 2] += dz;
}

/// Random displacement of every interior node, up to `amplitude` per coordinate (in plane if 2D).
void Jitter(TestMesh& grid, double amplitude, bool planar, unsigned seed)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  for (std::size_t n = 0; n < grid.Kinds.size(); ++n)
  {
    if (grid.Kinds[n] == NodeKind::Interior)
    {
      grid.Points[3 * n] += uniform(generator);
      grid.Points[3 * n + 1] += uniform(generator);
      if (!planar)
      {
        grid.Points[3 * n + 2] += uniform(generator);
      }
    }
  }
}

std::vector<CellQuality> Qualities(const TestMesh& grid, const std::vector<double>& points)
{
  std::vector<CellQuality> result;
  const CellMesh& mesh = grid.Mesh;
  for (std::size_t c = 0; c + 1 < mesh.Offsets.size(); ++c)
  {
    std::vector<double> original, deformed;
    for (std::int64_t k = mesh.Offsets[c]; k < mesh.Offsets[c + 1]; ++k)
    {
      const auto node = static_cast<std::size_t>(mesh.Connectivity[static_cast<std::size_t>(k)]);
      original.insert(
        original.end(), grid.Original.begin() + 3 * node, grid.Original.begin() + 3 * node + 3);
      deformed.insert(deformed.end(), points.begin() + 3 * node, points.begin() + 3 * node + 3);
    }
    result.push_back(dgmf::ComputeSizeSkew(mesh.Shapes[c], original.data(), deformed.data()));
  }
  return result;
}

struct Stats
{
  double Minimum = 1.0;
  std::size_t Inverted = 0;
  std::size_t Bad = 0;
};

Stats Summarize(const TestMesh& grid, const std::vector<double>& points, double threshold)
{
  Stats stats;
  for (const CellQuality& q : Qualities(grid, points))
  {
    stats.Minimum = std::min(stats.Minimum, q.SizeSkew);
    stats.Inverted += q.Inverted ? 1 : 0;
    stats.Bad += dgmf::IsBadCell(q, threshold) ? 1 : 0;
  }
  return stats;
}

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

using dgmf_test::TwoThreadFor;

RepairReport Repair(TestMesh& grid, const RepairParameters& parameters,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  return RepairCells(grid.Mesh, grid.Original.data(), grid.Points.data(), grid.Kinds.data(),
    parameters, parallelFor);
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
