/**
 * dgmf-deform: deforms a mesh file or an OpenFOAM case with vtkDGMFDeformFilter from the command
 * line.
 *
 *   dgmf-deform INPUT OUTPUT.vtu [options]
 *   dgmf-deform CASE_DIR OUT_CASE_DIR --moving NAME[,NAME...] [--static ...] [--slip ...] [options]
 *
 * INPUT is a .vtu (XML) or .vtk (legacy) unstructured grid; the output is written as an XML
 * unstructured grid (.vtu, appended raw by default: --vtu-mode, --compression) or a
 * binary legacy file (.vtk), under a temporary name renamed into place. A motion in time
 * (--rotation-law, --pitch, --translation-law, --trajectory) writes a series: one output per time
 * and a .pvd collection (RunSeries). CASE_DIR is an OpenFOAM case (its directory or a .foam
 * file); the deformed points are written into OUT_CASE_DIR (vtkDGMFOpenFOAMWriter: a new
 * directory gets a copy of the case; OUT_CASE_DIR may be CASE_DIR itself). The quality summary
 * is printed on one line. Exit codes: DGMFCommandOptions.h (ExitCode). Messages:
 * DGMFCommandMessages.h.
 */
#include "DGMFBoundaryNameParts.h"
#include "DGMFCommandBoundaries.h"
#include "DGMFCommandChecks.h"
#include "DGMFCommandData.h"
#include "DGMFCommandMessages.h"
#include "DGMFCommandOptions.h"
#include "DGMFCommandSeries.h"

#include "dgmf/meshfile/MeshFileFormat.h"
#include "dgmf/openfoam/CaseDirectory.h"

#include "vtkDGMFDeformFilter.h"

#include "DGMFMotionInTime.h"
#include "dgmf/NumberText.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

namespace
{
using dgmf_cli::ExitFailure;
using dgmf_cli::ExitInvertedCells;
using dgmf_cli::ExitSuccess;
using dgmf_cli::ExitUsage;
using dgmf_cli::InputKind;

double FieldValue(vtkDataObject* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : 0.0;
}

long long CountValue(vtkDataObject* mesh, const char* name)
{
  return static_cast<long long>(FieldValue(mesh, name));
}

/// Where the time of a run went (seconds).
struct Times
{
  double Read = 0.0;
  double Deform = 0.0; ///< the filter: deformation, quality
  double Write = 0.0;
};

/// The one-line summary: size, time, quality, non-orthogonality, sub-steps, the file written ("":
/// none).
void PrintSummary(vtkDGMFDeformFilter* filter, const Times& times, const std::string& written)
{
  const double seconds = times.Deform;
  vtkDataObject* deformed = filter->GetOutputDataObject(0);
  // The mesh deformed: for a composite input (a solver's file), its merged volume, not the sum
  // of its blocks (which counted the boundary patches' points and faces on top).
  std::cout << "dgmf-deform: " << filter->GetLastNumberOfNodes() << " points, "
            << filter->GetLastNumberOfCells() << " cells, " << seconds << " s";
  if (filter->GetComputeQuality() || filter->GetComputeNonOrthogonality())
  {
    std::cout << " (quality " << filter->GetLastQualitySeconds() << " s)";
  }
  if (filter->GetComputeQuality() && CountValue(deformed, "SizeSkewEvaluatedCells") == 0)
  {
    // Quadratic cells and polyhedra have no SizeSkew: a minimum of 0 would read as the worst.
    std::cout << "; SizeSkew: no cell evaluated (the metric covers linear cells only)";
  }
  else if (filter->GetComputeQuality())
  {
    std::cout << "; SizeSkew mean " << FieldValue(deformed, "SizeSkewMean") << ", minimum "
              << FieldValue(deformed, "SizeSkewMinimum") << ", inverted cells "
              << CountValue(deformed, "InvertedCellCount")
              << " (invalid in the input: " << CountValue(deformed, "InputInvalidCellCount") << ")";
  }
  if (filter->GetComputeNonOrthogonality())
  {
    std::cout << "; non-orthogonality max " << FieldValue(deformed, "MaximumNonOrthogonality")
              << " (input " << FieldValue(deformed, "InputMaximumNonOrthogonality") << ")";
  }
  // Sub-steps and the guard are DGMF's (the other methods warn that they ignore them).
  const bool dgmf = filter->GetMethod() == vtkDGMFDeformFilter::DGMF;
  if (dgmf && (filter->GetSubSteps() != 1 || filter->GetRepairThreshold() > 0))
  {
    std::cout << "; sub-steps " << CountValue(deformed, "SubStepsUsed");
  }
  if (dgmf && filter->GetRepairThreshold() > 0)
  {
    std::cout << ", bad cells found " << CountValue(deformed, "RepairedCellCount")
              << ", left unrepaired " << CountValue(deformed, "UnrepairedCellCount");
  }
  std::cout << "; read " << times.Read << " s, written " << times.Write << " s";
  std::cout << (written.empty() ? std::string("; nothing written (--no-write)")
                                : "; wrote " + written)
            << std::endl;
}
/// Writes the deformed mesh where the options say; false (the error printed) when it cannot.
bool WriteOutput(vtkDGMFDeformFilter* filter, InputKind kind,
  const dgmf_cli::CommandOptions& options, std::string& written)
{
  written = options.Output;
  bool ok = true;
  if (dgmf_cli::IsMeshFileName(options.Output))
  {
    dgmf_cli::VTUEncoding encoding;
    encoding.Appended = options.VTUAppended;
    encoding.Compression = options.Compression;
    const vtkSmartPointer<vtkUnstructuredGrid> volume =
      dgmf_cli::VolumeToWrite(filter->GetOutputDataObject(0));
    ok = volume && dgmf_cli::WriteMeshFile(volume, options.Output, encoding);
  }
  else if (kind == InputKind::SolverFile)
  {
    ok = dgmf_cli::WriteSolverMeshFile(filter, options.Input, options.Output);
  }
  else
  {
    dgmf_cli::SetStage("writing into " + options.Output);
    written =
      dgmf_cli::WriteOpenFOAMPoints(filter, options.Output, options.Time, options.SeriesTimes);
    if (written.empty())
    {
      std::cerr << "dgmf-deform: error: could not write the points into " << options.Output << "\n";
      return false;
    }
  }
  if (!ok)
  {
    std::cerr << "dgmf-deform: error: could not write " << options.Output
              << " (any file already there is unchanged)\n";
  }
  return ok;
}
/**
 * Runs `update` (the filter's Update, or UpdateTimeStep), timed into `times`, and judges the
 * output: ExitSuccess, else the exit code with `why` the reason for the message (an error from the
 * filter or no output: ExitFailure; inverted cells with --fail-on-inverted: ExitInvertedCells).
 */
int DeformAndJudge(vtkDGMFDeformFilter* filter, bool failOnInverted,
  const std::function<void()>& update, Times& times, std::string& why)
{
  dgmf_cli::ResetErrorCount();
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  update();
  timer->StopTimer();
  times.Deform = timer->GetElapsedTime();
  vtkDataObject* deformed = filter->GetOutputDataObject(0);
  if (dgmf_cli::GetErrorCount() > 0 || deformed->GetNumberOfElements(vtkDataObject::POINT) == 0)
  {
    why = "the deformation failed";
    return ExitFailure;
  }
  const long long inverted = CountValue(deformed, "InvertedCellCount");
  if (failOnInverted && inverted > 0)
  {
    why = "the deformation inverts " + std::to_string(inverted) + " cells";
    return ExitInvertedCells;
  }
  return ExitSuccess;
}

/// Writes the output as `options` say (timed into `times`) and prints the summary line; false
/// (the error printed) when it cannot be written.
bool WriteAndReport(vtkDGMFDeformFilter* filter, InputKind kind,
  const dgmf_cli::CommandOptions& options, Times& times, std::string& written)
{
  const double writeStart = vtkTimerLog::GetUniversalTime();
  if (!options.NoWrite && !WriteOutput(filter, kind, options, written))
  {
    return false;
  }
  times.Write = vtkTimerLog::GetUniversalTime() - writeStart;
  PrintSummary(filter, times, written);
  return true;
}

/**
 * The series of a motion in time: the filter run at each time (the graph built once), each frame
 * written as the options say (OUTPUT's frame files and a .pvd collection, or one time directory
 * per time in an OpenFOAM case). Stops at the first frame that fails.
 */
int RunSeries(
  vtkDGMFDeformFilter* filter, InputKind kind, dgmf_cli::CommandOptions options, Times times)
{
  // Without --times, the motion's own times (0:1:21, or the table's), not the input's: an
  // OpenFOAM case's are its time directories (often "0" alone), which gave a series of one frame
  // at time 0 until 2026-11-30.
  std::vector<double> steps = options.Times;
  if (steps.empty())
  {
    try
    {
      steps =
        dgmf_vtk::MotionTimeSteps(filter, vtkTable::SafeDownCast(filter->GetInputDataObject(1, 0)));
    }
    catch (const std::exception& e)
    {
      std::cerr << "dgmf-deform: error: " << e.what() << "\n";
      return ExitFailure;
    }
  }
  if (steps.empty())
  {
    std::cerr << "dgmf-deform: error: the motion has no time steps\n";
    return ExitFailure;
  }
  const bool files = kind != InputKind::OpenFOAMCase;
  if (!files && steps.front() < 0.0)
  {
    // Said before the first frame (it was "could not write the points" after it).
    std::cerr << "dgmf-deform: error: an OpenFOAM series writes time directories from 0 on: "
                 "the series starts at "
              << dgmf::NumberText(steps.front()) << " (give --times from 0)\n";
    return options.Times.empty() ? ExitFailure : ExitUsage; // the table's times, or --times
  }
  // The time a solver run of the case starts from (its controlDict's startFrom, once the series
  // is written; the output case's, or the input's that it will copy).
  double solverStart = 0.0;
  const std::filesystem::path outputCase = dgmf::openfoam::CaseDirectoryOf(options.Output);
  const bool newCase = !dgmf::openfoam::IsCase(outputCase); // to be a copy of the input's
  if (!files &&
    dgmf::openfoam::SolverStartTime(
      newCase ? dgmf::openfoam::CaseDirectoryOf(options.Input) : outputCase, steps, newCase,
      solverStart))
  {
    // Every frame before it: a run of the case meshes its start with the newest polyMesh at or
    // before it, the last frame's (which the fields of that time were not computed on), and
    // never reaches the others (a series before a later start is the mistake worth a word).
    if (std::all_of(
          steps.begin(), steps.end(), [solverStart](double t) { return t < solverStart; }))
    {
      std::cerr << "dgmf-deform: warning: all " << steps.size()
                << " frames come before the time a solver run of the case starts from, "
                << dgmf::NumberText(solverStart)
                << " (its controlDict's startFrom): such a run takes the newest mesh at or before "
                   "its start, the last frame's (time "
                << dgmf::NumberText(steps.back())
                << ", unless the start time has a polyMesh of its own), with its start time's "
                   "fields, and never reaches the other frames (give --times up to "
                << dgmf::NumberText(solverStart) << ", or change startFrom)\n";
    }
  }
  const std::string firstFrame = files ? dgmf_cli::FramePath(options.Output, 0, steps.size()) : "";
  if (files && firstFrame.empty())
  {
    std::cerr << "dgmf-deform: the output's % must be one integer conversion (%d, %04d; at "
                 "most 20 digits) in the file's name, not in a folder: "
              << options.Output << "\n";
    return ExitUsage;
  }
  for (std::size_t k = 0; files && k < steps.size(); ++k)
  {
    // A series started from a frame of an earlier one ("p_0000.vtu" into "p.vtu").
    std::error_code error;
    const std::string frame = dgmf_cli::FramePath(options.Output, k, steps.size());
    if (std::filesystem::equivalent(frame, options.Input, error))
    {
      std::cerr << "dgmf-deform: error: frame " << k << " of the series would overwrite the "
                << "input " << options.Input << ": give the series another name\n";
      return ExitUsage;
    }
  }
  if (files && !options.NoWrite)
  {
    // The series' folder is made if it is new (a series is many files: users give it its own).
    const std::filesystem::path folder = std::filesystem::path(firstFrame).parent_path();
    std::error_code ignored;
    if (!folder.empty())
    {
      std::filesystem::create_directories(folder, ignored);
    }
  }
  std::vector<std::pair<double, std::string>> frames;
  // The .pvd of the frames written so far (a .vtu series: ParaView's .pvd reader reads XML files
  // only; a .vtk series opens as a numbered file group): after each frame, so that a series
  // stopped by a frame or by a signal keeps one of the whole frames before, and at the end.
  const bool collected = files && !options.NoWrite && dgmf_cli::IsVTUFileName(options.Output);
  const std::string collection = collected ? dgmf_cli::CollectionPath(options.Output) : "";
  const auto writeCollection = [&](bool say = true)
  {
    if (!collected || frames.empty())
    {
      return true;
    }
    if (!dgmf_cli::WriteCollection(collection, frames))
    {
      std::cerr << "dgmf-deform: error: could not write " << collection << "\n";
      return false;
    }
    if (say)
    {
      std::cout << "dgmf-deform: wrote the series " << collection << " (" << frames.size()
                << " frames)" << std::endl;
    }
    return true;
  };
  // Distinct directory names (times closer than 6 digits tell apart share one at 6 digits).
  const std::vector<std::string> timeNames = dgmf_cli::OpenFOAMTimeNames(steps);
  for (std::size_t k = 0; k < steps.size(); ++k)
  {
    const double t = steps[k];
    dgmf_cli::SetStage("deforming " + options.Input + " at time " + dgmf::NumberText(t));
    // The frame's line first, then what the frame's run says (each frame's warnings, even those
    // an earlier frame gave word for word). An OpenFOAM series names each frame by its time
    // directory.
    std::cout << "dgmf-deform: time ";
    std::cout << (files ? dgmf::NumberText(t) : timeNames[k]); // exactly; a case: its directory
    std::cout << " (frame " << k + 1 << " of " << steps.size() << ")" << std::endl;
    dgmf_cli::ForgetPrintedMessages();
    std::string why;
    const int verdict = DeformAndJudge(
      filter, options.FailOnInverted, [&]() { filter->UpdateTimeStep(t); }, times, why);
    if (verdict != ExitSuccess)
    {
      std::cerr << "dgmf-deform: " << why << " at time " << dgmf::NumberText(t) << "; "
                << (verdict == ExitInvertedCells
                       ? "this frame was not written (--fail-on-inverted), " +
                         std::to_string(frames.size()) + " earlier frames were written\n"
                       : std::to_string(frames.size()) + " earlier frames were written\n");
      writeCollection();
      return verdict;
    }
    dgmf_cli::CommandOptions frame = options;
    if (files)
    {
      frame.Output = dgmf_cli::FramePath(options.Output, k, steps.size());
    }
    else
    {
      frame.Time = timeNames[k];
      frame.SeriesTimes = timeNames;
    }
    std::string written;
    if (!WriteAndReport(filter, kind, frame, times, written))
    {
      writeCollection();
      return ExitFailure;
    }
    frames.emplace_back(t, frame.Output);
    if (k + 1 < steps.size())
    {
      const bool kept = writeCollection(false);
      dgmf_cli::SetWrittenSoFar(std::to_string(frames.size()) + " frames before it were written" +
        (collected && kept ? " (and " + collection + " of them)" : ""));
    }
  }
  return writeCollection() ? ExitSuccess : ExitFailure;
}
} // namespace

int main(int argc, char* argv[])
{
  dgmf_cli::InstallMessageWindow();
  dgmf_cli::InstallSignalHandlers();
  // --help (or -h) anywhere: the usage on stdout, exit 0 (asked for, not a bad option).
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
    {
      std::cout << dgmf_cli::Usage();
      return ExitSuccess;
    }
  }
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_cli::CommandOptions options;
  const int parsed = dgmf_cli::ParseCommandLine(argc, argv, filter, options);
  if (parsed != ExitSuccess)
  {
    return parsed;
  }
  // VTK's own threaded loops in this program (the ranges of every array the .vtu writer records:
  // 2.4 s of the 3.5 s write of an 8.26M-node mesh on one thread) run on the filter's threads:
  // Debian's ParaView build defaults to the Sequential backend.
  const char* backend = vtkSMPTools::GetBackend();
  if (!backend || std::string(backend) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  vtkSMPTools::Initialize(filter->GetNumberOfThreads());

  // The input: a VTK mesh file (boundaries by marker), or a solver's mesh file or an OpenFOAM
  // case (boundaries by name).
  const std::string& input = options.Input;
  const InputKind kind = dgmf_cli::KindOf(input);
  const std::string inputProblem = dgmf_cli::InputProblem(kind, input);
  if (!inputProblem.empty())
  {
    std::cerr << "dgmf-deform: error: " << inputProblem << "\n";
    return ExitFailure;
  }
  const std::string outputProblem = dgmf_cli::OutputProblem(kind, input, options.Output);
  if (!outputProblem.empty())
  {
    std::cerr << "dgmf-deform: " << outputProblem << "\n";
    return ExitUsage;
  }
  if (!dgmf_cli::OptionsFitTheInput(kind, options, filter))
  {
    return ExitUsage;
  }
  // A single output file's folder must be there (a series makes its own): said before the work,
  // not as a write failure after it.
  const std::filesystem::path outputFolder = std::filesystem::path(options.Output).parent_path();
  std::error_code folderError;
  if (kind != InputKind::OpenFOAMCase && !options.Series && !options.NoWrite &&
    !outputFolder.empty() && !std::filesystem::is_directory(outputFolder, folderError))
  {
    std::cerr << "dgmf-deform: error: the output's folder " << outputFolder.string()
              << (folderError && folderError != std::errc::no_such_file_or_directory
                     ? " cannot be used: " + folderError.message()
                     : " does not exist")
              << "\n";
    return ExitFailure;
  }
  Times times;
  const double readStart = vtkTimerLog::GetUniversalTime();
  vtkSmartPointer<vtkAlgorithm> reader;
  vtkSmartPointer<vtkUnstructuredGrid> mesh;
  if (kind == InputKind::VTKFile)
  {
    mesh = dgmf_cli::ReadMeshFile(input);
    if (dgmf_cli::GetErrorCount() > 0 || !mesh || mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "dgmf-deform: error: could not read a mesh with points from " << input << "\n";
      return ExitFailure;
    }
    filter->SetInputData(mesh);
  }
  else
  {
    reader = kind == InputKind::OpenFOAMCase
      ? dgmf_cli::ReadOpenFOAMCase(input, options.DecomposePolyhedra)
      : dgmf_cli::ReadSolverMeshFile(input);
    if (!reader)
    {
      return ExitFailure;
    }
    const std::vector<std::string> names = kind == InputKind::OpenFOAMCase
      ? std::vector<std::string>{ dgmf_cli::ListPatchNames(input) }
      : dgmf_cli::BoundaryNamesOf(reader->GetOutputDataObject(0));
    if (!options.ByName && !options.MarkerGiven)
    {
      // With their families (a CGNS FamilyName), which name boundaries too.
      std::vector<std::string> labels = names;
      const std::vector<std::string> families = kind == InputKind::OpenFOAMCase
        ? std::vector<std::string>()
        : dgmf_cli::BoundaryFamiliesOf(reader->GetOutputDataObject(0));
      for (std::size_t k = 0; k < labels.size() && k < families.size(); ++k)
      {
        labels[k] = dgmf_vtk::WithFamily(labels[k], families[k]);
      }
      std::cerr << "dgmf-deform: name the moving boundaries with --moving (the file has: "
                << dgmf_cli::Listed(labels) << ")\n";
      return ExitUsage;
    }
    filter->SetInputConnection(reader->GetOutputPort());
    if (kind == InputKind::OpenFOAMCase)
    {
      // A patch group ("wall", "motorBikeGroup") is one boundary of its patches.
      const std::string cyclic = dgmf_cli::CyclicSlipProblem(input, options);
      if (!cyclic.empty())
      {
        std::cerr << "dgmf-deform: error: " << cyclic << "\n";
        return ExitUsage;
      }
      dgmf_cli::GiveOpenFOAMBoundaries(filter, input, options);
      filter->ComputeNonOrthogonalityOn(); // what checkMesh will say
    }
    else if (options.ByName)
    {
      dgmf_cli::KeepWholeNames(options, names, filter);
      dgmf_cli::PrintBoundaries(
        options, names, dgmf_cli::BoundaryFamiliesOf(reader->GetOutputDataObject(0)));
    }
  }
  times.Read = vtkTimerLog::GetUniversalTime() - readStart;
  // Defaults: use the conventional array names when the input has them.
  if (options.MarkerGiven || (mesh && mesh->GetPointData()->GetArray(options.Marker.c_str())))
  {
    filter->SetBoundaryMarkerArrayName(options.Marker.c_str());
  }
  if (options.DisplacementGiven ||
    (mesh && mesh->GetPointData()->GetArray(options.Displacement.c_str())))
  {
    filter->SetDisplacementArrayName(options.Displacement.c_str());
  }
  if (mesh && !dgmf_cli::NodesCanMove(mesh, options))
  {
    return ExitFailure;
  }

  if (!options.Trajectory.empty())
  {
    vtkSmartPointer<vtkTable> table = dgmf_cli::ReadTrajectoryCSV(options.Trajectory);
    if (!table)
    {
      return ExitFailure;
    }
    filter->SetTrajectoryData(table);
  }
  if (options.Series)
  {
    dgmf_cli::ShowProgress(filter, "deforming", options.ProgressDelay);
    return RunSeries(filter, kind, options, times);
  }

  // The deformation: the filter's messages reach stderr through the message window.
  dgmf_cli::SetStage("deforming " + input);
  dgmf_cli::ShowProgress(filter, "deforming", options.ProgressDelay);
  std::string why;
  const int verdict = DeformAndJudge(
    filter, options.FailOnInverted, [&]() { filter->Update(); }, times, why);
  if (verdict != ExitSuccess)
  {
    if (verdict == ExitFailure && kind == InputKind::OpenFOAMCase && options.ByName)
    {
      std::cerr << "dgmf-deform: the case's patches: " << dgmf_cli::ListPatchNames(input) << "\n";
    }
    std::cerr << "dgmf-deform: " << why << "; nothing was written"
              << (verdict == ExitInvertedCells ? " (--fail-on-inverted)" : "") << "\n";
    return verdict;
  }
  std::string written;
  return WriteAndReport(filter, kind, options, times, written) ? ExitSuccess : ExitFailure;
}
