#include "DGMFCellQuality.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace dgmf_vtk
{
namespace
{
/// The metric's shape for a VTK cell type and the corner order (VTK ids in the shape's order).
bool GetShape(int vtkType, dgmf::CellShape& shape, const int*& order)
{
  static const int identity[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  static const int pixel[4] = { 0, 1, 3, 2 };
  static const int voxel[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  order = identity;
  switch (vtkType)
  {
    case VTK_TRIANGLE:
      shape = dgmf::CellShape::Triangle;
      return true;
    case VTK_QUAD:
      shape = dgmf::CellShape::Quad;
      return true;
    case VTK_PIXEL:
      shape = dgmf::CellShape::Quad;
      order = pixel;
      return true;
    case VTK_TETRA:
      shape = dgmf::CellShape::Tetra;
      return true;
    case VTK_HEXAHEDRON:
      shape = dgmf::CellShape::Hexahedron;
      return true;
    case VTK_VOXEL:
      shape = dgmf::CellShape::Hexahedron;
      order = voxel;
      return true;
    case VTK_WEDGE:
      shape = dgmf::CellShape::Wedge;
      return true;
    case VTK_PYRAMID:
      shape = dgmf::CellShape::Pyramid;
      return true;
    default:
      return false;
  }
}
} // namespace

dgmf::QualitySummary ComputeCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDoubleArray* sizeSkew, vtkUnsignedCharArray* inverted,
  const dgmf::ParallelFor& parallelFor)
{
  const vtkIdType numberOfCells = mesh->GetNumberOfCells();
  sizeSkew->SetNumberOfComponents(1);
  sizeSkew->SetNumberOfTuples(numberOfCells);
  inverted->SetNumberOfComponents(1);
  inverted->SetNumberOfTuples(numberOfCells);
  double* values = sizeSkew->GetPointer(0);
  unsigned char* flags = inverted->GetPointer(0);
  vtkCellArray* cells = mesh->GetCells();

  parallelFor(0, static_cast<std::size_t>(numberOfCells), 4096,
    [&](std::size_t begin, std::size_t end)
    {
      vtkNew<vtkIdList> scratch;
      double original[8 * 3];
      double deformed[8 * 3];
      for (std::size_t c = begin; c < end; ++c)
      {
        const auto cellId = static_cast<vtkIdType>(c);
        dgmf::CellShape shape;
        const int* order;
        vtkIdType npts;
        const vtkIdType* pts;
        if (!GetShape(mesh->GetCellType(cellId), shape, order))
        {
          values[c] = std::numeric_limits<double>::quiet_NaN();
          flags[c] = 0;
          continue;
        }
        cells->GetCellAtId(cellId, npts, pts, scratch);
        const int corners = dgmf::GetNumberOfCorners(shape);
        if (npts < corners)
        {
          values[c] = std::numeric_limits<double>::quiet_NaN();
          flags[c] = 0;
          continue;
        }
        for (int k = 0; k < corners; ++k)
        {
          const auto p = static_cast<std::size_t>(pts[order[k]]);
          for (int c = 0; c < 3; ++c)
          {
            original[3 * k + c] = originalPoints[3 * p + c];
            deformed[3 * k + c] = deformedPoints[3 * p + c];
          }
        }
        const dgmf::CellQuality quality = dgmf::ComputeSizeSkew(shape, original, deformed);
        values[c] = quality.SizeSkew;
        flags[c] = quality.Inverted ? 1 : 0;
      }
    });
  // Ghost cells are evaluated (their arrays must be complete) but counted by their owner.
  std::vector<std::uint8_t> ghost;
  if (vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray())
  {
    ghost.resize(static_cast<std::size_t>(numberOfCells));
    for (vtkIdType c = 0; c < numberOfCells; ++c)
    {
      ghost[static_cast<std::size_t>(c)] =
        (ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL) != 0 ? 1 : 0;
    }
  }
  return dgmf::SummarizeQuality(values, flags, static_cast<std::size_t>(numberOfCells),
    ghost.empty() ? nullptr : ghost.data());
}

} // namespace dgmf_vtk
