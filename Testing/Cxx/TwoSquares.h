/**
 * @file TwoSquares.h
 * @brief A small 2D grid for the adapter tests.
 */
#ifndef DGMFTestTwoSquares_h
#define DGMFTestTwoSquares_h

#include "vtkCellType.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

/// Two unit squares side by side in the plane z = 0 (6 nodes, 2 quads), with a marker: the left
/// edge static, the right edge moving.
inline vtkSmartPointer<vtkUnstructuredGrid> TwoSquares(double x0 = 0.0)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      points->InsertNextPoint(x0 + i, j, 0.0);
    }
  }
  grid->SetPoints(points);
  const vtkIdType left[4] = { 0, 1, 4, 3 }, right[4] = { 1, 2, 5, 4 };
  grid->InsertNextCell(VTK_QUAD, 4, left);
  grid->InsertNextCell(VTK_QUAD, 4, right);
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  for (int value : { 1, 0, 2, 1, 0, 2 })
  {
    marker->InsertNextValue(value);
  }
  grid->GetPointData()->AddArray(marker);
  return grid;
}

#endif
