/**
 * @file NumberingCoherence.h
 * @brief Whether a mesh numbers its nodes with spatial coherence: then each walk of the location
 * starts from the previous node's element; else from a start grid's (LocationStartGrid).
 */
#ifndef dgmf_NumberingCoherence_h
#define dgmf_NumberingCoherence_h

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

/// Pairs of consecutive nodes IsNumberingCoherent looks at.
constexpr std::size_t CoherenceSamples = 4096;

} // namespace dgmf

#endif
