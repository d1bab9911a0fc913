/**
 * @file DGMFGridCells.h
 * @brief Hands a vtkUnstructuredGrid its cell arrays without VTK's scan of the types. Header only
 * (in the DGMFTupleAllocation INTERFACE library), so that the filters' module and dgmf-deform's
 * .vtu reader share it without linking one another.
 */
#ifndef DGMFGridCells_h
#define DGMFGridCells_h

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cstddef>
#include <cstring>

namespace dgmf_vtk
{
/**
 * `grid->SetCells(types, cells)`, the same result. VTK 9.2's two-argument form looks for a
 * polyhedron type one value at a time (10 ms at 8M cells), to read the special layout such cells
 * have there; without one it sets the arrays as the four-argument form with no faces, which a
 * `memchr` lets this call directly.
 */
inline void SetGridCells(
  vtkUnstructuredGrid* grid, vtkUnsignedCharArray* types, vtkCellArray* cells)
{
  const auto n = static_cast<std::size_t>(types->GetNumberOfValues());
  if (n > 0 && std::memchr(types->GetPointer(0), VTK_POLYHEDRON, n))
  {
    grid->SetCells(types, cells);
  }
  else
  {
    grid->SetCells(types, cells, nullptr, nullptr);
  }
}
} // namespace dgmf_vtk

#endif
