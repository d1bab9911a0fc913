#include "vtkSizeSkewQualityFilter.h"

#include "DGMFCellQuality.h"
#include "DGMFSMPTools.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <vector>

vtkStandardNewMacro(vtkSizeSkewQualityFilter);

namespace
{
/// True when both meshes have the same cells (types and point ids).
bool SameCells(vtkUnstructuredGrid* a, vtkUnstructuredGrid* b)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  if (a->GetCells() == b->GetCells() && a->GetCellTypesArray() == b->GetCellTypesArray())
  {
    return true; // the same arrays (a deformed mesh usually shares its cells with the original)
  }
  vtkDataArray* ca = a->GetCells()->GetConnectivityArray();
  vtkDataArray* cb = b->GetCells()->GetConnectivityArray();
  if (ca->GetNumberOfValues() != cb->GetNumberOfValues())
  {
    return false;
  }
  for (vtkIdType i = 0; i < ca->GetNumberOfValues(); ++i)
  {
    if (ca->GetComponent(i, 0) != cb->GetComponent(i, 0))
    {
      return false;
    }
  }
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    if (a->GetCellType(c) != b->GetCellType(c))
    {
      return false;
    }
  }
  return true;
}
} // namespace

vtkSizeSkewQualityFilter::vtkSizeSkewQualityFilter()
{
  this->SetNumberOfInputPorts(2);
}

int vtkSizeSkewQualityFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* mesh = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* reference = vtkUnstructuredGrid::GetData(inputVector[1], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!mesh || !reference || !output)
  {
    vtkErrorMacro("Both inputs (the mesh and its reference) must be vtkUnstructuredGrid.");
    return 0;
  }
  if (mesh->GetNumberOfPoints() != reference->GetNumberOfPoints() || !SameCells(mesh, reference))
  {
    vtkErrorMacro("The mesh (" << mesh->GetNumberOfPoints() << " points, "
                               << mesh->GetNumberOfCells() << " cells) and the reference ("
                               << reference->GetNumberOfPoints() << " points, "
                               << reference->GetNumberOfCells()
                               << " cells) must have the same points and cells.");
    output->Initialize();
    return 0;
  }
  std::vector<double> deformedCopy, originalCopy; // only for points that are not doubles
  const double* deformed = dgmf_vtk::PointsAsDouble(mesh->GetPoints(), deformedCopy);
  const double* original = dgmf_vtk::PointsAsDouble(reference->GetPoints(), originalCopy);

  output->ShallowCopy(mesh);
  vtkNew<vtkDoubleArray> sizeSkew;
  sizeSkew->SetName("SizeSkew");
  vtkNew<vtkUnsignedCharArray> inverted;
  inverted->SetName("Inverted");
  dgmf::QualitySummary summary;
  dgmf_vtk::RunWithThreads(this->NumberOfThreads,
    [&]()
    {
      summary = dgmf_vtk::ComputeCellQuality(
        reference, original, deformed, sizeSkew, inverted, dgmf_vtk::MakeSMPParallelFor());
    });
  output->GetCellData()->AddArray(sizeSkew);
  output->GetCellData()->AddArray(inverted);
  vtkNew<vtkDoubleArray> mean;
  mean->SetName("SizeSkewMean");
  mean->InsertNextValue(summary.Mean);
  vtkNew<vtkDoubleArray> minimum;
  minimum->SetName("SizeSkewMinimum");
  minimum->InsertNextValue(summary.Minimum);
  vtkNew<vtkIdTypeArray> count;
  count->SetName("InvertedCellCount");
  count->InsertNextValue(static_cast<vtkIdType>(summary.Inverted));
  vtkNew<vtkFieldData> fieldData;
  fieldData->PassData(mesh->GetFieldData());
  fieldData->AddArray(mean);
  fieldData->AddArray(minimum);
  fieldData->AddArray(count);
  output->SetFieldData(fieldData);
  return 1;
}

void vtkSizeSkewQualityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
