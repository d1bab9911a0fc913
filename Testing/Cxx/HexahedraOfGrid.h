/**
 * @file HexahedraOfGrid.h
 * @brief The filter tests' structured boxes: the hexahedra of an (n+1)^3 grid of points.
 */
#ifndef dgmf_test_HexahedraOfGrid_h
#define dgmf_test_HexahedraOfGrid_h

#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
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

/// The unit box grid of n^3 hexahedra: points (i, j, k) for i, j, k in [0, n], as doubles, in the
/// numbering of AddHexahedraOfGrid, and those hexahedra.
inline vtkSmartPointer<vtkUnstructuredGrid> HexahedralBox(int n)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        points->InsertNextPoint(i, j, k);
  grid->SetPoints(points);
  AddHexahedraOfGrid(grid, n);
  return grid;
}

} // namespace dgmf_test

#endif
