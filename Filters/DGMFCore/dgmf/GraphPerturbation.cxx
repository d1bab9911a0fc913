#include "dgmf/GraphPerturbation.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>

namespace dgmf
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// splitmix64: a well-mixed 64-bit hash.
std::uint64_t Mix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

/// A hash of the point's coordinates rounded to a grid of spacing `cell` from `origin`
/// (PerturbPoints).
std::uint64_t HashPoint(const double* p, int dimension, const double* origin, double cell)
{
  std::uint64_t h = 0x12345678ull;
  for (int c = 0; c < dimension; ++c)
  {
    // To the nearest grid point: a mesh's round values (i / 8 of its size) lie on grid points,
    // far from the half-way lines where round-off could change the hash.
    const double q = std::floor((p[c] - origin[c]) / cell + 0.5);
    h = Mix(h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(q)));
  }
  return h;
}

/// Uniform in [-1, 1] from a hash.
double Signed(std::uint64_t h)
{
  return 2.0 * static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0) - 1.0;
}

/// Distance from each distinct point to its nearest distinct neighbour (CGAL kd-tree).
template <int Dimension>
std::vector<double> NearestDistances(const std::vector<std::array<double, 3>>& unique)
{
  using Point = typename std::conditional<Dimension == 2, Kernel::Point_2, Kernel::Point_3>::type;
  using Traits = typename std::conditional<Dimension == 2, CGAL::Search_traits_2<Kernel>,
    CGAL::Search_traits_3<Kernel>>::type;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  std::vector<Point> points;
  points.reserve(unique.size());
  for (const auto& p : unique)
  {
    if constexpr (Dimension == 2)
    {
      points.emplace_back(p[0], p[1]);
    }
    else
    {
      points.emplace_back(p[0], p[1], p[2]);
    }
  }
  typename Search::Tree tree(points.begin(), points.end());
  std::vector<double> distance(points.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    Search search(tree, points[i], 2);
    for (auto it = search.begin(); it != search.end(); ++it)
    {
      if (it->second > 0.0)
      {
        distance[i] = std::sqrt(it->second);
      }
    }
  }
  return distance;
}
} // namespace

std::vector<double> PerturbPoints(
  int dimension, const double* xyz, std::size_t count, double relative)
{
  std::vector<double> moved(3 * count);
  if (count == 0)
  {
    return moved;
  }
  // Distinct points, in lexicographic order.
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](std::size_t a, std::size_t b)
  {
    return std::lexicographical_compare(
      xyz + 3 * a, xyz + 3 * a + dimension, xyz + 3 * b, xyz + 3 * b + dimension);
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::array<double, 3>> unique;
  unique.reserve(count); // no regrowth (each new block of memory is faulted in again)
  std::vector<std::size_t> uniqueOf(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t i = order[k];
    if (unique.empty() || less(order[k - 1], i))
    {
      unique.push_back({ xyz[3 * i], xyz[3 * i + 1], dimension == 3 ? xyz[3 * i + 2] : 0.0 });
    }
    uniqueOf[i] = unique.size() - 1;
  }
  const std::vector<double> nearest =
    dimension == 2 ? NearestDistances<2>(unique) : NearestDistances<3>(unique);
  // The grid the directions are hashed on: 2^-33 of the bounding box (about 1e-10), far above
  // round-off and far below any mesh spacing (coordinates are finite: ValidateProblem).
  double origin[3] = { unique[0][0], unique[0][1], unique[0][2] },
         top[3] = { origin[0], origin[1], origin[2] };
  for (const auto& p : unique)
  {
    for (int c = 0; c < 3; ++c)
    {
      origin[c] = std::min(origin[c], p[c]);
      top[c] = std::max(top[c], p[c]);
    }
  }
  double size = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    size = std::max(size, top[c] - origin[c]);
  }
  const double cell = size > 0.0 && std::isfinite(size) ? std::ldexp(size, -33) : 1.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t u = uniqueOf[i];
    const double step = relative * nearest[u];
    std::uint64_t h = HashPoint(unique[u].data(), dimension, origin, cell);
    for (int c = 0; c < 3; ++c)
    {
      h = Mix(h);
      moved[3 * i + c] = unique[u][c] + (c < dimension ? step * Signed(h) : 0.0);
    }
  }
  return moved;
}

bool SpansDimension(int dimension, const double* xyz, std::size_t count)
{
  if (dimension == 2)
  {
    auto point = [&](std::size_t i) { return Kernel::Point_2(xyz[3 * i], xyz[3 * i + 1]); };
    std::size_t second = 1;
    while (second < count && point(second) == point(0))
    {
      ++second;
    }
    for (std::size_t i = second + 1; i < count; ++i)
    {
      if (CGAL::orientation(point(0), point(second), point(i)) != CGAL::COLLINEAR)
      {
        return true;
      }
    }
    return false;
  }
  auto point = [&](std::size_t i)
  { return Kernel::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
  std::size_t second = 1;
  while (second < count && point(second) == point(0))
  {
    ++second;
  }
  std::size_t third = second + 1;
  while (third < count && CGAL::collinear(point(0), point(second), point(third)))
  {
    ++third;
  }
  for (std::size_t i = third + 1; i < count; ++i)
  {
    if (CGAL::orientation(point(0), point(second), point(third), point(i)) != CGAL::COPLANAR)
    {
      return true;
    }
  }
  return false;
}

} // namespace dgmf
