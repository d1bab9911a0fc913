#include "dgmf/NonOrthogonality.h"

#include "dgmf/CellFaces.h"
#include "dgmf/CellGeometry.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/Simd.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>

namespace dgmf
{
namespace
{
constexpr double RootVSmall = 1e-150; // OpenFOAM's ROOTVSMALL (double)
constexpr double VSmall = 1e-300;     // OpenFOAM's VSMALL
constexpr double Pi = 3.14159265358979323846;

/// A face's centre and area vector, as OpenFOAM computes them (primitiveMeshFaceCentresAndAreas).
struct FaceGeometry
{
  Vec3 Centre;
  Vec3 Area;
};

/// A polygon of `n` corners (more than 3) by OpenFOAM's decomposition about its mean point.
FaceGeometry PolygonOf(const Vec3* p, std::int64_t n)
{
  Vec3 mean{ 0.0, 0.0, 0.0 };
  for (std::int64_t k = 0; k < n; ++k)
  {
    mean = mean + p[k];
  }
  mean = (1.0 / static_cast<double>(n)) * mean;
  Vec3 sumN{ 0.0, 0.0, 0.0 }, sumAc{ 0.0, 0.0, 0.0 };
  double sumA = 0.0;
  for (std::int64_t k = 0; k < n; ++k)
  {
    const Vec3& next = p[(k + 1) % n];
    const Vec3 normal = Cross(next - p[k], mean - p[k]);
    const double a = Norm(normal);
    sumN = sumN + normal;
    sumA += a;
    sumAc = sumAc + a * (p[k] + next + mean);
  }
  if (sumA < RootVSmall)
  {
    return { mean, { 0.0, 0.0, 0.0 } };
  }
  return { (1.0 / (3.0 * sumA)) * sumAc, 0.5 * sumN };
}

/**
 * PolygonOf of four quadrilaterals at once, lane l taking the corners `corners[l]` and giving
 * `*geometry[l]`: the same
 * operations in each lane, in the same order, so the same bits (the square roots are IEEE's in
 * any lane; this file is compiled without errno for them, so that they are one vector square
 * root). 2.8 times faster than four quadrilaterals one at a time in cache (9.2 against 25.7 ns a
 * face).
 */
DGMF_SIMD_AVX2_CLONES
void QuadrilateralsOf(const Vec3 (*corners)[4], FaceGeometry* const* geometry)
{
  using simd::Double4;
  using Vec4 = Vec3Of<Double4>;
  Vec4 p[4];
  for (int k = 0; k < 4; ++k)
  {
    for (int l = 0; l < 4; ++l)
    {
      p[k].X[l] = corners[l][k].X;
      p[k].Y[l] = corners[l][k].Y;
      p[k].Z[l] = corners[l][k].Z;
    }
  }
  const Double4 zero{ 0.0, 0.0, 0.0, 0.0 };
  Vec4 mean{ zero, zero, zero };
  for (int k = 0; k < 4; ++k)
  {
    mean = mean + p[k];
  }
  const double quarter = 1.0 / 4.0;
  mean = { quarter * mean.X, quarter * mean.Y, quarter * mean.Z };
  Vec4 sumN{ zero, zero, zero }, sumAc{ zero, zero, zero };
  Double4 sumA = zero;
  for (int k = 0; k < 4; ++k)
  {
    const Vec4& next = p[(k + 1) % 4];
    const Vec4 normal = Cross(next - p[k], mean - p[k]);
    const Double4 squared = Dot(normal, normal);
    Double4 a;
    for (int l = 0; l < 4; ++l)
    {
      a[l] = std::sqrt(squared[l]);
    }
    sumN = sumN + normal;
    sumA += a;
    const Vec4 c = p[k] + next + mean;
    sumAc = sumAc + Vec4{ a * c.X, a * c.Y, a * c.Z };
  }
  const Double4 scale = 1.0 / (3.0 * sumA);
  for (int l = 0; l < 4; ++l)
  {
    *geometry[l] = sumA[l] < RootVSmall
      ? FaceGeometry{ { mean.X[l], mean.Y[l], mean.Z[l] }, { 0.0, 0.0, 0.0 } }
      : FaceGeometry{ { scale[l] * sumAc.X[l], scale[l] * sumAc.Y[l], scale[l] * sumAc.Z[l] },
          { 0.5 * sumN.X[l], 0.5 * sumN.Y[l], 0.5 * sumN.Z[l] } };
  }
}

/// A face other than a quadrilateral (CellCentreOf takes those four at a time): a triangle, or a
/// polyhedron's face of any number of corners.
FaceGeometry FaceOf(const double* points, const std::int64_t* ids, std::int64_t n)
{
  if (n == 3)
  {
    const Vec3 p0 = Load(points, ids[0]), p1 = Load(points, ids[1]), p2 = Load(points, ids[2]);
    return { (1.0 / 3.0) * (p0 + p1 + p2), 0.5 * Cross(p1 - p0, p2 - p0) };
  }
  thread_local std::vector<Vec3> corners;
  corners.resize(static_cast<std::size_t>(std::max<std::int64_t>(n, 0)));
  for (std::int64_t k = 0; k < n; ++k)
  {
    corners[static_cast<std::size_t>(k)] = Load(points, ids[k]);
  }
  return PolygonOf(corners.data(), n);
}

/**
 * Quadrilaterals queued from the faces of one or more cells and computed four at a time
 * (QuadrilateralsOf), each result written to where its face's geometry goes. A hexahedron has six:
 * two of them wait for the next cell's, instead of two lanes computed for nothing.
 */
class QuadrilateralQueue
{
public:
  /// Where the next quadrilateral's corners go (loaded there directly: copied from elsewhere in
  /// 16-byte pieces across the 24-byte corners, they would wait for their stores).
  Vec3 (&Next())[4] { return this->Corners[this->Pending]; }

  /// Queues the quadrilateral whose corners were put at Next(); its geometry goes to `*target`.
  void Add(FaceGeometry* target)
  {
    this->Target[this->Pending++] = target;
    if (this->Pending == 4)
    {
      this->Flush();
    }
  }

  /// Computes the quadrilaterals queued.
  void Flush()
  {
    if (this->Pending == 0)
    {
      return;
    }
    // The results are written where they go (copied from a local array, they would be read
    // before their stores had landed); the empty lanes repeat the first and write to a scrap.
    FaceGeometry scrap;
    for (int l = this->Pending; l < 4; ++l)
    {
      std::copy(this->Corners[0], this->Corners[0] + 4, this->Corners[l]);
      this->Target[l] = &scrap;
    }
    QuadrilateralsOf(this->Corners, this->Target);
    this->Pending = 0;
  }

  /// True when every quadrilateral queued has been computed.
  bool IsEmpty() const { return this->Pending == 0; }

private:
  Vec3 Corners[4][4];
  FaceGeometry* Target[4] = {};
  int Pending = 0;
};

/**
 * The faces of a cell into `geometry`, in the stream's order: the quadrilaterals through `queue`
 * (computed when it has four, or flushed), the other faces at once. The stream's entries are
 * point ids through `idOf` (the identity for GetFaces' streams, the corner's id for a shape's
 * stream over corner positions).
 */
template <typename IdOf>
void FacesOf(const double* points, const std::int64_t* stream, const IdOf& idOf,
  std::vector<FaceGeometry>& geometry, std::vector<std::int64_t>& faceIds,
  QuadrilateralQueue& queue)
{
  const std::int64_t faces = stream ? stream[0] : 0;
  geometry.resize(static_cast<std::size_t>(std::max<std::int64_t>(faces, 0)));
  for (std::int64_t f = 0, at = 1; f < faces; ++f)
  {
    const std::int64_t n = stream[at];
    const std::int64_t* entries = &stream[at + 1];
    if (n == 4)
    {
      Vec3(&corners)[4] = queue.Next();
      for (int k = 0; k < 4; ++k)
      {
        corners[k] = Load(points, idOf(entries[k]));
      }
      queue.Add(&geometry[static_cast<std::size_t>(f)]);
    }
    else
    {
      faceIds.resize(static_cast<std::size_t>(std::max<std::int64_t>(n, 0)));
      for (std::int64_t k = 0; k < n; ++k)
      {
        faceIds[static_cast<std::size_t>(k)] = idOf(entries[k]);
      }
      geometry[static_cast<std::size_t>(f)] = FaceOf(points, faceIds.data(), n);
    }
    at += 1 + n;
  }
}

/// The centre of a cell as OpenFOAM computes it (primitiveMeshCellCentresAndVols) from its faces'
/// geometry (FacesOf), with the pyramid volumes taken positive whatever the orientation of the
/// cell's faces; `signedVolume` gets 3 x the volume the faces give as they are oriented.
Vec3 CellCentreOf(const std::vector<FaceGeometry>& geometry, double& signedVolume)
{
  Vec3 estimate{ 0.0, 0.0, 0.0 };
  for (const FaceGeometry& face : geometry)
  {
    estimate = estimate + face.Centre;
  }
  estimate = (1.0 / static_cast<double>(std::max<std::size_t>(geometry.size(), 1))) * estimate;
  Vec3 sum{ 0.0, 0.0, 0.0 };
  double volume = 0.0;
  signedVolume = 0.0;
  for (const FaceGeometry& face : geometry)
  {
    const double v3 = Dot(face.Area, face.Centre - estimate);
    signedVolume += v3;
    sum = sum + std::abs(v3) * (0.75 * face.Centre + 0.25 * estimate);
    volume += std::abs(v3);
  }
  return std::abs(volume) > VSmall ? (1.0 / volume) * sum : estimate;
}

/// Cells whose quadrilaterals may still wait in the queue, at most this many.
constexpr std::size_t CellsInFlight = 4;

/**
 * The centres of all cells, the signed volumes (3 x) their faces give, and the area vector of
 * every internal face as its owner's stream gives it (3 per face of `faces`, in their order):
 * the angles reuse it instead of computing the face again.
 */
void CellCentres(const FaceCells& cells, const InternalFaces& faces, const double* points,
  UninitializedVector<double>& centres, UninitializedVector<double>& volumes,
  UninitializedVector<double>& areas, const ParallelFor& parallelFor)
{
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  centres.resize(3 * numberOfCells);
  volumes.resize(numberOfCells);
  areas.resize(3 * faces.Size());
  parallelFor(0, numberOfCells, 2048,
    [&](std::size_t begin, std::size_t end)
    {
      std::vector<std::int64_t> stream, faceIds;
      // The cells whose faces are being computed, in order (their quadrilaterals share the
      // queue's lanes), and each one's faces.
      std::vector<FaceGeometry> geometry[CellsInFlight];
      std::size_t inFlight[CellsInFlight];
      std::size_t flying = 0;
      QuadrilateralQueue queue;
      // The internal faces come by owner (FindInternalFaces): those of this block's cells follow
      // one another from the first whose owner is in the block.
      auto owned = static_cast<std::size_t>(
        std::lower_bound(faces.Owner.begin(), faces.Owner.end(), static_cast<std::int64_t>(begin)) -
        faces.Owner.begin());
      // The cells in flight, all of whose faces are computed: their centres, volumes and owned
      // faces' areas, in order.
      const auto finishAll = [&]()
      {
        for (std::size_t k = 0; k < flying; ++k)
        {
          const std::size_t c = inFlight[k];
          Store(
            CellCentreOf(geometry[k], volumes[c]), centres.data(), static_cast<std::int64_t>(c));
          for (; owned < faces.Size() && faces.Owner[owned] == static_cast<std::int64_t>(c);
               ++owned)
          {
            Store(geometry[k][static_cast<std::size_t>(faces.Face[owned])].Area, areas.data(),
              static_cast<std::int64_t>(owned));
          }
        }
        flying = 0;
      };
      ForEachCellFaceStream(
        cells, begin, end, stream,
        [&](std::size_t c, const std::int64_t* faceStream, const std::int64_t* corners)
        {
          if (flying == CellsInFlight)
          {
            queue.Flush();
            finishAll();
          }
          inFlight[flying] = c;
          std::vector<FaceGeometry>& cellGeometry = geometry[flying++];
          if (corners) // a run of one shape: the shape's faces over the cell's corners
          {
            const auto idOf = [corners](std::int64_t corner) { return corners[corner]; };
            FacesOf(points, faceStream, idOf, cellGeometry, faceIds, queue);
          }
          else
          {
            const auto same = [](std::int64_t id) { return id; };
            FacesOf(points, faceStream, same, cellGeometry, faceIds, queue);
          }
          if (queue.IsEmpty())
          {
            finishAll();
          }
        },
        points);
      queue.Flush();
      finishAll();
    });
}

/// The angle, in degrees, of a face whose cosine (clamped to [-1, 1]) is `cosine`. It decreases
/// as the cosine grows, so a cell's largest angle is the angle of its smallest cosine.
double AngleOf(double cosine)
{
  return std::acos(cosine) * 180.0 / Pi;
}

/// Lowers a cell's smallest cosine so far to `cosine` if that is smaller (from any thread).
void LowerCosine(std::atomic<double>& slot, double cosine)
{
  double current = slot.load(std::memory_order_relaxed);
  while (
    cosine < current && !slot.compare_exchange_weak(current, cosine, std::memory_order_relaxed))
  {
  }
}

/// The largest angle of the internal faces, degrees, per cell and overall. Each face's cosine
/// lowers its two cells' smallest cosine (the faces come by owner, so the owner's is kept until
/// the owner changes); the angles are taken per cell at the end: one arc cosine a cell instead of
/// one a face, and no array of the faces' angles.
NonOrthogonalityResult Angles(std::size_t numberOfCells, const InternalFaces& faces,
  const std::vector<std::int8_t>& cellSign, const UninitializedVector<double>& areas,
  const UninitializedVector<double>& centres, const ParallelFor& parallelFor)
{
  constexpr double NoFace = 2.0;
  const std::unique_ptr<std::atomic<double>[]> smallest(new std::atomic<double>[numberOfCells]);
  parallelFor(0, numberOfCells, 1 << 16,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t c = begin; c < end; ++c)
      {
        smallest[c].store(NoFace, std::memory_order_relaxed);
      }
    });
  parallelFor(0, faces.Size(), 4096,
    [&](std::size_t begin, std::size_t end)
    {
      std::int64_t ownerCell = -1;
      double ownerSmallest = NoFace;
      for (std::size_t f = begin; f < end; ++f)
      {
        const std::int64_t owner = faces.Owner[f], neighbour = faces.Neighbour[f];
        if (owner != ownerCell) // the faces come by owner (FindInternalFaces)
        {
          if (ownerCell >= 0)
          {
            LowerCosine(smallest[static_cast<std::size_t>(ownerCell)], ownerSmallest);
          }
          ownerCell = owner;
          ownerSmallest = NoFace;
        }
        const Vec3 area = Load(areas.data(), static_cast<std::int64_t>(f));
        const Vec3 d = Load(centres.data(), neighbour) - Load(centres.data(), owner);
        const double cosine = cellSign[static_cast<std::size_t>(owner)] * Dot(d, area) /
          (Norm(d) * Norm(area) + RootVSmall);
        const double clamped = std::max(-1.0, std::min(1.0, cosine)); // NaN: 1, an angle of 0
        ownerSmallest = std::min(ownerSmallest, clamped);
        LowerCosine(smallest[static_cast<std::size_t>(neighbour)], clamped);
      }
      if (ownerCell >= 0)
      {
        LowerCosine(smallest[static_cast<std::size_t>(ownerCell)], ownerSmallest);
      }
    });
  NonOrthogonalityResult result;
  result.CellMaximum.resize(numberOfCells);
  const std::size_t blocks = (numberOfCells + (1 << 16) - 1) >> 16;
  std::vector<double> blockMaximum(blocks, 0.0);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t b)
    {
      const std::size_t end = std::min(numberOfCells, (b + 1) << 16);
      double maximum = 0.0;
      for (std::size_t c = b << 16; c < end; ++c)
      {
        const double cosine = smallest[c].load(std::memory_order_relaxed);
        result.CellMaximum[c] = cosine == NoFace ? 0.0 : AngleOf(cosine);
        maximum = std::max(maximum, result.CellMaximum[c]);
      }
      blockMaximum[b] = maximum;
    });
  for (const double maximum : blockMaximum)
  {
    result.Maximum = std::max(result.Maximum, maximum);
  }
  return result;
}

} // namespace

InputOrientation OrientCells(const FaceCells& cells, const InternalFaces& faces,
  const double* original, const ParallelFor& parallelFor)
{
  UninitializedVector<double> centres, volumes, areas;
  CellCentres(cells, faces, original, centres, volumes, areas, parallelFor);
  InputOrientation orientation;
  orientation.CellSign.resize(volumes.size());
  for (std::size_t c = 0; c < volumes.size(); ++c)
  {
    orientation.CellSign[c] = volumes[c] < 0.0 ? -1 : 1;
  }
  orientation.InputMaximum =
    Angles(volumes.size(), faces, orientation.CellSign, areas, centres, parallelFor).Maximum;
  return orientation;
}

NonOrthogonalityResult ComputeNonOrthogonality(const FaceCells& cells, const InternalFaces& faces,
  const InputOrientation& orientation, const double* points, const ParallelFor& parallelFor)
{
  UninitializedVector<double> centres, volumes, areas;
  CellCentres(cells, faces, points, centres, volumes, areas, parallelFor);
  return Angles(volumes.size(), faces, orientation.CellSign, areas, centres, parallelFor);
}

} // namespace dgmf
