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

/// Sub-cells per axis of a seed cell.
constexpr std::int64_t SubCells = 8;

/// The layout of a node's sort key: id in bits 0-30, sub-cell rank in 31-39, cell rank above.
constexpr int SubShift = 31;
constexpr int RankShift = 40;
constexpr int MaximumRankBits = 64 - RankShift;
constexpr std::uint64_t NodeMask = (std::uint64_t{ 1 } << SubShift) - 1;
/// Bits sorted per pass of the radix sort.
constexpr int DigitBits = 13;
/// Nodes per block of the parallel passes.
constexpr std::size_t KeyBlock = 4096;

/// The rank of every cell of an nx x ny x nz lattice (index i + nx (j + ny k)) along CGAL's
/// Hilbert curve through the cells' centres.
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

/// Where a node lies in the seed grid: its cell (i, j, k) and, in units of sub-cells, its
/// position inside the cell (0 .. SubCells - 1 per axis). Points outside the grid are clamped.
struct GridPosition
{
  std::int64_t Cell[3] = { 0, 0, 0 };
  std::int64_t Sub[3] = { 0, 0, 0 };

  GridPosition(const Grid& grid, const double* x, int dimension)
  {
    for (int c = 0; c < dimension; ++c)
    {
      const double along = std::clamp((x[c] - grid.Origin[c]) * grid.InverseCellSize, 0.0,
        static_cast<double>(grid.Cells[c]) - 1e-9);
      this->Cell[c] = static_cast<std::int64_t>(along);
      this->Sub[c] = std::min<std::int64_t>(
        static_cast<std::int64_t>((along - static_cast<double>(this->Cell[c])) * SubCells),
        SubCells - 1);
    }
  }

  std::size_t CellIndex(const Grid& grid) const
  {
    return static_cast<std::size_t>(
      this->Cell[0] + grid.Cells[0] * (this->Cell[1] + grid.Cells[1] * this->Cell[2]));
  }
  std::size_t SubIndex() const
  {
    return static_cast<std::size_t>(
      this->Sub[0] + SubCells * (this->Sub[1] + SubCells * this->Sub[2]));
  }
};

/**
 * Sorts `keys` by their bits [low, high), stably: an LSD radix sort in digits of up to DigitBits
 * bits (8,192 buckets: the writes stay within the caches). Each pass counts the digits of fixed
 * blocks of keys in parallel, then each block writes its keys from its own offsets, so the result
 * does not depend on the threads.
 */
void RadixSort(
  UninitializedVector<std::uint64_t>& keys, int low, int high, const ParallelFor& parallelFor)
{
  const std::size_t blocks =
    std::max<std::size_t>(1, std::min<std::size_t>(64, keys.size() / KeyBlock));
  const std::size_t perBlock = (keys.size() + blocks - 1) / blocks;
  // Not zeroed: every pass writes all of it (its pages are first touched there, on the threads).
  UninitializedVector<std::uint64_t> scratch(keys.size());
  std::vector<std::size_t> offsets;
  for (int first = low; first < high; first += DigitBits)
  {
    const int bits = std::min(DigitBits, high - first);
    const std::uint64_t mask = (std::uint64_t{ 1 } << bits) - 1;
    const std::size_t digits = std::size_t{ 1 } << bits;
    offsets.assign(
      blocks * digits, 0); // block b's count, then offset, of digit d: [b * digits + d]
    const auto forBlock = [&](std::size_t b, const auto& body)
    {
      const std::size_t end = std::min(keys.size(), (b + 1) * perBlock);
      for (std::size_t k = b * perBlock; k < end; ++k)
      {
        body(keys[k]);
      }
    };
    ForEachBlock(parallelFor, blocks,
      [&](std::size_t b)
      {
        std::size_t* count = offsets.data() + b * digits;
        forBlock(b, [&](std::uint64_t key) { ++count[(key >> first) & mask]; });
      });
    std::size_t total = 0;
    for (std::size_t d = 0; d < digits; ++d)
    {
      for (std::size_t b = 0; b < blocks; ++b)
      {
        const std::size_t count = offsets[b * digits + d];
        offsets[b * digits + d] = total;
        total += count;
      }
    }
    ForEachBlock(parallelFor, blocks,
      [&](std::size_t b)
      {
        std::size_t* next = offsets.data() + b * digits;
        forBlock(b, [&](std::uint64_t key) { scratch[next[(key >> first) & mask]++] = key; });
      });
    keys.swap(scratch);
  }
}
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
    const GridPosition a(grid, points + 3 * i, dimension);
    const GridPosition b(grid, points + 3 * (i + 1), dimension);
    ++pairs;
    bool adjacent = true;
    for (int c = 0; c < 3; ++c)
    {
      adjacent = adjacent && std::abs(a.Cell[c] - b.Cell[c]) <= 1;
    }
    near += adjacent ? 1 : 0;
  }
  return 2 * near >= pairs;
}

UninitializedVector<std::int32_t> SpatialLocationOrder(const DelaunayGraph& graph,
  const double* points, const NodeKind* kinds, std::size_t numberOfNodes,
  const ParallelFor& parallelFor)
{
  const Grid grid = graph.GetSeedGridGeometry();
  const int dimension = graph.GetDimension();
  // Each interior node as one 64-bit key: its cell's rank along the curve (bits 40 and up), its
  // sub-cell's rank (bits 31-39), its id (bits 0-30). Sorted by the ranks, stably, the nodes of a
  // sub-cell stay in increasing id: the keys carry the ids, so no pass reads a node's data in the
  // sorted (random) order.
  const std::vector<std::uint32_t> cellRank = HilbertRanks(grid.Cells, dimension);
  const std::int64_t sub[3] = { SubCells, SubCells, dimension == 3 ? SubCells : 1 };
  const std::vector<std::uint32_t> subRank = HilbertRanks(sub, dimension);
  int rankBits = 0;
  while ((std::size_t{ 1 } << rankBits) < cellRank.size())
  {
    ++rankBits;
  }
  // Beyond 2^24 cells (about 10 million boundary nodes) neighbouring ranks share a key.
  const int coarsen = std::max(0, rankBits - MaximumRankBits);
  rankBits -= coarsen;
  // The interior nodes of each fixed block counted, then each block's keys written from its
  // offset: one pass over the points, in parallel, whatever the threads.
  const std::size_t blocks = (numberOfNodes + KeyBlock - 1) / KeyBlock;
  std::vector<std::size_t> offsets(blocks + 1, 0);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t b)
    {
      const std::size_t end = std::min(numberOfNodes, (b + 1) * KeyBlock);
      std::size_t interior = 0;
      for (std::size_t i = b * KeyBlock; i < end; ++i)
      {
        interior += IsBoundary(kinds[i]) ? 0 : 1;
      }
      offsets[b + 1] = interior;
    });
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  UninitializedVector<std::uint64_t> keys(offsets.back()); // every key written below
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t b)
    {
      const std::size_t end = std::min(numberOfNodes, (b + 1) * KeyBlock);
      std::uint64_t* key = keys.data() + offsets[b];
      for (std::size_t i = b * KeyBlock; i < end; ++i)
      {
        if (!IsBoundary(kinds[i]))
        {
          const GridPosition position(grid, points + 3 * i, dimension);
          *key++ = static_cast<std::uint64_t>(cellRank[position.CellIndex(grid)] >> coarsen)
              << RankShift |
            static_cast<std::uint64_t>(subRank[position.SubIndex()]) << SubShift | i;
        }
      }
    });
  RadixSort(keys, SubShift, RankShift + rankBits, parallelFor);
  UninitializedVector<std::int32_t> order(keys.size());
  ForEachIndex(parallelFor, keys.size(), KeyBlock,
    [&](std::size_t k) { order[k] = static_cast<std::int32_t>(keys[k] & NodeMask); });
  return order;
}

} // namespace dgmf
