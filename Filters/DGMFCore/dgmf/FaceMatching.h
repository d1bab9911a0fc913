/**
 * @file FaceMatching.h
 * @brief The faces of a mesh's cells matched by their points: the faces two cells share
 * (internal faces) and the faces of one cell only (boundary faces), in O(faces), on several
 * threads, with a result that does not depend on their number.
 */
#ifndef dgmf_FaceMatching_h
#define dgmf_FaceMatching_h

#include "dgmf/FirstTouch.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/Simd.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/// The faces of the cells of a mesh (the adapter gives VTK's).
class FaceCells
{
public:
  virtual ~FaceCells() = default;
  virtual std::size_t GetNumberOfCells() const = 0;
  /**
   * The faces of `cell` as a face stream with the mesh's point ids (CellFaces.h): the number of
   * faces, then each face's number of points and its points in order around it. A stream of 0
   * faces for cells that take no part (2D cells, cells without faces). Called concurrently.
   */
  virtual void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const = 0;
  /**
   * The faces of `cell` as its corners' point ids (into `corners`) and a face stream over the
   * corners' positions (the cell's shape's, GetShapeFaceStream), when the cell has a standard
   * shape: the same faces as GetFaces, for readers that need each corner once. nullptr (the
   * default) when the faces come as GetFaces gives them only. Called concurrently.
   */
  virtual const std::int64_t* GetCornerFaces(
    std::size_t /*cell*/, std::vector<std::int64_t>& /*corners*/) const
  {
    return nullptr;
  }
  /**
   * A run of cells from `cell` on (at most `maxCells`) of one standard shape whose corners' point
   * ids (64-bit integers) lie one cell after the other in memory, in the shape's corner order:
   * cell `cell + k` has the corners at ids + 8 * (k * cornersPerCell ...) bytes. Returns the
   * shape's face stream over corner positions (as GetCornerFaces) and sets `ids`, `count` (>= 1)
   * and `cornersPerCell`; nullptr (the default) when `cell` starts no such run. The same faces as
   * GetCornerFaces, for readers that go through whole runs without a call per cell. Called
   * concurrently.
   */
  virtual const std::int64_t* GetCornerRun(std::size_t /*cell*/, std::size_t /*maxCells*/,
    const void*& /*ids*/, std::size_t& /*count*/, int& /*cornersPerCell*/) const
  {
    return nullptr;
  }
};

/**
 * Calls `visit(cell, stream, corners)` for each cell of [begin, end), in order, with the cell's
 * face stream (CellFaces.h; null for a cell without faces): for a run of one shape
 * (FaceCells::GetCornerRun) the shape's stream over corner positions and `corners` the cell's
 * corners' point ids, otherwise GetFaces' stream of point ids (built in `scratch`) and `corners`
 * null. Runs save the face stream a call per cell builds.
 *
 * With `prefetchPoints` (3 coordinates per point), the corners' coordinates of the cell
 * CornersAhead cells on in a run are asked for while a cell is visited: in an unstructured mesh
 * they lie anywhere in memory.
 */
template <typename Visit>
void ForEachCellFaceStream(const FaceCells& cells, std::size_t begin, std::size_t end,
  std::vector<std::int64_t>& scratch, const Visit& visit, const double* prefetchPoints = nullptr)
{
  constexpr std::size_t CornersAhead = 4;
  for (std::size_t c = begin; c < end; ++c)
  {
    const void* ids = nullptr;
    std::size_t count = 0;
    int perCell = 0;
    if (const std::int64_t* local = cells.GetCornerRun(c, end - c, ids, count, perCell))
    {
      const auto* corners = static_cast<const std::int64_t*>(ids);
      for (std::size_t k = 0; k < count; ++k, corners += perCell)
      {
        if (prefetchPoints && k + CornersAhead < count)
        {
          const std::int64_t* ahead = corners + CornersAhead * static_cast<std::size_t>(perCell);
          for (int j = 0; j < perCell; ++j)
          {
            simd::Prefetch(prefetchPoints + 3 * ahead[j]);
          }
        }
        visit(c + k, local, corners);
      }
      c += count - 1;
      continue;
    }
    cells.GetFaces(c, scratch);
    visit(c, scratch.empty() ? nullptr : scratch.data(), static_cast<const std::int64_t*>(nullptr));
  }
}

/// The faces shared by two cells, each once, in increasing order of owner, then of face.
struct InternalFaces
{
  UninitializedVector<std::int64_t> Owner;     ///< the cell whose face stream gives the face
  UninitializedVector<std::int64_t> Neighbour; ///< the other cell
  UninitializedVector<std::int32_t> Face;      ///< the face's position in the owner's stream

  std::size_t Size() const { return this->Owner.size(); }
};

/// The faces used by one cell only, in increasing order of cell, then of face.
struct BoundaryFaces
{
  std::vector<std::int64_t> Cell;
  std::vector<std::int32_t> Face; ///< the face's position in the cell's stream

  std::size_t Size() const { return this->Cell.size(); }
};

/**
 * The internal faces of `cells`: faces with the same set of points in two different cells. A
 * face found in more than two cells (a non-manifold mesh) is paired in the order of the cells,
 * and the rest left unpaired. Point ids must lie in [0, numberOfPoints) (else
 * std::invalid_argument, naming the cell).
 *
 * How: every face goes into the bucket of its smallest point id (a count and a fill over fixed
 * chunks of the cells, in parallel, into groups of buckets), then each bucket is sorted by the
 * face's other point ids and equal faces are paired. Memory while it runs: about 24 bytes per face
 * (48 with 2^32 - 1 points or cells or more).
 */
InternalFaces FindInternalFaces(
  const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor);

/// The faces of `cells` that no other cell has (as FindInternalFaces matches them).
BoundaryFaces FindBoundaryFaces(
  const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
