/**
 * @file FreshPages.h
 * @brief Fresh anonymous memory for the first-touch tests (Linux): mapped with no page resident,
 * and the check that exactly the pages of a range became resident, reading as zeros; the flags
 * of the mapping that holds an address (huge pages advised: "hg").
 */
#ifndef dgmf_test_FreshPages_h
#define dgmf_test_FreshPages_h

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace dgmf_test
{

/// Fresh anonymous memory of `bytes` bytes (no page resident until touched), or null.
inline unsigned char* MapFresh(std::size_t bytes)
{
  void* mapped = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  return mapped == MAP_FAILED ? nullptr : static_cast<unsigned char*>(mapped);
}

/// Checks that of the `bytes` bytes mapped at `base`, exactly the pages holding a byte of
/// [begin, end) are resident, and that the range reads as zeros (fresh memory after its touch).
inline void ExpectOnlyRangeResident(
  const unsigned char* base, std::size_t bytes, std::size_t begin, std::size_t end)
{
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t pages = bytes / page;
  std::vector<unsigned char> resident(pages, 0);
  ASSERT_EQ(mincore(const_cast<unsigned char*>(base), bytes, resident.data()), 0);
  for (std::size_t p = 0; p < pages; ++p)
  {
    const bool inRange = p >= begin / page && p <= (end - 1) / page;
    ASSERT_EQ((resident[p] & 1) != 0, inRange) << "page " << p << " of " << pages;
  }
  for (std::size_t i = begin; i < end; i += 997)
  {
    ASSERT_EQ(base[i], 0) << "byte " << i;
  }
}

/// The VmFlags of the mapping of this process that holds `address` (from /proc/self/smaps), or
/// "" when none does.
inline std::string MappingFlags(const void* address)
{
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    std::uintptr_t low = 0, high = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> low >> dash >> high && dash == '-')
    {
      inside = low <= at && at < high;
    }
    else if (inside && line.rfind("VmFlags:", 0) == 0)
    {
      return line;
    }
  }
  return "";
}

/// True when the kernel has transparent huge pages (the advice is then recorded on mappings).
inline bool KernelHasHugePages()
{
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

} // namespace dgmf_test

#endif
