#include "DGMFArrayAllocation.h"

#include "vtkDataArray.h"
#include "vtkPoints.h"

#include <cstdlib>
#include <new>

namespace dgmf_vtk
{

void AllocateTuples(vtkDataArray* array, vtkIdType tuples)
{
  const auto values =
    static_cast<std::size_t>(tuples) * static_cast<std::size_t>(array->GetNumberOfComponents());
  if (values == 0 || !array->HasStandardMemoryLayout())
  {
    array->SetNumberOfTuples(tuples);
    return;
  }
  void* memory = std::malloc(values * static_cast<std::size_t>(array->GetDataTypeSize()));
  if (!memory)
  {
    throw std::bad_alloc();
  }
  array->SetVoidArray(
    memory, static_cast<vtkIdType>(values), 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
}

void AllocatePoints(vtkPoints* points, vtkIdType count)
{
  AllocateTuples(points->GetData(), count);
  points->Modified();
}

void EnsureAvailableMemory(std::size_t bytes)
{
  void* probe = std::malloc(bytes);
  if (!probe)
  {
    throw std::bad_alloc();
  }
  std::free(probe);
}

} // namespace dgmf_vtk
