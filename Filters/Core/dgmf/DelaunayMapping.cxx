#include "dgmf/DelaunayMapping.h"

#include <algorithm>
#include <array>
#include <limits>
#include <chrono>
#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
{
/// Steps of the walk from the previous node's element before the recent nodes are consulted.
constexpr int ShortWalkSteps = 16;

/// The last located nodes of a block (a ring buffer), to restart a walk near a node after a jump.
class RecentNodes
{
public:
  void Add(const double p[3], std::int32_t element)
  {
    Entry& entry = this->Entries[this->Next];
    entry.Position[0] = p[0];
    entry.Position[1] = p[1];
    entry.Position[2] = p[2];
    entry.Element = element;
    this->Next = (this->Next + 1) % Capacity;
    this->Count = this->Count < Capacity ? this->Count + 1 : Capacity;
  }

  /// Element of the recent node nearest to p, or `fallback` when there is none.
  std::int32_t Nearest(const double p[3], std::int32_t fallback) const
  {
    double best = std::numeric_limits<double>::infinity();
    std::int32_t element = fallback;
    for (std::size_t k = 0; k < this->Count; ++k)
    {
      const Entry& entry = this->Entries[k];
      const double dx = entry.Position[0] - p[0];
      const double dy = entry.Position[1] - p[1];
      const double dz = entry.Position[2] - p[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      if (d2 < best)
      {
        best = d2;
        element = entry.Element;
      }
    }
    return element;
  }

private:
  static constexpr std::size_t Capacity = 256;
  struct Entry
  {
    double Position[3];
    std::int32_t Element;
  };
  std::array<Entry, Capacity> Entries;
  std::size_t Next = 0;
  std::size_t Count = 0;
};
} // namespace

DelaunayMapping::DelaunayMapping(int dimension, const double* points, std::size_t numberOfNodes,
  const NodeKind* kinds, const ParallelFor& parallelFor)
{
  if (numberOfNodes > static_cast<std::size_t>(INT32_MAX))
  {
    throw std::invalid_argument("DelaunayMapping: more than 2^31 - 1 nodes are not supported");
  }
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  this->Kinds.assign(kinds, kinds + numberOfNodes);
  // Step 1: the graph of all boundary nodes.
  std::vector<double> boundaryXYZ;
  for (std::size_t i = 0; i < numberOfNodes; ++i)
  {
    if (IsBoundary(kinds[i]))
    {
      this->BoundaryNodes.push_back(static_cast<std::int32_t>(i));
    }
  }
  if (this->BoundaryNodes.empty())
  {
    throw std::invalid_argument("DelaunayMapping: the mesh has no boundary node");
  }
  boundaryXYZ.reserve(3 * this->BoundaryNodes.size());
  for (std::int32_t node : this->BoundaryNodes)
  {
    const double* p = points + 3 * static_cast<std::size_t>(node);
    boundaryXYZ.insert(boundaryXYZ.end(), p, p + 3);
  }
  this->Graph = std::make_unique<DelaunayGraph>(dimension, boundaryXYZ.data(), this->BoundaryNodes.size());
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
  this->MovingVertices = static_cast<std::size_t>(
    std::count(this->VertexKind.begin(), this->VertexKind.end(), NodeKind::MovingBoundary));
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
  const int n = dimension + 1;
  this->NodeElement.assign(numberOfNodes, 0);
  this->Weights.assign(numberOfNodes * static_cast<std::size_t>(n), 0.0);
  for (std::size_t b = 0; b < this->BoundaryNodes.size(); ++b)
  {
    const auto node = static_cast<std::size_t>(this->BoundaryNodes[b]);
    this->NodeElement[node] = -vertexOfPoint[b] - 1;
    this->Weights[node * n] = 1.0;
  }

  const std::size_t blocks = (numberOfNodes + BlockSize - 1) / BlockSize;
  std::vector<std::size_t> outsidePerBlock(blocks, 0);
  std::vector<std::size_t> walksPerBlock(blocks, 0);
  const DelaunayGraph& graph = *this->Graph;
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      const std::size_t begin = block * BlockSize;
      const std::size_t end = std::min(begin + BlockSize, numberOfNodes);
      // Hints: the previous node's element; when a short walk from it fails (a jump in the
      // numbering, such as a new row of a structured block), the element of the nearest of the
      // block's most recent nodes.
      RecentNodes recent;
      std::int32_t hint = -1;
      std::size_t outside = 0;
      std::size_t walks = 0;
      for (std::size_t i = begin; i < end; ++i)
      {
        if (IsBoundary(kinds[i]))
        {
          continue;
        }
        const double p[3] = { points[3 * i], points[3 * i + 1], dimension == 3 ? points[3 * i + 2] : 0.0 };
        DelaunayGraph::Location location;
        if (hint < 0 || !graph.Walk(p, hint, ShortWalkSteps, location))
        {
          location = graph.Locate(p, recent.Nearest(p, hint));
          ++walks;
        }
        outside += location.Outside ? 1 : 0;
        hint = location.Element;
        recent.Add(p, hint);
        this->NodeElement[i] = location.Element;
        std::copy(location.Weights, location.Weights + n, this->Weights.begin() + i * n);
      }
      outsidePerBlock[block] = outside;
      walksPerBlock[block] = walks;
    });
  for (std::size_t block = 0; block < blocks; ++block)
  {
    this->OutsideNodes += outsidePerBlock[block];
    this->Walks += walksPerBlock[block];
  }
  this->LocationSeconds = std::chrono::duration<double>(Clock::now() - graphBuilt).count();
}

std::size_t DelaunayMapping::GetMemorySize() const
{
  return this->Graph->GetMemorySize() + this->BoundaryNodes.capacity() * sizeof(std::int32_t) +
    this->NodeElement.capacity() * sizeof(std::int32_t) + this->Weights.capacity() * sizeof(double) +
    this->Kinds.capacity() * sizeof(NodeKind) + this->VertexKind.capacity() * sizeof(NodeKind) + this->VertexNode.capacity() * sizeof(std::int32_t);
}

} // namespace dgmf
