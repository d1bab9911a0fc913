#include "DGMFBoundaryDetection.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkGeometryFilter.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace dgmf_vtk
{
namespace
{
void FindBoundaryNodes3D(vtkUnstructuredGrid* mesh, std::vector<std::uint8_t>& flags)
{
  // The geometry filter works on a structure-only copy, so no array of the input goes through it.
  vtkNew<vtkUnstructuredGrid> structure;
  structure->CopyStructure(mesh);
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputData(structure);
  surface->PassThroughPointIdsOn();
  surface->MergingOff();
  surface->Update();
  vtkPolyData* boundary = surface->GetOutput();
  vtkDataArray* ids = boundary->GetPointData()->GetArray(surface->GetOriginalPointIdsName());
  if (!ids)
  {
    return;
  }
  auto faces = vtk::TakeSmartPointer(boundary->GetPolys()->NewIterator());
  for (faces->GoToFirstCell(); !faces->IsDoneWithTraversal(); faces->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    faces->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      const auto id = static_cast<std::size_t>(ids->GetTuple1(pts[k]));
      if (id < flags.size())
      {
        flags[id] = 1;
      }
    }
  }
}

struct PairHash
{
  std::size_t operator()(const std::pair<vtkIdType, vtkIdType>& p) const
  {
    return std::hash<vtkIdType>()(p.first) * 1000003u ^ std::hash<vtkIdType>()(p.second);
  }
};

void FindBoundaryNodes2D(vtkUnstructuredGrid* mesh, std::vector<std::uint8_t>& flags)
{
  // Count how many 2D cells use each edge (keyed by its end nodes); edges used once are on the
  // boundary, and all their nodes (with mid-edge nodes of higher-order cells) are boundary nodes.
  using EdgeKey = std::pair<vtkIdType, vtkIdType>;
  std::unordered_map<EdgeKey, int, PairHash> uses;
  uses.reserve(static_cast<std::size_t>(2 * mesh->GetNumberOfCells()));
  vtkNew<vtkGenericCell> cell;
  for (int pass = 0; pass < 2; ++pass)
  {
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      mesh->GetCell(c, cell);
      if (cell->GetCellDimension() != 2)
      {
        continue;
      }
      for (int e = 0; e < cell->GetNumberOfEdges(); ++e)
      {
        vtkIdList* edge = cell->GetEdge(e)->GetPointIds();
        const vtkIdType a = edge->GetId(0);
        const vtkIdType b = edge->GetId(1);
        const EdgeKey key(std::min(a, b), std::max(a, b));
        if (pass == 0)
        {
          ++uses[key];
        }
        else if (uses[key] == 1)
        {
          for (vtkIdType k = 0; k < edge->GetNumberOfIds(); ++k)
          {
            flags[static_cast<std::size_t>(edge->GetId(k))] = 1;
          }
        }
      }
    }
  }
}
} // namespace

std::vector<std::uint8_t> FindBoundaryNodes(vtkUnstructuredGrid* mesh, int dimension)
{
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(mesh->GetNumberOfPoints()), 0);
  if (dimension == 2)
  {
    FindBoundaryNodes2D(mesh, flags);
  }
  else
  {
    FindBoundaryNodes3D(mesh, flags);
  }
  return flags;
}

} // namespace dgmf_vtk
