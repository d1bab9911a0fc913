#include "vtkDGMFOpenFOAMWriter.h"

#include "DGMFWriterInputs.h"

#include "dgmf/NumberText.h"
#include "dgmf/openfoam/CaseDirectory.h"
#include "dgmf/openfoam/PointsFile.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenFOAMReader.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <set>
#include <vector>

vtkStandardNewMacro(vtkDGMFOpenFOAMWriter);

using dgmf_vtk::InternalMeshOf;
using dgmf_vtk::PointsOf;

vtkDGMFOpenFOAMWriter::vtkDGMFOpenFOAMWriter()
{
  this->SetNumberOfInputPorts(2);
  this->SetTimeDirectory("constant");
}

vtkDGMFOpenFOAMWriter::~vtkDGMFOpenFOAMWriter()
{
  this->SetFileName(nullptr);
  this->SetSourceCase(nullptr);
  this->SetTimeDirectory(nullptr);
}

void vtkDGMFOpenFOAMWriter::SetReferenceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkDGMFOpenFOAMWriter::SetReferenceData(vtkDataObject* reference)
{
  this->SetInputData(1, reference);
}

int vtkDGMFOpenFOAMWriter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkDGMFOpenFOAMWriter::WriteData()
{
  namespace fs = std::filesystem;
  namespace of = dgmf::openfoam;
  this->LastWrittenFile.clear();
  const auto fail = [this](const std::string& message)
  {
    vtkErrorMacro(<< message);
    this->SetErrorCode(vtkErrorCode::UserError);
  };
  if (!this->FileName || !*this->FileName)
  {
    fail("No FileName: give the case to write (a directory, or a .foam file in it).");
    return;
  }
  vtkPointSet* deformed = InternalMeshOf(this->GetInput(0));
  // Under MPI (pvbatch) the case is written by the process that holds the mesh as the reader
  // gives it; a process without a piece has nothing to write (it said "no unstructured grid").
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  if (processes > 1 && (!deformed || deformed->GetNumberOfPoints() == 0))
  {
    return;
  }
  const std::string distributedHint = processes > 1
    ? " In a distributed run (" + std::to_string(processes) +
      " processes), the mesh to write is the reader's as it gives it on its process, not "
      "redistributed or gathered (their points are ordered otherwise); or write with dgmf-deform "
      "(Documentation/distributed.md)."
    : "";
  if (!deformed)
  {
    fail("The input has no unstructured grid (the OpenFOAM reader's internalMesh).");
    return;
  }
  vtkOpenFOAMReader* reader = dgmf_vtk::FindUpstream<vtkOpenFOAMReader>(this);
  vtkDataObject* referenceData = this->GetNumberOfInputConnections(1) > 0
    ? this->GetInput(1)
    : (reader ? reader->GetOutputDataObject(0) : nullptr);
  vtkPointSet* reference = InternalMeshOf(referenceData);
  std::string source = this->SourceCase ? this->SourceCase : "";
  if (source.empty() && reader && reader->GetFileName())
  {
    source = reader->GetFileName();
  }
  if (!reference || source.empty())
  {
    fail("No undeformed mesh or no source case: read the case with an OpenFOAM reader upstream, "
         "or set SourceCase and connect the Reference input (the mesh as read)." +
      distributedHint);
    return;
  }
  if (reference->GetNumberOfPoints() != deformed->GetNumberOfPoints())
  {
    fail("The input has " + std::to_string(deformed->GetNumberOfPoints()) +
      " points and the undeformed mesh " + std::to_string(reference->GetNumberOfPoints()) +
      ": they must be the same mesh." + distributedHint);
    return;
  }
  const fs::path target(this->FileName);
  try
  {
    const std::vector<double> before = PointsOf(reference), after = PointsOf(deformed);
    const fs::path caseDirectory = of::CaseDirectoryOf(target);
    const std::string time = this->TimeDirectory ? this->TimeDirectory : "constant";
    // A time's points already there (a mesh a solver moved, as a dynamic-mesh run writes; in
    // the case, or in the copy of the source case a new output gets) are replaced by the
    // deformation of constant's mesh: said (silent until 2026-11-30).
    bool replacing = false;
    this->LastWrittenFile = of::WriteDeformedPoints(of::CaseDirectoryOf(fs::path(source)),
      caseDirectory, time, before.data(), after.data(),
      static_cast<std::size_t>(deformed->GetNumberOfPoints()), &replacing)
                              .string();
    if (replacing)
    {
      vtkWarningMacro(<< this->LastWrittenFile
                      << " held points already (a mesh a solver moved, or an earlier run's): they "
                         "are replaced by the deformation of the mesh in constant, not of that "
                         "time's.");
    }
    if (target != caseDirectory && !fs::exists(target))
    {
      std::ofstream(target.string()).flush(); // the empty file ParaView opens a case with
    }
    try
    {
      this->WarnAboutOtherMeshes(caseDirectory);
    }
    catch (const std::exception&)
    {
      // The points are written: a directory that cannot be listed only loses the warnings.
    }
  }
  catch (const std::bad_alloc&)
  {
    fail("Out of memory while writing the points; nothing was written.");
  }
  catch (const std::exception& e)
  {
    fail(e.what());
  }
}

void vtkDGMFOpenFOAMWriter::WarnAboutOtherMeshes(const std::filesystem::path& caseDirectory)
{
  namespace fs = std::filesystem;
  // Meshes a solver may read instead of the one written. A solver started at time S reads the
  // newest polyMesh at or before S, else constant's: written to constant, any time directory's
  // polyMesh hides it (0/polyMesh from a solver started at 0); written to time T, a later time's
  // does (a restart from it; not the earlier frames of a series). And the processor directories
  // of a decomposed case (a parallel run reads theirs).
  const std::string written = this->TimeDirectory ? this->TimeDirectory : "constant";
  double writtenTime = 0.0;
  const bool toATime = dgmf::openfoam::TimeValue(written, writtenTime);
  std::error_code error;
  std::vector<std::string> shadowing, sameTime;
  bool decomposed = false;
  for (const fs::directory_entry& entry : fs::directory_iterator(caseDirectory, error))
  {
    const std::string name = entry.path().filename().string();
    decomposed = decomposed || name.rfind("processor", 0) == 0;
    double time = 0.0;
    const bool isTime = dgmf::openfoam::TimeValue(name, time);
    // A time of the series this write is a frame of is replaced by the series itself.
    const bool ofTheSeries = std::find(this->SeriesTimes.begin(), this->SeriesTimes.end(), name) !=
      this->SeriesTimes.end();
    const bool hides = !ofTheSeries && (!toATime || (writtenTime < time && name != written));
    std::error_code missing;
    if (isTime && hides && fs::exists(entry.path() / "polyMesh", missing))
    {
      shadowing.push_back(name);
    }
    // The same time written another way ("0.0002" beside "2e-4"): OpenFOAM lists both.
    if (isTime && toATime && name != written && time == writtenTime)
    {
      sameTime.push_back(name);
    }
  }
  for (const std::string& name : sameTime)
  {
    vtkWarningMacro(<< (caseDirectory / name).string() << " is the time " << written
                    << " written another way: OpenFOAM lists both and reads one of them; write "
                       "to --time "
                    << name << " (or TimeDirectory " << name << ") instead.");
  }
  for (const std::string& name : shadowing)
  {
    vtkWarningMacro(<< (caseDirectory / name / "polyMesh").string()
                    << " has a mesh of its own: a solver started at time " << name
                    << " or later reads it, not the deformed points written to " << written
                    << "/polyMesh (remove it, or write to that time).");
  }
  // One time written after the time a solver run of the case starts from: the run meshes its
  // start with an older mesh (constant's, as a rule) and a solver whose mesh does not move never
  // reads these points (silent until 2026-11-30). A series says this of all its frames at once.
  double start = 0.0;
  if (toATime && this->SeriesTimes.empty() &&
    dgmf::openfoam::SolverStartTime(caseDirectory, { writtenTime }, false, start) &&
    start < writtenTime)
  {
    vtkWarningMacro(<< "A solver run of " << caseDirectory.string() << " starts from time "
                    << dgmf::NumberText(start)
                    << " (its controlDict's startFrom) on the newest mesh at or before it, not on "
                       "the deformed points written to "
                    << written << "/polyMesh: write to --time " << dgmf::NumberText(start)
                    << " (TimeDirectory), or change startFrom.");
  }
  if (decomposed && (this->SeriesTimes.empty() || written == this->SeriesTimes.back()))
  {
    vtkWarningMacro(<< caseDirectory.string()
                    << " is decomposed: its processor* directories keep the old mesh; run "
                       "decomposePar again (-force) before a parallel run.");
  }
}

void vtkDGMFOpenFOAMWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SourceCase: "
     << (this->SourceCase && *this->SourceCase ? this->SourceCase : "(the reader's)") << "\n";
  os << indent << "TimeDirectory: " << (this->TimeDirectory ? this->TimeDirectory : "") << "\n";
}
