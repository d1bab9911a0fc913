#include "dgmf/NumberingCoherence.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

namespace dgmf
{
namespace
{
/// The seed grid cell (i, j, k) of a point: DelaunayGraph::GetSeedCell's, clamped to the grid.
std::array<std::int64_t, 3> SeedCellOf(
  const DelaunayGraph& graph, const DelaunayGraph::SeedGridGeometry& grid, const double* x)
{
  std::int64_t index = static_cast<std::int64_t>(graph.GetSeedCell(x));
  std::array<std::int64_t, 3> cell{};
  for (int c = 0; c < 3; ++c)
  {
    cell[c] = index % grid.Cells[c];
    index /= grid.Cells[c];
  }
  return cell;
}
} // namespace

bool IsNumberingCoherent(const DelaunayGraph& graph, const double* points, const NodeKind* kinds,
  std::size_t numberOfNodes)
{
  const DelaunayGraph::SeedGridGeometry grid = graph.GetSeedGridGeometry();
  const std::size_t step = std::max<std::size_t>(1, numberOfNodes / CoherenceSamples);
  std::size_t pairs = 0, near = 0;
  for (std::size_t i = 0; i + 1 < numberOfNodes; i += step)
  {
    if (IsBoundary(kinds[i]) || IsBoundary(kinds[i + 1]))
    {
      continue;
    }
    const std::array<std::int64_t, 3> a = SeedCellOf(graph, grid, points + 3 * i);
    const std::array<std::int64_t, 3> b = SeedCellOf(graph, grid, points + 3 * (i + 1));
    ++pairs;
    bool adjacent = true;
    for (int c = 0; c < 3; ++c)
    {
      adjacent = adjacent && std::abs(a[c] - b[c]) <= 1;
    }
    near += adjacent ? 1 : 0;
  }
  return 2 * near >= pairs;
}

} // namespace dgmf
