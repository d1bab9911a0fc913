#include "dgmf/FaceMatching.h"

#include "dgmf/CellFaces.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

namespace dgmf
{
namespace
{
constexpr std::size_t CellChunks = 64; // blocks of cells read in parallel
/// Groups of buckets at most: a face goes to the group of its smallest point id's high bits.
constexpr std::size_t MaximumGroups = 4096;
constexpr std::size_t GroupsPerBlock = 4; // groups of buckets matched per parallel task

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
  Id Smallest; ///< the face's smallest point id: its bucket
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
    record.Smallest = key[0];
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
    record.Smallest = static_cast<Id>(sorted[0]);
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

/// The shift that cuts ids [0, count) into at most MaximumGroups groups (id >> shift).
int GroupShift(std::size_t count)
{
  int shift = 0;
  while ((count >> shift) >= MaximumGroups)
  {
    ++shift;
  }
  return shift;
}

/**
 * Turns `place`, each chunk's count of items per group ([chunk][group]), into each chunk's first
 * position in each group: the groups one after the other, each in chunk order. Returns where each
 * group starts (and, last, the total).
 */
std::vector<std::uint64_t> PlaceByGroup(
  std::vector<std::uint64_t>& place, std::size_t chunks, std::size_t groups)
{
  std::vector<std::uint64_t> groupStart(groups + 1, 0);
  std::uint64_t total = 0;
  for (std::size_t g = 0; g < groups; ++g)
  {
    groupStart[g] = total;
    for (std::size_t k = 0; k < chunks; ++k)
    {
      const std::uint64_t size = place[k * groups + g];
      place[k * groups + g] = total;
      total += size;
    }
  }
  groupStart[groups] = total;
  return groupStart;
}

/**
 * Every face in the bucket of its smallest point id, and each bucket sorted and its equal faces
 * paired. The buckets come in groups (the smallest id's high bits): each fixed chunk of cells
 * counts its faces per group, then writes them at its own place in each group (a prefix sum in
 * group, then chunk order), without atomic operations or a table per point; each group (a few
 * hundred KB) is then sorted into its buckets in cache. The order of the faces in a group depends
 * on the chunks only, and the buckets are sorted by key, cell and face: nothing depends on the
 * threads.
 */
template <typename Id>
std::vector<MatchSink> MatchAll(const FaceCells& cells, std::size_t numberOfPoints,
  const ParallelFor& parallelFor, bool keepPairs)
{
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  const std::size_t cellsPerChunk = (numberOfCells + CellChunks - 1) / CellChunks;
  const int shift = GroupShift(numberOfPoints); // a point's group: id >> shift
  const std::size_t groups = (numberOfPoints >> shift) + 1;
  // For each face of the cells of chunk k, `body(k, cell, face, ids, count)`.
  const auto forEachFace = [&](const auto& body)
  {
    ForEachBlock(parallelFor, CellChunks,
      [&](std::size_t k)
      {
        std::vector<std::int64_t> stream, faceIds;
        const std::size_t end = std::min(numberOfCells, (k + 1) * cellsPerChunk);
        ForEachCellFaceStream(cells, std::min(numberOfCells, k * cellsPerChunk), end, stream,
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
              body(k, c, static_cast<std::size_t>(f), ids, n);
            }
          });
      });
  };
  // 1. Each chunk's faces per group ([chunk][group]: counts, then positions).
  std::vector<std::uint64_t> place(CellChunks * groups, 0);
  forEachFace(
    [&](std::size_t k, std::size_t c, std::size_t f, const std::int64_t* ids, std::int64_t count)
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
      ++place[k * groups + (static_cast<std::size_t>(smallest) >> shift)];
    });
  // 2. The groups one after the other, each in chunk order.
  const std::vector<std::uint64_t> groupStart = PlaceByGroup(place, CellChunks, groups);
  const std::uint64_t total = groupStart[groups];
  // Not initialised (a GB on large meshes); its pages faulted in parts on the threads first (the
  // fill writes each group's part from both threads).
  std::unique_ptr<FaceRecord<Id>[]> records(new FaceRecord<Id>[total]);
  {
    std::vector<FirstTouchPart> parts;
    AppendFirstTouchParts(records.get(), total * sizeof(FaceRecord<Id>), parts);
    FirstTouchParts(parts, parallelFor);
  }
  forEachFace(
    [&](std::size_t k, std::size_t c, std::size_t f, const std::int64_t* ids, std::int64_t count)
    {
      std::size_t smallest = 0;
      const FaceRecord<Id> record = MakeRecord<Id>(ids, count, c, f, smallest);
      records[place[k * groups + (smallest >> shift)]++] = record;
    });
  // 3. Each group into its buckets (a counting sort by the smallest id's low bits, in cache), each
  //    bucket sorted and its equal faces paired.
  const std::size_t blocks = (groups + GroupsPerBlock - 1) / GroupsPerBlock;
  std::vector<MatchSink> sinks(blocks);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      MatchSink& sink = sinks[block];
      sink.KeepPairs = keepPairs;
      std::vector<std::uint8_t> paired;
      std::vector<FaceRecord<Id>> sorted;
      std::vector<std::size_t> bucketStart;
      const std::size_t firstGroup = block * GroupsPerBlock;
      const std::size_t endGroup = std::min(groups, firstGroup + GroupsPerBlock);
      if (keepPairs)
      {
        // At most one pair per two of the block's records: no growth (copies and their page
        // faults: a tenth of the first run's faults at 8.2M hexahedra).
        sink.Pairs.reserve(
          static_cast<std::size_t>(groupStart[endGroup] - groupStart[firstGroup]) / 2);
      }
      for (std::size_t g = firstGroup; g < endGroup; ++g)
      {
        const FaceRecord<Id>* group = records.get() + groupStart[g];
        const auto size = static_cast<std::size_t>(groupStart[g + 1] - groupStart[g]);
        const std::size_t firstPoint = g << shift;
        const std::size_t points = std::min(numberOfPoints, (g + 1) << shift) - firstPoint;
        bucketStart.assign(points + 1, 0);
        for (std::size_t r = 0; r < size; ++r)
        {
          ++bucketStart[static_cast<std::size_t>(group[r].Smallest) - firstPoint + 1];
        }
        for (std::size_t p = 0; p < points; ++p)
        {
          bucketStart[p + 1] += bucketStart[p];
        }
        sorted.resize(size);
        for (std::size_t r = 0; r < size; ++r)
        {
          sorted[bucketStart[static_cast<std::size_t>(group[r].Smallest) - firstPoint]++] =
            group[r];
        }
        // Each bucket now ends where the next began.
        for (std::size_t p = 0, first = 0; p < points; first = bucketStart[p++])
        {
          FaceRecord<Id>* bucket = sorted.data() + first;
          const std::size_t bucketSize = bucketStart[p] - first;
          std::sort(bucket, bucket + bucketSize);
          for (std::size_t a = 0; a < bucketSize;)
          {
            std::size_t b = a + 1;
            while (b < bucketSize && bucket[b].SameKey(bucket[a]))
            {
              ++b;
            }
            PairGroup(cells, bucket + a, b - a, sink, paired);
            a = b;
          }
        }
      }
    });
  return sinks;
}

/**
 * The pairs of every sink by owner, then by face, on the threads, without atomic operations: the
 * owners come in groups (their ids' high bits); fixed chunks of sinks count their pairs per group
 * and write them at their own place in each group (a prefix sum in group, then chunk order), then
 * each group (in cache) is sorted by owner, and each owner's few faces by face. An owner pairs
 * each of its faces once, so the order is the same whatever the threads did.
 */
InternalFaces InternalFacesOf(
  const std::vector<MatchSink>& sinks, std::size_t numberOfCells, const ParallelFor& parallelFor)
{
  const int shift = GroupShift(numberOfCells); // a cell's group: id >> shift
  const std::size_t groups = (numberOfCells >> shift) + 1;
  const std::size_t chunks = std::max<std::size_t>(1, std::min(CellChunks, sinks.size()));
  const std::size_t sinksPerChunk = (sinks.size() + chunks - 1) / chunks;
  const auto forEachPair = [&](const auto& body)
  {
    ForEachBlock(parallelFor, chunks,
      [&](std::size_t k)
      {
        const std::size_t end = std::min(sinks.size(), (k + 1) * sinksPerChunk);
        for (std::size_t s = std::min(sinks.size(), k * sinksPerChunk); s < end; ++s)
        {
          for (const auto& pair : sinks[s].Pairs)
          {
            body(k, pair);
          }
        }
      });
  };
  // 1. Each chunk's pairs per group of owners ([chunk][group]: counts, then positions).
  std::vector<std::uint64_t> place(chunks * groups, 0);
  forEachPair([&](std::size_t k, const auto& pair)
    { ++place[k * groups + (static_cast<std::size_t>(std::get<0>(pair)) >> shift)]; });
  const std::vector<std::uint64_t> groupStart = PlaceByGroup(place, chunks, groups);
  const std::uint64_t total = groupStart[groups];
  InternalFaces faces;
  faces.Owner.resize(total);
  faces.Neighbour.resize(total);
  faces.Face.resize(total);
  // Their pages faulted in parts on the threads first: the pairs are written scattered over the
  // groups, and their page faults from both threads waited on each other.
  {
    std::vector<FirstTouchPart> parts;
    AppendFirstTouchParts(faces.Owner.data(), faces.Owner.size() * sizeof(std::int64_t), parts);
    AppendFirstTouchParts(
      faces.Neighbour.data(), faces.Neighbour.size() * sizeof(std::int64_t), parts);
    AppendFirstTouchParts(faces.Face.data(), faces.Face.size() * sizeof(std::int32_t), parts);
    FirstTouchParts(parts, parallelFor);
  }
  // 2. The pairs into their groups.
  forEachPair(
    [&](std::size_t k, const auto& pair)
    {
      const std::size_t at =
        place[k * groups + (static_cast<std::size_t>(std::get<0>(pair)) >> shift)]++;
      faces.Owner[at] = std::get<0>(pair);
      faces.Neighbour[at] = std::get<1>(pair);
      faces.Face[at] = std::get<2>(pair);
    });
  // 3. Each group by owner (a counting sort in cache), each owner's faces by face (insertion).
  ForEachBlock(parallelFor, groups,
    [&](std::size_t g)
    {
      const std::size_t begin = groupStart[g], end = groupStart[g + 1];
      if (begin == end)
      {
        return;
      }
      const std::size_t firstCell = g << shift;
      const std::size_t cellsInGroup = std::min(numberOfCells, (g + 1) << shift) - firstCell;
      std::vector<std::tuple<std::int64_t, std::int64_t, std::int32_t>> group(end - begin);
      std::vector<std::size_t> start(cellsInGroup + 1, 0);
      for (std::size_t i = begin; i < end; ++i)
      {
        group[i - begin] = { faces.Owner[i], faces.Neighbour[i], faces.Face[i] };
        ++start[static_cast<std::size_t>(faces.Owner[i]) - firstCell + 1];
      }
      for (std::size_t c = 0; c < cellsInGroup; ++c)
      {
        start[c + 1] += start[c];
      }
      for (const auto& pair : group)
      {
        const std::size_t at =
          begin + start[static_cast<std::size_t>(std::get<0>(pair)) - firstCell]++;
        faces.Owner[at] = std::get<0>(pair);
        faces.Neighbour[at] = std::get<1>(pair);
        faces.Face[at] = std::get<2>(pair);
      }
      // Each owner's range now ends where the next began.
      for (std::size_t c = 0, first = begin; c < cellsInGroup; first = begin + start[c++])
      {
        const std::size_t last = begin + start[c];
        for (std::size_t i = first + 1; i < last; ++i)
        {
          const std::int64_t neighbour = faces.Neighbour[i];
          const std::int32_t face = faces.Face[i];
          std::size_t at = i;
          for (; at > first && faces.Face[at - 1] > face; --at)
          {
            faces.Neighbour[at] = faces.Neighbour[at - 1];
            faces.Face[at] = faces.Face[at - 1];
          }
          faces.Neighbour[at] = neighbour;
          faces.Face[at] = face;
        }
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
