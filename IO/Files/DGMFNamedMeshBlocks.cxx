#include "DGMFNamedMeshBlocks.h"

#include "DGMFWriterInputs.h"

#include "DGMFTupleAllocation.h"
#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>

namespace dgmf_vtk
{
namespace mf = dgmf::meshfile;

namespace
{
/// An unstructured grid of `cells` on the nodes `nodes` (indices into the file's points) of
/// `mesh`; `local[node]` must map a file node to its index in `nodes` for every node used.
vtkSmartPointer<vtkUnstructuredGrid> Grid(const mf::NamedMesh& mesh, const mf::Cells& cells,
  const std::vector<std::int64_t>& nodes, const std::vector<std::int64_t>& local)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  AllocateTuples(coordinates, static_cast<vtkIdType>(nodes.size()));
  double* xyz = coordinates->GetPointer(0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    std::memcpy(xyz + 3 * i, mesh.Points.data() + 3 * nodes[i], 3 * sizeof(double));
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  vtkNew<vtkIdTypeArray> offsets, connectivity;
  AllocateTuples(offsets, static_cast<vtkIdType>(cells.Offsets.size()));
  std::copy(cells.Offsets.begin(), cells.Offsets.end(), offsets->GetPointer(0));
  AllocateTuples(connectivity, static_cast<vtkIdType>(cells.Connectivity.size()));
  vtkIdType* ids = connectivity->GetPointer(0);
  for (std::size_t k = 0; k < cells.Connectivity.size(); ++k)
  {
    ids[k] = static_cast<vtkIdType>(local[static_cast<std::size_t>(cells.Connectivity[k])]);
  }
  vtkNew<vtkCellArray> cellArray;
  cellArray->SetData(offsets, connectivity);
  vtkNew<vtkUnsignedCharArray> types;
  AllocateTuples(types, static_cast<vtkIdType>(cells.Types.size()));
  std::copy(cells.Types.begin(), cells.Types.end(), types->GetPointer(0));

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(types, cellArray);
  return grid;
}
} // namespace

vtkSmartPointer<vtkMultiBlockDataSet> ToBlocks(const mf::NamedMesh& mesh)
{
  const std::size_t n = mesh.NumberOfNodes();
  std::vector<std::int64_t> all(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    all[i] = static_cast<std::int64_t>(i);
  }
  vtkSmartPointer<vtkUnstructuredGrid> volume = Grid(mesh, mesh.Volume, all, all);
  vtkNew<vtkIdTypeArray> fileIds;
  fileIds->SetName("FileNodeId");
  AllocateTuples(fileIds, static_cast<vtkIdType>(n));
  std::copy(mesh.NodeIds.begin(), mesh.NodeIds.end(), fileIds->GetPointer(0));
  volume->GetPointData()->AddArray(fileIds);

  vtkNew<vtkMultiBlockDataSet> boundaries;
  boundaries->SetNumberOfBlocks(static_cast<unsigned int>(mesh.Boundaries.size()));
  std::vector<std::int64_t> local(n, -1);
  for (std::size_t b = 0; b < mesh.Boundaries.size(); ++b)
  {
    const mf::NamedBoundary& boundary = mesh.Boundaries[b];
    std::vector<std::int64_t> used(boundary.Faces.Connectivity);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    for (std::size_t i = 0; i < used.size(); ++i)
    {
      local[static_cast<std::size_t>(used[i])] = static_cast<std::int64_t>(i);
    }
    const auto block = static_cast<unsigned int>(b);
    boundaries->SetBlock(block, Grid(mesh, boundary.Faces, used, local));
    boundaries->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), boundary.Name.c_str());
    if (!boundary.Family.empty())
    {
      vtkNew<vtkStringArray> family;
      family->SetName(dgmf::names::BoundaryFamily);
      family->InsertNextValue(boundary.Family);
      boundaries->GetBlock(block)->GetFieldData()->AddArray(family);
    }
  }

  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, volume);
  blocks->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), InternalMeshName);
  blocks->SetBlock(1, boundaries);
  blocks->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "boundary");
  if (!mesh.OtherGroups.empty())
  {
    // The file's named groups that are not boundaries (a physical curve of a 3D mesh), so that a
    // program told such a name can say what it is.
    vtkNew<vtkStringArray> names;
    names->SetName(dgmf::names::NonBoundaryGroups);
    vtkNew<vtkIntArray> dimensions;
    dimensions->SetName(dgmf::names::NonBoundaryGroupDimensions);
    for (const auto& group : mesh.OtherGroups)
    {
      names->InsertNextValue(group.first);
      dimensions->InsertNextValue(group.second);
    }
    blocks->GetFieldData()->AddArray(names);
    blocks->GetFieldData()->AddArray(dimensions);
  }
  return blocks;
}

} // namespace dgmf_vtk
