// Deforms a small grid built in code: the centre node is a one-node body that moves by 0.1 along
// x; the frame stays. Prints "consumer OK" when the body, the frame and the nodes between are
// where DGMF puts them.
#include "vtkDGMFDeformFilter.h"

#include "vtkCellType.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cstdio>

int main()
{
  const int n = 5; // 5 x 5 nodes on [-2, 2]^2
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      points->InsertNextPoint(i - 2.0, j - 2.0, 0.0);
      const bool frame = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      marker->InsertNextValue(frame ? 1 : (i == 2 && j == 2 ? 2 : 0));
    }
  }
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(marker);
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType quad[4] = { j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i };
      grid->InsertNextCell(VTK_QUAD, 4, quad);
    }
  }
  vtkNew<vtkDGMFDeformFilter> deform;
  deform->SetInputData(grid);
  deform->SetBoundaryMarkerArrayName("BoundaryMarker");
  deform->SetTranslation(0.1, 0.0, 0.0);
  deform->Update();
  vtkUnstructuredGrid* out = deform->GetOutput();
  if (!out || out->GetNumberOfPoints() != n * n)
  {
    std::printf("consumer: no output\n");
    return 1;
  }
  const double body = out->GetPoint(12)[0];    // the centre, was 0
  const double frame = out->GetPoint(0)[0];    // a corner, was -2
  const double between = out->GetPoint(11)[0]; // between body and frame, was -1
  std::printf("body %.6f, frame %.6f, between %.6f\n", body, frame, between);
  if (body != 0.1 || frame != -2.0 || !(between > -1.0 && between < -0.9))
  {
    return 1;
  }
  std::printf("consumer OK\n");
  return 0;
}
