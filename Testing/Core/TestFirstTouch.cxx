// The first touch of new memory (dgmf/FirstTouch.h): only the range given is written, and the
// vector that does not zero its new elements still keeps the values it is given.
#include "dgmf/FirstTouch.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

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
