#include "DGMFWriterInputs.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <string>

namespace dgmf_vtk
{

vtkPointSet* InternalMeshOf(vtkDataObject* data)
{
  if (auto* points = vtkPointSet::SafeDownCast(data))
  {
    return points;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return nullptr;
  }
  vtkPointSet* first = nullptr;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* grid = vtkUnstructuredGrid::SafeDownCast(it->GetCurrentDataObject());
    if (!grid)
    {
      continue;
    }
    vtkInformation* meta = it->HasCurrentMetaData() ? it->GetCurrentMetaData() : nullptr;
    if (meta && meta->Has(vtkCompositeDataSet::NAME()) &&
      std::string(meta->Get(vtkCompositeDataSet::NAME())) == InternalMeshName)
    {
      return grid;
    }
    first = first ? first : grid;
  }
  return first;
}

std::vector<double> PointsOf(vtkPointSet* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    mesh->GetPoint(i, xyz.data() + 3 * i);
  }
  return xyz;
}

} // namespace dgmf_vtk
