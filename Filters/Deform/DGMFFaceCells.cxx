#include "DGMFFaceCells.h"

#include "DGMFMeshConversion.h"

#include "dgmf/CellFaces.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

namespace dgmf_vtk
{

VTKFaceCells::VTKFaceCells(vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>* canonical)
  : Mesh(mesh)
  , Types(mesh->GetCellTypesArray() && mesh->GetNumberOfCells() > 0
        ? mesh->GetCellTypesArray()->GetPointer(0)
        : nullptr)
  , Canonical(canonical && !canonical->empty() ? canonical : nullptr)
{
}

std::size_t VTKFaceCells::GetNumberOfCells() const
{
  return static_cast<std::size_t>(this->Mesh->GetNumberOfCells());
}

void VTKFaceCells::GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const
{
  const auto id = static_cast<vtkIdType>(cell);
  const int type = this->Types[cell];
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
  }
  else
  {
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
  if (this->Canonical)
  {
    for (std::int64_t f = 0, at = 1; f < stream[0]; ++f, at += 1 + stream[at])
    {
      for (std::int64_t k = 0; k < stream[at]; ++k)
      {
        std::int64_t& point = stream[at + 1 + k];
        if (point >= 0 && static_cast<std::size_t>(point) < this->Canonical->size())
        {
          point = (*this->Canonical)[static_cast<std::size_t>(point)];
        }
      }
    }
  }
}

const std::int64_t* VTKFaceCells::GetCornerFaces(
  std::size_t cell, std::vector<std::int64_t>& corners) const
{
  const int type = this->Types[cell];
  dgmf::CellShape shape;
  const int* order = nullptr;
  if (type == VTK_POLYHEDRON || type == VTK_EMPTY_CELL ||
    vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) != 3 ||
    !CellShapeOf(type, shape, order))
  {
    return nullptr;
  }
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  thread_local vtkNew<vtkIdList> scratch;
  this->Mesh->GetCells()->GetCellAtId(static_cast<vtkIdType>(cell), npts, pts, scratch);
  const int n = dgmf::GetNumberOfCorners(shape);
  if (npts < n)
  {
    return nullptr; // GetFaces gives such a cell no faces
  }
  corners.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
  {
    const vtkIdType point = pts[order[k]];
    corners[static_cast<std::size_t>(k)] =
      this->Canonical && point >= 0 && static_cast<std::size_t>(point) < this->Canonical->size()
      ? (*this->Canonical)[static_cast<std::size_t>(point)]
      : point;
  }
  return dgmf::GetShapeFaceStream(shape);
}

bool VTKFaceCells::CoversAll3DCells(const std::array<bool, 256>& types)
{
  for (int type = 0; type < 256; ++type)
  {
    dgmf::CellShape shape;
    const int* order = nullptr;
    if (types[type] && type != VTK_EMPTY_CELL && type != VTK_POLYHEDRON &&
      vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 3 &&
      !CellShapeOf(type, shape, order))
    {
      return false;
    }
  }
  return true;
}

} // namespace dgmf_vtk
