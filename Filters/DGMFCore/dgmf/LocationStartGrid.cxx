#include "dgmf/LocationStartGrid.h"

#include "dgmf/NodeLocation.h"
#include "dgmf/Simd.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dgmf
{
namespace
{
/// Nodes per chunk of the count of nodes per cell (each chunk counts into its own array).
constexpr std::size_t CountChunk = std::size_t{ 1 } << 20;
/// One node in CountStride is counted: the sides need only the nodes' density.
constexpr std::size_t CountStride = 8;
/// Chunks at most: their count arrays are summed serially.
constexpr std::size_t MaximumCountChunks = 16;
/// Sub-cells per block of the centres' location.
constexpr std::size_t CentreBlock = 4096;
} // namespace

LocationStartGrid::LocationStartGrid(const DelaunayGraph& graph, const double* points,
  const NodeKind* kinds, std::size_t numberOfNodes, const ParallelFor& parallelFor)
  : Dimension(graph.GetDimension())
  , Geometry(graph.GetSeedGridGeometry())
{
  const DelaunayGraph::SeedGridGeometry& grid = this->Geometry;
  const auto cells = static_cast<std::size_t>(grid.Cells[0] * grid.Cells[1] * grid.Cells[2]);
  for (int c = 0; c < 3; ++c)
  {
    this->Below[c] = std::nextafter(static_cast<double>(grid.Cells[c]), 0.0);
  }

  // The interior nodes of each seed cell, counted in fixed chunks of the numbering.
  const std::size_t chunks =
    std::clamp<std::size_t>((numberOfNodes + CountChunk - 1) / CountChunk, 1, MaximumCountChunks);
  const std::size_t perChunk = (numberOfNodes + chunks - 1) / chunks;
  std::vector<std::vector<std::uint32_t>> counts(chunks);
  ForEachBlock(parallelFor, chunks,
    [&](std::size_t chunk)
    {
      std::vector<std::uint32_t>& count = counts[chunk];
      count.assign(cells, 0);
      const std::size_t end = std::min(numberOfNodes, (chunk + 1) * perChunk);
      for (std::size_t i = chunk * perChunk; i < end; i += CountStride)
      {
        if (!IsBoundary(kinds[i]))
        {
          ++count[graph.GetSeedCell(points + 3 * i)];
        }
      }
    });

  // Each cell's side, and its sub-cells' place: the cells in their own (row) order.
  this->Side.resize(cells);
  for (std::size_t c = 0; c < cells; ++c)
  {
    double nodes = 0.0;
    for (const std::vector<std::uint32_t>& count : counts)
    {
      nodes += CountStride * count[c];
    }
    const double side = std::ceil(std::pow(nodes / NodesPerSubCell, 1.0 / this->Dimension));
    this->Side[c] =
      static_cast<std::uint8_t>(std::clamp(side, 1.0, static_cast<double>(MaximumSide)));
  }
  counts = std::vector<std::vector<std::uint32_t>>();
  this->FirstSubCell.assign(cells + 1, 0);
  for (std::size_t cell = 0; cell < cells; ++cell)
  {
    std::size_t subCells = 1;
    for (int c = 0; c < this->Dimension; ++c)
    {
      subCells *= this->Side[cell];
    }
    if (this->FirstSubCell[cell] + subCells > std::numeric_limits<std::uint32_t>::max())
    {
      throw std::length_error("LocationStartGrid: too many sub-cells");
    }
    this->FirstSubCell[cell + 1] = static_cast<std::uint32_t>(this->FirstSubCell[cell] + subCells);
  }

  // The sub-cells' centres located in fixed blocks, each walk from the previous centre's element.
  this->Elements.resize(this->FirstSubCell.back());
  const std::size_t blocks = (this->Elements.size() + CentreBlock - 1) / CentreBlock;
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      const std::size_t begin = block * CentreBlock;
      const std::size_t count = std::min(this->Elements.size(), begin + CentreBlock) - begin;
      std::vector<double> centres(3 * count, 0.0);
      // The cell holding sub-cell `begin`, then its sub-cells in order.
      std::size_t owner = static_cast<std::size_t>(
        std::upper_bound(this->FirstSubCell.begin(), this->FirstSubCell.end(), begin) -
        this->FirstSubCell.begin() - 1);
      for (std::size_t k = 0; k < count; ++k)
      {
        while (begin + k >= this->FirstSubCell[owner + 1])
        {
          ++owner;
        }
        std::size_t cell = owner;
        const std::size_t side = this->Side[cell];
        std::size_t sub = begin + k - this->FirstSubCell[owner];
        for (int c = 0; c < this->Dimension; ++c)
        {
          const std::size_t along = cell % static_cast<std::size_t>(grid.Cells[c]);
          cell /= static_cast<std::size_t>(grid.Cells[c]);
          const std::size_t within = sub % side;
          sub /= side;
          // The grid reaches up to a cell beyond the graph's bounding box: centres there would be
          // outside the hull, each left to CGAL's exact location. They are moved onto the box.
          centres[3 * k + c] = std::clamp(grid.Origin[c] +
              (static_cast<double>(along) +
                (static_cast<double>(within) + 0.5) / static_cast<double>(side)) /
                grid.InverseCellSize,
            grid.Origin[c], grid.Upper[c]);
        }
      }
      const std::vector<NodeKind> interior(count, NodeKind::Interior);
      std::vector<double> weights(4 * count);
      std::int32_t* element = this->Elements.data() + begin;
      std::fill_n(element, count, std::numeric_limits<std::int32_t>::min());
      LocateNodes(graph, centres.data(), interior.data(), 0, count, element, weights.data());
      for (std::size_t k = 0; k < count; ++k)
      {
        // LocateNodes gives every centre an element (CGAL's, when a walk fails); a guard only.
        element[k] = element[k] >= 0 ? element[k] : graph.GetSeedElement(centres.data() + 3 * k);
      }
    });
}

void LocationStartGrid::GetStartElements(const double* points, const NodeKind* kinds,
  std::size_t begin, std::size_t end, std::int32_t* starts) const
{
  // Two stages: a node's sub-cell (from its coordinates, read in order) and a prefetch of its
  // entry; LookAhead nodes later, the entry itself.
  constexpr std::size_t LookAhead = 16;
  std::size_t subCell[LookAhead];
  const std::size_t count = end - begin;
  for (std::size_t k = 0; k < count + LookAhead; ++k)
  {
    if (k >= LookAhead)
    {
      const std::size_t j = k - LookAhead;
      starts[j] = IsBoundary(kinds[begin + j]) ? -1 : this->Elements[subCell[j % LookAhead]];
    }
    if (k < count)
    {
      const std::size_t cell = this->GetSubCell(points + 3 * (begin + k));
      subCell[k % LookAhead] = cell;
      simd::Prefetch(this->Elements.data() + cell);
    }
  }
}

std::size_t LocationStartGrid::GetMemorySize() const
{
  return this->FirstSubCell.capacity() * sizeof(std::uint32_t) +
    this->Side.capacity() * sizeof(std::uint8_t) + this->Elements.capacity() * sizeof(std::int32_t);
}

} // namespace dgmf
