#include "dgmf/DecomposedSizeSkew.h"

#include "dgmf/CellFaces.h"
#include "dgmf/CellGeometry.h"

#include <algorithm>

namespace dgmf
{
namespace
{
/// Pieces whose input shape quality is below this are flat in the input: left out.
constexpr double MinimumInputShape = 1e-6;

/// The vertex average of the corners `ids` (count of them) of `points`.
Vec3 Average(const double* points, const std::int64_t* ids, std::int64_t count)
{
  Vec3 sum{ 0.0, 0.0, 0.0 };
  for (std::int64_t k = 0; k < count; ++k)
  {
    sum = sum + Load(points, ids[k]);
  }
  return (1.0 / static_cast<double>(count)) * sum;
}

Vec3 AverageAll(const double* points, int count)
{
  Vec3 sum{ 0.0, 0.0, 0.0 };
  for (int k = 0; k < count; ++k)
  {
    sum = sum + Load(points, k);
  }
  return (1.0 / static_cast<double>(count)) * sum;
}
} // namespace

CellQuality ComputeDecomposedSizeSkew(
  int corners, const double* original, const double* deformed, const std::int64_t* faceStream)
{
  CellQuality cell;
  cell.SizeSkew = 1.0;
  bool judged = false;
  const bool polygon = faceStream[0] == 1;
  const Vec3 cellCentre[2] = { AverageAll(original, corners), AverageAll(deformed, corners) };
  std::int64_t at = 1;
  for (std::int64_t f = 0; f < faceStream[0]; ++f)
  {
    const std::int64_t n = faceStream[at];
    const std::int64_t* ids = faceStream + at + 1;
    const Vec3 faceCentre[2] = { Average(original, ids, n), Average(deformed, ids, n) };
    for (std::int64_t k = 0; k < n; ++k)
    {
      // The piece before and after: (face centre,) two corners, the cell's (polygon's) centre.
      double piece[2][12];
      const double* points[2] = { original, deformed };
      for (int s = 0; s < 2; ++s)
      {
        Store(Load(points[s], ids[k]), piece[s], 0);
        Store(Load(points[s], ids[(k + 1) % n]), piece[s], 1);
        Store(polygon ? cellCentre[s] : faceCentre[s], piece[s], 2);
        Store(cellCentre[s], piece[s], 3);
      }
      const CellShape shape = polygon ? CellShape::Triangle : CellShape::Tetra;
      const CellQuality before = ComputeSizeSkew(shape, piece[0], piece[0]);
      if (!(before.SizeSkew > MinimumInputShape))
      {
        continue; // (nearly) zero size in the input: its rounding would be taken for a change
      }
      const CellQuality after = ComputeSizeSkew(shape, piece[0], piece[1]);
      judged = true;
      cell.Inverted = cell.Inverted || after.Inverted;
      cell.SizeSkew = std::min(cell.SizeSkew, std::min(1.0, after.SizeSkew / before.SizeSkew));
    }
    at += 1 + n;
  }
  if (!judged || cell.Inverted)
  {
    cell.SizeSkew = 0.0;
  }
  return cell;
}

CellQuality JudgeInvalidInputCell(CellShape shape, const double* original, const double* deformed)
{
  CellQuality quality = ComputeDecomposedSizeSkew(
    GetNumberOfCorners(shape), original, deformed, GetShapeFaceStream(shape));
  quality.InputInvalid = true;
  return quality;
}

CellQuality ComputeCellSizeSkew(CellShape shape, const double* original, const double* deformed)
{
  const CellQuality quality = ComputeSizeSkew(shape, original, deformed);
  return quality.InputInvalid ? JudgeInvalidInputCell(shape, original, deformed) : quality;
}

} // namespace dgmf
