#include "dgmf/CoincidentPoints.h"

#include "dgmf/Simd.h"

#include <algorithm>
#include <cstring>

namespace dgmf
{
namespace
{
constexpr std::size_t PointsPerBlock = 1 << 16; // blocks of points hashed and spread in parallel
constexpr std::size_t PointsPerPart = 1 << 14;  // about this many points share a table
constexpr int MaxPartBits = 12;
constexpr int PartShift = 29; // parts from bits 29-40; a table's slots from the lowest bits
constexpr int TagShift = 41;  // and its tags from bits 41-63
constexpr std::size_t PrefetchAhead = 16; // records whose table slot is asked for ahead

/// A hash of the coordinates, -0 as +0 (the same point).
std::uint64_t Hash(const double p[3])
{
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (int c = 0; c < 3; ++c)
  {
    const double value = p[c] == 0.0 ? 0.0 : p[c];
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    h = (h ^ bits) * 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return h;
}

/// A point on its way to its part's table.
struct Record
{
  std::uint64_t Hash;
  std::int64_t Index;
};

/// A block of points of one piece: [Begin, End) in piece Piece, the first numbered First.
struct Block
{
  std::size_t Piece, Begin, End, First;
};
} // namespace

UninitializedVector<std::int64_t> FirstCoincidentPoints(
  const PointPieces& pieces, const ParallelFor& parallelFor)
{
  std::vector<Block> blocks;
  std::vector<std::size_t> pieceFirst{ 0 };
  for (std::size_t k = 0; k < pieces.Counts.size(); ++k)
  {
    for (std::size_t b = 0; b < pieces.Counts[k]; b += PointsPerBlock)
    {
      blocks.push_back(
        { k, b, std::min(pieces.Counts[k], b + PointsPerBlock), pieceFirst.back() + b });
    }
    pieceFirst.push_back(pieceFirst.back() + pieces.Counts[k]);
  }
  const std::size_t count = pieceFirst.back();
  const auto pointAt = [&](std::int64_t index)
  {
    const auto i = static_cast<std::size_t>(index);
    const std::size_t k =
      static_cast<std::size_t>(
        std::upper_bound(pieceFirst.begin(), pieceFirst.end(), i) - pieceFirst.begin()) -
      1;
    return pieces.Points[k] + 3 * (i - pieceFirst[k]);
  };
  int bits = 0;
  while (bits < MaxPartBits && (count >> bits) > PointsPerPart)
  {
    ++bits;
  }
  const std::size_t parts = std::size_t(1) << bits;
  const auto partOf = [&](std::uint64_t h) { return (h >> PartShift) & (parts - 1); };

  // 1. How many points of each block go to each part.
  std::vector<std::size_t> start(blocks.size() * parts, 0); // [block][part]: counts, positions
  ForEachBlock(parallelFor, blocks.size(),
    [&](std::size_t b)
    {
      const Block& block = blocks[b];
      const double* xyz = pieces.Points[block.Piece];
      std::size_t* counts = start.data() + b * parts;
      for (std::size_t i = block.Begin; i < block.End; ++i)
      {
        ++counts[partOf(Hash(xyz + 3 * i))];
      }
    });
  // 2. Parts one after the other, each in the order of the blocks.
  std::vector<std::size_t> partStart(parts + 1, 0);
  std::size_t position = 0;
  for (std::size_t part = 0; part < parts; ++part)
  {
    partStart[part] = position;
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
      const std::size_t n = start[b * parts + part];
      start[b * parts + part] = position;
      position += n;
    }
  }
  partStart[parts] = position;
  // 3. The points' hashes and indices spread over the parts, in their order within each part.
  //    Not initialised: the threads that fill them touch their pages first.
  UninitializedVector<Record> records(count);
  ForEachBlock(parallelFor, blocks.size(),
    [&](std::size_t b)
    {
      const Block& block = blocks[b];
      const double* xyz = pieces.Points[block.Piece];
      std::size_t* next = start.data() + b * parts;
      for (std::size_t i = block.Begin; i < block.End; ++i)
      {
        const std::uint64_t h = Hash(xyz + 3 * i);
        records[next[partOf(h)]++] = { h,
          static_cast<std::int64_t>(block.First + i - block.Begin) };
      }
    });
  // 4. Each part through its own table (slots: -1, or a record's position in the part and 23
  //    bits of its hash): a point found there takes the first one's index.
  UninitializedVector<std::int64_t> first(count);
  ForEachIndex(parallelFor, count, PointsPerBlock,
    [&](std::size_t i) { first[i] = static_cast<std::int64_t>(i); });
  ForEachBlock(parallelFor, parts,
    [&](std::size_t part)
    {
      const Record* part0 = records.data() + partStart[part];
      const std::size_t size = partStart[part + 1] - partStart[part];
      // A table an eighth full at the end: a new point finds an empty slot at once as a rule (at
      // a half, the mispredicted probes took most of the pass's time).
      std::size_t capacity = 16;
      while (capacity < 8 * size)
      {
        capacity *= 2;
      }
      std::vector<std::int64_t> slots(capacity, -1);
      for (std::size_t k = 0; k < size; ++k)
      {
        if (k + PrefetchAhead < size)
        {
          simd::Prefetch(slots.data() + (part0[k + PrefetchAhead].Hash & (capacity - 1)));
        }
        const Record& record = part0[k];
        const auto tag = static_cast<std::int64_t>(record.Hash >> TagShift);
        for (std::size_t slot = record.Hash & (capacity - 1);; slot = (slot + 1) & (capacity - 1))
        {
          if (slots[slot] < 0)
          {
            slots[slot] = (tag << 32) | static_cast<std::int64_t>(k);
            break;
          }
          const Record& kept = part0[slots[slot] & 0xffffffff];
          if ((slots[slot] >> 32) == tag)
          {
            const double* a = pointAt(kept.Index);
            const double* b = pointAt(record.Index);
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2])
            {
              first[static_cast<std::size_t>(record.Index)] = kept.Index;
              break;
            }
          }
        }
      }
    });
  return first;
}

UninitializedVector<std::int64_t> FirstCoincidentPoints(
  const double* xyz, std::size_t count, const ParallelFor& parallelFor)
{
  PointPieces pieces;
  pieces.Points.push_back(xyz);
  pieces.Counts.push_back(count);
  return FirstCoincidentPoints(pieces, parallelFor);
}

} // namespace dgmf
