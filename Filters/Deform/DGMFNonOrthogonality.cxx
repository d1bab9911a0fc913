#include "DGMFNonOrthogonality.h"

#include "DGMFArrayAllocation.h"
#include "DGMFFaceCells.h"
#include "DGMFOutputArrays.h"
#include "DGMFTupleAllocation.h"

#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

namespace dgmf_vtk
{
const dgmf::InternalFaces& InternalFacesCache::Get(
  vtkUnstructuredGrid* mesh, const dgmf::ParallelFor& parallelFor)
{
  vtkCellArray* cells = mesh->GetCells();
  auto hashCells = [mesh]() { return HashCells(mesh); };
  if (!this->Faces || !this->Cells.Matches(cells, hashCells))
  {
    this->Faces = std::make_unique<dgmf::InternalFaces>(dgmf::FindInternalFaces(
      VTKFaceCells(mesh), static_cast<std::size_t>(mesh->GetNumberOfPoints()), parallelFor));
    this->Cells.Set(cells, hashCells);
    this->Orientation.reset();
  }
  return *this->Faces;
}

const dgmf::InputOrientation& InternalFacesCache::Orient(
  vtkUnstructuredGrid* mesh, const double* original, const dgmf::ParallelFor& parallelFor)
{
  const dgmf::InternalFaces& faces = this->Get(mesh, parallelFor);
  const std::uint64_t hash =
    HashBytes(original, 3 * sizeof(double) * static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  if (!this->Orientation || hash != this->OriginalHash)
  {
    this->Orientation = std::make_unique<dgmf::InputOrientation>(
      dgmf::OrientCells(VTKFaceCells(mesh), faces, original, parallelFor));
    this->OriginalHash = hash;
  }
  return *this->Orientation;
}

double AddNonOrthogonality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDataSetAttributes* cellData, vtkFieldData* fieldData,
  InternalFacesCache& cache, const dgmf::ParallelFor& parallelFor)
{
  const VTKFaceCells cells(mesh);
  const dgmf::InputOrientation& orientation = cache.Orient(mesh, originalPoints, parallelFor);
  const dgmf::NonOrthogonalityResult result = dgmf::ComputeNonOrthogonality(
    cells, cache.Get(mesh, parallelFor), orientation, deformedPoints, parallelFor);
  vtkNew<vtkDoubleArray> perCell;
  perCell->SetName(dgmf::names::NonOrthogonality);
  AllocateTuples(perCell, static_cast<vtkIdType>(result.CellMaximum.size()));
  std::copy(result.CellMaximum.begin(), result.CellMaximum.end(), perCell->GetPointer(0));
  cellData->AddArray(perCell);
  AddFieldValue(fieldData, dgmf::names::MaximumNonOrthogonality, result.Maximum);
  AddFieldValue(fieldData, dgmf::names::InputMaximumNonOrthogonality, orientation.InputMaximum);
  return result.Maximum;
}

} // namespace dgmf_vtk
