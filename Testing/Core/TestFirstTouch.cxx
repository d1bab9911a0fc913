// The first touch of new memory (dgmf/FirstTouch.h): only the range given is written, and the
// vector that does not zero its new elements still keeps the values it is given.
#include "dgmf/FirstTouch.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#if defined(__linux__)
#include "FreshPages.h"
#endif

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
  const std::size_t bytes = 64 * page;
  unsigned char* base = dgmf_test::MapFresh(bytes);
  ASSERT_NE(base, nullptr);
  const std::size_t begin = 3 * page + 100, end = 40 * page + 7; // pages 3 to 40
  dgmf::FirstTouch(base + begin, end - begin);
  dgmf_test::ExpectOnlyRangeResident(base, bytes, begin, end);
  munmap(base, bytes);
}
#endif

TEST(FirstTouch, PartsCoverTheRangeOnceInPiecesOfAtMostThePartSize)
{
  // Sizes below, at and around multiples of the part size; parts are appended to what is there.
  const std::size_t part = dgmf::FirstTouchPartBytes;
  // Memory of this process's own (the parts are advised huge pages; nothing is written).
  std::vector<char> room;
  room.reserve(3 * part + 17);
  for (const std::size_t bytes :
    { std::size_t{ 0 }, std::size_t{ 1 }, part - 1, part, part + 1, 3 * part, 3 * part + 17 })
  {
    std::vector<dgmf::FirstTouchPart> parts{ { nullptr, 5 } };
    char* begin = room.data();
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
