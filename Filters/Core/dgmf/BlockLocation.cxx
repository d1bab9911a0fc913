#include "dgmf/BlockLocation.h"

#include <algorithm>

namespace dgmf
{
namespace
{
/// Interleaved walks per block: enough to keep several cache misses in flight.
constexpr std::size_t Lanes = 8;

/// How many nodes ahead of a run's current node its coordinates and outputs are prefetched.
constexpr std::size_t PrefetchNodes = 4;

/// Steps of a walk from the previous node's element before it restarts from the seed grid.
constexpr int ShortWalkSteps = 16;

/// The state of one run of consecutive nodes.
struct Lane
{
  std::size_t Node;     ///< node being located
  std::size_t End;      ///< end of the run
  std::int32_t Element; ///< current element of the walk
  int Steps;            ///< steps taken by the current walk
  bool FromSeed;        ///< the current walk started from the seed grid
  double P[3];          ///< the node's coordinates
};
} // namespace

BlockLocationCounts LocateBlock(const DelaunayGraph& graph, const double* points, const NodeKind* kinds,
  std::size_t begin, std::size_t end, std::int32_t* nodeElement, double* weights)
{
  const int dimension = graph.GetDimension();
  const int n = dimension + 1;
  BlockLocationCounts counts;

  auto nextInterior = [kinds](std::size_t i, std::size_t runEnd)
  {
    while (i < runEnd && IsBoundary(kinds[i]))
    {
      ++i;
    }
    return i;
  };
  auto loadPoint = [&](Lane& lane)
  {
    const double* x = points + 3 * lane.Node;
    lane.P[0] = x[0];
    lane.P[1] = x[1];
    lane.P[2] = dimension == 3 ? x[2] : 0.0;
  };
  auto startFromSeed = [&](Lane& lane)
  {
    lane.Element = graph.GetSeedElement(lane.P);
    lane.Steps = 0;
    lane.FromSeed = true;
    ++counts.Restarts;
    graph.PrefetchElement(lane.Element);
  };
  // Stores the node's location and moves the lane to its next node (Node == End when the run is done).
  auto finish = [&](Lane& lane, std::int32_t element, const double* w, bool outside)
  {
    nodeElement[lane.Node] = element;
    std::copy(w, w + n, weights + lane.Node * static_cast<std::size_t>(n));
    counts.Outside += outside ? 1 : 0;
    lane.Node = nextInterior(lane.Node + 1, lane.End);
    if (lane.Node < lane.End)
    {
      // The run's next nodes are read and written a few walks from now: start loading them.
      const std::size_t ahead = std::min(lane.Node + PrefetchNodes, lane.End - 1);
      __builtin_prefetch(points + 3 * ahead);
      __builtin_prefetch(weights + ahead * static_cast<std::size_t>(n), 1);
      loadPoint(lane);
      lane.Element = element;
      lane.Steps = 0;
      lane.FromSeed = false;
    }
  };

  Lane lanes[Lanes];
  std::size_t active = 0;
  const std::size_t perLane = (end - begin + Lanes - 1) / Lanes;
  for (std::size_t j = 0; j < Lanes; ++j)
  {
    Lane& lane = lanes[active];
    const std::size_t first = std::min(end, begin + j * perLane);
    lane.End = std::min(end, first + perLane);
    lane.Node = nextInterior(first, lane.End);
    if (lane.Node < lane.End)
    {
      // The run's next nodes are read and written a few walks from now: start loading them.
      const std::size_t ahead = std::min(lane.Node + PrefetchNodes, lane.End - 1);
      __builtin_prefetch(points + 3 * ahead);
      __builtin_prefetch(weights + ahead * static_cast<std::size_t>(n), 1);
      loadPoint(lane);
      startFromSeed(lane);
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
        SubVolumesPair3(graph.GetWalkRecord(lanes[j].Element), graph.GetWalkRecord(lanes[j + 1].Element),
          lanes[j].P, lanes[j + 1].P, w[j], w[j + 1], total[j], total[j + 1]);
      }
    }
    for (; j < active; ++j)
    {
      total[j] = SubVolumes(graph.GetWalkRecord(lanes[j].Element), dimension, lanes[j].P, w[j]);
    }
    for (j = 0; j < active; ++j)
    {
      inside[j] = IsInside(w[j], total[j], dimension);
      next[j] = graph.GetWalkRecord(lanes[j].Element).Neighbors[MostNegativeWeight(w[j], dimension)];
    }
    // ... then the decisions.
    for (std::size_t k = 0; k < active; ++k)
    {
      Lane& lane = lanes[k];
      if (inside[k])
      {
        const double inv = 1.0 / total[k];
        for (int c = 0; c < n; ++c)
        {
          w[k][c] *= inv;
        }
        ClampWeights(w[k], n);
        finish(lane, lane.Element, w[k], false);
      }
      else
      {
        // Visibility walk: cross the face opposite the most negative coordinate.
        ++lane.Steps;
        if (next[k] >= 0 && lane.Steps <= (lane.FromSeed ? DelaunayGraph::MaximumWalkSteps : ShortWalkSteps))
        {
          lane.Element = next[k];
          graph.PrefetchElement(next[k]);
        }
        else if (!lane.FromSeed)
        {
          startFromSeed(lane);
        }
        else
        {
          // Leaving the hull, or no end in sight: CGAL decides exactly.
          const DelaunayGraph::Location location = graph.LocateExactly(lane.P, lane.Element);
          finish(lane, location.Element, location.Weights, location.Outside);
        }
      }
    }
    // Drop the lanes whose run is done (their state was not advanced past End).
    std::size_t kept = 0;
    for (std::size_t j = 0; j < active; ++j)
    {
      if (lanes[j].Node < lanes[j].End)
      {
        lanes[kept++] = lanes[j];
      }
    }
    active = kept;
  }
  return counts;
}

} // namespace dgmf
