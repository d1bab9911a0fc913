/**
 * @file LocationOrder.h
 * @brief The order in which the nodes of a mesh are located in the Delaunay graph: their own
 * numbering when it is spatially coherent, a spatial order when it is not.
 */
#ifndef dgmf_LocationOrder_h
#define dgmf_LocationOrder_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/NodeKind.h"
#include "dgmf/ParallelFor.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/**
 * True when the mesh numbers its nodes with spatial coherence: of up to CoherenceSamples pairs of
 * consecutive interior nodes (i, i + 1), evenly spread over the numbering, at least half lie in
 * the same or adjacent cells of the graph's seed grid. Mesh generators, structured blocks and
 * renumberings along space-filling curves pass; random permutations and meshes reassembled from
 * many pieces do not. Deterministic (a fixed sample), O(CoherenceSamples).
 */
bool IsNumberingCoherent(const DelaunayGraph& graph, const double* points, const NodeKind* kinds,
  std::size_t numberOfNodes);

/// Pairs of consecutive nodes IsNumberingCoherent looks at.
constexpr std::size_t CoherenceSamples = 4096;

/**
 * The interior nodes in a spatial order: grouped by the graph's seed grid cell, the cells visited
 * along CGAL's Hilbert curve through the grid (Hilbert_sort_middle_policy), the nodes of a cell by
 * the same curve through its 8^3 sub-cells, then by increasing id. Consecutive nodes are then near
 * each other whatever the mesh's numbering, so each visibility walk starts next to its node
 * (LocateNodes). Each node's key (cell rank, sub-cell rank, id) is computed in parallel, in node
 * order; a radix sort of the keys, O(numberOfNodes + cells log cells). The order depends only on
 * the graph and the points.
 */
UninitializedVector<std::int32_t> SpatialLocationOrder(const DelaunayGraph& graph,
  const double* points, const NodeKind* kinds, std::size_t numberOfNodes,
  const ParallelFor& parallelFor);

} // namespace dgmf

#endif
