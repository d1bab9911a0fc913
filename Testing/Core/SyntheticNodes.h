/**
 * @file SyntheticNodes.h
 * @brief Node sets for the core tests: a body inside a box, boundary nodes marked, interior nodes
 * random but reproducible and ordered along a sweep (as a mesh generator would number them).
 */
#ifndef dgmf_test_SyntheticNodes_h
#define dgmf_test_SyntheticNodes_h

#include "dgmf/NodeKind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace dgmf_test
{

struct NodeSet
{
  int Dimension = 2;
  std::vector<double> Points; ///< 3 per node
  std::vector<dgmf::NodeKind> Kinds;

  std::size_t Size() const { return this->Kinds.size(); }
  void Add(double x, double y, double z, dgmf::NodeKind kind)
  {
    this->Points.push_back(x);
    this->Points.push_back(y);
    this->Points.push_back(z);
    this->Kinds.push_back(kind);
  }
};

/// Circle of radius 1 (moving, `circle` nodes) in the square [-5, 5]^2 (static), interior nodes
/// between.
inline NodeSet CircleInSquare(
  int circle = 64, int side = 20, int interior = 2000, unsigned seed = 1)
{
  NodeSet set;
  set.Dimension = 2;
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < circle; ++k)
  {
    const double a = 2 * pi * k / circle;
    set.Add(std::cos(a), std::sin(a), 0.0, dgmf::NodeKind::MovingBoundary);
  }
  for (int k = 0; k < side; ++k)
  {
    const double t = -5.0 + 10.0 * k / side;
    set.Add(t, -5.0, 0.0, dgmf::NodeKind::StaticBoundary);
    set.Add(5.0, t, 0.0, dgmf::NodeKind::StaticBoundary);
    set.Add(-t, 5.0, 0.0, dgmf::NodeKind::StaticBoundary);
    set.Add(-5.0, -t, 0.0, dgmf::NodeKind::StaticBoundary);
  }
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-4.99, 4.99);
  std::vector<std::pair<double, double>> inside;
  while (static_cast<int>(inside.size()) < interior)
  {
    const double x = coordinate(random);
    const double y = coordinate(random);
    if (x * x + y * y > 1.05 * 1.05)
    {
      inside.emplace_back(x, y);
    }
  }
  std::sort(inside.begin(), inside.end()); // sweep order, like a mesh numbering
  for (const auto& p : inside)
  {
    set.Add(p.first, p.second, 0.0, dgmf::NodeKind::Interior);
  }
  return set;
}

/// Sphere of radius 1 (moving) in the cube [-5, 5]^3 (static), interior nodes between.
inline NodeSet SphereInBox(int interior = 3000, unsigned seed = 2)
{
  NodeSet set;
  set.Dimension = 3;
  const double pi = 3.14159265358979323846;
  // Sphere: a latitude-longitude set without the duplicated poles.
  set.Add(0, 0, 1, dgmf::NodeKind::MovingBoundary);
  set.Add(0, 0, -1, dgmf::NodeKind::MovingBoundary);
  for (int i = 1; i < 10; ++i)
  {
    const double theta = pi * i / 10;
    for (int j = 0; j < 20; ++j)
    {
      const double phi = 2 * pi * j / 20;
      set.Add(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta),
        dgmf::NodeKind::MovingBoundary);
    }
  }
  // Box faces on a regular grid (coplanar and cospherical points on purpose: real farfields).
  const int m = 8;
  for (int i = 0; i <= m; ++i)
  {
    for (int j = 0; j <= m; ++j)
    {
      for (int k = 0; k <= m; ++k)
      {
        if (i == 0 || i == m || j == 0 || j == m || k == 0 || k == m)
        {
          set.Add(-5.0 + 10.0 * i / m, -5.0 + 10.0 * j / m, -5.0 + 10.0 * k / m,
            dgmf::NodeKind::StaticBoundary);
        }
      }
    }
  }
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-4.99, 4.99);
  std::vector<std::array<double, 3>> inside;
  while (static_cast<int>(inside.size()) < interior)
  {
    const double x = coordinate(random);
    const double y = coordinate(random);
    const double z = coordinate(random);
    if (x * x + y * y + z * z > 1.1 * 1.1)
    {
      inside.push_back({ x, y, z });
    }
  }
  std::sort(inside.begin(), inside.end());
  for (const auto& p : inside)
  {
    set.Add(p[0], p[1], p[2], dgmf::NodeKind::Interior);
  }
  return set;
}

} // namespace dgmf_test

#endif
