#include "NamedBlocks.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataSet.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <unordered_map>

namespace dgmf_bench
{
namespace
{
/// The quads `first` (the hexahedra's first 4 nodes) or last 4 nodes of cells [begin, end), with
/// points of their own.
vtkSmartPointer<vtkPolyData> Patch(
  vtkUnstructuredGrid* mesh, vtkIdType begin, vtkIdType end, bool first)
{
  std::unordered_map<vtkIdType, vtkIdType> local;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = begin; c < end; ++c)
  {
    mesh->GetCellPoints(c, ids);
    vtkIdType quad[4];
    for (int k = 0; k < 4; ++k)
    {
      const vtkIdType id = ids->GetId(first ? k : 4 + k);
      const auto found = local.emplace(id, points->GetNumberOfPoints());
      if (found.second)
      {
        points->InsertNextPoint(mesh->GetPoint(id));
      }
      quad[k] = found.first->second;
    }
    quads->InsertNextCell(4, quad);
  }
  auto patch = vtkSmartPointer<vtkPolyData>::New();
  patch->SetPoints(points);
  patch->SetPolys(quads);
  return patch;
}

void Add(vtkMultiBlockDataSet* blocks, unsigned int index, vtkDataObject* block, const char* name)
{
  blocks->SetBlock(index, block);
  blocks->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name);
}
} // namespace

vtkSmartPointer<vtkMultiBlockDataSet> MakeNamedBlocks(
  vtkUnstructuredGrid* mesh, const LayeredMeshSize& size)
{
  vtkNew<vtkUnstructuredGrid> volume;
  volume->SetPoints(mesh->GetPoints());
  volume->SetCells(mesh->GetCellTypesArray(), mesh->GetCells());
  // The hexahedra go layer by layer: the first layer's bottom quads lie on the sphere, the last
  // layer's top quads on the box.
  const vtkIdType perLayer = mesh->GetNumberOfCells() / (size.Layers - 1);
  vtkNew<vtkMultiBlockDataSet> patches;
  Add(patches, 0, Patch(mesh, 0, perLayer, true), "body");
  Add(patches, 1, Patch(mesh, mesh->GetNumberOfCells() - perLayer, mesh->GetNumberOfCells(), false),
    "farfield");
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  Add(blocks, 0, volume, "internalMesh");
  Add(blocks, 1, patches, "boundary");
  return blocks;
}

} // namespace dgmf_bench
