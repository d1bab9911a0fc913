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
  vtkCellArray* cells = mesh->GetCells();
  if (cells && cells->IsStorage64Bit() && mesh->GetNumberOfCells() > 0)
  {
    this->Offsets64 = cells->GetOffsetsArray64()->GetPointer(0);
    this->Connectivity64 = cells->GetConnectivityArray64()->GetPointer(0);
  }
  const std::array<bool, 256> present = CellTypesPresent(mesh);
  for (int type = 0; type < 256; ++type)
  {
    dgmf::CellShape shape;
    const int* order = nullptr;
    if (present[type] && type != VTK_EMPTY_CELL && type != VTK_POLYHEDRON &&
      vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 3 &&
      CellShapeOf(type, shape, order))
    {
      const int corners = dgmf::GetNumberOfCorners(shape);
      bool inOrder = true;
      for (int k = 0; k < corners; ++k)
      {
        inOrder = inOrder && order[k] == k;
      }
      this->Shapes[type] = { order, dgmf::GetShapeFaceStream(shape), corners, inOrder };
    }
  }
}

std::size_t VTKFaceCells::GetNumberOfCells() const
{
  return static_cast<std::size_t>(this->Mesh->GetNumberOfCells());
}

void VTKFaceCells::GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const
{
  thread_local std::vector<std::int64_t> corners; // GetFaces is called for every cell
  if (const std::int64_t* local = this->GetCornerFaces(cell, corners))
  {
    // A standard shape: its face stream with its corners' (canonical) point ids.
    stream.assign(local, local + dgmf::FaceStreamLength(local));
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        stream[at + 1 + k] = corners[static_cast<std::size_t>(local[at + 1 + k])];
      }
    }
    return;
  }
  stream.assign(1, 0); // no faces, but for a polyhedron's
  if (this->Types[cell] != VTK_POLYHEDRON)
  {
    return;
  }
  vtkIdType faces = 0;
  const vtkIdType* ids = nullptr;
  this->Mesh->GetFaceStream(static_cast<vtkIdType>(cell), faces, ids);
  stream[0] = faces;
  vtkIdType length = 0;
  for (vtkIdType f = 0; f < faces; ++f)
  {
    length += 1 + ids[length];
  }
  stream.insert(stream.end(), ids, ids + length);
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
  const ShapeOfType& shape = this->Shapes[this->Types[cell]];
  if (!shape.Faces)
  {
    return nullptr;
  }
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  const vtkTypeInt64* pts64 = nullptr;
  if (this->Offsets64)
  {
    npts = static_cast<vtkIdType>(this->Offsets64[cell + 1] - this->Offsets64[cell]);
    pts64 = this->Connectivity64 + this->Offsets64[cell];
  }
  else
  {
    thread_local vtkNew<vtkIdList> scratch;
    this->Mesh->GetCells()->GetCellAtId(static_cast<vtkIdType>(cell), npts, pts, scratch);
  }
  if (npts < shape.Corners)
  {
    return nullptr; // GetFaces gives such a cell no faces
  }
  corners.resize(static_cast<std::size_t>(shape.Corners));
  for (int k = 0; k < shape.Corners; ++k)
  {
    const auto point = static_cast<vtkIdType>(pts64 ? pts64[shape.Order[k]] : pts[shape.Order[k]]);
    corners[static_cast<std::size_t>(k)] =
      this->Canonical && point >= 0 && static_cast<std::size_t>(point) < this->Canonical->size()
      ? (*this->Canonical)[static_cast<std::size_t>(point)]
      : point;
  }
  return shape.Faces;
}

const std::int64_t* VTKFaceCells::GetCornerRun(std::size_t cell, std::size_t maxCells,
  const void*& ids, std::size_t& count, int& cornersPerCell) const
{
  const unsigned char type = this->Types ? this->Types[cell] : 0;
  const ShapeOfType& shape = this->Shapes[type];
  if (!shape.Faces || !shape.InOrder || !this->Offsets64 || this->Canonical)
  {
    return nullptr;
  }
  // The run: the same type, each cell with exactly the shape's corners.
  const vtkTypeInt64 corners = shape.Corners;
  std::size_t end = cell;
  while (end < cell + maxCells && this->Types[end] == type &&
    this->Offsets64[end + 1] - this->Offsets64[end] == corners)
  {
    ++end;
  }
  if (end == cell)
  {
    return nullptr;
  }
  ids = this->Connectivity64 + this->Offsets64[cell];
  count = end - cell;
  cornersPerCell = shape.Corners;
  return shape.Faces;
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
