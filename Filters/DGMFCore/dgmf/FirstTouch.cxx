#include "dgmf/FirstTouch.h"

#include <algorithm>
#include <atomic>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace dgmf
{
namespace
{
/// The smallest page size of the platforms the core runs on: touching more often than once per
/// page costs a store, touching less often would leave pages unfaulted.
constexpr std::size_t Page = 4096;

#if defined(__linux__)
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23 // Linux 5.14 and later; older C libraries do not name it
#endif
/// Cleared once the kernel has refused MADV_POPULATE_WRITE (before Linux 5.14): stores then.
std::atomic<bool> PopulateWorks{ true };

/// Asks the kernel to fault in the whole pages of the range for writing, in one call: on this
/// project's machines a fifth cheaper per page than a fault per page. False when it could not.
bool Populate(void* begin, std::size_t bytes)
{
  const auto start = reinterpret_cast<std::uintptr_t>(begin);
  const std::uintptr_t first = (start + Page - 1) / Page * Page;
  const std::uintptr_t last = (start + bytes) / Page * Page;
  if (last <= first)
  {
    return true; // no whole page: the stores at both ends do it
  }
  if (!PopulateWorks.load(std::memory_order_relaxed))
  {
    return false;
  }
  if (madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE) == 0)
  {
    return true;
  }
  PopulateWorks.store(false, std::memory_order_relaxed);
  return false;
}
#else
bool Populate(void*, std::size_t)
{
  return false;
}
#endif
} // namespace

void FirstTouch(void* begin, std::size_t bytes)
{
  if (bytes == 0)
  {
    return;
  }
  // A store into the first and the last page (which may be partly outside the whole pages that
  // Populate faults in), and when the kernel cannot populate, a store at each page boundary:
  // every page is faulted once, for writing (reading first would map the shared zero page, then
  // copy it on the write: two faults a page, measured 4 times slower beside CGAL's insertion).
  volatile unsigned char* bytesOf = static_cast<unsigned char*>(begin);
  bytesOf[0] = 0;
  bytesOf[bytes - 1] = 0;
  if (Populate(begin, bytes))
  {
    return;
  }
  const std::size_t toNextPage = (Page - reinterpret_cast<std::uintptr_t>(begin) % Page) % Page;
  for (std::size_t offset = toNextPage; offset < bytes; offset += Page)
  {
    bytesOf[offset] = 0;
  }
}

void AppendFirstTouchParts(void* begin, std::size_t bytes, std::vector<FirstTouchPart>& parts)
{
  // The whole range, once, on the caller's thread: the parts' ends need not fall on huge pages,
  // and the advice takes the address space's lock for writing, which the parts' threads must not
  // contend for beside CGAL's insertion (see DelaunayGraph.cxx, ReserveStorage).
  AdviseHugePages(begin, bytes);
  for (std::size_t offset = 0; offset < bytes; offset += FirstTouchPartBytes)
  {
    parts.push_back(
      { static_cast<char*>(begin) + offset, std::min(FirstTouchPartBytes, bytes - offset) });
  }
}

void FirstTouchParts(const std::vector<FirstTouchPart>& parts, const ParallelFor& parallelFor)
{
  ForEachBlock(parallelFor, parts.size(),
    [&parts](std::size_t k) { FirstTouch(parts[k].Begin, parts[k].Bytes); });
}

} // namespace dgmf
