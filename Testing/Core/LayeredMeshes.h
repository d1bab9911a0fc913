// Meshes and checks shared by the location tests: a small layered sphere-in-box mesh, a
// two-thread ParallelFor, and the check that two mappings agree bit for bit and are right.
#ifndef dgmftest_LayeredMeshes_h
#define dgmftest_LayeredMeshes_h

#include "dgmf/DelaunayMapping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

namespace dgmftest
{
/// A small version of the benchmark's mesh: a sphere in a box, hexahedra in layers, numbered
/// layer by layer (the surface grid of an a^3 box; the first layer moving, the last static).
struct LayeredMesh
{
  std::vector<double> Points;
  std::vector<dgmf::NodeKind> Kinds;
  std::vector<std::vector<std::int64_t>> Cells;
  std::size_t NodesPerLayer = 0;
};

inline LayeredMesh MakeLayeredMesh(int a, int layers)
{
  LayeredMesh mesh;
  std::vector<int> index(static_cast<std::size_t>(a * a * a), -1);
  std::vector<std::array<double, 3>> unit;
  auto lattice = [a](int i, int j, int k) { return static_cast<std::size_t>((k * a + j) * a + i); };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int v = 0; v < a; ++v)
        for (int u = 0; u < a; ++u)
        {
          int ijk[3];
          ijk[axis] = side ? a - 1 : 0;
          ijk[(axis + 1) % 3] = u;
          ijk[(axis + 2) % 3] = v;
          int& id = index[lattice(ijk[0], ijk[1], ijk[2])];
          if (id < 0)
          {
            id = static_cast<int>(unit.size());
            unit.push_back({ 2.0 * ijk[0] / (a - 1) - 1, 2.0 * ijk[1] / (a - 1) - 1,
              2.0 * ijk[2] / (a - 1) - 1 });
          }
        }
  const std::size_t ns = unit.size();
  mesh.NodesPerLayer = ns;
  for (int l = 0; l < layers; ++l)
  {
    const double t = static_cast<double>(l) / (layers - 1);
    for (const auto& p : unit)
    {
      const double norm = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (int c = 0; c < 3; ++c)
      {
        mesh.Points.push_back(p[c] / norm + t * (10.0 * p[c] - p[c] / norm));
      }
      mesh.Kinds.push_back(l == 0 ? dgmf::NodeKind::MovingBoundary
          : l == layers - 1       ? dgmf::NodeKind::StaticBoundary
                                  : dgmf::NodeKind::Interior);
    }
  }
  // Hexahedra on the faces z = -1 (side 0 of axis 2), between consecutive layers.
  for (int l = 0; l + 1 < layers; ++l)
    for (int j = 0; j + 1 < a; ++j)
      for (int i = 0; i + 1 < a; ++i)
      {
        const std::int64_t q[4] = { index[lattice(i, j, 0)], index[lattice(i + 1, j, 0)],
          index[lattice(i + 1, j + 1, 0)], index[lattice(i, j + 1, 0)] };
        std::vector<std::int64_t> hex;
        for (int layer : { l, l + 1 })
          for (std::int64_t id : q)
            hex.push_back(id + layer * static_cast<std::int64_t>(ns));
        mesh.Cells.push_back(hex);
      }
  return mesh;
}

/// A ParallelFor on two threads that take the chunks in turn.
inline dgmf::ParallelFor TwoThreads()
{
  return [](std::size_t begin, std::size_t end, std::size_t grain, const dgmf::RangeFunction& body)
  {
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t)
    {
      threads.emplace_back(
        [&, t]
        {
          for (std::size_t b = begin + t * grain; b < end; b += 2 * grain)
          {
            body(b, std::min(end, b + grain));
          }
        });
    }
    for (std::thread& thread : threads)
    {
      thread.join();
    }
  };
}
/// The same elements and weights, bit for bit, with 1 and 2 threads; every interior node's
/// weights are non-negative and reproduce it (the element found is right). In 2D the graph's
/// elements are triangles with 3 weights, and z is not compared.
inline void ExpectSameAndRightLocations(
  const dgmf::DelaunayMapping& one, const dgmf::DelaunayMapping& two, const double* points)
{
  const dgmf::DelaunayGraph& graph = one.GetGraph();
  const int dimension = graph.GetDimension();
  for (std::size_t i = 0; i < one.GetNumberOfNodes(); ++i)
  {
    ASSERT_EQ(one.GetElementOfNode(i), two.GetElementOfNode(i)) << "node " << i;
    ASSERT_EQ(
      std::memcmp(one.GetWeights(i), two.GetWeights(i), (dimension + 1) * sizeof(double)), 0)
      << "node " << i;
    if (one.IsBoundaryNode(i))
      continue;
    const std::int32_t* v = graph.GetElement(one.GetElementOfNode(i));
    for (int c = 0; c < dimension; ++c)
    {
      double x = 0.0;
      for (int k = 0; k <= dimension; ++k)
      {
        ASSERT_GE(one.GetWeights(i)[k], 0.0);
        x += one.GetWeights(i)[k] * graph.GetVertexPosition(v[k])[c];
      }
      // Weights within 1e-12 of 0 are clamped; elements are ~10 long.
      ASSERT_NEAR(x, points[3 * i + c], 1e-10) << "node " << i;
    }
  }
}
} // namespace dgmftest

#endif
