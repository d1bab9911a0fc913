/**
 * @file HexahedraOfGrid.h
 * @brief The filter tests' structured boxes: the hexahedra of an (n+1)^3 grid of points.
 */
#ifndef dgmf_test_HexahedraOfGrid_h
#define dgmf_test_HexahedraOfGrid_h

#include "vtkCellType.h"
#include "vtkUnstructuredGrid.h"

namespace dgmf_test
{

/// Adds to `grid` the n^3 hexahedra of its (n+1)^3 points, point (i, j, k) being number
/// i + (n+1) (j + (n+1) k), the cells along x, then y, then z.
inline void AddHexahedraOfGrid(vtkUnstructuredGrid* grid, int n)
{
  const auto id = [n](int i, int j, int k)
  { return static_cast<vtkIdType>(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
}

} // namespace dgmf_test

#endif
