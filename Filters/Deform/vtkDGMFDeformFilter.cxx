#include "vtkDGMFDeformFilter.h"

#include "DGMFCompositeMesh.h"
#include "DGMFContentKey.h"
#include "DGMFCoreDeformation.h"
#include "DGMFDistributed.h"
#include "DGMFFilterParameters.h"
#include "DGMFMeshConversion.h"
#include "DGMFMotionInTime.h"
#include "DGMFOutputArrays.h"
#include "DGMFSMPTools.h"

#include "dgmf/DeformationMethod.h"
#include "dgmf/Progress.h"
#include "dgmf/ResultNames.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <exception>
#include <new>
#include <optional>
#include <system_error>

vtkStandardNewMacro(vtkDGMFDeformFilter);
vtkCxxSetObjectMacro(vtkDGMFDeformFilter, Controller, vtkMultiProcessController);

/// What the filter keeps between executions, and the boundaries named.
struct vtkDGMFDeformFilter::Internals
{
  std::unique_ptr<dgmf_vtk::DeformationCaches> Cache =
    std::make_unique<dgmf_vtk::DeformationCaches>();
  dgmf_vtk::BodyMotionTable BodyMotions;  ///< SetBodyMotion
  dgmf_vtk::BoundarySelection Boundaries; ///< AddMovingBoundary, AddStaticBoundary, AddSlipBoundary
  dgmf_vtk::MotionInTime Motion; ///< this execution's time, and the trajectory table's motions
  /// The last execution's input and its own MTime after it (DistrustedObjects).
  const void* LastInput = nullptr;
  vtkMTimeType LastInputMTime = 0;
};

vtkDGMFDeformFilter::vtkDGMFDeformFilter()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2); // the mesh; the optional trajectory table
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkDGMFDeformFilter::~vtkDGMFDeformFilter()
{
  this->SetController(nullptr);
}

const char* vtkDGMFDeformFilter::GetMethodName(int method)
{
  const dgmf::MethodInfo* info = dgmf::FindMethod(method);
  return info ? info->Name : nullptr;
}

const char* vtkDGMFDeformFilter::GetMethodKey(int method)
{
  const dgmf::MethodInfo* info = dgmf::FindMethod(method);
  return info ? info->Key : nullptr;
}

int vtkDGMFDeformFilter::GetMethodFromName(const char* name)
{
  const dgmf::MethodInfo* info = name ? dgmf::FindMethod(name) : nullptr;
  return info ? static_cast<int>(info->Id) : -1;
}

std::string vtkDGMFDeformFilter::GetMethodKeys(const char* separator)
{
  return dgmf::ListMethodKeys(separator ? separator : ", ");
}

vtkUnstructuredGrid* vtkDGMFDeformFilter::GetOutput()
{
  return this->GetOutput(0);
}

vtkUnstructuredGrid* vtkDGMFDeformFilter::GetOutput(int port)
{
  return vtkUnstructuredGrid::SafeDownCast(this->GetOutputDataObject(port));
}

void vtkDGMFDeformFilter::SetBodyMotion(double bodyId, double tx, double ty, double tz, double cx,
  double cy, double cz, double ax, double ay, double az)
{
  const double translation[3] = { tx, ty, tz }, center[3] = { cx, cy, cz },
               angles[3] = { ax, ay, az };
  if (!this->Internal->BodyMotions.Set(bodyId, translation, center, angles))
  {
    vtkErrorMacro("SetBodyMotion: the body id must be 1, 2, ... (got "
      << bodyId << "); the filter fails until RemoveAllBodyMotions().");
  }
  this->Modified();
}

void vtkDGMFDeformFilter::RemoveAllBodyMotions()
{
  if (this->Internal->BodyMotions.Clear())
  {
    this->Modified();
  }
}

void vtkDGMFDeformFilter::AddMovingBoundary(const char* name)
{
  if (dgmf_vtk::BoundarySelection::Add(this->Internal->Boundaries.Moving, name))
  {
    this->Modified();
  }
}

void vtkDGMFDeformFilter::AddStaticBoundary(const char* name)
{
  if (dgmf_vtk::BoundarySelection::Add(this->Internal->Boundaries.Static, name))
  {
    this->Modified();
  }
}

void vtkDGMFDeformFilter::AddSlipBoundary(const char* name)
{
  if (dgmf_vtk::BoundarySelection::Add(this->Internal->Boundaries.Slip, name))
  {
    this->Modified();
  }
}

void vtkDGMFDeformFilter::RemoveAllMovingBoundaries()
{
  this->Internal->Boundaries.Moving.clear();
  this->Modified();
}

void vtkDGMFDeformFilter::RemoveAllStaticBoundaries()
{
  this->Internal->Boundaries.Static.clear();
  this->Modified();
}

void vtkDGMFDeformFilter::RemoveAllSlipBoundaries()
{
  this->Internal->Boundaries.Slip.clear();
  this->Modified();
}

void vtkDGMFDeformFilter::SetDisplacementArrayName(const char* name)
{
  dgmf_vtk::SelectPointArray(this, dgmf_vtk::DisplacementArrayIndex, name);
}

void vtkDGMFDeformFilter::SetBoundaryMarkerArrayName(const char* name)
{
  dgmf_vtk::SelectPointArray(this, dgmf_vtk::MarkerArrayIndex, name);
}

void vtkDGMFDeformFilter::SetBodyIdArrayName(const char* name)
{
  dgmf_vtk::SelectPointArray(this, dgmf_vtk::BodyIdArrayIndex, name);
}

std::size_t vtkDGMFDeformFilter::GetCacheMemorySize() const
{
  const dgmf_vtk::DeformationCaches& cache = *this->Internal->Cache;
  return cache.Inputs.GetMemorySize() + cache.Mapping.GetMemorySize() +
    cache.Composite.GetMemorySize() + cache.HexReferences.GetMemorySize();
}

void vtkDGMFDeformFilter::ReleaseCache()
{
  this->Internal->Cache = std::make_unique<dgmf_vtk::DeformationCaches>();
}

double vtkDGMFDeformFilter::GetLastMotionTime() const
{
  return this->Internal->Motion.Time;
}

void vtkDGMFDeformFilter::SetTrajectoryConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkDGMFDeformFilter::SetTrajectoryData(vtkTable* table)
{
  this->SetInputData(1, table);
}

int vtkDGMFDeformFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  if (port == 1)
  {
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkTable");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  // Any data set reaches RequestData, which says what it takes (VTK's own check printed "is of
  // type vtkPolyData, but a vtkUnstructuredGrid is required" once per pipeline pass instead).
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkDGMFDeformFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // A motion in time on an input without time: the filter's own time steps (input with time steps
  // keeps them: the pipeline copied them already).
  // The table's times are needed now: its source runs ahead of this filter's data pass (a reader
  // reads it once; data set directly is there already).
  vtkTable* table = nullptr;
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    this->GetInputAlgorithm(1, 0)->Update(this->GetInputConnection(1, 0)->GetIndex());
    table = vtkTable::SafeDownCast(this->GetInputDataObject(1, 0));
  }
  dgmf_vtk::ReportMotionTimeSteps(
    this, table, inputVector[0]->GetInformationObject(0), outputVector->GetInformationObject(0));
  return 1;
}

int vtkDGMFDeformFilter::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  // A distributed mesh without a boundary marker needs one layer of ghost cells.
  if (dgmf_vtk::IsDistributed(this->Controller) &&
    dgmf_vtk::GetSelectedArrays(this, this->GetInputDataObject(0, 0)).Marker.empty())
  {
    dgmf_vtk::RequestOneGhostLevel(inputVector[0]->GetInformationObject(0));
  }
  return 1;
}

int vtkDGMFDeformFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // 1. The input as one unstructured grid: a grid, or the blocks of a composite dataset merged at
  //    their shared nodes (scattered back into the blocks at the end).
  vtkDataObject* inputObject = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* outputObject = vtkDataObject::GetData(outputVector, 0);
  auto* compositeInput = vtkCompositeDataSet::SafeDownCast(inputObject);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(outputObject);
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::SafeDownCast(inputObject);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::SafeDownCast(outputObject);
  const bool merged = compositeInput && compositeOutput;
  if (!merged && (!input || !output))
  {
    vtkErrorMacro("The input is a " << (inputObject ? inputObject->GetClassName() : "nothing")
                                    << ": the filter deforms meshes given as a vtkUnstructuredGrid "
                                       "or a composite dataset of them (ParaView's Append Datasets "
                                       "makes a vtkUnstructuredGrid of any data set).");
    return 0;
  }
  if (!merged && !this->Internal->Boundaries.Empty())
  {
    vtkErrorMacro("Boundaries chosen by name need a composite input (a multiblock, as the "
                  "OpenFOAM, Exodus and CGNS readers give); for one unstructured grid, select a "
                  "boundary-marker array.");
    return 0;
  }

  // The motion's time: the one asked for downstream (else the first step), when it depends on
  // time; and the trajectories of the table, if one is connected.
  Internals& internal = *this->Internal;
  internal.Motion = dgmf_vtk::MotionInTime(); // none, until this execution's is read
  try
  {
    internal.Motion = dgmf_vtk::MotionOfExecution(
      this, vtkTable::GetData(inputVector[1], 0), outputVector->GetInformationObject(0));
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    outputObject->Initialize();
    return 0;
  }

  // The merge (1) and steps 2-4, check, deform and write the outputs (Execute), on the filter's
  // threads; in a distributed run every process takes part, and the quality summary is made
  // global.
  const dgmf_vtk::CompositeMesh* composite = nullptr;
  vtkNew<vtkUnstructuredGrid> mergedOutput;
  vtkNew<vtkUnstructuredGrid> patchesOutput; // the merged input's patches, deformed
  vtkNew<vtkUnstructuredGrid> noMesh;        // a process whose merge failed takes part with it
  if (merged)
  {
    output = mergedOutput;
  }
  int status = 0;
  // An input marked Modified() since the last execution (its points or cells changed in place,
  // then grid->Modified()), or another input object (one changed in place while another was
  // deformed): compared by content, not by its arrays' identity and MTime; in a distributed run
  // on every process when on one (the graph holds every piece's boundary nodes).
  bool changed = inputObject != internal.LastInput ||
    inputObject->vtkObject::GetMTime() != internal.LastInputMTime;
  if (dgmf_vtk::IsDistributed(this->Controller))
  {
    changed = !dgmf_vtk::AllProcessesAgree(this->Controller, !changed);
  }
  const dgmf_vtk::DistrustedObjects distrust(changed);
  try
  {
    dgmf_vtk::RunWithThreads(this->NumberOfThreads,
      [&]()
      {
        std::string mergeFailure;
        std::optional<dgmf_vtk::DistrustedObjects> leafDistrust;
        if (merged)
        {
          // Kept while the blocks are unchanged: a new motion does not merge them again. In a
          // distributed run a failure here must still reach the other processes' agreement.
          try
          {
            const dgmf_vtk::SelectedArrays arrays =
              dgmf_vtk::GetSelectedArrays(this, compositeInput);
            composite = &this->Internal->Cache->Composite.Get(
              compositeInput, arrays.Displacement, arrays.Marker);
            // A block changed in place (block->Modified()): the merge may share its arrays.
            if (this->Internal->Cache->Composite.FoundLeafChangedInPlace())
            {
              leafDistrust.emplace(true);
            }
          }
          catch (const std::bad_alloc&)
          {
            mergeFailure = "Out of memory while merging the input's blocks (" +
              std::to_string(compositeInput->GetNumberOfPoints()) + " points).";
          }
          catch (const std::exception& e)
          {
            mergeFailure = e.what();
          }
          if (composite && composite->GetNumberOfSkippedBlocks() > 0)
          {
            vtkWarningMacro(<< composite->GetNumberOfSkippedBlocks()
                            << " blocks without explicit points (e.g. image data) are passed "
                               "unchanged.");
          }
          input = composite ? composite->GetMergedMesh() : noMesh.Get();
          // The last output's blocks share the filter's output points: released, those can be
          // reused.
          compositeOutput->Initialize();
        }
        status = this->Execute(input, output, patchesOutput, composite, mergeFailure);
      });
  }
  catch (const dgmf::Aborted& e)
  {
    vtkWarningMacro(<< e.what());
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory while deforming "
      << input->GetNumberOfPoints() << " points ("
      << dgmf_vtk::CellsWithPatches(input, composite ? composite->GetPatches() : nullptr)
      << " cells).");
  }
  catch (const std::system_error& e) // a thread that cannot be started
  {
    vtkErrorMacro("Out of resources: " << e.what()
                                       << " (a thread could not be started; try NumberOfThreads 1 "
                                          "or more memory).");
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
  }
  if (dgmf_vtk::IsDistributed(this->Controller))
  {
    bool ok = status != 0;
    dgmf_vtk::ReduceFieldData(
      this->Controller, ok, output->GetFieldData(), this->ComputeNonOrthogonality);
    status = ok ? 1 : 0;
  }
  if (!status)
  {
    outputObject->Initialize(); // no output
  }
  else if (composite)
  {
    composite->ScatterResult(output, patchesOutput, compositeOutput);
  }
  if (status && internal.Motion.TimeDependent)
  {
    outputObject->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), internal.Motion.Time);
  }
  // After the execution: what it did to the input (a cell array built on demand) is no change.
  internal.LastInput = inputObject;
  internal.LastInputMTime = inputObject->vtkObject::GetMTime();
  return status;
}

int vtkDGMFDeformFilter::Execute(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output,
  vtkUnstructuredGrid* patchesOutput, const dgmf_vtk::CompositeMesh* composite,
  const std::string& failure)
{
  this->LastExecutionReusedGraph = false;
  this->LastGraphSeconds = this->LastLocationSeconds = this->LastDeformationSeconds =
    this->LastQualitySeconds = 0.0;
  this->LastNumberOfNodes = this->LastNumberOfCells = 0;
  dgmf_vtk::DeformationCaches& cache = *this->Internal->Cache;
  const bool distributed = dgmf_vtk::IsDistributed(this->Controller);

  // 2. The nodes, with the selected arrays found and of the right shape or the boundaries named
  //    (the core checks the values). A distributed run agrees on the dimension and fails on every
  //    process if it fails on one (no process may wait for another in the exchanges).
  dgmf_vtk::GatherOptions options;
  options.Arrays = dgmf_vtk::GetSelectedArrays(this, input);
  options.Distributed = distributed;
  options.OneCellThick = this->OneCellThickMode;
  options.DistinctPoints = composite != nullptr; // the merge made every point distinct
  vtkUnstructuredGrid* patches = composite ? composite->GetPatches() : nullptr;
  options.Patches = patches;
  if (distributed)
  {
    double z = 0.0;
    options.Dimension = dgmf_vtk::AgreeOnDimension(this->Controller, input, z);
  }
  dgmf_vtk::InputNodes nodes;
  const std::string settingsFailure = dgmf_vtk::SettingsError(this);
  const std::string error = !failure.empty() ? failure
    : !settingsFailure.empty()
    ? settingsFailure
    : dgmf_vtk::GatherInputNodes(input, composite, this->Internal->Boundaries,
        this->OneCellThickMode != OFF && !distributed, options, cache, nodes);
  bool ok = error.empty();
  std::string agreementError; // the same on every process
  if (distributed && (ok = dgmf_vtk::AllProcessesAgree(this->Controller, ok)))
  {
    dgmf_vtk::JoinOptions join;
    join.Selection = &this->Internal->Boundaries;
    join.Roles = composite ? options.Roles : nullptr;
    join.CheckLayers = this->OneCellThickMode == DETECT;
    join.NonOrthogonality = this->ComputeNonOrthogonality;
    agreementError = dgmf_vtk::JoinPieces(this->Controller, join, input, nodes);
  }
  if (!ok || !agreementError.empty())
  {
    vtkErrorMacro(<< (!error.empty() || !agreementError.empty()
                      ? error + agreementError
                      : std::string(
                          "Another process of the distributed run failed (its message says why): "
                          "every process stops.")));
    return 0;
  }
  if (nodes.LocalNodes == 0)
  {
    output->ShallowCopy(input); // an empty piece of a distributed mesh
    return 1;
  }
  for (const std::string& warning : nodes.Warnings)
  {
    vtkWarningMacro(<< warning);
  }

  // 3. Deform through the core's method interface: the method says what it needs.
  const auto method =
    dgmf::CreateMethod(dgmf_vtk::MethodOf(this), dgmf_vtk::MethodParametersOf(this));
  const std::string settingsWarning = dgmf_vtk::SettingsWarning(this);
  if (!settingsWarning.empty())
  {
    vtkWarningMacro(<< settingsWarning);
  }
  dgmf::DeformationProblem problem = nodes.ToProblem();
  problem.ExtractRigidMotion = this->RigidMotionMode == EXTRACTED;
  const Internals& internal = *this->Internal;
  problem.Motions =
    internal.BodyMotions.For(this, nodes, dgmf_vtk::PropertiesMotionAt(this, internal.Motion.Time),
      internal.Motion.Trajectory.get(), internal.Motion.Time);
  if (internal.Motion.TimeDependent && !problem.ExtractRigidMotion &&
    internal.BodyMotions.PropertiesMove(this, nodes, internal.Motion.Trajectory.get()))
  {
    // What the laws reach at their largest, judged now: a series is not half written before an
    // axis of length 0 or a 2D mesh turned out of its plane shows (at angle 0 both pass).
    dgmf::ValidateMotion(problem, dgmf_vtk::PropertiesMotionAt(this, internal.Motion.Time, true),
      "The motion at its largest: ");
  }
  const std::size_t n = nodes.NumberOfNodes;
  const vtkSmartPointer<vtkPoints> newPoints =
    dgmf_vtk::ReuseOutputPoints(cache.OutputPoints, input, output, n);
  auto* newCoordinates = vtkDoubleArray::SafeDownCast(newPoints->GetData());
  // Progress: 0.1 gathered, 0.45 graph and location, up to 0.8 the method (sub-steps, repair),
  // then the outputs and the quality. ParaView's abort stops the run at each report.
  const dgmf::Progress progress(
    [this](double fraction)
    {
      this->UpdateProgress(fraction);
      return !this->GetAbortExecute();
    },
    0.1, 0.8);
  progress.Report(0.0);
  const dgmf_vtk::CoreDeformation result = dgmf_vtk::DeformThroughCore(*method, problem, nodes,
    input, distributed, cache, newCoordinates, dgmf_vtk::MakeSMPParallelFor(), progress);
  this->LastExecutionReusedGraph = result.GraphReused;
  this->LastGraphSeconds = result.GraphSeconds;
  this->LastLocationSeconds = result.LocationSeconds;
  this->LastDeformationSeconds = result.DeformationSeconds;
  for (const std::string& warning : result.Report.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  progress.Report(1.0); // 0.8; an abort here skips the quality

  // 4. The outputs: the input's cells and arrays, the new points, the method's results, the
  // quality.
  dgmf_vtk::SetDeformedGrid(input, output, newPoints, nodes.LocalNodes);
  if (patches)
  {
    dgmf_vtk::SetDeformedGrid(patches, patchesOutput, newPoints, nodes.LocalNodes);
  }
  dgmf_vtk::AddMethodResults(output, result.R, result.F, result.Report, result.Needs.Graph,
    result.GraphReused, method->GetInfo().Name, nodes.LocalNodes);
  if (internal.Motion.TimeDependent)
  {
    dgmf_vtk::AddFieldValue(output->GetFieldData(), dgmf::names::MotionTime, internal.Motion.Time);
  }
  const auto qualityStart = std::chrono::steady_clock::now();
  const dgmf_vtk::HexReferences hexReferences = this->ComputeQuality && input->GetPoints()
    ? cache.HexReferences.For(input, input->GetPoints()->GetData())
    : dgmf_vtk::HexReferences();
  const dgmf::QualitySummary summary =
    dgmf_vtk::AddOutputQuality(input, nodes.Points, newCoordinates->GetPointer(0), output,
      this->ComputeQuality, hexReferences, this->ComputeNonOrthogonality ? &cache.Faces : nullptr,
      dgmf_vtk::MakeSMPParallelFor(), &cache.Quality);
  if (patches && this->ComputeQuality)
  {
    // The patches' polygons get their SizeSkew; the summary is the volume's, as for one grid
    // (ComputeCellQuality leaves the cells of a lower dimension out of it).
    dgmf_vtk::AddCellQuality(patches, nodes.Points, newCoordinates->GetPointer(0),
      patchesOutput->GetCellData(), patchesOutput->GetFieldData(), dgmf_vtk::HexReferences(),
      dgmf_vtk::MakeSMPParallelFor(), &cache.PatchQuality);
  }
  this->LastQualitySeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - qualityStart).count();
  if (this->ComputeQuality && this->Method == DGMF && this->RepairThreshold > 0.0)
  {
    // The guard repairs the cells the metric's corner form covers; bad polyhedra are left, and
    // counted with the cells it could not repair.
    const std::string warning =
      dgmf_vtk::CountUnguardedCellsAsUnrepaired(output, this->RepairThreshold);
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning);
    }
  }
  if (this->ComputeQuality && this->FailOnInvertedCells && summary.Inverted > 0)
  {
    vtkErrorMacro(
      "The deformation inverts " << summary.Inverted << " cells (FailOnInvertedCells is on).");
    return 0;
  }
  this->LastNumberOfNodes = input->GetNumberOfPoints();
  this->LastNumberOfCells = dgmf_vtk::CountCellsOfLargestDimension(input);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkDGMFDeformFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "DampingFunction: U" << this->DampingFunction << "\n";
  os << indent << "StaticBoundaryR0: " << this->StaticBoundaryR0 << "\n";
  const auto vector = [&os, indent](const char* name, const double* v)
  { os << indent << name << ": (" << v[0] << ", " << v[1] << ", " << v[2] << ")\n"; };
  vector("Translation", this->Translation);
  vector("RotationCenter", this->RotationCenter);
  vector("RotationAngles", this->RotationAngles);
  os << indent << "DeformationMode: DGMF" << this->DeformationMode << "\n";
  os << indent
     << "RigidMotionMode: " << (this->RigidMotionMode == EXTRACTED ? "Extracted" : "Properties")
     << " (" << this->Internal->BodyMotions.Size() << " body motions set)\n";
  os << indent << "SupportRadius: " << this->SupportRadius
     << ", RBFGreedy: " << (this->RBFGreedy ? "on" : "off") << " (tolerance "
     << this->RBFGreedyTolerance << ", at most " << this->RBFGreedyMaximumPoints << " points)\n";
  os << indent << "IDWAlpha: " << this->IDWAlpha
     << ", IDWReferenceLength: " << this->IDWReferenceLength << "\n";
  os << indent << "SubSteps: " << this->SubSteps << ", RepairThreshold: " << this->RepairThreshold
     << " (layers " << this->RepairLayers << ", passes " << this->RepairPasses << ")\n";
  os << indent << "ComputeQuality: " << (this->ComputeQuality ? "on" : "off")
     << ", ComputeNonOrthogonality: " << (this->ComputeNonOrthogonality ? "on" : "off")
     << ", FailOnInvertedCells: " << (this->FailOnInvertedCells ? "on" : "off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads
     << ", OneCellThickMode: " << this->OneCellThickMode << "\n";
  const dgmf_vtk::BoundarySelection& names = this->Internal->Boundaries;
  os << indent << "Boundaries by name: " << names.Moving.size() << " moving, "
     << names.Static.size() << " static, " << names.Slip.size() << " slip\n";
}
