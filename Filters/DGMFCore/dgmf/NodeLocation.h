/**
 * @file NodeLocation.h
 * @brief Locates a block of mesh nodes in the Delaunay graph with several interleaved walks.
 */
#ifndef dgmf_NodeLocation_h
#define dgmf_NodeLocation_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/NodeKind.h"

#include <cstddef>
#include <cstdint>

namespace dgmf
{

/// What the location of a block counted.
struct NodeLocationCounts
{
  std::size_t Outside = 0;     ///< nodes outside the graph's convex hull
  std::size_t SlipOutside = 0; ///< those of them that are slip nodes (NodeKind::SlipBoundary)
  std::size_t Restarts = 0;    ///< walks started from the graph's seed grid
  std::size_t StrideHits = 0;  ///< nodes found by the walk from their stride neighbour's element
  std::size_t Steps = 0;       ///< steps of the visibility walks (elements crossed)
};

/**
 * Finds the element and barycentric coordinates of every interior node in [begin, end).
 *
 * The block is cut into Lanes runs of consecutive nodes. A node's walk starts from:
 * - the element of node i - `stride` (the "stride neighbour"; 0 = none) when that node is
 *   interior and already located: before `locatedBefore`, or in this block. Structured
 *   and layered meshes number a node's neighbour across the layers at a fixed stride, and the
 *   graph's elements, long slivers from the body to the far field, usually contain both. A walk
 *   from it that takes more than a few steps starts again from:
 * - the element of the run's previous node (mesh generators number nodes with spatial coherence,
 *   so that is a few steps), and if that takes more than a few steps (a jump in the numbering):
 * - the graph's seed element (DelaunayGraph::GetSeedElement), which also starts each run.
 * With `startElements` (a numbering without spatial coherence, whose previous node is anywhere),
 * every walk starts from the element given for its node instead (a negative entry: the starts
 * above). CGAL's exact location is the fallback when a walk from the seed leaves the hull or does
 * not end. A block that finds the stride neighbour mostly far away stops using it.
 *
 * A walk step is a cache miss into the graph, so the runs advance in turn, one step each, with the
 * next element of each run prefetched: the processor loads several elements at once instead of
 * waiting for each. A node's result depends only on its run and on nodes before `locatedBefore`,
 * never on the timing of other blocks, so it is the same for any number of threads.
 *
 * @param points 3 coordinates per mesh node (z ignored in 2D)
 * @param nodeElement in: the elements of the nodes before `locatedBefore`, and
 *   DelaunayMapping::NotLocated for the block's interior nodes; out: their elements
 * @param weights output: dim+1 barycentric coordinates per node (node i at i * (dim + 1))
 * @param startElements when given, the walk of interior node i starts from element
 *   startElements[i - begin] (LocationStartGrid::GetStartElements); `stride` must then be 0.
 */
NodeLocationCounts LocateNodes(const DelaunayGraph& graph, const double* points,
  const NodeKind* kinds, std::size_t begin, std::size_t end, std::int32_t* nodeElement,
  double* weights, std::size_t stride = 0, std::size_t locatedBefore = 0,
  const std::int32_t* startElements = nullptr);

} // namespace dgmf

#endif
