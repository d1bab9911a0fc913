/**
 * @file HexBoxBlocks.h
 * @brief Test helper: a box of hexahedra with its six sides as named boundary patches, as a CFD
 * reader (OpenFOAM's, CGNS's) gives a volume and its patches.
 */
#ifndef HexBoxBlocks_h
#define HexBoxBlocks_h

#include "HexahedraOfGrid.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <string>

namespace dgmf_test
{
/**
 * A box of n^3 hexahedra as a CFD reader gives it: block "internalMesh" and one polydata block
 * of quads per side ("xmin", "xmax", "ymin", "ymax", "zmin", "zmax"), points their own, but for
 * the side `omit` (a patch the reader was not asked for).
 */
inline vtkSmartPointer<vtkMultiBlockDataSet> HexBoxBlocks(int n, const std::string& omit)
{
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  const vtkSmartPointer<vtkUnstructuredGrid> volume = HexahedralBox(n);
  vtkPoints* points = volume->GetPoints();
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetBlock(0, volume);
  blocks->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "internalMesh");
  vtkNew<vtkMultiBlockDataSet> boundary;
  unsigned int index = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const std::string name = std::string(1, "xyz"[axis]) + (side ? "max" : "min");
      if (name == omit)
      {
        continue;
      }
      // The side's (n+1)^2 points in a grid of their own, and its n^2 quads.
      const auto point = [&](int a, int b)
      {
        int ijk[3];
        ijk[axis] = side * n;
        ijk[(axis + 1) % 3] = a;
        ijk[(axis + 2) % 3] = b;
        return id(ijk[0], ijk[1], ijk[2]);
      };
      vtkNew<vtkPoints> own;
      own->SetDataTypeToDouble();
      for (int b = 0; b <= n; ++b)
        for (int a = 0; a <= n; ++a)
          own->InsertNextPoint(points->GetPoint(point(a, b)));
      vtkNew<vtkCellArray> quads;
      for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a)
        {
          const vtkIdType quad[4] = { a + (n + 1) * b, a + 1 + (n + 1) * b,
            a + 1 + (n + 1) * (b + 1), a + (n + 1) * (b + 1) };
          quads->InsertNextCell(4, quad);
        }
      vtkNew<vtkPolyData> faces;
      faces->SetPoints(own);
      faces->SetPolys(quads);
      boundary->SetBlock(index, faces);
      boundary->GetMetaData(index++)->Set(vtkCompositeDataSet::NAME(), name.c_str());
    }
  }
  blocks->SetBlock(1, boundary);
  blocks->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "boundary");
  return blocks;
}

} // namespace dgmf_test

#endif
