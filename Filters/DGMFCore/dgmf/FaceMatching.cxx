#include "dgmf/FaceMatching.h"

#include "dgmf/CellFaces.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

namespace dgmf
{
namespace
{
constexpr std::size_t CellChunks = 64;        // blocks of cells read in parallel
constexpr std::size_t PointsPerBlock = 16384; // blocks of buckets matched in parallel

/**
 * A face as the matching sees it, in the bucket of its smallest point id: its next three point
 * ids in increasing order (the largest value where the face has fewer), so that two faces of at
 * most 4 points with the same keys are the same face; faces with more points put a hash of the
 * rest in the third key and are compared point by point. `Id` is 32 bits when every point and
 * cell id fits.
 */
template <typename Id>
struct FaceRecord
{
  Id Key[3];
  Id Cell;
  std::uint16_t Face;
  std::uint16_t Count; ///< number of points of the face

  bool SameKey(const FaceRecord& o) const
  {
    return this->Count == o.Count && this->Key[0] == o.Key[0] && this->Key[1] == o.Key[1] &&
      this->Key[2] == o.Key[2];
  }
  bool operator<(const FaceRecord& o) const
  {
    return std::tie(this->Count, this->Key[0], this->Key[1], this->Key[2], this->Cell, this->Face) <
      std::tie(o.Count, o.Key[0], o.Key[1], o.Key[2], o.Cell, o.Face);
  }
};

std::uint64_t Mix(std::uint64_t h, std::uint64_t v)
{
  h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  h ^= h >> 31;
  return h * 0xbf58476d1ce4e5b9ULL;
}

/// The record of a face of `count` point ids (checked before); `smallest` gets its bucket.
template <typename Id>
FaceRecord<Id> MakeRecord(const std::int64_t* ids, std::int64_t count, std::size_t cell,
  std::size_t face, std::size_t& smallest)
{
  FaceRecord<Id> record;
  if (count <= 4)
  {
    // The ids sorted by insertion; missing ones are the largest value.
    const Id none = std::numeric_limits<Id>::max();
    Id key[4] = { none, none, none, none };
    for (std::int64_t k = 0; k < count; ++k)
    {
      const Id v = static_cast<Id>(ids[k]);
      std::int64_t at = k;
      for (; at > 0 && key[at - 1] > v; --at)
      {
        key[at] = key[at - 1];
      }
      key[at] = v;
    }
    smallest = static_cast<std::size_t>(key[0]);
    std::copy(key + 1, key + 4, record.Key);
  }
  else
  {
    thread_local std::vector<std::int64_t> sorted;
    sorted.assign(ids, ids + count);
    std::sort(sorted.begin(), sorted.end());
    std::uint64_t h = 0;
    for (std::size_t k = 3; k < sorted.size(); ++k)
    {
      h = Mix(h, static_cast<std::uint64_t>(sorted[k]));
    }
    smallest = static_cast<std::size_t>(sorted[0]);
    record.Key[0] = static_cast<Id>(sorted[1]);
    record.Key[1] = static_cast<Id>(sorted[2]);
    record.Key[2] = static_cast<Id>(h);
  }
  record.Cell = static_cast<Id>(cell);
  record.Face = static_cast<std::uint16_t>(face);
  record.Count = static_cast<std::uint16_t>(count);
  return record;
}

/// What the matching of a block of buckets reports: pairs and unpaired faces.
struct MatchSink
{
  bool KeepPairs = true; // false: only the unpaired faces are wanted
  std::vector<std::tuple<std::int64_t, std::int64_t, std::int32_t>> Pairs; // owner, other, face
  std::vector<std::pair<std::int64_t, std::int32_t>> Single;               // cell, face

  template <typename Record>
  void AddPair(const Record& owner, const Record& other)
  {
    if (this->KeepPairs)
    {
      this->Pairs.emplace_back(owner.Cell, other.Cell, owner.Face);
    }
  }
};

/// Two faces of more than 4 points with the same keys: the same points?
bool SamePoints(const FaceCells& cells, std::size_t cellA, std::int32_t faceA, std::size_t cellB,
  std::int32_t faceB)
{
  thread_local std::vector<std::int64_t> stream, a, b;
  std::int64_t n = 0;
  cells.GetFaces(cellA, stream);
  const std::int64_t* ids = FaceOfStream(stream.data(), faceA, n);
  a.assign(ids, ids + n);
  cells.GetFaces(cellB, stream);
  ids = FaceOfStream(stream.data(), faceB, n);
  b.assign(ids, ids + n);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

/// Pairs the faces of one group of equal keys, in their order (cell, then face).
template <typename Id>
void PairGroup(const FaceCells& cells, const FaceRecord<Id>* group, std::size_t size,
  MatchSink& sink, std::vector<std::uint8_t>& paired)
{
  if (size == 1)
  {
    sink.Single.emplace_back(group[0].Cell, group[0].Face);
    return;
  }
  if (size == 2 && group[0].Cell != group[1].Cell && group[0].Count <= 4)
  {
    sink.AddPair(group[0], group[1]);
    return;
  }
  paired.assign(size, 0);
  for (std::size_t a = 0; a < size; ++a)
  {
    if (paired[a])
    {
      continue;
    }
    for (std::size_t b = a + 1; b < size; ++b)
    {
      if (!paired[b] && group[b].Cell != group[a].Cell &&
        (group[a].Count <= 4 ||
          SamePoints(cells, group[a].Cell, group[a].Face, group[b].Cell, group[b].Face)))
      {
        paired[a] = paired[b] = 1;
        sink.AddPair(group[a], group[b]);
        break;
      }
    }
    if (!paired[a])
    {
      sink.Single.emplace_back(group[a].Cell, group[a].Face);
    }
  }
}

/**
 * Every face in the bucket of its smallest point id (a count, then a fill, both on the cells'
 * blocks in parallel, with atomic bucket positions), then each bucket sorted and its equal faces
 * paired. The order within a bucket after the fill depends on the threads; sorted by key, cell and
 * face, it does not.
 */
template <typename Id>
std::vector<MatchSink> MatchAll(const FaceCells& cells, std::size_t numberOfPoints,
  const ParallelFor& parallelFor, bool keepPairs)
{
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  const std::size_t cellsPerChunk = (numberOfCells + CellChunks - 1) / CellChunks;
  // For each face of the cells of a block, `body(cell, face, ids, count)`.
  const auto forEachFace = [&](const auto& body)
  {
    ForEachBlock(parallelFor, CellChunks,
      [&](std::size_t k)
      {
        std::vector<std::int64_t> stream, faceIds;
        const std::size_t end = std::min(numberOfCells, (k + 1) * cellsPerChunk);
        ForEachCellFaceStream(cells, k * cellsPerChunk, end, stream,
          [&](std::size_t c, const std::int64_t* faceStream, const std::int64_t* corners)
          {
            for (std::int64_t f = 0, at = 1; faceStream && f < faceStream[0];
                 ++f, at += 1 + faceStream[at])
            {
              const std::int64_t n = faceStream[at];
              if (n <= 0)
              {
                continue;
              }
              const std::int64_t* ids = &faceStream[at + 1];
              if (corners) // positions in the cell's corners
              {
                faceIds.resize(static_cast<std::size_t>(n));
                for (std::int64_t j = 0; j < n; ++j)
                {
                  faceIds[static_cast<std::size_t>(j)] = corners[ids[j]];
                }
                ids = faceIds.data();
              }
              body(c, static_cast<std::size_t>(f), ids, n);
            }
          });
      });
  };
  // 1. The size of each bucket.
  std::unique_ptr<std::atomic<std::uint64_t>[]> next(
    new std::atomic<std::uint64_t>[numberOfPoints + 1]);
  ForEachIndex(parallelFor, numberOfPoints + 1, 1 << 16,
    [&](std::size_t p) { next[p].store(0, std::memory_order_relaxed); });
  forEachFace(
    [&](std::size_t c, std::size_t f, const std::int64_t* ids, std::int64_t count)
    {
      const std::int64_t smallest = *std::min_element(ids, ids + count);
      const std::int64_t largest = *std::max_element(ids, ids + count);
      if (smallest < 0 || static_cast<std::size_t>(largest) >= numberOfPoints)
      {
        throw std::invalid_argument("Cell " + std::to_string(c) + " uses point id " +
          std::to_string(smallest < 0 ? smallest : largest) + ", outside 0 .. " +
          std::to_string(numberOfPoints - 1) + ".");
      }
      if (f > std::numeric_limits<std::uint16_t>::max() ||
        count > std::numeric_limits<std::uint16_t>::max())
      {
        throw std::invalid_argument(
          "Cell " + std::to_string(c) + " has more than 65,535 faces or face points.");
      }
      next[static_cast<std::size_t>(smallest)].fetch_add(1, std::memory_order_relaxed);
    });
  // 2. Bucket p starts where bucket p - 1 ends; the fill moves each start to its bucket's end.
  std::uint64_t total = 0;
  for (std::size_t p = 0; p <= numberOfPoints; ++p)
  {
    const std::uint64_t size = next[p].load(std::memory_order_relaxed);
    next[p].store(total, std::memory_order_relaxed);
    total += size;
  }
  // Not initialised (a GB on large meshes).
  std::unique_ptr<FaceRecord<Id>[]> records(new FaceRecord<Id>[total]);
  // Its pages faulted in parts on the threads first: the fill writes it scattered by bucket, and
  // its page faults from both threads waited on each other (0.05 s more at 49M records).
  {
    std::vector<FirstTouchPart> parts;
    AppendFirstTouchParts(records.get(), total * sizeof(FaceRecord<Id>), parts);
    FirstTouchParts(parts, parallelFor);
  }
  forEachFace(
    [&](std::size_t c, std::size_t f, const std::int64_t* ids, std::int64_t count)
    {
      std::size_t smallest = 0;
      const FaceRecord<Id> record = MakeRecord<Id>(ids, count, c, f, smallest);
      records[next[smallest].fetch_add(1, std::memory_order_relaxed)] = record;
    });
  // 3. Each bucket [end of p - 1, end of p): sorted, equal faces paired.
  const std::size_t blocks = (numberOfPoints + PointsPerBlock - 1) / PointsPerBlock;
  std::vector<MatchSink> sinks(blocks);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      MatchSink& sink = sinks[block];
      sink.KeepPairs = keepPairs;
      std::vector<std::uint8_t> paired;
      const std::size_t end = std::min(numberOfPoints, (block + 1) * PointsPerBlock);
      if (keepPairs && end > block * PointsPerBlock)
      {
        // At most one pair per two of the block's records: no growth (copies and their page
        // faults: a tenth of the first run's faults at 8.2M hexahedra).
        const std::size_t begin = block * PointsPerBlock;
        const std::uint64_t first =
          begin == 0 ? 0 : next[begin - 1].load(std::memory_order_relaxed);
        sink.Pairs.reserve(
          static_cast<std::size_t>(next[end - 1].load(std::memory_order_relaxed) - first) / 2);
      }
      for (std::size_t p = block * PointsPerBlock; p < end; ++p)
      {
        const std::uint64_t first = p == 0 ? 0 : next[p - 1].load(std::memory_order_relaxed);
        FaceRecord<Id>* bucket = records.get() + first;
        const auto size = static_cast<std::size_t>(next[p].load(std::memory_order_relaxed) - first);
        std::sort(bucket, bucket + size);
        for (std::size_t a = 0; a < size;)
        {
          std::size_t b = a + 1;
          while (b < size && bucket[b].SameKey(bucket[a]))
          {
            ++b;
          }
          PairGroup(cells, bucket + a, b - a, sink, paired);
          a = b;
        }
      }
    });
  return sinks;
}

/**
 * The pairs of every sink by owner, then by face, on the threads: each owner's faces counted
 * (atomically, one task per group of sinks), the owners' ranges by a prefix sum, the pairs placed
 * in their owner's range in any order, then each owner's few faces ordered by face. An owner
 * pairs each of its faces once, so the order is the same whatever the threads did.
 */
InternalFaces InternalFacesOf(
  const std::vector<MatchSink>& sinks, std::size_t numberOfCells, const ParallelFor& parallelFor)
{
  std::unique_ptr<std::atomic<std::uint32_t>[]> placed(
    new std::atomic<std::uint32_t>[numberOfCells]);
  ForEachIndex(parallelFor, numberOfCells, 1 << 16,
    [&](std::size_t c) { placed[c].store(0, std::memory_order_relaxed); });
  ForEachBlock(parallelFor, sinks.size(),
    [&](std::size_t s)
    {
      for (const auto& pair : sinks[s].Pairs)
      {
        placed[static_cast<std::size_t>(std::get<0>(pair))].fetch_add(1, std::memory_order_relaxed);
      }
    });
  std::vector<std::size_t> start(numberOfCells + 1, 0);
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    start[c + 1] = start[c] + placed[c].load(std::memory_order_relaxed);
  }
  ForEachIndex(parallelFor, numberOfCells, 1 << 16,
    [&](std::size_t c) { placed[c].store(0, std::memory_order_relaxed); });
  InternalFaces faces;
  faces.Owner.resize(start[numberOfCells]);
  faces.Neighbour.resize(start[numberOfCells]);
  faces.Face.resize(start[numberOfCells]);
  // Their pages faulted in parts on the threads first: the placement below writes them in the
  // owners' order, scattered, and its page faults from both threads waited on each other (0.19 -
  // 0.36 s of placement at 24.6M faces instead of 0.08 s after 0.08 s of this).
  {
    std::vector<FirstTouchPart> parts;
    AppendFirstTouchParts(faces.Owner.data(), faces.Owner.size() * sizeof(std::int64_t), parts);
    AppendFirstTouchParts(
      faces.Neighbour.data(), faces.Neighbour.size() * sizeof(std::int64_t), parts);
    AppendFirstTouchParts(faces.Face.data(), faces.Face.size() * sizeof(std::int32_t), parts);
    FirstTouchParts(parts, parallelFor);
  }
  ForEachBlock(parallelFor, sinks.size(),
    [&](std::size_t s)
    {
      for (const auto& pair : sinks[s].Pairs)
      {
        const auto owner = static_cast<std::size_t>(std::get<0>(pair));
        const std::size_t at = start[owner] + placed[owner].fetch_add(1, std::memory_order_relaxed);
        faces.Owner[at] = std::get<0>(pair);
        faces.Neighbour[at] = std::get<1>(pair);
        faces.Face[at] = std::get<2>(pair);
      }
    });
  ForEachIndex(parallelFor, numberOfCells, 1 << 14,
    [&](std::size_t c)
    {
      // Insertion by face (a cell has a few faces).
      for (std::size_t i = start[c] + 1; i < start[c + 1]; ++i)
      {
        const std::int64_t neighbour = faces.Neighbour[i];
        const std::int32_t face = faces.Face[i];
        std::size_t at = i;
        for (; at > start[c] && faces.Face[at - 1] > face; --at)
        {
          faces.Neighbour[at] = faces.Neighbour[at - 1];
          faces.Face[at] = faces.Face[at - 1];
        }
        faces.Neighbour[at] = neighbour;
        faces.Face[at] = face;
      }
    });
  return faces;
}

BoundaryFaces BoundaryFacesOf(const std::vector<MatchSink>& sinks)
{
  std::vector<std::pair<std::int64_t, std::int32_t>> all;
  for (const MatchSink& sink : sinks)
  {
    all.insert(all.end(), sink.Single.begin(), sink.Single.end());
  }
  std::sort(all.begin(), all.end());
  BoundaryFaces faces;
  faces.Cell.reserve(all.size());
  faces.Face.reserve(all.size());
  for (const auto& face : all)
  {
    faces.Cell.push_back(face.first);
    faces.Face.push_back(face.second);
  }
  return faces;
}

std::vector<MatchSink> Match(const FaceCells& cells, std::size_t numberOfPoints,
  const ParallelFor& parallelFor, bool keepPairs)
{
  // 32-bit records when every id fits (the largest value marks a missing point).
  const std::size_t limit = std::numeric_limits<std::uint32_t>::max();
  if (numberOfPoints < limit && cells.GetNumberOfCells() < limit)
  {
    return MatchAll<std::uint32_t>(cells, numberOfPoints, parallelFor, keepPairs);
  }
  return MatchAll<std::uint64_t>(cells, numberOfPoints, parallelFor, keepPairs);
}
} // namespace

InternalFaces FindInternalFaces(
  const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor)
{
  return InternalFacesOf(
    Match(cells, numberOfPoints, parallelFor, true), cells.GetNumberOfCells(), parallelFor);
}

BoundaryFaces FindBoundaryFaces(
  const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor)
{
  return BoundaryFacesOf(Match(cells, numberOfPoints, parallelFor, false));
}

} // namespace dgmf
