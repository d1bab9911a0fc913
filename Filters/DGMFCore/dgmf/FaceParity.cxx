#include "dgmf/FaceParity.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace dgmf
{
namespace
{
constexpr std::size_t CellsPerBlock = 1 << 14;

/// splitmix64's finaliser: a bijective mix of 64 bits.
std::uint64_t Mix64(std::uint64_t x)
{
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The two 64-bit halves of a hash (independent seeds).
struct Hash128
{
  std::uint64_t Low = 0;
  std::uint64_t High = 0;

  bool operator==(const Hash128& o) const { return this->Low == o.Low && this->High == o.High; }
  bool operator<(const Hash128& o) const
  {
    return this->Low < o.Low || (this->Low == o.Low && this->High < o.High);
  }
};

/// Whether two of `hashes` are equal (a cell with two faces of the same points).
bool HasTwinFaces(std::vector<Hash128>& hashes)
{
  if (hashes.size() <= 8)
  {
    for (std::size_t a = 1; a < hashes.size(); ++a)
    {
      for (std::size_t b = 0; b < a; ++b)
      {
        if (hashes[a] == hashes[b])
        {
          return true;
        }
      }
    }
    return false;
  }
  std::sort(hashes.begin(), hashes.end());
  return std::adjacent_find(hashes.begin(), hashes.end()) != hashes.end();
}
} // namespace

bool FacesPairUp(const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor)
{
  // A face's hash is the sum of its points' mixes (and of its number of points, mixed), so
  // neither order nor start matters; a standard shape's corners are mixed once per cell.
  std::array<Hash128, 16> countHash; // the mix of a face's number of points, for the usual ones
  for (std::size_t n = 0; n < countHash.size(); ++n)
  {
    countHash[n] = { Mix64(n), 0 };
  }
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  const std::size_t blocks = (numberOfCells + CellsPerBlock - 1) / CellsPerBlock;
  std::vector<Hash128> sums(blocks);
  std::vector<std::uint8_t> refused(blocks, 0); // twin faces, or a point id out of range
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      std::vector<std::int64_t> stream;
      std::vector<std::int64_t> corners;
      std::vector<Hash128> cornerHash;
      std::vector<Hash128> faces;
      Hash128 sum;
      bool refuse = false; // written to `refused` once: its bytes are shared by the threads
      const auto hashOf = [&](std::int64_t id)
      {
        if (id < 0 || static_cast<std::size_t>(id) >= numberOfPoints)
        {
          refuse = true;
          return Hash128();
        }
        const auto p = static_cast<std::uint64_t>(id);
        return Hash128{ Mix64(p ^ 0x6a09e667f3bcc908ULL), Mix64(p ^ 0xbb67ae8584caa73bULL) };
      };
      // Each face of a stream whose ids `hashAt(id)` turns into hashes.
      const auto addFaces = [&](const std::int64_t* faceStream, const auto& hashAt)
      {
        faces.clear();
        for (std::int64_t f = 0, at = 1; f < faceStream[0]; ++f, at += 1 + faceStream[at])
        {
          const std::int64_t count = faceStream[at];
          if (count <= 0)
          {
            continue;
          }
          Hash128 face = static_cast<std::size_t>(count) < countHash.size()
            ? countHash[static_cast<std::size_t>(count)]
            : Hash128{ Mix64(static_cast<std::uint64_t>(count)), 0 };
          for (std::int64_t k = 0; k < count; ++k)
          {
            const Hash128 point = hashAt(faceStream[at + 1 + k]);
            face.Low += point.Low;
            face.High += point.High;
          }
          faces.push_back(face);
          sum.Low ^= face.Low;
          sum.High ^= face.High;
        }
        refuse = refuse || HasTwinFaces(faces);
      };
      const std::size_t end = std::min(numberOfCells, (block + 1) * CellsPerBlock);
      for (std::size_t c = block * CellsPerBlock; c < end && !refuse; ++c)
      {
        if (const std::int64_t* local = cells.GetCornerFaces(c, corners))
        {
          // A standard shape: each corner's hash once.
          cornerHash.resize(corners.size());
          for (std::size_t k = 0; k < corners.size(); ++k)
          {
            cornerHash[k] = hashOf(corners[k]);
          }
          addFaces(local, [&](std::int64_t k) { return cornerHash[static_cast<std::size_t>(k)]; });
          continue;
        }
        cells.GetFaces(c, stream);
        if (!stream.empty())
        {
          addFaces(stream.data(), hashOf);
        }
      }
      refused[block] = refuse ? 1 : 0;
      sums[block] = sum;
    });
  Hash128 total;
  for (std::size_t block = 0; block < blocks; ++block)
  {
    if (refused[block])
    {
      return false;
    }
    total.Low ^= sums[block].Low;
    total.High ^= sums[block].High;
  }
  return total.Low == 0 && total.High == 0;
}

} // namespace dgmf
