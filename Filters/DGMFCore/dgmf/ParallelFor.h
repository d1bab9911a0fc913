/**
 * @file ParallelFor.h
 * @brief How the core runs loops over index ranges, without depending on a thread library.
 *
 * The core never starts threads itself. Every loop that may run in parallel takes a ParallelFor,
 * which the caller supplies: the VTK adapter passes one built on vtkSMPTools, tests and
 * command-line tools may use SerialFor. Work is always split into fixed blocks by the core, so
 * results do not depend on how (or whether) the blocks are spread over threads.
 */
#ifndef dgmf_ParallelFor_h
#define dgmf_ParallelFor_h

#include <algorithm>
#include <cstddef>
#include <functional>

namespace dgmf
{

/// A loop body over the half-open index range [begin, end).
using RangeFunction = std::function<void(std::size_t begin, std::size_t end)>;

/**
 * Runs `body` over [begin, end), possibly in several threads, in chunks of about `grain` indices.
 * Chunks must not overlap and must cover the range.
 */
using ParallelFor = std::function<void(
  std::size_t begin, std::size_t end, std::size_t grain, const RangeFunction& body)>;

/// Runs the whole range in the calling thread.
void SerialFor(std::size_t begin, std::size_t end, std::size_t grain, const RangeFunction& body);

/**
 * Runs `body(block)` for every block index in [0, numberOfBlocks): a convenience over ParallelFor
 * for code whose result must not depend on the chunking.
 */
void ForEachBlock(const ParallelFor& parallelFor, std::size_t numberOfBlocks,
  const std::function<void(std::size_t)>& body);

/**
 * Runs `body(i)` for every index i in [0, count), in fixed blocks of `blockSize` indices that may
 * run in parallel (the split does not depend on the number of threads, so neither does a result
 * that depends only on i).
 */
template <typename Body>
void ForEachIndex(
  const ParallelFor& parallelFor, std::size_t count, std::size_t blockSize, Body&& body)
{
  ForEachBlock(parallelFor, (count + blockSize - 1) / blockSize,
    [&](std::size_t block)
    {
      const std::size_t end = std::min(block * blockSize + blockSize, count);
      for (std::size_t i = block * blockSize; i < end; ++i)
      {
        body(i);
      }
    });
}

} // namespace dgmf

#endif
