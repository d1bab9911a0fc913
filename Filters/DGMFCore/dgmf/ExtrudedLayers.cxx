#include "dgmf/ExtrudedLayers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace dgmf
{
namespace
{
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The in-plane coordinates of a node as a hashable key (bit patterns; -0 and +0 alike).
struct PlaneKey
{
  std::uint64_t U, V;
  bool operator==(const PlaneKey& other) const { return this->U == other.U && this->V == other.V; }
};

struct PlaneKeyHash
{
  std::size_t operator()(const PlaneKey& key) const
  {
    std::uint64_t h = (key.U ^ 0x9e3779b97f4a7c15ull) * 0xff51afd7ed558ccdull;
    h = (h ^ key.V ^ (h >> 29)) * 0xc4ceb9fe1a85ec53ull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

std::uint64_t Bits(double value)
{
  value = value == 0.0 ? 0.0 : value;
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

/// Rank of a kind in a merged layer node: moving over static over slip over interior.
int Rank(NodeKind kind)
{
  switch (kind)
  {
    case NodeKind::MovingBoundary:
      return 3;
    case NodeKind::StaticBoundary:
      return 2;
    case NodeKind::SlipBoundary:
      return 1;
    default:
      return 0;
  }
}

void TurnMotion(int axis, RigidMotion& motion)
{
  double v[3];
  for (double* vector : { motion.Translation, motion.Center, motion.AnglesDegrees, motion.Axis })
  {
    ToLayer(axis, vector, v);
    std::copy(v, v + 3, vector);
  }
}

/// Nodes per block of the extremes pass.
constexpr std::size_t ExtremesBlock = 1 << 16;

/**
 * Each axis's smallest and largest coordinate over some nodes and how many nodes have it (NaN
 * coordinates ignored). Blocks combine in any grouping, in order, to the whole range's.
 */
struct Extremes
{
  double Low[3] = { kInfinity, kInfinity, kInfinity };
  double High[3] = { -kInfinity, -kInfinity, -kInfinity };
  std::size_t LowCount[3] = { 0, 0, 0 };
  std::size_t HighCount[3] = { 0, 0, 0 };

  void Add(const Extremes& other)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (other.Low[axis] < this->Low[axis])
      {
        this->Low[axis] = other.Low[axis];
        this->LowCount[axis] = other.LowCount[axis];
      }
      else if (other.Low[axis] == this->Low[axis])
      {
        this->LowCount[axis] += other.LowCount[axis];
      }
      if (other.High[axis] > this->High[axis])
      {
        this->High[axis] = other.High[axis];
        this->HighCount[axis] = other.HighCount[axis];
      }
      else if (other.High[axis] == this->High[axis])
      {
        this->HighCount[axis] += other.HighCount[axis];
      }
    }
  }
};

/// Nodes per chunk of FindExtremes: their coordinates (48 KB) stay in cache for its second loop.
constexpr std::size_t ExtremesChunk = 2048;

/**
 * The extremes of nodes [begin, end), chunk by chunk: the smallest and largest values first (no
 * branch, no dependence on counts), then how many equal them, in cache. A NaN is never below or
 * above a value, nor equal to one: ignored.
 */
Extremes FindExtremes(const double* points, std::size_t begin, std::size_t end)
{
  Extremes all;
  for (std::size_t first = begin; first < end; first += ExtremesChunk)
  {
    const std::size_t last = std::min(end, first + ExtremesChunk);
    Extremes chunk;
    for (int axis = 0; axis < 3; ++axis)
    {
      double low = kInfinity, high = -kInfinity;
      for (std::size_t i = first; i < last; ++i)
      {
        const double value = points[3 * i + axis];
        low = value < low ? value : low;
        high = value > high ? value : high;
      }
      std::size_t lowCount = 0, highCount = 0;
      for (std::size_t i = first; i < last; ++i)
      {
        const double value = points[3 * i + axis];
        lowCount += value == low;
        highCount += value == high;
      }
      chunk.Low[axis] = low;
      chunk.High[axis] = high;
      chunk.LowCount[axis] = lowCount;
      chunk.HighCount[axis] = highCount;
    }
    all.Add(chunk);
  }
  return all;
}
/**
 * The layers of nodes along `axis` between the planes `low` and `high` within `tolerance`
 * (FindExtrudedLayers' second try): the nodes within it of a plane are its nodes, each node of
 * the high plane paired with the low plane's node within it in the other two coordinates, found
 * in a grid of cells of twice the tolerance (the 3 x 3 cells around a node hold its partner).
 * False when the nodes are not so.
 */
bool FindLayersWithin(const double* points, std::size_t n, int axis, double low, double high,
  double tolerance, const ParallelFor& parallelFor, ExtrudedLayers& layers)
{
  // The nodes near each plane, counted on the threads in fixed blocks.
  const std::size_t blocks = (n + ExtremesBlock - 1) / ExtremesBlock;
  std::vector<std::size_t> lowPerBlock(blocks, 0), highPerBlock(blocks, 0);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      for (std::size_t i = block * ExtremesBlock; i < std::min(n, (block + 1) * ExtremesBlock); ++i)
      {
        const double value = points[3 * i + axis];
        lowPerBlock[block] += std::abs(value - low) <= tolerance ? 1 : 0;
        highPerBlock[block] += std::abs(value - high) <= tolerance ? 1 : 0;
      }
    });
  std::size_t lowNodes = 0, highNodes = 0;
  for (std::size_t block = 0; block < blocks; ++block)
  {
    lowNodes += lowPerBlock[block];
    highNodes += highPerBlock[block];
  }
  if (lowNodes != highNodes || 3 * lowNodes <= n || !(high - low > 2 * tolerance))
  {
    return false;
  }
  const double cell = 2 * tolerance;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const auto cellOf = [&](std::size_t i, int du, int dv, PlaneKey& key)
  {
    const double cu = std::floor(points[3 * i + u] / cell) + du;
    const double cv = std::floor(points[3 * i + v] / cell) + dv;
    if (!(std::abs(cu) < 4e18 && std::abs(cv) < 4e18))
    {
      return false;
    }
    key = { static_cast<std::uint64_t>(static_cast<std::int64_t>(cu)),
      static_cast<std::uint64_t>(static_cast<std::int64_t>(cv)) };
    return true;
  };
  std::unordered_map<PlaneKey, std::int32_t, PlaneKeyHash> front;
  front.reserve(lowNodes);
  std::vector<std::int32_t> layer(n, -1), frontNodes;
  frontNodes.reserve(lowNodes);
  PlaneKey key{};
  for (std::size_t i = 0; i < n; ++i)
  {
    if (std::abs(points[3 * i + axis] - low) <= tolerance)
    {
      // Two nodes of a plane within one cell: not a mesh's nodes (or not its planes).
      if (!cellOf(i, 0, 0, key) ||
        !front.emplace(key, static_cast<std::int32_t>(frontNodes.size())).second)
      {
        return false;
      }
      layer[i] = static_cast<std::int32_t>(frontNodes.size());
      frontNodes.push_back(static_cast<std::int32_t>(i));
    }
  }
  // The low plane's node within the tolerance of node i in the other two coordinates, or -1.
  const auto partnerOf = [&](std::size_t i)
  {
    for (int du = -1; du <= 1; ++du)
    {
      for (int dv = -1; dv <= 1; ++dv)
      {
        const auto found = cellOf(i, du, dv, key) ? front.find(key) : front.end();
        if (found == front.end())
        {
          continue;
        }
        const auto j =
          static_cast<std::size_t>(frontNodes[static_cast<std::size_t>(found->second)]);
        if (std::abs(points[3 * j + u] - points[3 * i + u]) <= tolerance &&
          std::abs(points[3 * j + v] - points[3 * i + v]) <= tolerance)
        {
          return found->second;
        }
      }
    }
    return std::int32_t(-1);
  };
  const std::size_t pairs = frontNodes.size();
  std::vector<std::uint8_t> taken(pairs, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double value = points[3 * i + axis];
    if (std::abs(value - low) <= tolerance)
    {
      continue;
    }
    const std::int32_t partner = partnerOf(i);
    if (std::abs(value - high) <= tolerance)
    {
      if (partner < 0 || taken[static_cast<std::size_t>(partner)])
      {
        return false;
      }
      taken[static_cast<std::size_t>(partner)] = 1;
      layer[i] = partner;
    }
    else if (partner >= 0) // above a plane node: a layer of a thicker mesh
    {
      return false;
    }
    else
    {
      layer[i] = static_cast<std::int32_t>(frontNodes.size());
      frontNodes.push_back(static_cast<std::int32_t>(i));
    }
  }
  if (pairs * 2 <= n - pairs) // the inner nodes are a minority
  {
    return false;
  }
  layers.Axis = axis;
  layers.Low = low;
  layers.High = high;
  layers.Tolerance = tolerance;
  layers.Front = std::move(frontNodes);
  layers.Pairs = pairs;
  layers.Layer = std::move(layer);
  return true;
}
} // namespace

void ToLayer(int axis, const double in[3], double out[3])
{
  const double u = in[(axis + 1) % 3], v = in[(axis + 2) % 3], w = in[axis];
  out[0] = u;
  out[1] = v;
  out[2] = w;
}

void FromLayer(int axis, const double in[3], double out[3])
{
  const double u = in[0], v = in[1], w = in[2];
  out[(axis + 1) % 3] = u;
  out[(axis + 2) % 3] = v;
  out[axis] = w;
}

ExtrudedLayers FindExtrudedLayers(
  const double* points, std::size_t n, const ParallelFor& parallelFor)
{
  ExtrudedLayers layers;
  if (n < 6)
  {
    return layers;
  }
  // A one-cell-thick mesh has as many nodes on each of its two planes, and more than a third of
  // all on each. One streaming pass finds every axis's extremes and how many nodes lie on them, so
  // that a volume mesh, which fails here, costs no hash lookups (measured: 0.55 s of a 0.9 s
  // repeated deformation on the 8.26M-node benchmark mesh before this check).
  const std::size_t blocks = (n + ExtremesBlock - 1) / ExtremesBlock;
  std::vector<Extremes> perBlock(blocks);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      perBlock[block] =
        FindExtremes(points, block * ExtremesBlock, std::min(n, (block + 1) * ExtremesBlock));
    });
  Extremes all;
  for (const Extremes& extremes : perBlock)
  {
    all.Add(extremes);
  }
  double low[3], high[3];
  std::size_t lowCount[3], highCount[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    // A NaN first coordinate keeps the axis out, as a scan started from it always did.
    const bool nan = std::isnan(points[axis]);
    low[axis] = nan ? points[axis] : all.Low[axis];
    high[axis] = nan ? points[axis] : all.High[axis];
    lowCount[axis] = all.LowCount[axis];
    highCount[axis] = all.HighCount[axis];
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!(low[axis] < high[axis]) || lowCount[axis] != highCount[axis] || 3 * lowCount[axis] <= n)
    {
      continue;
    }
    const auto key = [&](std::size_t i) {
      return PlaneKey{ Bits(points[3 * i + (axis + 1) % 3]), Bits(points[3 * i + (axis + 2) % 3]) };
    };
    // Pair the nodes of the two planes by their in-plane coordinates.
    std::unordered_map<PlaneKey, std::int32_t, PlaneKeyHash> front;
    front.reserve(n / 2);
    std::vector<std::int32_t> layer(n, -1);
    std::vector<std::int32_t> frontNodes;
    frontNodes.reserve(n / 2);
    bool paired = true;
    for (std::size_t i = 0; i < n && paired; ++i)
    {
      if (points[3 * i + axis] == low[axis])
      {
        paired = front.emplace(key(i), static_cast<std::int32_t>(frontNodes.size())).second;
        layer[i] = static_cast<std::int32_t>(frontNodes.size());
        frontNodes.push_back(static_cast<std::int32_t>(i));
      }
    }
    const std::size_t pairs = frontNodes.size();
    std::size_t highNodes = 0;
    std::vector<std::uint8_t> taken(pairs, 0);
    for (std::size_t i = 0; i < n && paired; ++i)
    {
      const double value = points[3 * i + axis];
      if (value == low[axis])
      {
        continue;
      }
      const auto found = front.find(key(i));
      if (value == high[axis])
      {
        paired = found != front.end() && !taken[static_cast<std::size_t>(found->second)];
        if (paired)
        {
          taken[static_cast<std::size_t>(found->second)] = 1;
          layer[i] = found->second;
          ++highNodes;
        }
      }
      else // an inner node; one above a plane node would be a layer of a thicker mesh
      {
        paired = found == front.end();
        layer[i] = static_cast<std::int32_t>(frontNodes.size());
        frontNodes.push_back(static_cast<std::int32_t>(i));
      }
    }
    if (paired && highNodes == pairs && pairs * 2 > n - pairs) // the inner nodes are a minority
    {
      layers.Axis = axis;
      layers.Low = low[axis];
      layers.High = high[axis];
      layers.Front = std::move(frontNodes);
      layers.Pairs = pairs;
      layers.Layer = std::move(layer);
      return layers;
    }
  }
  // No exact planes: a thin axis within the tolerance (a mesh turned by a transform).
  double extent[3], diagonal = 0.0, largest = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    extent[axis] = high[axis] - low[axis];
    diagonal += extent[axis] * extent[axis];
    largest = std::max(largest, extent[axis]);
  }
  const double tolerance = ExtrudedLayersTolerance * std::sqrt(diagonal);
  for (int axis = 0; axis < 3; ++axis)
  {
    if (extent[axis] > 0.0 && 4.0 * extent[axis] <= largest && std::isfinite(diagonal) &&
      FindLayersWithin(points, n, axis, low[axis], high[axis], tolerance, parallelFor, layers))
    {
      return layers;
    }
  }
  return layers;
}

DeformationProblem ReduceToLayer(
  const ExtrudedLayers& layers, const DeformationProblem& problem, LayerProblemStorage& storage)
{
  const int axis = layers.Axis;
  const std::size_t m = layers.Front.size();
  const std::size_t n = problem.NumberOfNodes;
  storage.Points.resize(3 * m);
  for (std::size_t k = 0; k < m; ++k)
  {
    ToLayer(
      axis, problem.Points + 3 * static_cast<std::size_t>(layers.Front[k]), &storage.Points[3 * k]);
    storage.Points[3 * k + 2] = layers.Low; // inner nodes too
  }
  storage.Kinds.assign(m, NodeKind::Interior);
  for (std::size_t i = 0; i < n; ++i)
  {
    NodeKind& kind = storage.Kinds[static_cast<std::size_t>(layers.Layer[i])];
    kind = Rank(problem.Kinds[i]) > Rank(kind) ? problem.Kinds[i] : kind;
  }
  DeformationProblem layer = problem;
  layer.Dimension = 2;
  layer.LayerAxis = axis;
  layer.NumberOfNodes = m;
  layer.Points = storage.Points.data();
  layer.Kinds = storage.Kinds.data();
  layer.Cells = nullptr;
  layer.BoundaryWeights = nullptr;
  if (problem.Displacement)
  {
    storage.Displacement.resize(3 * m);
    for (std::size_t k = 0; k < m; ++k)
    {
      ToLayer(axis, problem.Displacement + 3 * static_cast<std::size_t>(layers.Front[k]),
        &storage.Displacement[3 * k]);
    }
    layer.Displacement = storage.Displacement.data();
  }
  if (problem.BodyIds)
  {
    storage.BodyIds.assign(m, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
      std::int32_t& id = storage.BodyIds[static_cast<std::size_t>(layers.Layer[i])];
      id = id != 0 ? id : problem.BodyIds[i];
    }
    layer.BodyIds = storage.BodyIds.data();
  }
  for (RigidMotion& motion : layer.Motions)
  {
    TurnMotion(axis, motion);
  }
  layer.Slip = SlipConstraint();
  for (const SlipPlane& plane : problem.Slip.Planes)
  {
    SlipPlane turned;
    ToLayer(axis, plane.Point, turned.Point);
    ToLayer(axis, plane.Normal, turned.Normal);
    turned.Axis = plane.Axis < 0 ? -1 : (plane.Axis - axis + 2) % 3; // u -> 0, v -> 1, w -> 2
    turned.Deviation = plane.Deviation;
    layer.Slip.Planes.push_back(turned);
  }
  std::vector<std::uint8_t> listed(m, 0);
  for (std::size_t s = 0; s < problem.Slip.Nodes.size(); ++s)
  {
    const auto k =
      static_cast<std::size_t>(layers.Layer[static_cast<std::size_t>(problem.Slip.Nodes[s])]);
    if (problem.Slip.SecondPlaneOf(s) >= 0 && storage.Kinds[k] == NodeKind::SlipBoundary)
    {
      // On two planes normal to the layer: a point of the 2D problem, which cannot move.
      storage.Kinds[k] = NodeKind::StaticBoundary;
      continue;
    }
    if (!listed[k] && storage.Kinds[k] == NodeKind::SlipBoundary)
    {
      listed[k] = 1;
      layer.Slip.Nodes.push_back(static_cast<std::int32_t>(k));
      layer.Slip.NodePlanes.push_back(problem.Slip.NodePlanes[s]);
    }
  }
  return layer;
}

void ExpandFromLayer(
  const ExtrudedLayers& layers, const double* points, const double* deformedLayer, double* deformed)
{
  const std::size_t n = layers.Layer.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    FromLayer(
      layers.Axis, deformedLayer + 3 * static_cast<std::size_t>(layers.Layer[i]), deformed + 3 * i);
    deformed[3 * i + layers.Axis] = points[3 * i + layers.Axis];
  }
}

void ExpandValuesFromLayer(const ExtrudedLayers& layers, const double* layerValues, double* values)
{
  for (std::size_t i = 0; i < layers.Layer.size(); ++i)
  {
    values[i] = layerValues[static_cast<std::size_t>(layers.Layer[i])];
  }
}

} // namespace dgmf
