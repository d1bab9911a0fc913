#include "DGMFOutputBuffers.h"

#include "DGMFArrayAllocation.h"
#include "DGMFTupleAllocation.h"

#include "dgmf/ResultNames.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace dgmf_vtk
{

vtkSmartPointer<vtkPoints> ReuseOutputPoints(vtkSmartPointer<vtkPoints>& last,
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, std::size_t n)
{
  if (last && input->GetPoints() != last.GetPointer())
  {
    const int holders = output->GetPoints() == last.GetPointer() ? 2 : 1;
    vtkDataArray* data = last->GetData();
    if (last->GetReferenceCount() == holders && data->GetReferenceCount() == 1 &&
      vtkDoubleArray::SafeDownCast(data) && data->GetNumberOfComponents() == 3 &&
      data->GetNumberOfTuples() == static_cast<vtkIdType>(n))
    {
      return last;
    }
  }
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  AllocateTuples(coordinates, static_cast<vtkIdType>(n));
  last = vtkSmartPointer<vtkPoints>::New();
  last->SetData(coordinates);
  return last;
}

FieldArrays::Field& FieldArrays::Select(const char* field)
{
  if (std::strcmp(field, dgmf::names::R) == 0)
  {
    return this->R;
  }
  if (std::strcmp(field, dgmf::names::F) == 0)
  {
    return this->F;
  }
  throw std::invalid_argument(std::string("no per-node field named ") + field);
}

void FieldArrays::Reset(std::size_t numberOfNodes)
{
  this->Size = numberOfNodes;
  this->R.Key = dgmf::FieldKey();
  this->F.Key = dgmf::FieldKey();
}

const double* FieldArrays::Find(const char* field, const dgmf::FieldKey& key)
{
  Field& stored = this->Select(field);
  const bool current = stored.Array && stored.Key == key &&
    stored.Array->GetNumberOfTuples() == static_cast<vtkIdType>(this->Size);
  return current ? stored.Array->GetPointer(0) : nullptr;
}

double* FieldArrays::Store(const char* field, const dgmf::FieldKey& key)
{
  Field& stored = this->Select(field);
  vtkSmartPointer<vtkDoubleArray>& array = stored.Array;
  if (!array || array->GetReferenceCount() != 1 || array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfTuples() != static_cast<vtkIdType>(this->Size))
  {
    array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(field);
    AllocateTuples(array, static_cast<vtkIdType>(this->Size));
  }
  array->Modified();
  stored.Key = key;
  return array->GetPointer(0);
}

vtkDoubleArray* FieldArrays::GetArray(const char* field)
{
  return this->Select(field).Array;
}

std::vector<vtkDoubleArray*> FieldArrays::Prepare(bool r, bool f)
{
  std::vector<vtkDoubleArray*> prepared;
  for (Field* field : { r ? &this->R : nullptr, f ? &this->F : nullptr })
  {
    if (field)
    {
      this->Store(field == &this->R ? dgmf::names::R : dgmf::names::F, dgmf::FieldKey());
      prepared.push_back(field->Array);
    }
  }
  return prepared;
}

} // namespace dgmf_vtk
