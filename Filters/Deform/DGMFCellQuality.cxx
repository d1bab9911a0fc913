#include "DGMFCellQuality.h"

#include "DGMFMeshConversion.h"

#include "vtkPoints.h"

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
  const unsigned char* types = mesh->GetCellTypesArray()->GetPointer(0);

  parallelFor(0, static_cast<std::size_t>(numberOfCells), 4096,
    [&](std::size_t begin, std::size_t end)
    {
      vtkNew<vtkIdList> scratch;
      // Hexahedra go by two (ComputeHexSizeSkewPair, the same bits): `pending` is one waiting
      // for its partner, its corners in the second half of the buffers.
      double original[2][8 * 3];
      double deformed[2][8 * 3];
      std::size_t pending = end;
      for (std::size_t c = begin; c < end; ++c)
      {
        const auto cellId = static_cast<vtkIdType>(c);
        dgmf::CellShape shape;
        const int* order;
        vtkIdType npts;
        const vtkIdType* pts;
        if (!CellShapeOf(types[c], shape, order))
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
        const bool hexahedron = shape == dgmf::CellShape::Hexahedron;
        const int slot = hexahedron && pending == end ? 1 : 0;
        for (int k = 0; k < corners; ++k)
        {
          const auto p = static_cast<std::size_t>(pts[order[k]]);
          for (int d = 0; d < 3; ++d)
          {
            original[slot][3 * k + d] = originalPoints[3 * p + d];
            deformed[slot][3 * k + d] = deformedPoints[3 * p + d];
          }
        }
        dgmf::CellQuality quality;
        if (!hexahedron)
        {
          quality = dgmf::ComputeSizeSkew(shape, original[0], deformed[0]);
        }
        else if (slot == 1)
        {
          pending = c;
          continue;
        }
        else
        {
          dgmf::CellQuality first;
          dgmf::ComputeHexSizeSkewPair(
            original[1], deformed[1], original[0], deformed[0], first, quality);
          values[pending] = first.SizeSkew;
          flags[pending] = first.Inverted ? 1 : 0;
          pending = end;
        }
        values[c] = quality.SizeSkew;
        flags[c] = quality.Inverted ? 1 : 0;
      }
      if (pending < end)
      {
        const dgmf::CellQuality last =
          dgmf::ComputeSizeSkew(dgmf::CellShape::Hexahedron, original[1], deformed[1]);
        values[pending] = last.SizeSkew;
        flags[pending] = last.Inverted ? 1 : 0;
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
  return dgmf::SummarizeQuality(
    values, flags, static_cast<std::size_t>(numberOfCells), ghost.empty() ? nullptr : ghost.data());
}

} // namespace dgmf_vtk
