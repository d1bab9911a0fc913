#include "DGMFCompositeMeshCache.h"

#include "DGMFContentKey.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

namespace dgmf_vtk
{

std::vector<CompositeMeshCache::LeafKey> CompositeMeshCache::KeyOf(vtkCompositeDataSet* input)
{
  std::vector<LeafKey> leaves;
  auto iterator = vtk::TakeSmartPointer(input->NewIterator());
  iterator->SkipEmptyNodesOn();
  for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
  {
    vtkDataObject* leaf = iterator->GetCurrentDataObject();
    vtkInformation* metaData =
      iterator->HasCurrentMetaData() ? iterator->GetCurrentMetaData() : nullptr;
    leaves.push_back(LeafKey{ iterator->GetCurrentFlatIndex(), leaf, leaf->GetMTime(),
      metaData && metaData->Has(vtkCompositeDataSet::NAME())
        ? metaData->Get(vtkCompositeDataSet::NAME())
        : "" });
  }
  return leaves;
}

const CompositeMesh& CompositeMeshCache::Get(
  vtkCompositeDataSet* input, const std::string& displacementName, const std::string& markerName)
{
  std::vector<LeafKey> leaves = KeyOf(input);
  this->LeafChangedInPlace = false;
  for (std::size_t k = 0; this->Input == input && k < leaves.size() && k < this->Leaves.size(); ++k)
  {
    this->LeafChangedInPlace = this->LeafChangedInPlace ||
      (leaves[k].Object == this->Leaves[k].Object && leaves[k].MTime != this->Leaves[k].MTime);
  }
  this->Reused = !DistrustedObjects::Active() && this->Mesh && this->Input == input &&
    this->Leaves == leaves && this->Displacement == displacementName && this->Marker == markerName;
  if (!this->Reused)
  {
    this->Mesh.reset(); // its memory is free for the new merge
    this->Mesh = std::make_unique<CompositeMesh>(input, displacementName, markerName);
    ++this->Generation;
    this->Input = input;
    this->Leaves = std::move(leaves);
    this->Displacement = displacementName;
    this->Marker = markerName;
  }
  return *this->Mesh;
}

std::size_t CompositeMeshCache::GetMemorySize() const
{
  if (!this->Mesh)
  {
    return 0;
  }
  // What the input holds is not the cache's: its points, its volume's cells when shared.
  const auto kib = [](unsigned long size) { return 1024 * static_cast<std::size_t>(size); };
  vtkUnstructuredGrid* merged = this->Mesh->GetMergedMesh();
  std::size_t bytes = kib(merged->GetActualMemorySize());
  const std::size_t points =
    merged->GetPoints() ? kib(merged->GetPoints()->GetActualMemorySize()) : 0;
  if (this->Mesh->SharesInputPoints())
  {
    bytes -= points;
  }
  if (this->Mesh->SharesInputCells())
  {
    bytes -= kib(merged->GetCells()->GetActualMemorySize()) +
      kib(merged->GetCellTypesArray()->GetActualMemorySize());
    for (vtkIdTypeArray* faces : { merged->GetFaceLocations(), merged->GetFaces() })
    {
      bytes -= faces ? kib(faces->GetActualMemorySize()) : 0;
    }
  }
  if (vtkUnstructuredGrid* patches = this->Mesh->GetPatches())
  {
    bytes += kib(patches->GetActualMemorySize()) - points; // on the merged grid's points
  }
  for (const CompositeMesh::Leaf& leaf : this->Mesh->GetLeaves())
  {
    bytes += leaf.NodeOf.capacity() * sizeof(vtkIdType);
  }
  return bytes;
}

} // namespace dgmf_vtk
