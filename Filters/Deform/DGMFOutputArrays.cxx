#include "DGMFOutputArrays.h"

#include "DGMFArrayAllocation.h"
#include "DGMFTupleAllocation.h"

#include "DGMFCellQuality.h"
#include "DGMFNonOrthogonality.h"
#include "DGMFOutputBuffers.h"

#include "dgmf/ResultNames.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace dgmf_vtk
{

void AddFieldCount(vtkFieldData* fieldData, const char* name, std::size_t value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->InsertNextValue(static_cast<vtkIdType>(value));
  fieldData->AddArray(array);
}

void AddFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

void AddFieldString(vtkFieldData* fieldData, const char* name, const char* value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

double GetFieldValue(vtkFieldData* fieldData, const char* name)
{
  vtkDataArray* array = fieldData->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : 0.0;
}

void AddReport(vtkFieldData* fieldData, const dgmf::DeformationReport& report)
{
  for (const dgmf::ReportedValue& value : report.Values)
  {
    if (value.IsCount && value.Components == 1 && value.Values.size() == 1)
    {
      AddFieldCount(fieldData, value.Name.c_str(), static_cast<std::size_t>(value.Values[0]));
      continue;
    }
    vtkNew<vtkDoubleArray> array;
    array->SetName(value.Name.c_str());
    array->SetNumberOfComponents(value.Components);
    for (std::size_t t = 0; t + value.Components <= value.Values.size(); t += value.Components)
    {
      array->InsertNextTuple(value.Values.data() + t);
    }
    fieldData->AddArray(array);
  }
}

void SetDeformedGrid(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output,
  vtkPoints* deformedPoints, std::size_t localNodes)
{
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());
  vtkDataArray* coordinates = deformedPoints->GetData();
  if (static_cast<std::size_t>(coordinates->GetNumberOfTuples()) > localNodes)
  {
    coordinates->Resize(static_cast<vtkIdType>(localNodes)); // this piece's nodes
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(localNodes));
  }
  coordinates->Modified();
  deformedPoints->Modified();
  output->SetPoints(deformedPoints);
}

void AddMethodResults(vtkUnstructuredGrid* output, vtkDoubleArray* r, vtkDoubleArray* f,
  const dgmf::DeformationReport& report, bool usedGraph, bool graphReused, const char* methodName,
  std::size_t localNodes)
{
  vtkPointData* pointData = output->GetPointData();
  vtkFieldData* fieldData = output->GetFieldData();
  const auto local = static_cast<vtkIdType>(localNodes);
  for (vtkDoubleArray* array : { r, f })
  {
    if (array)
    {
      const char* name = array->GetName();
      if (array->GetNumberOfTuples() > local)
      {
        vtkNew<vtkDoubleArray> kept; // this piece's nodes only
        kept->SetName(name);
        AllocateTuples(kept, local);
        std::copy_n(array->GetPointer(0), localNodes, kept->GetPointer(0));
        pointData->AddArray(kept);
      }
      else
      {
        pointData->AddArray(array);
      }
    }
  }
  AddReport(fieldData, report);
  if (usedGraph)
  {
    AddFieldCount(fieldData, dgmf::names::GraphReused, graphReused ? 1 : 0);
  }
  AddFieldString(fieldData, dgmf::names::Method, methodName);
}

void SetQualitySummary(vtkFieldData* fieldData, const dgmf::QualitySummary& summary)
{
  // No cell evaluated (only quadratic cells or polyhedra): NaN, not a minimum of 0 that reads as
  // the worst possible quality.
  const double none = std::numeric_limits<double>::quiet_NaN();
  AddFieldValue(fieldData, dgmf::names::SizeSkewMean, summary.Evaluated > 0 ? summary.Mean : none);
  AddFieldValue(
    fieldData, dgmf::names::SizeSkewMinimum, summary.Evaluated > 0 ? summary.Minimum : none);
  AddFieldCount(fieldData, dgmf::names::InvertedCellCount, summary.Inverted);
  AddFieldCount(fieldData, dgmf::names::SizeSkewEvaluatedCells, summary.Evaluated);
  AddFieldCount(fieldData, dgmf::names::InputInvalidCellCount, summary.InputInvalid);
}

dgmf::QualitySummary AddCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDataSetAttributes* cellData, vtkFieldData* fieldData,
  const HexReferences& references, const dgmf::ParallelFor& parallelFor, QualityArrays* kept)
{
  QualityArrays fresh;
  QualityArrays& arrays = kept ? *kept : fresh;
  const vtkSmartPointer<vtkDoubleArray> sizeSkew = QualityArrays::Reuse(arrays.SizeSkew);
  sizeSkew->SetName(dgmf::names::SizeSkew);
  const vtkSmartPointer<vtkUnsignedCharArray> inverted = QualityArrays::Reuse(arrays.Inverted);
  inverted->SetName(dgmf::names::Inverted);
  const vtkSmartPointer<vtkUnsignedCharArray> inputInvalid =
    QualityArrays::Reuse(arrays.InputInvalid);
  inputInvalid->SetName(dgmf::names::InputInvalid);
  const dgmf::QualitySummary summary = ComputeCellQuality(mesh, originalPoints, deformedPoints,
    sizeSkew, inverted, inputInvalid, references, parallelFor);
  cellData->AddArray(sizeSkew);
  cellData->AddArray(inverted);
  cellData->AddArray(inputInvalid);
  SetQualitySummary(fieldData, summary);
  return summary;
}

dgmf::QualitySummary AddOutputQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkUnstructuredGrid* output, bool sizeSkew,
  const HexReferences& references, InternalFacesCache* faces, const dgmf::ParallelFor& parallelFor,
  QualityArrays* kept)
{
  dgmf::QualitySummary summary;
  if (sizeSkew)
  {
    summary = AddCellQuality(mesh, originalPoints, deformedPoints, output->GetCellData(),
      output->GetFieldData(), references, parallelFor, kept);
  }
  if (faces)
  {
    AddNonOrthogonality(mesh, originalPoints, deformedPoints, output->GetCellData(),
      output->GetFieldData(), *faces, parallelFor);
  }
  return summary;
}

} // namespace dgmf_vtk
