/**
 * @file ByteMutations.h
 * @brief Seeded mutants of a binary mesh file (Exodus II, CGNS): bytes flipped or set to 0 or 0xff,
 * runs of bytes overwritten, the file cut, a block duplicated. For the hostile-file tests of the
 * readers that go through a format library.
 */
#ifndef dgmf_test_ByteMutations_h
#define dgmf_test_ByteMutations_h

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

namespace dgmf_test
{
/// `bytes` with one to four random mutations drawn from `random`.
inline std::string MutateBytes(std::string bytes, std::mt19937_64& random)
{
  const auto below = [&random](std::size_t n)
  { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
  const std::size_t count = 1 + below(4);
  for (std::size_t k = 0; k < count && bytes.size() > 16; ++k)
  {
    const std::size_t at = below(bytes.size());
    switch (below(5))
    {
      case 0: // one bit
        bytes[at] = static_cast<char>(bytes[at] ^ (1 << below(8)));
        break;
      case 1: // a byte to 0 or 0xff
        bytes[at] = below(2) ? '\0' : static_cast<char>(0xff);
        break;
      case 2: // a run of random bytes
        for (std::size_t j = at, end = std::min(bytes.size(), at + 1 + below(16)); j < end; ++j)
        {
          bytes[j] = static_cast<char>(below(256));
        }
        break;
      case 3: // the file cut
        bytes.resize(at);
        break;
      default: // a block copied over another place
      {
        const std::size_t from = below(bytes.size());
        const std::size_t length =
          std::min({ bytes.size() - from, bytes.size() - at, 1 + below(64) });
        bytes.replace(at, length, bytes.substr(from, length));
      }
    }
  }
  return bytes;
}
/**
 * Writes `count` mutants of the file `valid` (seed `seed`) to `mutant`, one after the other, and
 * calls `check(k)` after writing mutant k.
 */
template <typename Check>
void ForEachMutant(const std::filesystem::path& valid, const std::filesystem::path& mutant,
  int count, std::uint64_t seed, Check check)
{
  std::ifstream in(valid, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::mt19937_64 random(seed);
  for (int k = 0; k < count; ++k)
  {
    {
      std::ofstream out(mutant, std::ios::binary | std::ios::trunc);
      out << MutateBytes(bytes, random);
    }
    check(k);
  }
}
} // namespace dgmf_test

#endif
