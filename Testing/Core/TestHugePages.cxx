// The advice that large arrays be backed by huge pages (dgmf/HugePages.h): recorded on large
// ranges only, never beyond them, values kept; the vectors grown on huge pages and the first touch
// of a large range (dgmf/FirstTouch.h) with it; allocations made of whole huge pages.
#include "dgmf/FirstTouch.h"
#include "dgmf/HugePages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include "FreshPages.h"

using dgmf_test::ExpectOnlyRangeResident;
using dgmf_test::KernelHasHugePages;
using dgmf_test::MapFresh;
using dgmf_test::MappingFlags;
#endif

namespace
{
#if defined(__linux__)
/// True when the kernel backs every large enough anonymous mapping with huge pages, advised or
/// not (policy "always"): pages beyond an advised range may then be faulted in with it.
bool HugePagesAlways()
{
  std::string policy;
  std::getline(std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"), policy);
  return policy.find("[always]") != std::string::npos;
}

#endif
} // namespace

#if defined(__linux__)
TEST(HugePages, TheFirstTouchOfALargeRangeMakesItsPagesResidentAndNoOther)
{
  // A range of several huge pages that starts and ends inside small pages: the huge pages it is
  // advised must not reach beyond it, even where they would be aligned.
  unsetenv("DGMF_HUGE_PAGES"); // whatever the environment of the tests says
  if (HugePagesAlways())
  {
    GTEST_SKIP() << "huge pages are the kernel's policy for all memory here, advised or not";
  }
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t huge = std::size_t(2) << 20;
  const std::size_t bytes = 8 * huge;
  unsigned char* base = MapFresh(bytes);
  ASSERT_NE(base, nullptr);
  const std::size_t begin = huge - 3 * page + 5, end = 6 * huge + 2 * page + 1;
  // The way the filter first touches large arrays: advised whole, touched in parts.
  std::vector<dgmf::FirstTouchPart> parts;
  dgmf::AppendFirstTouchParts(base + begin, end - begin, parts);
  dgmf::FirstTouchParts(parts, dgmf::SerialFor);
  ExpectOnlyRangeResident(base, bytes, begin, end);
  munmap(base, bytes);
}

TEST(HugePages, LargeArraysAreAdvisedAndSmallOnesAreNot)
{
  if (!KernelHasHugePages())
  {
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  }
  unsetenv("DGMF_HUGE_PAGES"); // whatever the environment of the tests says
  // Separate mappings, so that each one's flags are its own.
  const std::size_t large = 4 * dgmf::HugePageAdviceBytes;
  unsigned char* big = MapFresh(large);
  unsigned char* small = MapFresh(dgmf::HugePageAdviceBytes);
  ASSERT_NE(big, nullptr);
  ASSERT_NE(small, nullptr);
  EXPECT_EQ(MappingFlags(big + large / 2).find(" hg"), std::string::npos);
  dgmf::AdviseHugePages(big + 1, large - 2);
  dgmf::AdviseHugePages(small, dgmf::HugePageAdviceBytes - 1);
  EXPECT_NE(MappingFlags(big + large / 2).find(" hg"), std::string::npos)
    << MappingFlags(big + large / 2);
  // At the first 2 MiB boundary inside the small range, where its advice would have begun.
  const auto smallStart = reinterpret_cast<std::uintptr_t>(small);
  const std::uintptr_t hugePage = std::uintptr_t(2) << 20;
  const unsigned char* firstWhole = small + ((hugePage - smallStart % hugePage) % hugePage);
  EXPECT_EQ(MappingFlags(firstWhole).find(" hg"), std::string::npos) << MappingFlags(firstWhole);
  munmap(big, large);
  munmap(small, dgmf::HugePageAdviceBytes);

  // Not when the environment turns it off.
  unsigned char* off = MapFresh(large);
  ASSERT_NE(off, nullptr);
  setenv("DGMF_HUGE_PAGES", "0", 1);
  dgmf::AdviseHugePages(off, large);
  unsetenv("DGMF_HUGE_PAGES");
  EXPECT_EQ(MappingFlags(off + large / 2).find(" hg"), std::string::npos);
  munmap(off, large);

  // The vector that does not zero its elements asks for the advice when it allocates.
  // (Larger than malloc's largest mapping threshold, 32 MiB: a new mapping, not advised heap.)
  dgmf::UninitializedVector<double> values;
  values.reserve((std::size_t(64) << 20) / sizeof(double));
  EXPECT_NE(MappingFlags(values.data() + values.capacity() / 2).find(" hg"), std::string::npos);
}

TEST(HugePages, TheAdviceKeepsTheValues)
{
  std::vector<std::uint32_t> values(3 * dgmf::HugePageAdviceBytes / sizeof(std::uint32_t));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    values[i] = static_cast<std::uint32_t>(i * 2654435761u);
  }
  dgmf::AdviseHugePages(values.data(), values.size() * sizeof(std::uint32_t));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    ASSERT_EQ(values[i], static_cast<std::uint32_t>(i * 2654435761u)) << i;
  }
}

TEST(HugePages, AVectorGrownOnHugePagesKeepsItsValuesAndGrowsGeometrically)
{
  unsetenv("DGMF_HUGE_PAGES"); // whatever the environment of the tests says
  std::vector<std::int64_t> values{ 7, -3, 11 };
  dgmf::ReserveOnHugePages(values, 2); // room enough already: nothing changes
  EXPECT_EQ(values.capacity(), 3u);
  // Larger than malloc's largest mapping threshold (32 MiB), so that the memory is a new mapping,
  // not heap that an earlier test may have advised.
  const std::size_t large = (std::size_t(64) << 20) / sizeof(std::int64_t) + 5;
  dgmf::ResizeOnHugePages(values, large);
  ASSERT_EQ(values.size(), large);
  EXPECT_EQ(values[0], 7);
  EXPECT_EQ(values[1], -3);
  EXPECT_EQ(values[2], 11);
  for (std::size_t i = 3; i < large; ++i)
  {
    ASSERT_EQ(values[i], 0) << i; // value-initialised, as by resize()
  }
  if (KernelHasHugePages())
  {
    EXPECT_NE(MappingFlags(values.data() + large / 2).find(" hg"), std::string::npos);
  }
  // Growing one element at a time reallocates a logarithmic number of times, as std::vector.
  std::vector<std::uint8_t> bytes;
  std::size_t reallocations = 0;
  for (std::size_t n = 1; n <= 100000; ++n)
  {
    const std::uint8_t* before = bytes.data();
    dgmf::ResizeOnHugePages(bytes, n);
    bytes[n - 1] = static_cast<std::uint8_t>(n);
    reallocations += bytes.data() != before;
  }
  EXPECT_LE(reallocations, 20u);
  for (std::size_t n = 1; n <= 100000; n += 997)
  {
    ASSERT_EQ(bytes[n - 1], static_cast<std::uint8_t>(n)) << n;
  }
}

TEST(HugePages, AllocationsFromAMebibyteUpAreWholeAdvisedHugePages)
{
  unsetenv("DGMF_HUGE_PAGES"); // whatever the environment of the tests says
  const std::uintptr_t hugePage = std::uintptr_t(2) << 20;
  // Just above the size, so that the last page is mostly beyond what was asked for: the first
  // and the last byte lie in advised memory, so no part of the array is faulted in 4 KiB pages.
  const std::size_t bytes = dgmf::HugePageAllocationBytes + 2 * hugePage + 12345;
  auto* memory = static_cast<unsigned char*>(dgmf::AllocateOnHugePages(bytes));
  ASSERT_NE(memory, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % hugePage, 0u);
  if (KernelHasHugePages())
  {
    EXPECT_NE(MappingFlags(memory).find(" hg"), std::string::npos) << MappingFlags(memory);
    EXPECT_NE(MappingFlags(memory + bytes - 1).find(" hg"), std::string::npos)
      << MappingFlags(memory + bytes - 1);
  }
  std::fill_n(memory, bytes, static_cast<unsigned char>(7));
  EXPECT_EQ(memory[bytes - 1], 7);
  std::free(memory);

  // Small ones are malloc's, at the alignment asked for.
  for (const std::size_t alignment : { std::size_t(8), std::size_t(16), std::size_t(128) })
  {
    void* small = dgmf::AllocateOnHugePages(1000, alignment);
    ASSERT_NE(small, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small) % alignment, 0u) << alignment;
    std::free(small);
  }

  // Nothing advised when the environment turns it off (64 MiB: beyond malloc's largest mapping
  // threshold, a new mapping, not heap that an earlier allocation may have advised).
  setenv("DGMF_HUGE_PAGES", "0", 1);
  const std::size_t large = std::size_t(64) << 20;
  auto* off = static_cast<unsigned char*>(dgmf::AllocateOnHugePages(large));
  unsetenv("DGMF_HUGE_PAGES");
  ASSERT_NE(off, nullptr);
  EXPECT_EQ(MappingFlags(off + large / 2).find(" hg"), std::string::npos);
  std::free(off);
}

TEST(HugePages, TheUninitialisedVectorKeepsItsElementsAlignment)
{
  unsetenv("DGMF_HUGE_PAGES"); // whatever the environment of the tests says
  struct alignas(128) Padded
  {
    double Value[3];
  };
  for (const std::size_t count : { std::size_t(3), std::size_t(40000) }) // 384 B and 5 MB
  {
    dgmf::UninitializedVector<Padded> values(count);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % alignof(Padded), 0u) << count;
    values.back().Value[2] = 1.5;
    values.push_back(values.back()); // grows: the old storage freed as it was allocated
    EXPECT_EQ(values.back().Value[2], 1.5);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % alignof(Padded), 0u) << count;
  }
}
#endif
