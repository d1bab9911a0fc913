#include "dgmf/FaceParity.h"

#include "dgmf/CellFaces.h"
#include "dgmf/Simd.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
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

/// Whether two of the `count` face `hashes` are equal (a cell with two faces of the same points),
/// for a cell of a few faces: pair by pair.
inline bool HasTwinFacesAmongFew(const std::uint64_t* hashes, std::size_t count)
{
  for (std::size_t a = 1; a < count; ++a)
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

/// HasTwinFacesAmongFew for any number of faces (a polyhedron's); may reorder them.
inline bool HasTwinFaces(std::uint64_t* hashes, std::size_t count)
{
  if (count <= 8)
  {
    return HasTwinFacesAmongFew(hashes, count);
  }
  std::sort(hashes, hashes + count);
  return std::adjacent_find(hashes, hashes + count) != hashes + count;
}

/// A point id's mix.
inline std::uint64_t PointHash(std::uint64_t p)
{
  return Mix64(p ^ 0x6a09e667f3bcc908ULL);
}

/// The largest shape a run takes (hexagonal prism: 12 corners, 8 faces of up to 6 corners).
constexpr int RunCorners = 12;
constexpr int RunFaces = 8;
constexpr int RunFaceSize = 6;

/// A shape's face stream over its corners, decoded once per run.
struct RunShape
{
  int Faces = 0;
  int Size[RunFaces] = {};
  int Corner[RunFaces][RunFaceSize] = {};

  /// False when the shape is larger than a run takes (then cell by cell).
  constexpr bool Decode(const std::int64_t* local, int corners)
  {
    if (corners > RunCorners || local[0] > RunFaces)
    {
      return false;
    }
    this->Faces = static_cast<int>(local[0]);
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      if (local[at] <= 0 || local[at] > RunFaceSize)
      {
        return false;
      }
      this->Size[f] = static_cast<int>(local[at]);
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        this->Corner[f][k] = static_cast<int>(local[at + 1 + k]);
      }
    }
    return true;
  }

  bool operator==(const RunShape& o) const
  {
    if (this->Faces != o.Faces)
    {
      return false;
    }
    for (int f = 0; f < this->Faces; ++f)
    {
      if (this->Size[f] != o.Size[f] ||
        !std::equal(this->Corner[f], this->Corner[f] + this->Size[f], o.Corner[f]))
      {
        return false;
      }
    }
    return true;
  }
};

constexpr RunShape DecodedShape(const std::int64_t* faceStream, int corners)
{
  RunShape shape;
  shape.Decode(faceStream, corners);
  return shape;
}

/// The usual shapes, known at compile time: their face sums need no table lookups.
constexpr RunShape Hexahedron = DecodedShape(HexahedronFaceStream, 8);
constexpr RunShape Tetra = DecodedShape(TetraFaceStream, 4);
/// No shape known at compile time: the run's.
constexpr RunShape RunsOwnShape{};

/**
 * The faces of `count` cells of one shape whose corners follow one another in `ids`, into `sum`;
 * true when one of them refuses the answer (a point id out of range, twin faces). Each corner is
 * mixed once, the faces are summed from the shape's table, as the cell-by-cell path does.
 * `Fixed`: the shape when it is known at compile time (then `Corners`, `Faces` and `FaceSize`
 * are its own), else RunsOwnShape (and 0 for those: the run's `runShape`).
 */
template <const RunShape& Fixed, int Corners, int Faces, int FaceSize>
bool AddRun(const RunShape& runShape, const void* idBytes, std::size_t count, int cornersPerCell,
  std::size_t numberOfPoints, const std::uint64_t* countHash, std::uint64_t& sum)
{
  // The ids are read as bytes: their type is the caller's 64-bit integer (long or long long).
  const auto* ids = static_cast<const unsigned char*>(idBytes);
  const RunShape& shape = Fixed.Faces > 0 ? Fixed : runShape;
  const int corners = Corners > 0 ? Corners : cornersPerCell;
  const int faces = Faces > 0 ? Faces : shape.Faces;
  std::uint64_t cornerHash[RunCorners];
  std::uint64_t faceHash[RunFaces];
  for (std::size_t c = 0; c < count; ++c, ids += 8 * corners)
  {
    for (int k = 0; k < corners; ++k)
    {
      std::int64_t id;
      std::memcpy(&id, ids + 8 * k, sizeof id);
      if (id < 0 || static_cast<std::size_t>(id) >= numberOfPoints)
      {
        return true;
      }
      cornerHash[k] = PointHash(static_cast<std::uint64_t>(id));
    }
    for (int f = 0; f < faces; ++f)
    {
      const int size = FaceSize > 0 ? FaceSize : shape.Size[f];
      std::uint64_t face = countHash[size];
      for (int k = 0; k < size; ++k)
      {
        face += cornerHash[shape.Corner[f][k]];
      }
      faceHash[f] = face;
      sum ^= face;
    }
    if (HasTwinFacesAmongFew(faceHash, static_cast<std::size_t>(faces))) // at most RunFaces
    {
      return true;
    }
  }
  return false;
}

/// Mix64 of each lane.
DGMF_SIMD_INLINE simd::UInt4 Mix64(simd::UInt4 x)
{
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The faces AddHexahedra sums (from the sums of corners k and k + 4): VTK's hexahedron's.
constexpr int HexahedronFaces[6][4] = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 },
  { 3, 7, 6, 2 }, { 0, 3, 2, 1 }, { 4, 5, 6, 7 } };

constexpr bool HasFaces(const RunShape& shape, const int (&faces)[6][4])
{
  bool same = shape.Faces == 6;
  for (int f = 0; f < 6; ++f)
  {
    for (int k = 0; k < 4; ++k)
    {
      same = same && shape.Size[f] == 4 && shape.Corner[f][k] == faces[f][k];
    }
  }
  return same;
}
static_assert(HasFaces(Hexahedron, HexahedronFaces), "AddHexahedra sums VTK's hexahedron faces");

/**
 * AddRun for `count` hexahedra in VTK's corner order: the same faces and hashes, the corners of
 * a cell in two four-lane vectors (corners 0-3 and 4-7). With s_k the sum of corners k and
 * k + 4, faces 0 - 3 are s0 + s3, s1 + s2, s0 + s1 and s2 + s3, faces 4 and 5 the sums of each
 * vector. The faces' exclusive or is the same in any order; a refused run (an id out of range,
 * twin faces) is told at its end instead of at its cell, which gives the same answer.
 */
DGMF_SIMD_AVX2_CLONES bool AddHexahedra(const void* ids, std::size_t count,
  std::size_t numberOfPoints, std::uint64_t faceOfFour, std::uint64_t& sum)
{
  using simd::MakeUInt4;
  using simd::UInt4;
  const auto* bytes = static_cast<const unsigned char*>(ids);
  const UInt4 zero = MakeUInt4(0, 0, 0, 0);
  UInt4 faces03 = zero; // the exclusive or of faces 0 - 3
  UInt4 faces45 = zero; // of faces 4 and 5, in lanes 0 and 2
  UInt4 refused = zero;
  for (std::size_t c = 0; c < count; ++c, bytes += 64)
  {
    // The ids are the caller's 64-bit integers; as unsigned, a negative one is out of range too.
    UInt4 low = simd::LoadUInt4(bytes);
    UInt4 high = simd::LoadUInt4(bytes + 32);
    refused |= simd::AtLeast(low, numberOfPoints) | simd::AtLeast(high, numberOfPoints);
    low = Mix64(low ^ 0x6a09e667f3bcc908ULL); // PointHash of each corner
    high = Mix64(high ^ 0x6a09e667f3bcc908ULL);
    const UInt4 s = low + high;
    const UInt4 f =
      MakeUInt4(s[0], s[1], s[0], s[2]) + MakeUInt4(s[3], s[2], s[1], s[3]) + faceOfFour;
    const UInt4 t =
      MakeUInt4(low[0], low[1], high[0], high[1]) + MakeUInt4(low[2], low[3], high[2], high[3]);
    const UInt4 g = t + MakeUInt4(t[1], t[0], t[3], t[2]) + faceOfFour; // faces 4, 4, 5, 5
    faces03 ^= f;
    faces45 ^= g;
    // Two equal faces of the six (a collapsed cell).
    refused |= simd::Equal(f, MakeUInt4(f[1], f[2], f[3], f[0])) |
      simd::Equal(f, MakeUInt4(f[2], f[3], f[0], f[1])) |
      simd::Equal(f, MakeUInt4(g[0], g[0], g[0], g[0])) |
      simd::Equal(f, MakeUInt4(g[2], g[2], g[2], g[2])) |
      simd::Equal(g, MakeUInt4(g[2], g[3], g[0], g[1]));
  }
  sum ^= faces03[0] ^ faces03[1] ^ faces03[2] ^ faces03[3] ^ faces45[0] ^ faces45[2];
  return simd::AnyLane(refused);
}

} // namespace

bool FacesPairUp(const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor)
{
  // A face's hash is the sum of its points' mixes (and of its number of points, mixed), so
  // neither order nor start matters; a standard shape's corners are mixed once per cell.
  std::array<std::uint64_t, 16> countHash; // the mix of a face's number of points, usual ones
  for (std::size_t n = 0; n < countHash.size(); ++n)
  {
    countHash[n] = Mix64(n);
  }
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  const std::size_t blocks = (numberOfCells + CellsPerBlock - 1) / CellsPerBlock;
  std::vector<std::uint64_t> sums(blocks);
  std::vector<std::uint8_t> refused(blocks, 0); // twin faces, or a point id out of range
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      std::vector<std::int64_t> stream;
      std::vector<std::int64_t> corners;
      std::vector<std::uint64_t> cornerHash;
      std::vector<std::uint64_t> faces;
      std::uint64_t sum = 0;
      bool refuse = false; // written to `refused` once: its bytes are shared by the threads
      const auto hashOf = [&](std::int64_t id)
      {
        if (id < 0 || static_cast<std::size_t>(id) >= numberOfPoints)
        {
          refuse = true;
          return std::uint64_t(0);
        }
        return PointHash(static_cast<std::uint64_t>(id));
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
          std::uint64_t face = static_cast<std::size_t>(count) < countHash.size()
            ? countHash[static_cast<std::size_t>(count)]
            : Mix64(static_cast<std::uint64_t>(count));
          for (std::int64_t k = 0; k < count; ++k)
          {
            face += hashAt(faceStream[at + 1 + k]);
          }
          faces.push_back(face);
          sum ^= face;
        }
        refuse = refuse || HasTwinFaces(faces.data(), faces.size());
      };
      const std::size_t end = std::min(numberOfCells, (block + 1) * CellsPerBlock);
      for (std::size_t c = block * CellsPerBlock; c < end && !refuse; ++c)
      {
        // A run of cells of one shape, their corners one after the other: without a call per
        // cell (hexahedra and tetrahedra with their sizes fixed at compile time).
        const void* ids = nullptr;
        std::size_t count = 0;
        int perCell = 0;
        if (const std::int64_t* local = cells.GetCornerRun(c, end - c, ids, count, perCell))
        {
          RunShape shape;
          if (count >= 1 && shape.Decode(local, perCell))
          {
            refuse = perCell == 8 && shape == Hexahedron
              ? AddHexahedra(ids, count, numberOfPoints, countHash[4], sum)
              : perCell == 4 && shape == Tetra ? AddRun<Tetra, 4, 4, 3>(shape, ids, count, perCell,
                                                   numberOfPoints, countHash.data(), sum)
                                               : AddRun<RunsOwnShape, 0, 0, 0>(shape, ids, count,
                                                   perCell, numberOfPoints, countHash.data(), sum);
            c += count - 1;
            continue;
          }
        }
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
  std::uint64_t total = 0;
  for (std::size_t block = 0; block < blocks; ++block)
  {
    if (refused[block])
    {
      return false;
    }
    total ^= sums[block];
  }
  return total == 0;
}

} // namespace dgmf
