#include "DGMFNonOrthogonality.h"

#include "DGMFArrayAllocation.h"

#include "DGMFMeshConversion.h"
#include "DGMFOutputArrays.h"

#include "dgmf/CellFaces.h"
#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

namespace dgmf_vtk
{
namespace
{
/// The faces of a vtkUnstructuredGrid's 3D cells.
class VTKFaceCells : public dgmf::FaceCells
{
public:
  explicit VTKFaceCells(vtkUnstructuredGrid* mesh)
    : Mesh(mesh)
  {
  }

  std::size_t GetNumberOfCells() const override
  {
    return static_cast<std::size_t>(this->Mesh->GetNumberOfCells());
  }

  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override
  {
    const auto id = static_cast<vtkIdType>(cell);
    const int type = this->Mesh->GetCellType(id);
    stream.assign(1, 0);
    if (type == VTK_POLYHEDRON)
    {
      vtkIdType faces = 0;
      const vtkIdType* ids = nullptr;
      this->Mesh->GetFaceStream(id, faces, ids);
      stream[0] = faces;
      vtkIdType length = 0;
      for (vtkIdType f = 0; f < faces; ++f)
      {
        length += 1 + ids[length];
      }
      stream.insert(stream.end(), ids, ids + length);
      return;
    }
    dgmf::CellShape shape;
    const int* order = nullptr;
    if (type == VTK_EMPTY_CELL ||
      vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) != 3 ||
      !CellShapeOf(type, shape, order))
    {
      return;
    }
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    thread_local vtkNew<vtkIdList> scratch; // GetFaces is called for every cell, on every thread
    this->Mesh->GetCells()->GetCellAtId(id, npts, pts, scratch);
    if (npts < dgmf::GetNumberOfCorners(shape))
    {
      return;
    }
    const std::int64_t* local = dgmf::GetShapeFaceStream(shape);
    const std::int64_t length = dgmf::FaceStreamLength(local);
    stream.assign(local, local + length);
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        stream[at + 1 + k] = pts[order[local[at + 1 + k]]];
      }
    }
  }

private:
  vtkUnstructuredGrid* Mesh;
};
} // namespace

const dgmf::InternalFaces& InternalFacesCache::Get(vtkUnstructuredGrid* mesh)
{
  vtkCellArray* cells = mesh->GetCells();
  auto hashCells = [&]()
  {
    std::uint64_t h = HashArray(cells->GetConnectivityArray());
    h = HashArray(cells->GetOffsetsArray(), h);
    h = HashArray(mesh->GetCellTypesArray(), h);
    return mesh->GetFaces() ? HashArray(mesh->GetFaces(), h) : h;
  };
  if (!this->Faces || !this->Cells.Matches(cells, hashCells))
  {
    this->Faces = std::make_unique<dgmf::InternalFaces>(dgmf::FindInternalFaces(
      VTKFaceCells(mesh), static_cast<std::size_t>(mesh->GetNumberOfPoints())));
    this->Cells.Set(cells, hashCells);
    this->Orientation.reset();
  }
  return *this->Faces;
}

const dgmf::InputOrientation& InternalFacesCache::Orient(
  vtkUnstructuredGrid* mesh, const double* original, const dgmf::ParallelFor& parallelFor)
{
  const dgmf::InternalFaces& faces = this->Get(mesh);
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
  const dgmf::NonOrthogonalityResult result =
    dgmf::ComputeNonOrthogonality(cells, cache.Get(mesh), orientation, deformedPoints, parallelFor);
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
