#include "dgmf/HugePages.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace dgmf
{
namespace
{
/// The size of an x86-64 or AArch64 (4 KiB granule) transparent huge page.
constexpr std::uintptr_t HugePage = std::uintptr_t(2) << 20;

/// False when the environment says DGMF_HUGE_PAGES=0 (read at each call: calls are few, one per
/// large array, and tests and comparisons switch it while running).
bool AdviceWanted()
{
  const char* setting = std::getenv("DGMF_HUGE_PAGES");
  return !(setting && std::strcmp(setting, "0") == 0);
}
} // namespace

void AdviseHugePages(void* begin, std::size_t bytes) noexcept
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < HugePageAdviceBytes || !AdviceWanted())
  {
    return;
  }
  const auto start = reinterpret_cast<std::uintptr_t>(begin);
  const std::uintptr_t first = (start + HugePage - 1) / HugePage * HugePage;
  const std::uintptr_t last = (start + bytes) / HugePage * HugePage;
  if (last > first)
  {
    // Advice only: a refusal (EINVAL where THP is not built in) leaves 4 KiB pages.
    (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#else
  (void)begin;
  (void)bytes;
#endif
}

void* AllocateOnHugePages(std::size_t bytes, std::size_t alignment) noexcept
{
  if (bytes > SIZE_MAX - HugePage || alignment > HugePage)
  {
    return nullptr;
  }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= HugePageAllocationBytes && AdviceWanted())
  {
    const std::size_t rounded = (bytes + HugePage - 1) / HugePage * HugePage;
    void* memory = std::aligned_alloc(HugePage, rounded);
    if (memory)
    {
      // Advice only: a refusal (EINVAL where THP is not built in) leaves 4 KiB pages.
      (void)madvise(memory, rounded, MADV_HUGEPAGE);
    }
    return memory;
  }
#endif
  if (alignment > alignof(std::max_align_t))
  {
    return std::aligned_alloc(alignment, (bytes + alignment - 1) / alignment * alignment);
  }
  return std::malloc(bytes == 0 ? 1 : bytes);
}

} // namespace dgmf
