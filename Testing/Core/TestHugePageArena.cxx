// The huge-page arena (dgmf/HugePageArena.h): blocks aligned, distinct and kept; a large arena
// made of advised huge pages; its chunks given back when their blocks are; safe on two threads.
#include "dgmf/HugePageArena.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#if defined(__linux__)
#include "FreshPages.h"

using dgmf_test::KernelHasHugePages;
using dgmf_test::MappingFlags;
#endif

namespace
{
struct Block
{
  unsigned char* Bytes;
  std::size_t Size;
};

/// Blocks as CGAL's Compact_container asks for them: 14, 30, 46, ... elements of `element` bytes,
/// until `total` bytes; each filled with its own number.
std::vector<Block> GrowingBlocks(std::size_t element, std::size_t total)
{
  std::vector<Block> blocks;
  std::size_t sum = 0;
  for (std::size_t count = 14; sum < total; count += 16)
  {
    const std::size_t size = (count + 2) * element;
    auto* bytes = static_cast<unsigned char*>(dgmf::AllocateFromHugePageArena(size));
    std::memset(bytes, static_cast<int>(blocks.size() % 251), size);
    blocks.push_back({ bytes, size });
    sum += size;
  }
  return blocks;
}

/// Checks each block's alignment and values (nothing overlapped), then returns it.
void CheckAndReturn(const std::vector<Block>& blocks)
{
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    ASSERT_EQ(reinterpret_cast<std::uintptr_t>(blocks[b].Bytes) % alignof(std::max_align_t), 0u);
    for (std::size_t i = 0; i < blocks[b].Size; i += 61)
    {
      ASSERT_EQ(blocks[b].Bytes[i], b % 251) << "block " << b << ", byte " << i;
    }
    ASSERT_EQ(blocks[b].Bytes[blocks[b].Size - 1], b % 251) << "block " << b;
  }
  for (const Block& block : blocks)
  {
    dgmf::DeallocateToHugePageArena(block.Bytes);
  }
}
} // namespace

TEST(HugePageArena, BlocksAreAlignedAndDistinctAndTheirChunksAreGivenBackWithThem)
{
  const std::size_t before = dgmf::HugePageArenaBytes();
  const std::vector<Block> blocks = GrowingBlocks(72, std::size_t(20) << 20);
  // The chunks hold the blocks, and not much more (chunks grow with the demand).
  EXPECT_GE(dgmf::HugePageArenaBytes() - before, std::size_t(20) << 20);
  EXPECT_LE(dgmf::HugePageArenaBytes() - before, std::size_t(32) << 20);
  CheckAndReturn(blocks);
  EXPECT_EQ(dgmf::HugePageArenaBytes(), before);
  // A block larger than any chunk gets one of its own; an empty size is a block too.
  void* large = dgmf::AllocateFromHugePageArena(std::size_t(20) << 20);
  void* empty = dgmf::AllocateFromHugePageArena(0);
  EXPECT_NE(large, empty);
  dgmf::DeallocateToHugePageArena(large);
  dgmf::DeallocateToHugePageArena(empty);
  dgmf::DeallocateToHugePageArena(nullptr);
  EXPECT_EQ(dgmf::HugePageArenaBytes(), before);
}

TEST(HugePageArena, ImpossibleSizesThrowBadAlloc)
{
  EXPECT_THROW(dgmf::AllocateFromHugePageArena(SIZE_MAX - 64), std::bad_alloc);
  dgmf::HugePageArenaAllocator<double> doubles;
  EXPECT_THROW(doubles.allocate(SIZE_MAX / 4), std::bad_array_new_length);
}

#if defined(__linux__)
TEST(HugePageArena, ALargeArenaIsMadeOfAdvisedHugePages)
{
  unsetenv("DGMF_HUGE_PAGES"); // whatever the environment of the tests says
  if (!KernelHasHugePages())
  {
    GTEST_SKIP() << "no transparent huge pages in this kernel";
  }
  const std::vector<Block> blocks = GrowingBlocks(72, std::size_t(20) << 20);
  // The last blocks lie in chunks of several megabytes: advised, from their first byte to their
  // last (the small blocks of CGAL's containers were faulted in 4 KiB pages).
  for (std::size_t b = blocks.size() - 3; b < blocks.size(); ++b)
  {
    EXPECT_NE(MappingFlags(blocks[b].Bytes).find(" hg"), std::string::npos) << b;
    EXPECT_NE(MappingFlags(blocks[b].Bytes + blocks[b].Size - 1).find(" hg"), std::string::npos)
      << b;
  }
  CheckAndReturn(blocks);
}
#endif

TEST(HugePageArena, TwoThreadsAllocatingAndReturningAtOnceKeepTheirBlocks)
{
  const std::size_t before = dgmf::HugePageArenaBytes();
  const auto work = [](std::size_t element)
  {
    for (int round = 0; round < 4; ++round)
    {
      CheckAndReturn(GrowingBlocks(element, std::size_t(3) << 20));
    }
  };
  std::thread other(work, 40);
  work(72);
  other.join();
  EXPECT_EQ(dgmf::HugePageArenaBytes(), before);
}
