/**
 * @file CoincidentPoints.h
 * @brief Points at exactly the same coordinates, found on several threads: the merge of a
 * composite input's blocks at their shared nodes, and the coincident nodes of a mesh.
 */
#ifndef dgmf_CoincidentPoints_h
#define dgmf_CoincidentPoints_h

#include "dgmf/FirstTouch.h"
#include "dgmf/ParallelFor.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/// Points in pieces (a composite input's blocks), numbered one piece after the other: piece k
/// is Counts[k] points at Points[k] (x, y, z each).
struct PointPieces
{
  std::vector<const double*> Points;
  std::vector<std::size_t> Counts;
};

/**
 * For each point of `pieces`, the first point in their order at exactly the same coordinates
 * (-0 and +0 alike): itself when no point before it is there.
 *
 * How: the points are spread over parts of about 16,000 by a hash of their coordinates (a
 * stable counting sort of their hashes and indices: each part keeps the points' order), then
 * each part, on its own thread, goes through an open-addressing table of 8 slots per point (1 MB,
 * in the second-level cache; each slot asked for 16 points ahead), which reads coordinates only
 * when 23 bits of two hashes agree. The parts and blocks
 * depend on the counts only, so the result does not depend on the threads. About 18 bytes per
 * point while it runs, besides the result. The result and the records are allocated unwritten
 * (UninitializedVector, on huge pages when large) and first touched by the threads that fill them.
 */
UninitializedVector<std::int64_t> FirstCoincidentPoints(
  const PointPieces& pieces, const ParallelFor& parallelFor);

/// FirstCoincidentPoints of `count` points in one piece (x, y, z at xyz[3 i]).
UninitializedVector<std::int64_t> FirstCoincidentPoints(
  const double* xyz, std::size_t count, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
