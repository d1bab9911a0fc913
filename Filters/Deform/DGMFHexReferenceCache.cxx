#include "DGMFHexReferenceCache.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace dgmf_vtk
{

HexReferences HexReferenceCache::For(vtkUnstructuredGrid* mesh, vtkDataArray* originalPoints)
{
  vtkCellArray* cells = mesh->GetCells();
  const auto numberOfCells = static_cast<std::size_t>(mesh->GetNumberOfCells());
  HexReferences references;
  if (!this->Sizes.empty() && this->Sizes.size() == numberOfCells &&
    this->Cells.MatchesObject(cells) && this->Points.MatchesObject(originalPoints))
  {
    references.Sizes = this->Sizes.data();
    references.Known = true;
    return references;
  }
  this->Cells.Reset();
  this->Points.Reset();
  const unsigned char* types = mesh->GetCellTypesArray()->GetPointer(0);
  const auto hexahedra = static_cast<std::size_t>(std::count_if(types, types + numberOfCells,
    [](unsigned char type) { return type == VTK_HEXAHEDRON || type == VTK_VOXEL; }));
  if (numberOfCells == 0 || 2 * hexahedra < numberOfCells)
  {
    std::vector<double>().swap(this->Sizes);
    return references;
  }
  this->Sizes.assign(numberOfCells, 0.0);
  this->Sizes.shrink_to_fit();
  // Kept for the same objects, unmodified: computing the sizes again costs about what hashing
  // the cells and points would (a reader's new objects with the same content compute them again).
  this->Cells.SetObjectOnly(cells);
  this->Points.SetObjectOnly(originalPoints);
  references.Sizes = this->Sizes.data();
  return references;
}

} // namespace dgmf_vtk
