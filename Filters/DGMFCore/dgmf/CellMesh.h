/**
 * @file CellMesh.h
 * @brief The cells of a mesh as the core reads them (quality guard, sub-steps): connectivity and
 * shapes, without VTK.
 */
#ifndef dgmf_CellMesh_h
#define dgmf_CellMesh_h

#include "dgmf/SizeSkewQuality.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/**
 * Cells of a mesh, CSR style: the corners of cell c are Connectivity[Offsets[c]] ...
 * Connectivity[Offsets[c + 1] - 1], in VTK's order for its shape.
 */
struct CellMesh
{
  std::size_t NumberOfPoints = 0;         ///< node indices are in [0, NumberOfPoints)
  std::vector<std::int64_t> Offsets;      ///< number of cells + 1 entries, Offsets[0] = 0
  std::vector<std::int64_t> Connectivity; ///< node indices
  std::vector<CellShape> Shapes;          ///< one per cell (ignored where Covered is 0)
  /**
   * One per cell, or empty (all cells covered): 0 for a cell the size-skew metric does not cover
   * (polygon, polyhedron, quadratic cell, ...). Such a cell is never bad, and its nodes never
   * move (the repair cannot check that a move keeps it valid).
   */
  std::vector<std::uint8_t> Covered;

  /// Number of cells (Offsets.size() - 1, or 0).
  std::size_t GetNumberOfCells() const { return Offsets.empty() ? 0 : Offsets.size() - 1; }
};

} // namespace dgmf

#endif
