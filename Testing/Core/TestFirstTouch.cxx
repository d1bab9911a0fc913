// The first touch of new memory (dgmf/FirstTouch.h): only the range given is written, large
// arrays are advised huge pages (and only inside their range), and the vector that does not zero
// its new elements still keeps the values it is given.
#include "dgmf/FirstTouch.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace
{
#if defined(__linux__)
/// The VmFlags of the mapping of this process that holds `address` (from /proc/self/smaps), or
/// "" when none does.
std::string MappingFlags(const void* address)
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
bool KernelHasHugePages()
{
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

/// True when the kernel backs every large enough anonymous mapping with huge pages, advised or
/// not (policy "always"): pages beyond an advised range may then be faulted in with it.
bool HugePagesAlways()
{
  std::string policy;
  std::getline(std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"), policy);
  return policy.find("[always]") != std::string::npos;
}

/// Fresh anonymous memory of `bytes` bytes (no page resident), or null.
unsigned char* MapFresh(std::size_t bytes)
{
  void* mapped = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  return mapped == MAP_FAILED ? nullptr : static_cast<unsigned char*>(mapped);
}
#endif
} // namespace

TEST(FirstTouch, WritesNothingOutsideItsRangeWhateverTheAlignment)
{
  // Ranges that start and end inside pages, span several, or are shorter than a page.
  for (const std::size_t offset : { 0u, 1u, 3u, 4095u, 4096u, 5000u })
  {
    for (const std::size_t length : { 0u, 1u, 7u, 4096u, 4097u, 20000u })
    {
      std::vector<std::uint8_t> bytes(offset + length + 9000, 0xab);
      dgmf::FirstTouch(bytes.data() + offset, length);
      for (std::size_t i = 0; i < bytes.size(); ++i)
      {
        if (i < offset || i >= offset + length)
        {
          ASSERT_EQ(bytes[i], 0xab)
            << "offset " << offset << ", length " << length << ", byte " << i;
        }
      }
    }
  }
}

#if defined(__linux__)
TEST(FirstTouch, MakesEveryPageOfItsRangeResidentAndNoOther)
{
  // Fresh anonymous memory: no page is resident until touched. The range starts and ends inside
  // pages, so the pages at both ends are only partly in it.
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t pages = 64;
  void* mapped =
    mmap(nullptr, pages * page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(mapped, MAP_FAILED);
  auto* base = static_cast<unsigned char*>(mapped);
  const std::size_t begin = 3 * page + 100, end = 40 * page + 7; // pages 3 to 40
  dgmf::FirstTouch(base + begin, end - begin);
  std::vector<unsigned char> resident(pages, 0);
  ASSERT_EQ(mincore(mapped, pages * page, resident.data()), 0);
  for (std::size_t p = 0; p < pages; ++p)
  {
    const bool inRange = p >= begin / page && p <= (end - 1) / page;
    EXPECT_EQ((resident[p] & 1) != 0, inRange) << "page " << p;
  }
  for (std::size_t i = begin; i < end; i += 997)
  {
    ASSERT_EQ(base[i], 0) << "byte " << i; // fresh memory reads as zeros after the touch
  }
  munmap(mapped, pages * page);
}
#endif

#if defined(__linux__)
TEST(FirstTouch, MakesEveryPageOfALargeRangeResidentAndNoOtherWithHugePagesAdvised)
{
  // A range of several huge pages that starts and ends inside small pages: the huge pages it is
  // advised must not reach beyond it, even where they would be aligned.
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
  dgmf::FirstTouch(base + begin, end - begin);
  const std::size_t pages = bytes / page;
  std::vector<unsigned char> resident(pages, 0);
  ASSERT_EQ(mincore(base, bytes, resident.data()), 0);
  for (std::size_t p = 0; p < pages; ++p)
  {
    const bool inRange = p >= begin / page && p <= (end - 1) / page;
    ASSERT_EQ((resident[p] & 1) != 0, inRange) << "page " << p << " of " << pages;
  }
  for (std::size_t i = begin; i < end; i += 4093)
  {
    ASSERT_EQ(base[i], 0) << "byte " << i;
  }
  munmap(base, bytes);
}

TEST(FirstTouch, LargeArraysAreAdvisedHugePagesAndSmallOnesAreNot)
{
  if (!KernelHasHugePages())
  {
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  }
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
  EXPECT_EQ(MappingFlags(small + 4096).find(" hg"), std::string::npos)
    << MappingFlags(small + 4096);
  munmap(big, large);
  munmap(small, dgmf::HugePageAdviceBytes);

  // The vector that does not zero its elements asks for the advice when it allocates.
  dgmf::UninitializedVector<double> values;
  values.reserve(large / sizeof(double));
  EXPECT_NE(MappingFlags(values.data() + values.capacity() / 2).find(" hg"), std::string::npos);
}

TEST(FirstTouch, TheAdviceKeepsTheValues)
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
#endif

TEST(FirstTouch, PartsCoverTheRangeOnceInPiecesOfAtMostThePartSize)
{
  // Sizes below, at and around multiples of the part size; parts are appended to what is there.
  const std::size_t part = dgmf::FirstTouchPartBytes;
  for (const std::size_t bytes :
    { std::size_t{ 0 }, std::size_t{ 1 }, part - 1, part, part + 1, 3 * part, 3 * part + 17 })
  {
    std::vector<dgmf::FirstTouchPart> parts{ { nullptr, 5 } };
    char* begin = reinterpret_cast<char*>(std::uintptr_t{ 1 } << 20);
    dgmf::AppendFirstTouchParts(begin, bytes, parts);
    ASSERT_EQ(parts.front().Bytes, 5u);
    ASSERT_EQ(parts.size() - 1, (bytes + part - 1) / part) << bytes << " bytes";
    char* next = begin;
    for (std::size_t k = 1; k < parts.size(); ++k)
    {
      EXPECT_EQ(parts[k].Begin, next) << bytes << " bytes, part " << k;
      EXPECT_GT(parts[k].Bytes, 0u);
      EXPECT_LE(parts[k].Bytes, part);
      next += parts[k].Bytes;
    }
    EXPECT_EQ(next, begin + bytes);
  }
}

TEST(FirstTouch, AnUninitializedVectorKeepsTheValuesItIsGiven)
{
  dgmf::UninitializedVector<double> values(5, 2.5);
  values.resize(8); // the three new values are unspecified
  values.push_back(-1.0);
  ASSERT_EQ(values.size(), 9u);
  for (std::size_t i = 0; i < 5; ++i)
  {
    EXPECT_EQ(values[i], 2.5);
  }
  EXPECT_EQ(values[8], -1.0);
  const dgmf::UninitializedVector<int> copy(values.begin(), values.begin() + 2);
  EXPECT_EQ(copy[1], 2);
}
