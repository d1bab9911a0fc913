#include "dgmf/ParallelFor.h"

namespace dgmf
{

void SerialFor(std::size_t begin, std::size_t end, std::size_t /*grain*/, const RangeFunction& body)
{
  if (begin < end)
  {
    body(begin, end);
  }
}

void ForEachBlock(const ParallelFor& parallelFor, std::size_t numberOfBlocks,
  const std::function<void(std::size_t)>& body)
{
  const ParallelFor& run = parallelFor ? parallelFor : ParallelFor(SerialFor);
  run(0, numberOfBlocks, 1,
    [&body](std::size_t begin, std::size_t end)
    {
      for (std::size_t block = begin; block < end; ++block)
      {
        body(block);
      }
    });
}

} // namespace dgmf
