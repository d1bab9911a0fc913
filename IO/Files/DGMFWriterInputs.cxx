#include "DGMFWriterInputs.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <string>
#include <unordered_map>

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

long long PlacePointsByNodeId(vtkDataObject* data, const char* idArray,
  const std::vector<std::int64_t>& fileNodeIds, std::vector<double>& points)
{
  std::unordered_map<std::int64_t, std::size_t> indexOf;
  for (std::size_t i = 0; i < fileNodeIds.size(); ++i)
  {
    indexOf.emplace(fileNodeIds[i], i);
  }
  std::vector<bool> placed(fileNodeIds.size(), false);
  long long count = 0;
  const auto place = [&](vtkDataObject* leaf)
  {
    auto* mesh = vtkPointSet::SafeDownCast(leaf);
    vtkDataArray* ids = mesh ? mesh->GetPointData()->GetArray(idArray) : nullptr;
    if (!ids || ids->GetNumberOfTuples() != mesh->GetNumberOfPoints())
    {
      return true;
    }
    for (vtkIdType k = 0; k < mesh->GetNumberOfPoints(); ++k)
    {
      const auto found = indexOf.find(static_cast<std::int64_t>(ids->GetTuple1(k)));
      if (found == indexOf.end())
      {
        return false;
      }
      mesh->GetPoint(k, points.data() + 3 * found->second);
      count += placed[found->second] ? 0 : 1;
      placed[found->second] = true;
    }
    return true;
  };
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return place(data) ? count : -1;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (!place(it->GetCurrentDataObject()))
    {
      return -1;
    }
  }
  return count;
}

} // namespace dgmf_vtk
