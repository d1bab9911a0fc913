/**
 * @file DelaunayMapping.h
 * @brief The Delaunay graph of a mesh's boundary nodes and the location of every mesh node in it.
 */
#ifndef dgmf_DelaunayMapping_h
#define dgmf_DelaunayMapping_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/NodeKind.h"
#include "dgmf/NodeLocation.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/SlipPlanes.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace dgmf
{

/**
 * @class DelaunayMapping
 * @brief Steps 1-3 of the paper: the Delaunay graph of all boundary nodes (static and moving) of
 * the original mesh, the element of every other node, and its barycentric coordinates.
 *
 * It depends only on the original node positions and on which nodes are boundary nodes of which
 * kind, so one mapping serves every later motion of the same mesh (time steps, design loops).
 *
 * Nodes are located in fixed blocks of BlockSize nodes (LocateNodes): each block is cut into
 * runs of consecutive nodes; a node walks from the element of its stride neighbour (node
 * i - hintStride, for structured and layered meshes), else from the element of the run's
 * previous node (mesh generators number nodes with spatial coherence), else from the graph's
 * seed element, with CGAL as the exact fallback. For a numbering without spatial coherence
 * (IsNumberingCoherent), every walk starts instead from the element that a grid refined where the
 * nodes are gives for its node (LocationStartGrid), still in the nodes' own order. The runs of a
 * block walk in turn so that their cache misses overlap. With a hint stride of at least a block,
 * the nodes go in waves of one stride, each cut into WavePieces blocks; a node's stride neighbour
 * is at its place in the wave before, so the same piece of every wave (a column) is one task, with
 * no wait between the waves. Because blocks, runs and waves are fixed, the result does not depend
 * on the number of threads.
 *
 * Coincident boundary nodes share one graph vertex. Such a vertex is moving when any of its nodes
 * is moving; its shape deformation (DGMF2) is that of its first moving node. Each node keeps its
 * own kind: a static node coincident with a moving one stays where it is.
 */
class DelaunayMapping
{
public:
  /// Number of nodes per location block.
  static constexpr std::size_t BlockSize = 4096;

  /// Pieces located in parallel per wave, when the nodes are located in waves (see hintStride).
  static constexpr std::size_t WavePieces = 16;

  /// The element of an interior node not located yet (while the mapping is being built).
  static constexpr std::int32_t NotLocated = INT32_MIN;

  /// How far inside the graph a slip node is located, relative to the graph's size (the diagonal
  /// of its bounding box); see the constructor's `slip`.
  static constexpr double SlipOffset = 1e-7;
  /// ... and at least this many times its plane's deviation (SlipPlane::Deviation).
  static constexpr double SlipOffsetOverDeviation = 10.0;

  /**
   * Calls body(i) for every node i, in the fixed blocks of BlockSize nodes that run in parallel
   * (the split does not depend on the number of threads, so neither does the result).
   */
  template <typename Body>
  void ForEachNode(const ParallelFor& parallelFor, Body&& body) const
  {
    this->ForEachNodeBlock(parallelFor,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          body(i);
        }
      });
  }

  /// Calls body(begin, end) for each of the fixed blocks of ForEachNode (for loops that carry
  /// state from node to node within a block).
  template <typename Body>
  void ForEachNodeBlock(const ParallelFor& parallelFor, Body&& body) const
  {
    const std::size_t nodes = this->GetNumberOfNodes();
    ForEachBlock(parallelFor, (nodes + BlockSize - 1) / BlockSize,
      [&](std::size_t block)
      { body(block * BlockSize, std::min(block * BlockSize + BlockSize, nodes)); });
  }

  /**
   * @param dimension 2 (x, y used; all nodes in a plane z = constant) or 3
   * @param points 3 coordinates per node
   * @param kinds the kind of every node
   * @param hintStride 0, or the index difference of mesh neighbours across layers (see
   *   FindHintStride): node i's walk then starts from node i - hintStride's element (LocateNodes)
   * @param alongside jobs that do not need the mapping (such as the first touch of the caller's
   *   output arrays, in parts), run beside the graph's insertion with the mapping's own first
   *   touches (DelaunayGraph::SideJobs: on a second thread while the graph is built on one, then
   *   on both). Exceptions they throw are passed on.
   * @param slip the slip boundaries, or null. A slip plane bounds the domain, so it lies on the
   *   graph's hull, where the elements under it can be flat (a tilted plane's rounding, the
   *   graph's perturbation) and a node's barycentric coordinates in them arbitrary. Each slip node
   *   is therefore located at the point a hair inside the graph along its plane's normal
   *   (SlipOffset times the graph's size, and at least SlipOffsetOverDeviation times the plane's
   *   deviation, towards the graph's vertices): it gets the values of the well-shaped element
   *   beside the plane, the same whatever the plane's orientation. A node whose point is outside
   *   the graph keeps its own location.
   * Throws std::invalid_argument when there are no boundary nodes, when the boundary nodes do
   * not span the dimension, or when any node's coordinate is not finite.
   */
  DelaunayMapping(int dimension, const double* points, std::size_t numberOfNodes,
    const NodeKind* kinds, const ParallelFor& parallelFor, std::size_t hintStride = 0,
    const DelaunayGraph::SideJobs& alongside = {}, const SlipConstraint* slip = nullptr);

  int GetDimension() const { return this->Graph->GetDimension(); }
  std::size_t GetNumberOfNodes() const { return this->NodeElement.size(); }
  const DelaunayGraph& GetGraph() const { return *this->Graph; }

  /// Mesh node ids of the boundary nodes, increasing (the graph's input points, in order).
  const std::vector<std::int32_t>& GetBoundaryNodes() const { return this->BoundaryNodes; }

  /// The kind of node `i`, as given.
  NodeKind GetNodeKind(std::size_t i) const { return this->Kinds[i]; }
  /// The kinds of all nodes, as given.
  const UninitializedVector<NodeKind>& GetNodeKinds() const { return this->Kinds; }
  /// True if node `i` is a boundary node (a graph vertex).
  bool IsBoundaryNode(std::size_t i) const { return this->NodeElement[i] < 0; }
  /// The graph vertex of boundary node `i` (only valid when IsBoundaryNode(i)).
  std::int32_t GetVertexOfNode(std::size_t i) const { return -this->NodeElement[i] - 1; }
  /// The graph element containing interior node `i` (only valid when !IsBoundaryNode(i)).
  std::int32_t GetElementOfNode(std::size_t i) const { return this->NodeElement[i]; }
  /// Barycentric coordinates of interior node `i` in its element (dim+1 values).
  const double* GetWeights(std::size_t i) const
  {
    return this->Weights.data() + i * static_cast<std::size_t>(this->GetDimension() + 1);
  }

  /// Kind of graph vertex `v`: StaticBoundary or MovingBoundary.
  NodeKind GetVertexKind(std::int32_t v) const
  {
    return this->VertexKind[static_cast<std::size_t>(v)];
  }
  /// The mesh node whose prescribed motion a graph vertex carries.
  std::int32_t GetVertexNode(std::int32_t v) const
  {
    return this->VertexNode[static_cast<std::size_t>(v)];
  }

  /// Number of interior nodes outside the graph's convex hull (interpolated in the hull facet they
  /// project onto).
  std::size_t GetNumberOfOutsideNodes() const { return this->OutsideNodes; }
  /// The slip nodes among them (outside even a hair inside their plane).
  std::size_t GetNumberOfSlipOutsideNodes() const { return this->SlipOutsideNodes; }
  /// Number of interior nodes found from their stride neighbour's element (see hintStride).
  std::size_t GetNumberOfStrideHits() const { return this->StrideHits; }
  /// True when the walks started from a LocationStartGrid because the nodes' numbering is not
  /// spatially coherent (IsNumberingCoherent).
  bool GetLocatedFromStartGrid() const { return this->FromStartGrid; }
  /// Steps of the visibility walks of all interior nodes (not counting CGAL's exact fallback).
  std::size_t GetNumberOfWalkSteps() const { return this->WalkSteps; }
  /// Number of static boundary nodes that coincide with a moving one (they share its vertex).
  std::size_t GetNumberOfConflictingNodes() const { return this->ConflictingNodes; }

  /// Wall-clock seconds spent building the graph (step 1) and locating the nodes (steps 2-3).
  double GetGraphSeconds() const { return this->GraphSeconds; }
  double GetLocationSeconds() const { return this->LocationSeconds; }

  /// Approximate memory used, in bytes.
  std::size_t GetMemorySize() const;

private:
  /// Locates the nodes in waves of `hintStride` nodes, or in one wave (see the constructor).
  void LocateInWaves(const double* points, std::size_t numberOfNodes,
    const ParallelFor& parallelFor, std::size_t hintStride);
  /// Locates every slip node a hair inside the graph (see the constructor's `slip`).
  void LocateSlipNodesInside(
    const double* points, const SlipConstraint& slip, const ParallelFor& parallelFor);
  /// Adds the location blocks' counts to the mapping's.
  void AddCounts(const std::vector<NodeLocationCounts>& counts);

  std::unique_ptr<DelaunayGraph> Graph;
  std::vector<std::int32_t> BoundaryNodes;
  UninitializedVector<NodeKind> Kinds; ///< written in blocks on the threads
  /// >= 0: element of an interior node; < 0: -(vertex + 1) for a boundary node.
  UninitializedVector<std::int32_t> NodeElement;
  UninitializedVector<double> Weights; ///< dim+1 per node
  std::vector<NodeKind> VertexKind;
  std::vector<std::int32_t> VertexNode;
  std::size_t OutsideNodes = 0;
  std::size_t SlipOutsideNodes = 0; ///< slip nodes among the OutsideNodes
  std::size_t StrideHits = 0;
  std::size_t ConflictingNodes = 0;
  std::size_t WalkSteps = 0;
  bool FromStartGrid = false;
  double GraphSeconds = 0.0;
  double LocationSeconds = 0.0;
};

} // namespace dgmf

#endif
