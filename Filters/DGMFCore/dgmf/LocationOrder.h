/**
 * @file LocationOrder.h
 * @brief How the nodes of a mesh are located in the Delaunay graph: each walk from the previous
 * node's element when the numbering is spatially coherent, from a start grid's element
 * (LocationStartGrid) when it is not; and the Hilbert order of a grid's cells.
 */
#ifndef dgmf_LocationOrder_h
#define dgmf_LocationOrder_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/NodeKind.h"

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

/**
 * The rank of every cell of an nx x ny x nz lattice (index i + nx (j + ny k); nz = 1 in 2D) along
 * CGAL's Hilbert curve through the cells' centres (Hilbert_sort_middle_policy).
 */
std::vector<std::uint32_t> HilbertRanks(const std::int64_t cells[3], int dimension);

/// Pairs of consecutive nodes IsNumberingCoherent looks at.
constexpr std::size_t CoherenceSamples = 4096;

} // namespace dgmf

#endif
