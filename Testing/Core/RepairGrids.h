/**
 * @file RepairGrids.h
 * @brief Small 2D and 3D grids for the quality guard's tests (TestLocalRepair.cxx,
 * TestLocalRepairGiveUp.cxx): a mesh with its original and deformed points and node kinds, the
 * nodes displaced or jittered, the cells' qualities counted, and the guard run on them.
 */
#ifndef dgmf_test_RepairGrids_h
#define dgmf_test_RepairGrids_h

#include "dgmf/LocalRepair.h"
#include "dgmf/SizeSkewQuality.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <vector>

namespace dgmf_test
{
using dgmf::CellMesh;
using dgmf::CellQuality;
using dgmf::CellShape;
using dgmf::NodeKind;
using dgmf::RepairCells;
using dgmf::RepairParameters;
using dgmf::RepairReport;

/// A mesh, its original points, a deformed copy and the node kinds.
struct TestMesh
{
  CellMesh Mesh;
  std::vector<double> Original;
  std::vector<double> Points;
  std::vector<NodeKind> Kinds;
};

inline void AddCell(CellMesh& mesh, CellShape shape, std::initializer_list<std::int64_t> nodes)
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
inline TestMesh Grid2D(int n, bool triangles, bool rising = true, double z = 0.25)
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
inline TestMesh Grid3D(int n, bool tetrahedra)
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
inline TestMesh WedgePyramidGrid(int n)
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

inline std::size_t NodeIndex2D(int n, int i, int j)
{
  return static_cast<std::size_t>(j * n + i);
}

inline std::size_t NodeIndex3D(int n, int i, int j, int k)
{
  return static_cast<std::size_t>((k * n + j) * n + i);
}

inline void Displace(TestMesh& grid, std::size_t node, double dx, double dy, double dz)
{
  grid.Points[3 * node] += dx;
  grid.Points[3 * node + 1] += dy;
  grid.Points[3 * node + 2] += dz;
}

/// Random displacement of every interior node, up to `amplitude` per coordinate (in plane if 2D).
inline void Jitter(TestMesh& grid, double amplitude, bool planar, unsigned seed)
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

inline std::vector<CellQuality> Qualities(const TestMesh& grid, const std::vector<double>& points)
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

inline Stats Summarize(const TestMesh& grid, const std::vector<double>& points, double threshold)
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

inline RepairReport Repair(TestMesh& grid, const RepairParameters& parameters,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  return RepairCells(grid.Mesh, grid.Original.data(), grid.Points.data(), grid.Kinds.data(),
    parameters, parallelFor);
}

} // namespace dgmf_test

#endif
