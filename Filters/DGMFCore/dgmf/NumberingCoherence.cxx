#include "dgmf/NumberingCoherence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dgmf
{
namespace
{
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
