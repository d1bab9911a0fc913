#include "DGMFCommandChecks.h"

#include "DGMFCommandData.h"
#include "DGMFCommandSeries.h"

#include "dgmf/meshfile/MeshFileFormat.h"
#include "dgmf/openfoam/CaseDirectory.h"

#include "vtkDGMFDeformFilter.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <filesystem>
#include <iostream>

namespace dgmf_cli
{
namespace
{
std::string ExtensionOf(const std::string& path)
{
  return std::filesystem::path(path).extension().string();
}
} // namespace

InputKind KindOf(const std::string& input)
{
  return IsOpenFOAMCase(input) ? InputKind::OpenFOAMCase
    : IsSolverMeshFile(input)  ? InputKind::SolverFile
                               : InputKind::VTKFile;
}

std::string InputProblem(InputKind kind, const std::string& input)
{
  namespace fs = std::filesystem;
  std::error_code error;
  // (A case's .foam file need not exist: the case is its directory.)
  if (kind != InputKind::OpenFOAMCase && !fs::exists(input, error))
  {
    return input + " does not exist";
  }
  if (kind != InputKind::OpenFOAMCase)
  {
    if (fs::is_directory(input, error))
    {
      return input + " is a directory but not an OpenFOAM case (it has no system/controlDict)";
    }
    // (The Exodus and CGNS libraries word an empty file as one that does not exist.)
    return fs::is_regular_file(input, error) && fs::file_size(input, error) == 0 && !error
      ? input + " is empty (0 bytes)"
      : "";
  }
  const fs::path caseDirectory = dgmf::openfoam::CaseDirectoryOf(input);
  if (!fs::is_directory(caseDirectory, error))
  {
    return caseDirectory.string() + " (the case of " + input + ") does not exist";
  }
  if (!dgmf::openfoam::IsCase(caseDirectory))
  {
    return caseDirectory.string() + " (the case of " + input +
      ") is not an OpenFOAM case (it has no system/controlDict)";
  }
  if (fs::is_directory(caseDirectory / "constant" / "polyMesh", error))
  {
    return "";
  }
  bool decomposed = false;
  for (const fs::directory_entry& entry : fs::directory_iterator(caseDirectory, error))
  {
    decomposed = decomposed || entry.path().filename().string().rfind("processor", 0) == 0;
  }
  return caseDirectory.string() + " has no mesh (no constant/polyMesh): " +
    (decomposed ? "its processor* directories hold the decomposed mesh; run reconstructParMesh "
                  "-constant (or reconstructPar) first"
                : "make it first (blockMesh, snappyHexMesh, or a mesh converter)");
}

std::string OutputProblem(InputKind kind, const std::string& input, const std::string& output)
{
  if (kind == InputKind::OpenFOAMCase && !IsMeshFileName(output) && !IsOpenFOAMCase(output))
  {
    // Said before the work (CopyCase refuses it too, before copying anything).
    return dgmf::openfoam::CopyTargetProblem(dgmf::openfoam::CaseDirectoryOf(input), output);
  }
  if (IsMeshFileName(output) || kind == InputKind::OpenFOAMCase)
  {
    return "";
  }
  if (kind == InputKind::SolverFile &&
    dgmf::meshfile::FormatOfFileName(output) == dgmf::meshfile::FormatOfFileName(input))
  {
    return "";
  }
  return "the output must end in .vtu (XML) or .vtk (legacy VTK)" +
    std::string(
      kind == InputKind::SolverFile ? ", or " + ExtensionOf(input) + " as the input" : "") +
    ": " + output;
}

bool OptionsFitTheInput(InputKind kind, const CommandOptions& options, vtkDGMFDeformFilter* filter)
{
  if (options.Time != "constant" && kind != InputKind::OpenFOAMCase)
  {
    std::cerr << "dgmf-deform: --time names the time directory of an OpenFOAM case; "
              << options.Input << " is not one\n";
    return false;
  }
  // A time written otherwise than OpenFOAM writes it ("1e1", "0.50"): a solver run writes its
  // own directory of that time ("10", "0.5") beside it (silent until 2026-11-30).
  double time = 0.0;
  if (dgmf::openfoam::TimeValue(options.Time, time) &&
    OpenFOAMTimeNames({ time }).front() != options.Time)
  {
    std::cerr << "dgmf-deform: warning: OpenFOAM names the time " << options.Time << " '"
              << OpenFOAMTimeNames({ time }).front()
              << "' (6 significant digits, its default): a solver run writes that directory "
                 "beside "
              << options.Time << "; write to --time " << OpenFOAMTimeNames({ time }).front()
              << "\n";
  }
  if (options.MarkerGiven && options.ByName)
  {
    std::cerr << "dgmf-deform: warning: --marker is not read: the boundaries are chosen by name\n";
  }
  if (options.BodyIdGiven && options.ByName)
  {
    std::cerr << "dgmf-deform: warning: --body-id is not read: the boundaries are chosen by name "
                 "(each --moving entry is a body)\n";
  }
  if ((!options.Compression.empty() || !options.VTUAppended) && !IsVTUFileName(options.Output))
  {
    std::cerr << "dgmf-deform: warning: --compression and --vtu-mode are for .vtu outputs; "
              << options.Output << " is not one\n";
  }
  if (filter->GetRepairThreshold() <= 0.0 &&
    (filter->GetRepairPasses() != 20 || filter->GetRepairLayers() != 2))
  {
    std::cerr << "dgmf-deform: warning: --repair-passes and --repair-layers are the quality "
                 "guard's: without --repair they do nothing\n";
  }
  return true;
}

bool NodesCanMove(vtkUnstructuredGrid* mesh, const CommandOptions& options)
{
  if (mesh->GetPointData()->GetArray(options.Marker.c_str()) ||
    (options.MarkerGiven && !options.Marker.empty()))
  {
    return true; // (a marker named but missing is the filter's error)
  }
  vtkDataArray* displacement = mesh->GetPointData()->GetArray(options.Displacement.c_str());
  bool moving = false;
  for (int c = 0; displacement && c < displacement->GetNumberOfComponents() && !moving; ++c)
  {
    double range[2];
    displacement->GetRange(range, c);
    moving = range[0] != 0.0 || range[1] != 0.0;
  }
  if (!moving)
  {
    std::cerr << "dgmf-deform: error: the input has no boundary-marker array '" << options.Marker
              << "' and no non-zero displacement array '" << options.Displacement
              << "': no node would move. Give the marker (--marker NAME: 0 interior, 1 static, "
                 "2 moving, 3 slip) or the moving nodes' displacement (--displacement NAME).\n";
    return false;
  }
  std::cout << "dgmf-deform: no boundary-marker array '" << options.Marker
            << "': the boundary is the mesh's boundary faces, moving where '"
            << options.Displacement << "' is not zero" << std::endl;
  return true;
}

} // namespace dgmf_cli
