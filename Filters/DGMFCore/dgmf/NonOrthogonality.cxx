#include "dgmf/NonOrthogonality.h"

#include "dgmf/CellGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

FaceGeometry FaceOf(const double* points, const std::int64_t* ids, std::int64_t n)
{
  if (n == 3)
  {
    const Vec3 p0 = Load(points, ids[0]), p1 = Load(points, ids[1]), p2 = Load(points, ids[2]);
    return { (1.0 / 3.0) * (p0 + p1 + p2), 0.5 * Cross(p1 - p0, p2 - p0) };
  }
  Vec3 mean{ 0.0, 0.0, 0.0 };
  for (std::int64_t k = 0; k < n; ++k)
  {
    mean = mean + Load(points, ids[k]);
  }
  mean = (1.0 / static_cast<double>(n)) * mean;
  Vec3 sumN{ 0.0, 0.0, 0.0 }, sumAc{ 0.0, 0.0, 0.0 };
  double sumA = 0.0;
  for (std::int64_t k = 0; k < n; ++k)
  {
    const Vec3 p = Load(points, ids[k]), next = Load(points, ids[(k + 1) % n]);
    const Vec3 normal = Cross(next - p, mean - p);
    const double a = Norm(normal);
    sumN = sumN + normal;
    sumA += a;
    sumAc = sumAc + a * (p + next + mean);
  }
  if (sumA < RootVSmall)
  {
    return { mean, { 0.0, 0.0, 0.0 } };
  }
  return { (1.0 / (3.0 * sumA)) * sumAc, 0.5 * sumN };
}

/// The face `face` of a face stream: its first id and its number of ids.
const std::int64_t* FaceAt(
  const std::vector<std::int64_t>& stream, std::int32_t face, std::int64_t& n)
{
  std::int64_t at = 1;
  for (std::int32_t f = 0; f < face; ++f)
  {
    at += 1 + stream[at];
  }
  n = stream[at];
  return &stream[at + 1];
}
/// The centre of a cell as OpenFOAM computes it (primitiveMeshCellCentresAndVols), with the
/// pyramid volumes taken positive whatever the orientation of the cell's faces; `signedVolume`
/// gets 3 x the volume the faces give as they are oriented.
Vec3 CellCentreOf(
  const double* points, const std::vector<std::int64_t>& stream, double& signedVolume)
{
  thread_local std::vector<FaceGeometry> geometry;
  const std::int64_t faces = stream.empty() ? 0 : stream[0];
  geometry.clear();
  Vec3 estimate{ 0.0, 0.0, 0.0 };
  for (std::int64_t f = 0, at = 1; f < faces; ++f)
  {
    const std::int64_t n = stream[at];
    geometry.push_back(FaceOf(points, &stream[at + 1], n));
    estimate = estimate + geometry.back().Centre;
    at += 1 + n;
  }
  estimate = (1.0 / static_cast<double>(std::max<std::int64_t>(faces, 1))) * estimate;
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

/// The centres of all cells, and the signed volumes (3 x) their faces give.
void CellCentres(const FaceCells& cells, const double* points, std::vector<double>& centres,
  std::vector<double>& volumes, const ParallelFor& parallelFor)
{
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  centres.resize(3 * numberOfCells);
  volumes.resize(numberOfCells);
  parallelFor(0, numberOfCells, 2048,
    [&](std::size_t begin, std::size_t end)
    {
      std::vector<std::int64_t> stream;
      for (std::size_t c = begin; c < end; ++c)
      {
        cells.GetFaces(c, stream);
        Store(
          CellCentreOf(points, stream, volumes[c]), centres.data(), static_cast<std::int64_t>(c));
      }
    });
}

/// The angles of the internal faces, degrees, and their maximum per cell and overall.
NonOrthogonalityResult Angles(const FaceCells& cells, const InternalFaces& faces,
  const std::vector<std::int8_t>& cellSign, const double* points,
  const std::vector<double>& centres, const ParallelFor& parallelFor)
{
  std::vector<double> angles(faces.Size(), 0.0);
  parallelFor(0, faces.Size(), 4096,
    [&](std::size_t begin, std::size_t end)
    {
      std::vector<std::int64_t> stream;
      std::int64_t streamCell = -1;
      for (std::size_t f = begin; f < end; ++f)
      {
        const std::int64_t owner = faces.Owner[f], neighbour = faces.Neighbour[f];
        if (owner != streamCell) // the faces come by owner (FindInternalFaces)
        {
          cells.GetFaces(static_cast<std::size_t>(owner), stream);
          streamCell = owner;
        }
        std::int64_t n = 0;
        const std::int64_t* ids = FaceAt(stream, faces.Face[f], n);
        const FaceGeometry face = FaceOf(points, ids, n);
        const Vec3 d = Load(centres.data(), neighbour) - Load(centres.data(), owner);
        const double cosine = cellSign[static_cast<std::size_t>(owner)] * Dot(d, face.Area) /
          (Norm(d) * Norm(face.Area) + RootVSmall);
        angles[f] = std::acos(std::max(-1.0, std::min(1.0, cosine))) * 180.0 / Pi;
      }
    });
  NonOrthogonalityResult result;
  result.CellMaximum.assign(cells.GetNumberOfCells(), 0.0);
  for (std::size_t f = 0; f < faces.Size(); ++f)
  {
    result.Maximum = std::max(result.Maximum, angles[f]);
    for (std::int64_t cell : { faces.Owner[f], faces.Neighbour[f] })
    {
      double& cellMaximum = result.CellMaximum[static_cast<std::size_t>(cell)];
      cellMaximum = std::max(cellMaximum, angles[f]);
    }
  }
  return result;
}

} // namespace

InternalFaces FindInternalFaces(const FaceCells& cells, std::size_t numberOfPoints)
{
  const std::size_t numberOfCells = cells.GetNumberOfCells();
  // Bucket every face by its smallest point id (counting sort), then pair equal faces within
  // each bucket.
  std::vector<std::int64_t> start(numberOfPoints + 1, 0);
  std::vector<std::int64_t> stream;
  const auto smallest = [&stream](std::int64_t at)
  { return *std::min_element(&stream[at + 1], &stream[at + 1] + stream[at]); };
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    cells.GetFaces(c, stream);
    for (std::int64_t f = 0, at = 1; !stream.empty() && f < stream[0]; ++f, at += 1 + stream[at])
    {
      ++start[static_cast<std::size_t>(smallest(at)) + 1];
    }
  }
  for (std::size_t p = 0; p < numberOfPoints; ++p)
  {
    start[p + 1] += start[p];
  }
  struct Entry
  {
    std::int64_t Cell;
    std::int32_t Face;
  };
  std::vector<Entry> entries(static_cast<std::size_t>(start[numberOfPoints]));
  std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    cells.GetFaces(c, stream);
    for (std::int64_t f = 0, at = 1; !stream.empty() && f < stream[0]; ++f, at += 1 + stream[at])
    {
      entries[static_cast<std::size_t>(fill[static_cast<std::size_t>(smallest(at))]++)] = {
        static_cast<std::int64_t>(c), static_cast<std::int32_t>(f)
      };
    }
  }
  InternalFaces faces;
  std::vector<std::int64_t> other;
  const auto sortedFace = [&](const Entry& e, std::vector<std::int64_t>& ids)
  {
    cells.GetFaces(static_cast<std::size_t>(e.Cell), stream);
    std::int64_t n = 0;
    const std::int64_t* begin = FaceAt(stream, e.Face, n);
    ids.assign(begin, begin + n);
    std::sort(ids.begin(), ids.end());
  };
  std::vector<std::int64_t> first;
  std::vector<std::uint8_t> paired;
  for (std::size_t p = 0; p < numberOfPoints; ++p)
  {
    paired.assign(static_cast<std::size_t>(start[p + 1] - start[p]), 0);
    for (std::int64_t a = start[p]; a < start[p + 1]; ++a)
    {
      if (paired[static_cast<std::size_t>(a - start[p])])
      {
        continue;
      }
      sortedFace(entries[static_cast<std::size_t>(a)], first);
      for (std::int64_t b = a + 1; b < start[p + 1]; ++b)
      {
        if (paired[static_cast<std::size_t>(b - start[p])] ||
          entries[static_cast<std::size_t>(b)].Cell == entries[static_cast<std::size_t>(a)].Cell)
        {
          continue;
        }
        sortedFace(entries[static_cast<std::size_t>(b)], other);
        if (other == first)
        {
          paired[static_cast<std::size_t>(a - start[p])] = 1;
          paired[static_cast<std::size_t>(b - start[p])] = 1;
          const Entry& owner = entries[static_cast<std::size_t>(a)];
          faces.Owner.push_back(owner.Cell);
          faces.Face.push_back(owner.Face);
          faces.Neighbour.push_back(entries[static_cast<std::size_t>(b)].Cell);
          break;
        }
      }
    }
  }
  // In the order of their owners: the angles take each owner's faces in one go.
  std::vector<std::size_t> order(faces.Size());
  for (std::size_t f = 0; f < order.size(); ++f)
  {
    order[f] = f;
  }
  std::sort(order.begin(), order.end(),
    [&faces](std::size_t a, std::size_t b)
    { return std::tie(faces.Owner[a], faces.Face[a]) < std::tie(faces.Owner[b], faces.Face[b]); });
  InternalFaces sorted;
  for (std::size_t f : order)
  {
    sorted.Owner.push_back(faces.Owner[f]);
    sorted.Neighbour.push_back(faces.Neighbour[f]);
    sorted.Face.push_back(faces.Face[f]);
  }
  return sorted;
}

InputOrientation OrientCells(const FaceCells& cells, const InternalFaces& faces,
  const double* original, const ParallelFor& parallelFor)
{
  std::vector<double> centres, volumes;
  CellCentres(cells, original, centres, volumes, parallelFor);
  InputOrientation orientation;
  orientation.CellSign.resize(volumes.size());
  for (std::size_t c = 0; c < volumes.size(); ++c)
  {
    orientation.CellSign[c] = volumes[c] < 0.0 ? -1 : 1;
  }
  orientation.InputMaximum =
    Angles(cells, faces, orientation.CellSign, original, centres, parallelFor).Maximum;
  return orientation;
}

NonOrthogonalityResult ComputeNonOrthogonality(const FaceCells& cells, const InternalFaces& faces,
  const InputOrientation& orientation, const double* points, const ParallelFor& parallelFor)
{
  std::vector<double> centres, volumes;
  CellCentres(cells, points, centres, volumes, parallelFor);
  return Angles(cells, faces, orientation.CellSign, points, centres, parallelFor);
}

} // namespace dgmf
