#include "vtkDGMFDeformFilter.h"

#include "DGMFBoundaryDetection.h"
#include "DGMFCellQuality.h"
#include "DGMFSMPTools.h"

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDGMFDeformFilter);

namespace
{
/// Index of each input array in SetInputArrayToProcess.
enum InputArrays
{
  DisplacementArray = 0,
  MarkerArray = 1
};

/// 2 when the mesh is planar (no 3D cell, all z equal), 3 otherwise; -1 for 2D cells off a z plane.
int DetectDimension(vtkUnstructuredGrid* mesh, const double* xyz, std::size_t n)
{
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const int type = mesh->GetCellType(c);
    if (type != VTK_EMPTY_CELL && vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 3)
    {
      return 3;
    }
  }
  for (std::size_t i = 1; i < n; ++i)
  {
    if (xyz[3 * i + 2] != xyz[2])
    {
      return -1;
    }
  }
  return 2;
}

/// The points as a contiguous double array (no copy when they already are).
const double* PointsAsDouble(vtkPoints* points, std::vector<double>& copy)
{
  vtkDataArray* data = points->GetData();
  auto* doubles = vtkDoubleArray::SafeDownCast(data);
  if (doubles && doubles->GetNumberOfComponents() == 3)
  {
    return doubles->GetPointer(0);
  }
  const vtkIdType n = points->GetNumberOfPoints();
  copy.resize(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, copy.data() + 3 * i);
  }
  return copy.data();
}

bool IsIntegerType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}

bool AllFinite(const double* values, std::size_t count)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return false;
    }
  }
  return true;
}

/**
 * Name given to input array `index` with SetInputArrayToProcess, or "" if none. "None" (the
 * ParaView panel's choice for no array) also means none.
 */
std::string SelectedArrayName(vtkAlgorithm* algorithm, int index)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(index);
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    const char* name = info->Get(vtkDataObject::FIELD_NAME());
    const std::string selected = name ? name : "";
    return selected == "None" ? std::string() : selected;
  }
  return "";
}
} // namespace

/// What the filter keeps between executions: the graph and node locations, and r.
struct vtkDGMFDeformFilter::Cache
{
  // The key: what the mapping depends on.
  vtkDataArray* PointsArray = nullptr;
  vtkMTimeType PointsMTime = 0;
  vtkCellArray* Cells = nullptr;
  vtkMTimeType CellsMTime = 0;
  int Dimension = 0;
  std::vector<dgmf::NodeKind> Kinds;
  // The cached values.
  std::unique_ptr<dgmf::DelaunayMapping> Mapping;
  double StaticR0 = 0.0;
  std::vector<double> R;
  // Boundary detection (when there is no marker array) depends on the cells only.
  vtkCellArray* BoundaryCells = nullptr;
  vtkMTimeType BoundaryCellsMTime = 0;
  std::vector<std::uint8_t> BoundaryFlags;
};

vtkDGMFDeformFilter::vtkDGMFDeformFilter()
  : GraphCache(new Cache)
{
}

vtkDGMFDeformFilter::~vtkDGMFDeformFilter() = default;

void vtkDGMFDeformFilter::ReleaseCache()
{
  this->GraphCache.reset(new Cache);
}

void vtkDGMFDeformFilter::SetDisplacementArrayName(const char* name)
{
  this->SetInputArrayToProcess(
    DisplacementArray, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
}

void vtkDGMFDeformFilter::SetBoundaryMarkerArrayName(const char* name)
{
  this->SetInputArrayToProcess(MarkerArray, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
}

int vtkDGMFDeformFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Input and output must be vtkUnstructuredGrid.");
    return 0;
  }
  int status = 0;
  try
  {
    dgmf_vtk::RunWithThreads(
      this->NumberOfThreads, [&]() { status = this->Execute(input, output); });
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    status = 0;
  }
  if (!status)
  {
    output->Initialize();
  }
  return status;
}

int vtkDGMFDeformFilter::Execute(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  this->LastExecutionReusedGraph = false;
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints == 0 || input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input mesh is empty (" << numberOfPoints << " points, "
                                              << input->GetNumberOfCells() << " cells).");
    return 0;
  }
  const auto n = static_cast<std::size_t>(numberOfPoints);

  std::vector<double> pointCopy;
  const double* points = PointsAsDouble(input->GetPoints(), pointCopy);
  if (!AllFinite(points, 3 * n))
  {
    vtkErrorMacro("The input mesh has NaN or infinite point coordinates.");
    return 0;
  }
  const int dimension = DetectDimension(input, points, n);
  if (dimension < 0)
  {
    vtkErrorMacro("The mesh has no 3D cell but its points do not all have the same z: 2D meshes "
                  "must lie in a plane z = constant.");
    return 0;
  }

  // --- Arrays: the displacement (index 0) and the boundary marker (index 1).
  const std::string displacementName = SelectedArrayName(this, DisplacementArray);
  const std::string markerName = SelectedArrayName(this, MarkerArray);
  vtkDataArray* displacementArray = nullptr;
  vtkDataArray* markerArray = nullptr;
  if (!displacementName.empty())
  {
    displacementArray = input->GetPointData()->GetArray(displacementName.c_str());
    if (!displacementArray)
    {
      vtkErrorMacro("The displacement array '" << displacementName
                                               << "' is not a point array of the input.");
      return 0;
    }
    if (displacementArray->GetNumberOfComponents() != 3)
    {
      vtkErrorMacro("The displacement array '" << displacementName << "' has "
                                               << displacementArray->GetNumberOfComponents()
                                               << " components; it must have 3.");
      return 0;
    }
  }
  if (!markerName.empty())
  {
    markerArray = input->GetPointData()->GetArray(markerName.c_str());
    if (!markerArray)
    {
      vtkErrorMacro("The boundary-marker array '" << markerName
                                                  << "' is not a point array of the input.");
      return 0;
    }
    if (markerArray->GetNumberOfComponents() != 1 || !IsIntegerType(markerArray->GetDataType()))
    {
      vtkErrorMacro("The boundary-marker array '"
        << markerName << "' must be an integer array with 1 component (0 = interior, "
        << "1 = static boundary, 2 = moving boundary).");
      return 0;
    }
  }
  if (!displacementArray && !markerArray)
  {
    vtkErrorMacro("Select a boundary-marker array (0 = interior, 1 = static, 2 = moving) or a "
                  "displacement array (boundary nodes with a non-zero displacement move).");
    return 0;
  }

  std::vector<double> displacement;
  if (displacementArray)
  {
    displacement.resize(3 * n);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      displacementArray->GetTuple(i, displacement.data() + 3 * i);
    }
    if (!AllFinite(displacement.data(), displacement.size()))
    {
      vtkErrorMacro("The displacement array '" << displacementName
                                               << "' has NaN or infinite values.");
      return 0;
    }
  }

  // --- Motion.
  dgmf::RigidMotion motion;
  for (int c = 0; c < 3; ++c)
  {
    motion.Translation[c] = this->Translation[c];
    motion.Center[c] = this->RotationCenter[c];
    motion.AnglesDegrees[c] = this->RotationAngles[c];
  }
  if (!AllFinite(motion.Translation, 3) || !AllFinite(motion.Center, 3) ||
    !AllFinite(motion.AnglesDegrees, 3))
  {
    vtkErrorMacro("Translation, RotationCenter and RotationAngles must be finite.");
    return 0;
  }
  if (dimension == 2)
  {
    if (motion.AnglesDegrees[0] != 0.0 || motion.AnglesDegrees[1] != 0.0 ||
      motion.Translation[2] != 0.0)
    {
      vtkErrorMacro("This is a 2D mesh (all points at z = "
        << points[2] << "): it can only rotate about z and translate in x and y. Set the "
        << "rotation angles about x and y and the z translation to 0.");
      return 0;
    }
    for (std::size_t i = 0; i < displacement.size(); i += 3)
    {
      if (displacement[i + 2] != 0.0)
      {
        vtkErrorMacro("This is a 2D mesh, but the displacement array '"
          << displacementName << "' has a non-zero z component (node " << i / 3 << ").");
        return 0;
      }
    }
  }

  // --- Node kinds.
  Cache& cache = *this->GraphCache;
  std::vector<dgmf::NodeKind> kinds(n, dgmf::NodeKind::Interior);
  if (markerArray)
  {
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      const double value = markerArray->GetTuple1(i);
      if (value != 0.0 && value != 1.0 && value != 2.0)
      {
        vtkErrorMacro("The boundary-marker array '"
          << markerName << "' has the value " << value << " at point " << i
          << "; allowed values are 0 (interior), 1 (static boundary) and 2 (moving boundary).");
        return 0;
      }
      kinds[i] = static_cast<dgmf::NodeKind>(static_cast<int>(value));
    }
  }
  else
  {
    vtkCellArray* cells = input->GetCells();
    if (cache.BoundaryCells != cells || cache.BoundaryCellsMTime != cells->GetMTime() ||
      cache.BoundaryFlags.size() != n)
    {
      cache.BoundaryFlags = dgmf_vtk::FindBoundaryNodes(input, dimension);
      cache.BoundaryCells = cells;
      cache.BoundaryCellsMTime = cells->GetMTime();
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      if (cache.BoundaryFlags[i])
      {
        const double* d = displacement.data() + 3 * i;
        kinds[i] = (d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0) ? dgmf::NodeKind::MovingBoundary
                                                                : dgmf::NodeKind::StaticBoundary;
      }
    }
  }
  std::size_t moving = 0;
  for (dgmf::NodeKind kind : kinds)
  {
    moving += kind == dgmf::NodeKind::MovingBoundary ? 1 : 0;
  }
  if (moving == 0)
  {
    vtkWarningMacro("No node is marked as moving: the output has the input's points.");
  }
  this->UpdateProgress(0.1);

  // --- Steps 1-3: the Delaunay graph and the node locations (cached).
  const dgmf::ParallelFor parallelFor = dgmf_vtk::MakeSMPParallelFor();
  vtkDataArray* pointsArray = input->GetPoints()->GetData();
  vtkCellArray* cells = input->GetCells();
  const bool reuse = cache.Mapping && cache.PointsArray == pointsArray &&
    cache.PointsMTime == pointsArray->GetMTime() && cache.Cells == cells &&
    cache.CellsMTime == cells->GetMTime() && cache.Dimension == dimension && cache.Kinds == kinds;
  if (!reuse)
  {
    cache.Mapping.reset();
    cache.R.clear();
    cache.Mapping = std::make_unique<dgmf::DelaunayMapping>(
      dimension, points, n, kinds.data(), parallelFor);
    cache.PointsArray = pointsArray;
    cache.PointsMTime = pointsArray->GetMTime();
    cache.Cells = cells;
    cache.CellsMTime = cells->GetMTime();
    cache.Dimension = dimension;
    cache.Kinds = std::move(kinds);
  }
  this->LastExecutionReusedGraph = reuse;
  const dgmf::DelaunayMapping& mapping = *cache.Mapping;
  if (mapping.GetNumberOfConflictingNodes() > 0)
  {
    vtkWarningMacro(<< mapping.GetNumberOfConflictingNodes()
                    << " static boundary nodes coincide with moving ones; they stay in place, and "
                       "their shared graph vertex moves.");
  }
  if (mapping.GetNumberOfOutsideNodes() > 0)
  {
    vtkWarningMacro(<< mapping.GetNumberOfOutsideNodes()
                    << " nodes lie outside the Delaunay graph of the boundary nodes (is the whole "
                       "outer boundary marked?); they use the nearest hull element.");
  }
  this->UpdateProgress(0.6);
  if (this->GetAbortExecute())
  {
    return 0;
  }

  // --- Steps 3-4: r (cached with the mapping) and f.
  if (cache.R.size() != n || cache.StaticR0 != this->StaticBoundaryR0)
  {
    cache.R.resize(n);
    dgmf::ComputeBoundaryDistanceField(mapping, this->StaticBoundaryR0, cache.R.data(), parallelFor);
    cache.StaticR0 = this->StaticBoundaryR0;
  }
  vtkNew<vtkDoubleArray> rArray;
  rArray->SetName("r");
  rArray->SetNumberOfTuples(numberOfPoints);
  std::copy(cache.R.begin(), cache.R.end(), rArray->GetPointer(0));
  vtkNew<vtkDoubleArray> fArray;
  fArray->SetName("f");
  fArray->SetNumberOfTuples(numberOfPoints);
  dgmf::ComputeDampingFactor(mapping,
    static_cast<dgmf::DampingFunction>(this->DampingFunction), cache.R.data(),
    fArray->GetPointer(0), parallelFor);

  // --- Steps 5-6: the new positions.
  vtkNew<vtkDoubleArray> deformed;
  deformed->SetNumberOfComponents(3);
  deformed->SetNumberOfTuples(numberOfPoints);
  dgmf::DeformDGMF(mapping, fArray->GetPointer(0), motion,
    displacement.empty() ? nullptr : displacement.data(),
    static_cast<dgmf::DeformationMode>(this->DeformationMode), points, deformed->GetPointer(0),
    parallelFor);
  this->UpdateProgress(0.8);

  // --- Output: the input's structure and arrays, the new points, r, f and the quality.
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());
  vtkNew<vtkPoints> newPoints;
  newPoints->SetData(deformed);
  output->SetPoints(newPoints);
  output->GetPointData()->AddArray(rArray);
  output->GetPointData()->AddArray(fArray);

  vtkNew<vtkIdTypeArray> outsideCount;
  outsideCount->SetName("OutsideNodeCount");
  outsideCount->InsertNextValue(static_cast<vtkIdType>(mapping.GetNumberOfOutsideNodes()));
  output->GetFieldData()->AddArray(outsideCount);

  if (this->ComputeQuality)
  {
    vtkNew<vtkDoubleArray> sizeSkew;
    sizeSkew->SetName("SizeSkew");
    vtkNew<vtkUnsignedCharArray> inverted;
    inverted->SetName("Inverted");
    const dgmf::QualitySummary summary = dgmf_vtk::ComputeCellQuality(
      input, points, deformed->GetPointer(0), sizeSkew, inverted, parallelFor);
    output->GetCellData()->AddArray(sizeSkew);
    output->GetCellData()->AddArray(inverted);
    vtkNew<vtkDoubleArray> mean;
    mean->SetName("SizeSkewMean");
    mean->InsertNextValue(summary.Mean);
    vtkNew<vtkDoubleArray> minimum;
    minimum->SetName("SizeSkewMinimum");
    minimum->InsertNextValue(summary.Minimum);
    vtkNew<vtkIdTypeArray> invertedCount;
    invertedCount->SetName("InvertedCellCount");
    invertedCount->InsertNextValue(static_cast<vtkIdType>(summary.Inverted));
    output->GetFieldData()->AddArray(mean);
    output->GetFieldData()->AddArray(minimum);
    output->GetFieldData()->AddArray(invertedCount);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkDGMFDeformFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DampingFunction: U" << this->DampingFunction << "\n";
  os << indent << "StaticBoundaryR0: " << this->StaticBoundaryR0 << "\n";
  os << indent << "Translation: (" << this->Translation[0] << ", " << this->Translation[1] << ", "
     << this->Translation[2] << ")\n";
  os << indent << "RotationCenter: (" << this->RotationCenter[0] << ", " << this->RotationCenter[1]
     << ", " << this->RotationCenter[2] << ")\n";
  os << indent << "RotationAngles: (" << this->RotationAngles[0] << ", " << this->RotationAngles[1]
     << ", " << this->RotationAngles[2] << ")\n";
  os << indent << "DeformationMode: DGMF" << this->DeformationMode << "\n";
  os << indent << "ComputeQuality: " << (this->ComputeQuality ? "on" : "off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
