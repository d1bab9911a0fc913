#include "dgmf/NodeLocation.h"

#include "dgmf/Simd.h"

#include <algorithm>

namespace dgmf
{
namespace
{
/// Interleaved walks per block: enough to keep several cache misses in flight.
constexpr std::size_t Lanes = 16;

/// How many nodes ahead of a run's current node its coordinates and outputs are prefetched.
constexpr std::size_t PrefetchNodes = 4;

/// Steps of a walk from the stride neighbour's element before it starts again from the previous
/// node's element.
constexpr int StrideWalkSteps = 3;

/// Steps of a walk from the previous node's element before it restarts from the seed grid.
constexpr int ShortWalkSteps = 16;

/// A block stops using the stride hint when its score (+1 per node found from the stride
/// neighbour, -2 per walk from it that failed) falls to -StrideGiveUp: when it fails more than a
/// third of the time.
constexpr int StrideGiveUp = 64;

/// Where the current walk started.
enum class Start : std::uint8_t
{
  Stride,   ///< the element of the node `stride` before
  Previous, ///< the element of the run's previous node
  Seed,     ///< the graph's seed grid
  Grid      ///< the caller's start element (LocationStartGrid)
};

/// The state of one run of consecutive nodes.
struct Lane
{
  std::size_t Node;      ///< node being located
  std::size_t End;       ///< end of the run
  std::int32_t Element;  ///< current element of the walk
  std::int32_t Previous; ///< element of the run's previous node (-1 before the first)
  int Steps;             ///< steps taken by the current walk
  Start From;            ///< where the current walk started
  double P[3];           ///< the node's coordinates
};
} // namespace

NodeLocationCounts LocateNodes(const DelaunayGraph& graph, const double* points,
  const NodeKind* kinds, std::size_t begin, std::size_t end, std::int32_t* nodeElement,
  double* weights, std::size_t stride, std::size_t locatedBefore, const std::int32_t* startElements)
{
  const int dimension = graph.GetDimension();
  const int n = dimension + 1;
  NodeLocationCounts counts;
  int strideScore = 0;

  auto nextInterior = [kinds](std::size_t i, std::size_t runEnd)
  {
    while (i < runEnd && IsBoundary(kinds[i]))
    {
      ++i;
    }
    return i;
  };
  auto startFromSeed = [&](Lane& lane)
  {
    lane.Element = graph.GetSeedElement(lane.P);
    lane.From = Start::Seed;
    ++counts.Restarts;
  };
  // Starts the walk of the lane's current node from the best hint it has.
  auto startNode = [&](Lane& lane)
  {
    const double* x = points + 3 * lane.Node;
    lane.P[0] = x[0];
    lane.P[1] = x[1];
    lane.P[2] = dimension == 3 ? x[2] : 0.0;
    lane.Steps = 0;
    // The stride neighbour is usable when it is an interior node located before this block's
    // wave, or already located in this block (the runs of a block take turns in a fixed order,
    // so which ones are is deterministic); never a node another thread may be locating now.
    const std::size_t neighbour = lane.Node - stride;
    if (startElements != nullptr && startElements[lane.Node - begin] >= 0)
    {
      lane.Element = startElements[lane.Node - begin];
      lane.From = Start::Grid;
    }
    else if (stride > 0 && lane.Node >= stride && strideScore > -StrideGiveUp &&
      (neighbour < locatedBefore || neighbour >= begin) && nodeElement[neighbour] >= 0)
    {
      lane.Element = nodeElement[neighbour];
      lane.From = Start::Stride;
    }
    else if (lane.Previous >= 0)
    {
      lane.Element = lane.Previous;
      lane.From = Start::Previous;
    }
    else
    {
      startFromSeed(lane);
    }
    graph.PrefetchElement(lane.Element);
  };
  // Stores the node's location and moves the lane to its next node (Node == End when the run is
  // done).
  auto finish = [&](Lane& lane, std::int32_t element, const double* w, bool outside)
  {
    nodeElement[lane.Node] = element;
    StoreWeights(w, n, weights + lane.Node * static_cast<std::size_t>(n));
    if (outside)
    {
      ++counts.Outside;
      counts.SlipOutside += kinds[lane.Node] == NodeKind::SlipBoundary ? 1 : 0;
    }
    strideScore += lane.From == Start::Stride ? 1 : 0;
    counts.StrideHits += lane.From == Start::Stride ? 1 : 0;
    lane.Previous = element;
    lane.Node = nextInterior(lane.Node + 1, lane.End);
    if (lane.Node < lane.End)
    {
      // The run's next nodes are read and written a few walks from now: start loading them.
      const std::size_t ahead = std::min(lane.Node + PrefetchNodes, lane.End - 1);
      simd::Prefetch(points + 3 * ahead);
      simd::PrefetchForWrite(weights + ahead * static_cast<std::size_t>(n));
      if (startElements != nullptr && startElements[ahead - begin] >= 0)
      {
        graph.PrefetchElement(startElements[ahead - begin]);
      }
      if (stride > 0 && ahead >= stride)
      {
        simd::Prefetch(nodeElement + (ahead - stride));
      }
      startNode(lane);
    }
  };

  // The runs of a range take turns. A stride longer than a run but shorter than the block cuts
  // the block into ranges of `stride` nodes, located one after the other: every node's stride
  // neighbour is then in an earlier range.
  auto locateRange = [&](std::size_t rangeBegin, std::size_t rangeEnd)
  {
    Lane lanes[Lanes];
    std::size_t active = 0;
    const std::size_t perLane = (rangeEnd - rangeBegin + Lanes - 1) / Lanes;
    for (std::size_t j = 0; j < Lanes; ++j)
    {
      Lane& lane = lanes[active];
      const std::size_t first = std::min(rangeEnd, rangeBegin + j * perLane);
      lane.End = std::min(rangeEnd, first + perLane);
      lane.Node = nextInterior(first, lane.End);
      lane.Previous = -1;
      if (lane.Node < lane.End)
      {
        startNode(lane);
        ++active;
      }
    }

    while (active > 0)
    {
      // One step of every lane. First the arithmetic, without branches, so the processor works on
      // the lanes' (independent) element loads and barycentric coordinates at the same time...
      double w[Lanes][4];
      double total[Lanes];
      bool inside[Lanes];
      std::int32_t next[Lanes];
      std::size_t j = 0;
      if (dimension == 3)
      {
        for (; j + 1 < active; j += 2)
        {
          SubVolumesPair3(graph.GetWalkRecord(lanes[j].Element),
            graph.GetWalkRecord(lanes[j + 1].Element), lanes[j].P, lanes[j + 1].P, w[j], w[j + 1],
            total[j], total[j + 1]);
        }
      }
      for (; j < active; ++j)
      {
        total[j] = SubVolumes(graph.GetWalkRecord(lanes[j].Element), dimension, lanes[j].P, w[j]);
      }
      for (j = 0; j < active; ++j)
      {
        inside[j] = IsInside(w[j], total[j], dimension);
        next[j] =
          graph.GetWalkRecord(lanes[j].Element).Neighbors[MostNegativeWeight(w[j], dimension)];
      }
      // ... then the decisions.
      for (std::size_t k = 0; k < active; ++k)
      {
        Lane& lane = lanes[k];
        if (inside[k])
        {
          // Normalised, with round-off negatives (>= -WeightTolerance of the total) set to 0: one
          // division (the sum is positive: the point is inside an element of positive volume).
          // Four values in registers (a fourth of 0 in 2D adds nothing to the sum): written back
          // to w and read again, the multiplications would wait for the stores.
          double clamped[4];
          double sum = 0.0;
          for (int c = 0; c < 4; ++c)
          {
            clamped[c] = c < n && w[k][c] > 0.0 ? w[k][c] : 0.0;
            sum += clamped[c];
          }
          const double inv = 1.0 / sum;
          double normalised[4];
          for (int c = 0; c < 4; ++c)
          {
            normalised[c] = clamped[c] * inv;
          }
          finish(lane, lane.Element, normalised, false);
          continue;
        }
        // Visibility walk: cross the face opposite the most negative coordinate.
        ++lane.Steps;
        const int limit = lane.From == Start::Stride ? StrideWalkSteps
          : lane.From == Start::Previous             ? ShortWalkSteps
                                                     : DelaunayGraph::MaximumWalkSteps;
        if (next[k] >= 0 && lane.Steps <= limit)
        {
          ++counts.Steps;
          lane.Element = next[k];
          graph.PrefetchElement(next[k]);
        }
        else if (lane.From == Start::Stride)
        {
          // The stride neighbour was not near: the previous node's element, or the seed grid.
          strideScore -= 2;
          lane.Steps = 0;
          if (lane.Previous >= 0)
          {
            lane.Element = lane.Previous;
            lane.From = Start::Previous;
          }
          else
          {
            startFromSeed(lane);
          }
          graph.PrefetchElement(lane.Element);
        }
        else if (lane.From == Start::Previous)
        {
          lane.Steps = 0;
          startFromSeed(lane);
          graph.PrefetchElement(lane.Element);
        }
        else
        {
          // Leaving the hull, or no end in sight: CGAL decides exactly.
          const DelaunayGraph::Location location = graph.LocateExactly(lane.P, lane.Element);
          finish(lane, location.Element, location.Weights, location.Outside);
        }
      }
      // Drop the lanes whose run is done.
      std::size_t kept = 0;
      for (std::size_t l = 0; l < active; ++l)
      {
        if (lanes[l].Node < lanes[l].End)
        {
          lanes[kept++] = lanes[l];
        }
      }
      active = kept;
    }
  };
  const std::size_t length = end - begin;
  const std::size_t range =
    stride > (length + Lanes - 1) / Lanes && stride < length ? stride : length;
  for (std::size_t first = begin; first < end;)
  {
    // Once the stride has failed the block, the rest is one range.
    const std::size_t last = strideScore > -StrideGiveUp ? std::min(end, first + range) : end;
    locateRange(first, last);
    first = last;
  }
  return counts;
}

} // namespace dgmf
