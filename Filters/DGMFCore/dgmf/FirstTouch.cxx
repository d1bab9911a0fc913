#include "dgmf/FirstTouch.h"

#include <cstdint>

namespace dgmf
{
namespace
{
/// The smallest page size of the platforms the core runs on: touching more often than once per
/// page costs a store, touching less often would leave pages unfaulted.
constexpr std::size_t Page = 4096;
} // namespace

void FirstTouch(void* begin, std::size_t bytes)
{
  // A zero at the start of the range and at each page boundary inside it: every page is faulted
  // once, for writing (reading first would map the shared zero page, then copy it on the write:
  // two faults a page, measured 4 times slower beside CGAL's insertion).
  volatile unsigned char* bytesOf = static_cast<unsigned char*>(begin);
  if (bytes == 0)
  {
    return;
  }
  bytesOf[0] = 0;
  const std::size_t toNextPage = (Page - reinterpret_cast<std::uintptr_t>(begin) % Page) % Page;
  for (std::size_t offset = toNextPage; offset < bytes; offset += Page)
  {
    bytesOf[offset] = 0;
  }
}

} // namespace dgmf
