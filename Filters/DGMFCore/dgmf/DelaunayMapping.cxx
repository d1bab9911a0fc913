#include "dgmf/DelaunayMapping.h"

#include "dgmf/DeformationProblem.h"
#include "dgmf/Finite.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/LocationStartGrid.h"
#include "dgmf/NodeLocation.h"
#include "dgmf/NumberingCoherence.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <numeric>
#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
{
/// Nodes per block of the boundary nodes' search.
constexpr std::size_t KindBlock = std::size_t(1) << 16;

} // namespace

DelaunayMapping::DelaunayMapping(int dimension, const double* points, std::size_t numberOfNodes,
  const NodeKind* kinds, const ParallelFor& parallelFor, std::size_t hintStride,
  const DelaunayGraph::SideJobs& alongside, const SlipConstraint* slip)
{
  if (numberOfNodes > static_cast<std::size_t>(INT32_MAX))
  {
    throw std::invalid_argument("DelaunayMapping: more than 2^31 - 1 nodes are not supported");
  }
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  // Step 1: the graph of all boundary nodes, found (and the kinds copied) in fixed blocks on the
  // threads, listed in increasing order.
  this->Kinds.resize(numberOfNodes);
  const std::size_t kindBlocks = (numberOfNodes + KindBlock - 1) / KindBlock;
  std::vector<std::size_t> boundaryBefore(kindBlocks + 1, 0);
  ForEachBlock(parallelFor, kindBlocks,
    [&](std::size_t block)
    {
      const std::size_t begin = block * KindBlock;
      const std::size_t end = std::min(numberOfNodes, begin + KindBlock);
      std::copy(kinds + begin, kinds + end, this->Kinds.data() + begin);
      boundaryBefore[block + 1] = static_cast<std::size_t>(
        std::count_if(kinds + begin, kinds + end, [](NodeKind kind) { return IsBoundary(kind); }));
    });
  std::partial_sum(boundaryBefore.begin(), boundaryBefore.end(), boundaryBefore.begin());
  this->BoundaryNodes.resize(boundaryBefore.back());
  ForEachBlock(parallelFor, kindBlocks,
    [&](std::size_t block)
    {
      std::int32_t* next = this->BoundaryNodes.data() + boundaryBefore[block];
      for (std::size_t i = block * KindBlock; i < std::min(numberOfNodes, (block + 1) * KindBlock);
           ++i)
      {
        if (IsBoundary(kinds[i]))
        {
          *next++ = static_cast<std::int32_t>(i);
        }
      }
    });
  std::vector<double> boundaryXYZ;
  if (this->BoundaryNodes.empty())
  {
    throw std::invalid_argument(NoBoundaryNodeMessage);
  }
  boundaryXYZ.reserve(3 * this->BoundaryNodes.size());
  for (std::int32_t node : this->BoundaryNodes)
  {
    const double* p = points + 3 * static_cast<std::size_t>(node);
    boundaryXYZ.insert(boundaryXYZ.end(), p, p + 3);
  }
  // CGAL inserts the graph's points on one thread; meanwhile another prepares the node arrays,
  // whose first touch costs as much as a pass of the location (page faults), and runs the
  // caller's `alongside` jobs; once the insertion is done, both threads share what is left. With
  // one thread, one after the other. The check of every point explains a failure of the graph's
  // as well: its exception is thrown in preference.
  const int n = dimension + 1;
  DelaunayGraph::SideJobs jobs;
  jobs.emplace_back(
    [points, numberOfNodes]()
    {
      const std::size_t bad = FirstOutOfRange(points, 3 * numberOfNodes);
      if (bad < 3 * numberOfNodes)
      {
        throw std::invalid_argument(OutOfRangePointsMessage(bad));
      }
    });
  // The node arrays are allocated here without being written (so a failed allocation is thrown
  // here, before the points' check), and their pages faulted in parts (FirstTouch: every weight
  // is written later, boundary nodes' below; the elements need their "not located" mark).
  this->Weights.resize(numberOfNodes * static_cast<std::size_t>(n));
  this->NodeElement.resize(numberOfNodes);
  // The elements' marks (stores) before the caller's jobs and the weights' first touch (the
  // kernel's MADV_POPULATE_WRITE, which holds the address space's lock in turns): CGAL allocates
  // its large arrays (perturbation, insertion order) in the meantime, without waiting for it.
  const std::size_t elementPart = FirstTouchPartBytes / sizeof(std::int32_t);
  for (std::size_t begin = 0; begin < numberOfNodes; begin += elementPart)
  {
    const std::size_t count = std::min(elementPart, numberOfNodes - begin);
    jobs.emplace_back(
      [this, begin, count]() { std::fill_n(this->NodeElement.data() + begin, count, NotLocated); });
  }
  jobs.insert(jobs.end(), alongside.begin(), alongside.end());
  std::vector<FirstTouchPart> weightParts;
  AppendFirstTouchParts(this->Weights.data(), this->Weights.size() * sizeof(double), weightParts);
  AppendFirstTouchJobs(weightParts, jobs);
  this->Graph = std::make_unique<DelaunayGraph>(
    dimension, boundaryXYZ.data(), this->BoundaryNodes.size(), parallelFor, jobs);
  boundaryXYZ = std::vector<double>();

  // Vertex kinds: a vertex shared by coincident nodes is moving if any of them moves.
  const std::vector<std::int32_t>& vertexOfPoint = this->Graph->GetVertexOfPoint();
  const std::size_t vertices = this->Graph->GetNumberOfVertices();
  this->VertexKind.assign(vertices, NodeKind::StaticBoundary);
  this->VertexNode.assign(vertices, -1);
  for (std::size_t b = 0; b < this->BoundaryNodes.size(); ++b)
  {
    const std::int32_t node = this->BoundaryNodes[b];
    const auto v = static_cast<std::size_t>(vertexOfPoint[b]);
    if (kinds[node] == NodeKind::MovingBoundary && this->VertexKind[v] != NodeKind::MovingBoundary)
    {
      this->VertexKind[v] = NodeKind::MovingBoundary;
      this->VertexNode[v] = node;
    }
    else if (this->VertexNode[v] < 0)
    {
      this->VertexNode[v] = node;
    }
  }
  for (std::size_t b = 0; b < this->BoundaryNodes.size(); ++b)
  {
    const auto v = static_cast<std::size_t>(vertexOfPoint[b]);
    if (kinds[this->BoundaryNodes[b]] != this->VertexKind[v])
    {
      ++this->ConflictingNodes;
    }
  }

  const Clock::time_point graphBuilt = Clock::now();
  this->GraphSeconds = std::chrono::duration<double>(graphBuilt - start).count();

  // Steps 2-3: the element and barycentric coordinates of every interior node.
  for (std::size_t b = 0; b < this->BoundaryNodes.size(); ++b)
  {
    const auto node = static_cast<std::size_t>(this->BoundaryNodes[b]);
    this->NodeElement[node] = -vertexOfPoint[b] - 1;
    std::fill_n(this->Weights.data() + node * n, n, 0.0);
    this->Weights[node * n] = 1.0;
  }

  // A numbering without spatial coherence (and without a hint stride) starts every walk from the
  // start grid's element near its node instead of the previous node's (anywhere): the nodes are
  // still located in their own order, the node arrays read and written in order.
  if (hintStride == 0 &&
    !IsNumberingCoherent(*this->Graph, points, this->Kinds.data(), numberOfNodes))
  {
    const LocationStartGrid starts(
      *this->Graph, points, this->Kinds.data(), numberOfNodes, parallelFor);
    const std::size_t pieces = (numberOfNodes + BlockSize - 1) / BlockSize;
    std::vector<NodeLocationCounts> counts(pieces);
    ForEachBlock(parallelFor, pieces,
      [&](std::size_t piece)
      {
        const std::size_t begin = piece * BlockSize;
        const std::size_t end = std::min(begin + BlockSize, numberOfNodes);
        std::int32_t startElements[BlockSize];
        starts.GetStartElements(points, this->Kinds.data(), begin, end, startElements);
        counts[piece] = LocateNodes(*this->Graph, points, this->Kinds.data(), begin, end,
          this->NodeElement.data(), this->Weights.data(), 0, 0, startElements);
      });
    this->AddCounts(counts);
    this->FromStartGrid = true;
  }
  else
  {
    this->LocateInWaves(points, numberOfNodes, parallelFor, hintStride);
  }
  if (slip)
  {
    this->LocateSlipNodesInside(points, *slip, parallelFor);
  }
  this->LocationSeconds = std::chrono::duration<double>(Clock::now() - graphBuilt).count();
}

void DelaunayMapping::LocateInWaves(const double* points, std::size_t numberOfNodes,
  const ParallelFor& parallelFor, std::size_t hintStride)
{
  // The pieces located in parallel. With a hint stride of at least a block, the nodes go in
  // waves of `hintStride` nodes, each cut into WavePieces pieces: every node's stride neighbour
  // is then in an earlier wave, located whatever the number of threads. Otherwise one wave of
  // BlockSize pieces. The layout depends on the mesh only.
  const bool waves = hintStride >= BlockSize;
  const std::size_t waveLength = waves ? hintStride : std::max<std::size_t>(numberOfNodes, 1);
  const std::size_t piecesPerWave =
    waves ? WavePieces : (numberOfNodes + BlockSize - 1) / BlockSize;
  const std::size_t pieceLength = (waveLength + piecesPerWave - 1) / piecesPerWave;
  // A node's stride neighbour is at the same place in the wave before, so in the same piece of
  // it: each piece's column (that piece of every wave, in wave order) is located by one task,
  // with no wait between the waves (a barrier per wave left a thread idle a third of the time).
  std::vector<NodeLocationCounts> counts(piecesPerWave);
  ForEachBlock(parallelFor, piecesPerWave,
    [&](std::size_t piece)
    {
      for (std::size_t waveBegin = 0; waveBegin < numberOfNodes; waveBegin += waveLength)
      {
        const std::size_t waveEnd = std::min(numberOfNodes, waveBegin + waveLength);
        const std::size_t begin = waveBegin + piece * pieceLength;
        if (begin >= waveEnd)
        {
          continue;
        }
        const NodeLocationCounts count = LocateNodes(*this->Graph, points, this->Kinds.data(),
          begin, std::min(begin + pieceLength, waveEnd), this->NodeElement.data(),
          this->Weights.data(), hintStride, waveBegin);
        counts[piece].Outside += count.Outside;
        counts[piece].SlipOutside += count.SlipOutside;
        counts[piece].StrideHits += count.StrideHits;
        counts[piece].Steps += count.Steps;
      }
    });
  this->AddCounts(counts);
}

void DelaunayMapping::LocateSlipNodesInside(
  const double* points, const SlipConstraint& slip, const ParallelFor& parallelFor)
{
  const DelaunayGraph& graph = *this->Graph;
  const int dimension = graph.GetDimension();
  const std::size_t vertices = graph.GetNumberOfVertices();
  // The graph's size (its bounding box's diagonal) and, for each plane, the side of it the graph's
  // vertices are on: that of the vertex farthest from it (a symmetry plane bounds the domain, so
  // every vertex is on that side, up to the plane's deviation).
  double low[3], high[3];
  for (int c = 0; c < 3; ++c)
  {
    low[c] = high[c] = graph.GetVertexPosition(0)[c];
  }
  for (std::int32_t v = 1; v < static_cast<std::int32_t>(vertices); ++v)
  {
    for (int c = 0; c < 3; ++c)
    {
      low[c] = std::min(low[c], graph.GetVertexPosition(v)[c]);
      high[c] = std::max(high[c], graph.GetVertexPosition(v)[c]);
    }
  }
  const double size = std::sqrt((high[0] - low[0]) * (high[0] - low[0]) +
    (high[1] - low[1]) * (high[1] - low[1]) + (high[2] - low[2]) * (high[2] - low[2]));
  std::vector<std::array<double, 3>> inward(slip.Planes.size());
  for (std::size_t k = 0; k < slip.Planes.size(); ++k)
  {
    const SlipPlane& plane = slip.Planes[k];
    double farthest = 0.0;
    for (std::int32_t v = 0; v < static_cast<std::int32_t>(vertices); ++v)
    {
      const double* x = graph.GetVertexPosition(v);
      double distance = 0.0;
      for (int c = 0; c < dimension; ++c)
      {
        distance += (x[c] - plane.Point[c]) * plane.Normal[c];
      }
      farthest = std::abs(distance) > std::abs(farthest) ? distance : farthest;
    }
    const double offset = std::copysign(
      std::max(SlipOffset * size, SlipOffsetOverDeviation * plane.Deviation), farthest);
    for (int c = 0; c < 3; ++c)
    {
      inward[k][static_cast<std::size_t>(c)] = c < dimension ? offset * plane.Normal[c] : 0.0;
    }
  }
  // Each slip node on its own (any split gives the same result); the nodes outside the graph are
  // then the other nodes outside and the slip nodes whose point inside is still outside.
  const std::size_t count = slip.Nodes.size();
  const std::size_t blocks = (count + BlockSize - 1) / BlockSize;
  std::vector<std::size_t> stillOutside(blocks, 0);
  const int n = dimension + 1;
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      for (std::size_t k = block * BlockSize; k < std::min(count, (block + 1) * BlockSize); ++k)
      {
        const auto i = static_cast<std::size_t>(slip.Nodes[k]);
        if (this->IsBoundaryNode(i))
        {
          continue;
        }
        // A node on two planes (their line) goes inside from both.
        const double* p = points + 3 * i;
        const std::array<double, 3>& shift = inward[static_cast<std::size_t>(slip.NodePlanes[k])];
        const std::int32_t second = slip.SecondPlaneOf(k);
        double inside[3] = { p[0] + shift[0], p[1] + shift[1], p[2] + shift[2] };
        for (int c = 0; c < 3 && second >= 0; ++c)
        {
          inside[c] += inward[static_cast<std::size_t>(second)][static_cast<std::size_t>(c)];
        }
        const DelaunayGraph::Location location = graph.LocateExactly(inside, this->NodeElement[i]);
        if (location.Outside)
        {
          ++stillOutside[block]; // even a hair inside it: the node keeps its own location
          continue;
        }
        this->NodeElement[i] = location.Element;
        std::copy(location.Weights, location.Weights + n, this->Weights.data() + i * n);
      }
    });
  this->OutsideNodes -= this->SlipOutsideNodes;
  this->SlipOutsideNodes =
    std::accumulate(stillOutside.begin(), stillOutside.end(), std::size_t(0));
  this->OutsideNodes += this->SlipOutsideNodes;
}

void DelaunayMapping::AddCounts(const std::vector<NodeLocationCounts>& counts)
{
  for (const NodeLocationCounts& count : counts)
  {
    this->OutsideNodes += count.Outside;
    this->SlipOutsideNodes += count.SlipOutside;
    this->StrideHits += count.StrideHits;
    this->WalkSteps += count.Steps;
  }
}

std::size_t DelaunayMapping::GetMemorySize() const
{
  return this->Graph->GetMemorySize() + this->BoundaryNodes.capacity() * sizeof(std::int32_t) +
    this->NodeElement.capacity() * sizeof(std::int32_t) +
    this->Weights.capacity() * sizeof(double) + this->Kinds.capacity() * sizeof(NodeKind) +
    this->VertexKind.capacity() * sizeof(NodeKind) +
    this->VertexNode.capacity() * sizeof(std::int32_t);
}

} // namespace dgmf
