#include "dgmf/LocationOrder.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dgmf
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Grid = DelaunayGraph::SeedGridGeometry;

/// The seed grid cell (i, j, k) of a point, clamped to the grid.
struct GridCell
{
  std::int64_t Index[3] = { 0, 0, 0 };

  GridCell(const Grid& grid, const double* x, int dimension)
  {
    for (int c = 0; c < dimension; ++c)
    {
      const double along = std::clamp((x[c] - grid.Origin[c]) * grid.InverseCellSize, 0.0,
        static_cast<double>(grid.Cells[c]) - 1e-9);
      this->Index[c] = static_cast<std::int64_t>(along);
    }
  }
};
} // namespace

std::vector<std::uint32_t> HilbertRanks(const std::int64_t cells[3], int dimension)
{
  const auto total = static_cast<std::size_t>(cells[0] * cells[1] * cells[2]);
  std::vector<std::size_t> byCurve(total);
  std::iota(byCurve.begin(), byCurve.end(), std::size_t{ 0 });
  auto coordinate = [&](std::size_t c, int axis)
  {
    const auto index = static_cast<std::int64_t>(c);
    const std::int64_t along = axis == 0 ? index % cells[0]
      : axis == 1                        ? (index / cells[0]) % cells[1]
                                         : index / (cells[0] * cells[1]);
    return static_cast<double>(along);
  };
  if (dimension == 2)
  {
    std::vector<Kernel::Point_2> centres;
    centres.reserve(total);
    for (std::size_t c = 0; c < total; ++c)
    {
      centres.emplace_back(coordinate(c, 0), coordinate(c, 1));
    }
    using Traits = CGAL::Spatial_sort_traits_adapter_2<Kernel,
      CGAL::Pointer_property_map<Kernel::Point_2>::type>;
    CGAL::hilbert_sort(byCurve.begin(), byCurve.end(),
      Traits(CGAL::make_property_map(centres.data())), CGAL::Hilbert_sort_middle_policy());
  }
  else
  {
    std::vector<Kernel::Point_3> centres;
    centres.reserve(total);
    for (std::size_t c = 0; c < total; ++c)
    {
      centres.emplace_back(coordinate(c, 0), coordinate(c, 1), coordinate(c, 2));
    }
    using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel,
      CGAL::Pointer_property_map<Kernel::Point_3>::type>;
    CGAL::hilbert_sort(byCurve.begin(), byCurve.end(),
      Traits(CGAL::make_property_map(centres.data())), CGAL::Hilbert_sort_middle_policy());
  }
  std::vector<std::uint32_t> rank(total);
  for (std::size_t r = 0; r < total; ++r)
  {
    rank[byCurve[r]] = static_cast<std::uint32_t>(r);
  }
  return rank;
}

bool IsNumberingCoherent(const DelaunayGraph& graph, const double* points, const NodeKind* kinds,
  std::size_t numberOfNodes)
{
  const Grid grid = graph.GetSeedGridGeometry();
  const int dimension = graph.GetDimension();
  const std::size_t step = std::max<std::size_t>(1, numberOfNodes / CoherenceSamples);
  std::size_t pairs = 0, near = 0;
  for (std::size_t i = 0; i + 1 < numberOfNodes; i += step)
  {
    if (IsBoundary(kinds[i]) || IsBoundary(kinds[i + 1]))
    {
      continue;
    }
    const GridCell a(grid, points + 3 * i, dimension);
    const GridCell b(grid, points + 3 * (i + 1), dimension);
    ++pairs;
    bool adjacent = true;
    for (int c = 0; c < 3; ++c)
    {
      adjacent = adjacent && std::abs(a.Index[c] - b.Index[c]) <= 1;
    }
    near += adjacent ? 1 : 0;
  }
  return 2 * near >= pairs;
}

} // namespace dgmf
