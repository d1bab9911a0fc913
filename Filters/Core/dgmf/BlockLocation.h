/**
 * @file BlockLocation.h
 * @brief Locates a block of mesh nodes in the Delaunay graph with several interleaved walks.
 */
#ifndef dgmf_BlockLocation_h
#define dgmf_BlockLocation_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/NodeKind.h"

#include <cstddef>
#include <cstdint>

namespace dgmf
{

/// What the location of a block counted.
struct BlockLocationCounts
{
  std::size_t Outside = 0;  ///< nodes outside the graph's convex hull
  std::size_t Restarts = 0; ///< walks started from the graph's seed grid
};

/**
 * Finds the element and barycentric coordinates of every interior node in [begin, end).
 *
 * The block is cut into Lanes runs of consecutive nodes. Each run starts from the graph's seed
 * element for its first node (DelaunayGraph::GetSeedElement); every later node of the run walks
 * from the element of the run's previous node (mesh generators number nodes with spatial
 * coherence, so that is a few steps), and if that walk takes more than a few steps (a jump in the
 * numbering) it restarts from the seed element. CGAL's exact location is the fallback when a walk
 * from the seed leaves the hull or does not end.
 *
 * A walk step is a cache miss into the graph, so the runs advance in turn, one step each, with the
 * next element of each run prefetched: the processor loads several elements at once instead of
 * waiting for each. A node's result depends only on its run, never on the timing of the others,
 * so it is the same for any number of threads.
 *
 * @param points 3 coordinates per mesh node (z ignored in 2D)
 * @param nodeElement output: the element of each interior node of the block
 * @param weights output: dim+1 barycentric coordinates per node (node i at i * (dim + 1))
 */
BlockLocationCounts LocateBlock(const DelaunayGraph& graph, const double* points, const NodeKind* kinds,
  std::size_t begin, std::size_t end, std::int32_t* nodeElement, double* weights);

} // namespace dgmf

#endif
