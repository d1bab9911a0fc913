#include "vtkSizeSkewQualityFilter.h"

#include "DGMFHexReferenceCache.h"
#include "DGMFMeshConversion.h"
#include "DGMFNonOrthogonality.h"
#include "DGMFOutputArrays.h"

#include "DGMFSMPTools.h"
#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <string>
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

/**
 * The quality of `mesh` against `reference` added to `result` (a shallow copy of `mesh`): its
 * cell arrays and its field data. Returns false, with the reason in `error`, when the two do not
 * have the same points and cells.
 */
bool Measure(vtkPointSet* mesh, vtkPointSet* reference, vtkPointSet* result,
  dgmf::QualitySummary& summary, dgmf_vtk::HexReferenceCache* hexReferences,
  dgmf_vtk::InternalFacesCache* faces, double angles[2], std::string& error)
{
  const vtkSmartPointer<vtkUnstructuredGrid> grid = dgmf_vtk::AsUnstructuredGrid(mesh);
  const vtkSmartPointer<vtkUnstructuredGrid> original = dgmf_vtk::AsUnstructuredGrid(reference);
  if (mesh->GetNumberOfPoints() != reference->GetNumberOfPoints() || !SameCells(grid, original))
  {
    error = "The mesh (" + std::to_string(mesh->GetNumberOfPoints()) + " points, " +
      std::to_string(mesh->GetNumberOfCells()) + " cells) and the reference (" +
      std::to_string(reference->GetNumberOfPoints()) + " points, " +
      std::to_string(reference->GetNumberOfCells()) +
      " cells) must have the same points and cells.";
    return false;
  }
  if (mesh->GetNumberOfPoints() == 0)
  {
    return true;
  }
  std::vector<double> deformedCopy, originalCopy; // only for points that are not doubles
  const double* deformed = dgmf_vtk::PointsAsDouble(mesh->GetPoints(), deformedCopy);
  const double* undeformed = dgmf_vtk::PointsAsDouble(reference->GetPoints(), originalCopy);
  const dgmf_vtk::HexReferences references = hexReferences
    ? hexReferences->For(original, reference->GetPoints()->GetData())
    : dgmf_vtk::HexReferences();
  summary = dgmf_vtk::AddCellQuality(original, undeformed, deformed, result->GetCellData(),
    result->GetFieldData(), references, dgmf_vtk::MakeSMPParallelFor());
  if (faces)
  {
    dgmf_vtk::AddNonOrthogonality(original, undeformed, deformed, result->GetCellData(),
      result->GetFieldData(), *faces, dgmf_vtk::MakeSMPParallelFor());
    angles[0] = std::max(angles[0],
      dgmf_vtk::GetFieldValue(result->GetFieldData(), dgmf::names::MaximumNonOrthogonality));
    angles[1] = std::max(angles[1],
      dgmf_vtk::GetFieldValue(result->GetFieldData(), dgmf::names::InputMaximumNonOrthogonality));
  }
  return true;
}
} // namespace

/// The internal faces and the hexahedra's reference sizes of the last mesh measured, kept while
/// its cells (and, for the sizes, its reference points) are unchanged.
struct vtkSizeSkewQualityFilter::Internals
{
  dgmf_vtk::InternalFacesCache Faces;
  dgmf_vtk::HexReferenceCache HexReferences;
};

vtkSizeSkewQualityFilter::vtkSizeSkewQualityFilter()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkSizeSkewQualityFilter::~vtkSizeSkewQualityFilter() = default;

vtkUnstructuredGrid* vtkSizeSkewQualityFilter::GetOutput()
{
  return this->GetOutput(0);
}

vtkUnstructuredGrid* vtkSizeSkewQualityFilter::GetOutput(int port)
{
  return vtkUnstructuredGrid::SafeDownCast(this->GetOutputDataObject(port));
}

int vtkSizeSkewQualityFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkSizeSkewQualityFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* meshObject = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* referenceObject = vtkDataObject::GetData(inputVector[1], 0);
  vtkDataObject* outputObject = vtkDataObject::GetData(outputVector, 0);
  std::string error;
  bool ok = true;
  dgmf_vtk::InternalFacesCache* faces =
    this->ComputeNonOrthogonality ? &this->Internal->Faces : nullptr;
  double angles[2] = { 0.0, 0.0 }; // the largest non-orthogonality, deformed and input
  dgmf_vtk::RunWithThreads(this->NumberOfThreads,
    [&]()
    {
      auto* mesh = vtkUnstructuredGrid::SafeDownCast(meshObject);
      auto* reference = vtkUnstructuredGrid::SafeDownCast(referenceObject);
      auto* output = vtkUnstructuredGrid::SafeDownCast(outputObject);
      if (mesh && reference && output)
      {
        output->ShallowCopy(mesh);
        vtkNew<vtkFieldData> fieldData; // the output's own (a shallow copy shares the input's)
        fieldData->PassData(mesh->GetFieldData());
        output->SetFieldData(fieldData);
        dgmf::QualitySummary summary;
        ok = Measure(
          mesh, reference, output, summary, &this->Internal->HexReferences, faces, angles, error);
        return;
      }
      auto* meshes = vtkCompositeDataSet::SafeDownCast(meshObject);
      auto* references = vtkCompositeDataSet::SafeDownCast(referenceObject);
      auto* outputs = vtkCompositeDataSet::SafeDownCast(outputObject);
      if (!meshes || !references || !outputs)
      {
        error = "The mesh and its reference must both be unstructured grids, or both composite "
                "datasets of the same structure.";
        ok = false;
        return;
      }
      // Block by block; the summary over all blocks.
      outputs->CopyStructure(meshes);
      dgmf::QualitySummary total;
      auto iterator = vtk::TakeSmartPointer(meshes->NewIterator());
      iterator->SkipEmptyNodesOn();
      for (iterator->InitTraversal(); ok && !iterator->IsDoneWithTraversal();
           iterator->GoToNextItem())
      {
        auto* block = vtkPointSet::SafeDownCast(iterator->GetCurrentDataObject());
        if (!block)
        {
          outputs->SetDataSet(iterator, iterator->GetCurrentDataObject()); // passed unchanged
          continue;
        }
        auto* original = vtkPointSet::SafeDownCast(references->GetDataSet(iterator));
        if (!original)
        {
          error = "The reference has no mesh for block " +
            std::to_string(iterator->GetCurrentFlatIndex()) + " of the mesh.";
          ok = false;
          break;
        }
        vtkSmartPointer<vtkPointSet> result = vtk::TakeSmartPointer(block->NewInstance());
        result->ShallowCopy(block);
        vtkNew<vtkFieldData> blockFieldData;
        blockFieldData->PassData(block->GetFieldData());
        result->SetFieldData(blockFieldData);
        dgmf::QualitySummary summary;
        ok = Measure(block, original, result, summary, nullptr, faces, angles, error);
        total = dgmf::MergeQualitySummaries(total, summary);
        outputs->SetDataSet(iterator, result);
      }
      vtkNew<vtkFieldData> fieldData;
      fieldData->PassData(meshes->GetFieldData());
      dgmf_vtk::SetQualitySummary(fieldData, total);
      if (faces)
      {
        dgmf_vtk::AddFieldValue(fieldData, dgmf::names::MaximumNonOrthogonality, angles[0]);
        dgmf_vtk::AddFieldValue(fieldData, dgmf::names::InputMaximumNonOrthogonality, angles[1]);
      }
      outputs->SetFieldData(fieldData);
    });
  if (!ok)
  {
    vtkErrorMacro(<< error);
    outputObject->Initialize();
    return 0;
  }
  return 1;
}

void vtkSizeSkewQualityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads
     << ", ComputeNonOrthogonality: " << (this->ComputeNonOrthogonality ? "on" : "off") << "\n";
}
