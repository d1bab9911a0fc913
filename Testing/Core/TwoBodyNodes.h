/**
 * @file TwoBodyNodes.h
 * @brief Node sets with two moving bodies for the multi-body tests: boundary nodes marked with a
 * kind and a body id, interior nodes random but reproducible and ordered along a sweep.
 */
#ifndef dgmf_test_TwoBodyNodes_h
#define dgmf_test_TwoBodyNodes_h

#include "SyntheticNodes.h"

#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace dgmf_test
{

/// The Delaunay mapping of a node set (its graph from its boundary nodes, every node located).
inline dgmf::DelaunayMapping Map(
  const NodeSet& set, const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  return dgmf::DelaunayMapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), parallelFor);
}

/// A node set with one body id per node (0: not on a body; 1, 2: the body).
struct BodyNodeSet : NodeSet
{
  std::vector<std::int32_t> BodyIds;
  double Centers[2][3] = { { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 } }; ///< centre of body 1 and 2

  void AddNode(double x, double y, double z, dgmf::NodeKind kind, std::int32_t body)
  {
    this->Add(x, y, z, kind);
    this->BodyIds.push_back(body);
  }
};

/**
 * Two circles of radius `radius` centred at (-distance, 0) (body 1) and (distance, 0) (body 2),
 * `circle` moving nodes each, in the square [-5, 5]^2 (static, `side` nodes per side), with
 * `interior` nodes outside 1.05 radius of both centres.
 */
inline BodyNodeSet TwoCirclesInSquare(int circle = 48, int side = 20, int interior = 3000,
  double distance = 2.5, double radius = 0.8, unsigned seed = 3)
{
  BodyNodeSet set;
  set.Dimension = 2;
  const double pi = 3.14159265358979323846;
  for (int body = 0; body < 2; ++body)
  {
    const double cx = body == 0 ? -distance : distance;
    set.Centers[body][0] = cx;
    for (int k = 0; k < circle; ++k)
    {
      const double a = 2 * pi * k / circle;
      set.AddNode(cx + radius * std::cos(a), radius * std::sin(a), 0.0,
        dgmf::NodeKind::MovingBoundary, body + 1);
    }
  }
  for (int k = 0; k < side; ++k)
  {
    const double t = -5.0 + 10.0 * k / side;
    set.AddNode(t, -5.0, 0.0, dgmf::NodeKind::StaticBoundary, 0);
    set.AddNode(5.0, t, 0.0, dgmf::NodeKind::StaticBoundary, 0);
    set.AddNode(-t, 5.0, 0.0, dgmf::NodeKind::StaticBoundary, 0);
    set.AddNode(-5.0, -t, 0.0, dgmf::NodeKind::StaticBoundary, 0);
  }
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-4.99, 4.99);
  const double keep = 1.05 * radius;
  std::vector<std::pair<double, double>> inside;
  while (static_cast<int>(inside.size()) < interior)
  {
    const double x = coordinate(random);
    const double y = coordinate(random);
    if (std::hypot(x + distance, y) > keep && std::hypot(x - distance, y) > keep)
    {
      inside.emplace_back(x, y);
    }
  }
  std::sort(inside.begin(), inside.end()); // sweep order, like a mesh numbering
  for (const auto& p : inside)
  {
    set.AddNode(p.first, p.second, 0.0, dgmf::NodeKind::Interior, 0);
  }
  return set;
}

/**
 * Two spheres of radius 0.8 centred at (-2.5, 0, 0) (body 1) and (2.5, 0, 0) (body 2) in the cube
 * [-5, 5]^3 (static), with `interior` nodes outside 1.1 radius of both centres.
 */
inline BodyNodeSet TwoSpheresInBox(int interior = 3000, unsigned seed = 4)
{
  BodyNodeSet set;
  set.Dimension = 3;
  const double pi = 3.14159265358979323846;
  const double radius = 0.8;
  for (int body = 0; body < 2; ++body)
  {
    const double cx = body == 0 ? -2.5 : 2.5;
    set.Centers[body][0] = cx;
    const std::int32_t id = body + 1;
    set.AddNode(cx, 0, radius, dgmf::NodeKind::MovingBoundary, id);
    set.AddNode(cx, 0, -radius, dgmf::NodeKind::MovingBoundary, id);
    for (int i = 1; i < 8; ++i)
    {
      const double theta = pi * i / 8;
      for (int j = 0; j < 16; ++j)
      {
        const double phi = 2 * pi * j / 16;
        set.AddNode(cx + radius * std::sin(theta) * std::cos(phi),
          radius * std::sin(theta) * std::sin(phi), radius * std::cos(theta),
          dgmf::NodeKind::MovingBoundary, id);
      }
    }
  }
  const int m = 8;
  for (int i = 0; i <= m; ++i)
  {
    for (int j = 0; j <= m; ++j)
    {
      for (int k = 0; k <= m; ++k)
      {
        if (i == 0 || i == m || j == 0 || j == m || k == 0 || k == m)
        {
          set.AddNode(-5.0 + 10.0 * i / m, -5.0 + 10.0 * j / m, -5.0 + 10.0 * k / m,
            dgmf::NodeKind::StaticBoundary, 0);
        }
      }
    }
  }
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-4.99, 4.99);
  const double keep = 1.1 * radius;
  std::vector<std::array<double, 3>> inside;
  while (static_cast<int>(inside.size()) < interior)
  {
    const double x = coordinate(random);
    const double y = coordinate(random);
    const double z = coordinate(random);
    if (std::sqrt((x + 2.5) * (x + 2.5) + y * y + z * z) > keep &&
      std::sqrt((x - 2.5) * (x - 2.5) + y * y + z * z) > keep)
    {
      inside.push_back({ x, y, z });
    }
  }
  std::sort(inside.begin(), inside.end());
  for (const auto& p : inside)
  {
    set.AddNode(p[0], p[1], p[2], dgmf::NodeKind::Interior, 0);
  }
  return set;
}

} // namespace dgmf_test

#endif
