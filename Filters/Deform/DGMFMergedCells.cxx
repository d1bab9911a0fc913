#include "DGMFMergedCells.h"

#include "DGMFArrayAllocation.h"
#include "DGMFGridCells.h"
#include "DGMFMeshConversion.h"
#include "DGMFSMPTools.h"
#include "DGMFTupleAllocation.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkIdList.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace dgmf_vtk
{
namespace
{
/// `count` values of `from` (of an integer type), each mapped by `map`, into `to`, on the
/// vtkSMPTools threads.
template <typename Array, typename Map>
void CopyMapped(Array* from, vtkIdType first, vtkIdType count, vtkIdType* to, const Map& map)
{
  const auto* values = from->GetPointer(first);
  MakeSMPParallelFor()(0, static_cast<std::size_t>(count), 1 << 16,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        to[k] = map(static_cast<vtkIdType>(values[k]));
      }
    });
}
} // namespace

/// The number of cells of `block` and of point ids in their connectivity.
void CountCells(vtkPointSet* block, vtkIdType& cells, vtkIdType& ids)
{
  cells = block->GetNumberOfCells();
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(block))
  {
    ids = grid->GetCells() ? grid->GetCells()->GetNumberOfConnectivityIds() : 0;
    return;
  }
  ids = 0;
  if (auto* polyData = vtkPolyData::SafeDownCast(block))
  {
    for (vtkCellArray* part :
      { polyData->GetVerts(), polyData->GetLines(), polyData->GetPolys(), polyData->GetStrips() })
    {
      ids += part ? part->GetNumberOfConnectivityIds() : 0;
    }
    return;
  }
  for (vtkIdType c = 0; c < cells; ++c)
  {
    ids += block->GetCellSize(c);
  }
}

MergedCells::MergedCells(vtkIdType cells, vtkIdType ids)
{
  AllocateTuples(this->Types, cells);
  AllocateTuples(this->Offsets, cells + 1);
  AllocateTuples(this->Connectivity, ids);
  this->Offsets->SetValue(0, 0);
}

void MergedCells::Append(
  vtkPointSet* block, const CompositeMesh::Leaf& leaf, const std::array<bool, 256>& types)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(block);
  if (grid && grid->GetCells() && grid->GetNumberOfCells() > 0)
  {
    if (!types[VTK_POLYHEDRON] || (grid->GetFaceLocations() && grid->GetFaces()))
    {
      this->AppendGrid(grid, leaf, types);
      return;
    }
  }
  this->AppendCellByCell(block, leaf);
}

void MergedCells::SetOn(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkCellArray> cells;
  cells->SetData(this->Offsets, this->Connectivity);
  if (this->FaceLocations.empty())
  {
    SetGridCells(grid, this->Types, cells);
    return;
  }
  const auto idArray = [](const std::vector<vtkIdType>& values)
  {
    vtkNew<vtkIdTypeArray> array;
    AllocateTuples(array, static_cast<vtkIdType>(values.size()));
    std::copy(values.begin(), values.end(), array->GetPointer(0));
    return vtkSmartPointer<vtkIdTypeArray>(array.GetPointer());
  };
  this->FaceLocations.resize(static_cast<std::size_t>(this->NumberOfCells), -1);
  grid->SetCells(this->Types, cells, idArray(this->FaceLocations), idArray(this->Faces));
}

void MergedCells::AppendGrid(
  vtkUnstructuredGrid* grid, const CompositeMesh::Leaf& leaf, const std::array<bool, 256>& present)
{
  const vtkIdType cells = grid->GetNumberOfCells();
  vtkCellArray* source = grid->GetCells();
  const vtkIdType ids = source->GetNumberOfConnectivityIds();
  std::memcpy(this->Types->GetPointer(this->NumberOfCells),
    grid->GetCellTypesArray()->GetPointer(0), static_cast<std::size_t>(cells));
  vtkIdType* offsets = this->Offsets->GetPointer(this->NumberOfCells);
  vtkIdType* connectivity = this->Connectivity->GetPointer(this->NumberOfIds);
  const vtkIdType base = this->NumberOfIds;
  const auto shift = [base](vtkIdType offset) { return base + offset; };
  const auto renumber = [&leaf](vtkIdType id) { return leaf.Node(id); };
  const auto same = [](vtkIdType id) { return id; }; // a plain copy (the volume, as a rule)
  if (source->IsStorage64Bit())
  {
    CopyMapped(source->GetOffsetsArray64(), 0, cells + 1, offsets, shift);
    if (leaf.SameNumbering)
    {
      CopyMapped(source->GetConnectivityArray64(), 0, ids, connectivity, same);
    }
    else
    {
      CopyMapped(source->GetConnectivityArray64(), 0, ids, connectivity, renumber);
    }
  }
  else
  {
    CopyMapped(source->GetOffsetsArray32(), 0, cells + 1, offsets, shift);
    CopyMapped(source->GetConnectivityArray32(), 0, ids, connectivity, renumber);
  }
  if (present[VTK_POLYHEDRON])
  {
    this->AppendPolyhedronFaces(grid, leaf);
  }
  this->NumberOfCells += cells;
  this->NumberOfIds += ids;
}

void CheckPolyhedronFaces(vtkUnstructuredGrid* grid)
{
  const vtkIdType cells = grid->GetNumberOfCells();
  const vtkIdType* location = grid->GetFaceLocations()->GetPointer(0);
  const vtkIdType* stream = grid->GetFaces()->GetPointer(0);
  const vtkIdType length = grid->GetFaces()->GetNumberOfValues();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    // nfaces, then (count, ids...) per face.
    vtkIdType at = location[c];
    bool inside = at < length;
    const vtkIdType faces = at >= 0 && inside ? stream[at++] : 0;
    for (vtkIdType f = 0; f < faces && inside; ++f)
    {
      inside = at < length && stream[at] >= 0 && stream[at] <= length - at - 1;
      at += inside ? stream[at] + 1 : 0;
    }
    if (!inside)
    {
      throw std::runtime_error("Cell " + std::to_string(c) +
        " is a polyhedron whose faces run past the end of the grid's face array.");
    }
  }
}

void MergedCells::AppendPolyhedronFaces(vtkUnstructuredGrid* grid, const CompositeMesh::Leaf& leaf)
{
  CheckPolyhedronFaces(grid);
  const vtkIdType cells = grid->GetNumberOfCells();
  const vtkIdType* location = grid->GetFaceLocations()->GetPointer(0);
  const vtkIdType* stream = grid->GetFaces()->GetPointer(0);
  this->FaceLocations.resize(static_cast<std::size_t>(this->NumberOfCells), -1);
  this->FaceLocations.reserve(static_cast<std::size_t>(this->NumberOfCells + cells));
  for (vtkIdType c = 0; c < cells; ++c)
  {
    if (location[c] < 0)
    {
      this->FaceLocations.push_back(-1);
      continue;
    }
    // nfaces, then (count, ids...) per face, the ids renumbered like the points.
    this->FaceLocations.push_back(static_cast<vtkIdType>(this->Faces.size()));
    vtkIdType at = location[c];
    const vtkIdType faces = stream[at++];
    this->Faces.push_back(faces);
    for (vtkIdType f = 0; f < faces; ++f)
    {
      const vtkIdType count = stream[at++];
      this->Faces.push_back(count);
      for (vtkIdType m = 0; m < count; ++m)
      {
        this->Faces.push_back(leaf.Node(stream[at++]));
      }
    }
  }
}

void MergedCells::AppendCellByCell(vtkPointSet* block, const CompositeMesh::Leaf& leaf)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(block);
  auto* polyData = vtkPolyData::SafeDownCast(block);
  vtkNew<vtkIdList> ids;
  vtkIdType* connectivity = this->Connectivity->GetPointer(0);
  vtkIdType* offsets = this->Offsets->GetPointer(0);
  unsigned char* types = this->Types->GetPointer(0);
  for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c)
  {
    vtkIdType count = 0;
    const vtkIdType* points = nullptr;
    if (grid)
    {
      grid->GetCellPoints(c, count, points);
    }
    else if (polyData)
    {
      polyData->GetCellPoints(c, count, points);
    }
    else
    {
      block->GetCellPoints(c, ids);
      count = ids->GetNumberOfIds();
      points = ids->GetPointer(0);
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      connectivity[this->NumberOfIds++] = leaf.Node(points[k]);
    }
    const int type = block->GetCellType(c);
    types[this->NumberOfCells++] = static_cast<unsigned char>(type);
    offsets[this->NumberOfCells] = this->NumberOfIds;
    if (type == VTK_POLYHEDRON && grid)
    {
      // Polyhedra need their faces, renumbered like their points.
      this->FaceLocations.resize(static_cast<std::size_t>(this->NumberOfCells - 1), -1);
      this->FaceLocations.push_back(static_cast<vtkIdType>(this->Faces.size()));
      grid->GetFaceStream(c, ids);
      const vtkIdType* stream = ids->GetPointer(0);
      const vtkIdType length = ids->GetNumberOfIds();
      this->Faces.push_back(length > 0 ? stream[0] : 0);
      for (vtkIdType k = 1; k < length;)
      {
        const vtkIdType faceCount = stream[k++];
        this->Faces.push_back(faceCount);
        for (vtkIdType m = 0; m < faceCount; ++m, ++k)
        {
          this->Faces.push_back(leaf.Node(stream[k]));
        }
      }
    }
  }
}

} // namespace dgmf_vtk
