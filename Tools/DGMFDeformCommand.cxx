/**
 * dgmf-deform: deforms a mesh file or an OpenFOAM case with vtkDGMFDeformFilter from the command
 * line.
 *
 *   dgmf-deform INPUT OUTPUT.vtu [options]
 *   dgmf-deform CASE_DIR OUT_CASE_DIR --moving NAME[,NAME...] [--static ...] [--slip ...] [options]
 *
 * INPUT is a .vtu (XML) or .vtk (legacy) unstructured grid; the output is written as an XML
 * unstructured grid in inline binary mode (.vtu) or a binary legacy file (.vtk), under a
 * temporary name renamed into place. CASE_DIR is an OpenFOAM case (its directory or a .foam
 * file); the deformed points are written into OUT_CASE_DIR (vtkDGMFOpenFOAMWriter: a new
 * directory gets a copy of the case; OUT_CASE_DIR may be CASE_DIR itself). The quality summary
 * is printed on one line. Exit codes: DGMFCommandOptions.h (ExitCode). Messages:
 * DGMFCommandMessages.h.
 */
#include "DGMFCommandData.h"
#include "DGMFCommandMessages.h"
#include "DGMFCommandOptions.h"

#include "vtkDGMFDeformFilter.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using dgmf_cli::ExitFailure;
using dgmf_cli::ExitInvertedCells;
using dgmf_cli::ExitSuccess;
using dgmf_cli::ExitUsage;

double FieldValue(vtkDataObject* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : 0.0;
}

long long CountValue(vtkDataObject* mesh, const char* name)
{
  return static_cast<long long>(FieldValue(mesh, name));
}

/// The one-line summary: size, time, quality, non-orthogonality, sub-steps.
void PrintSummary(vtkDGMFDeformFilter* filter, double seconds, const std::string& written)
{
  vtkDataObject* deformed = filter->GetOutputDataObject(0);
  std::cout << "dgmf-deform: " << deformed->GetNumberOfElements(vtkDataObject::POINT) << " points, "
            << deformed->GetNumberOfElements(vtkDataObject::CELL) << " cells, " << seconds << " s";
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
  if (filter->GetSubSteps() != 1 || filter->GetRepairThreshold() > 0)
  {
    std::cout << "; sub-steps " << CountValue(deformed, "SubStepsUsed") << ", cells repaired "
              << CountValue(deformed, "RepairedCellCount") << ", left unrepaired "
              << CountValue(deformed, "UnrepairedCellCount");
  }
  std::cout << "; wrote " << written << std::endl;
}
} // namespace

int main(int argc, char* argv[])
{
  dgmf_cli::InstallMessageWindow();
  dgmf_cli::InstallSignalHandlers();
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_cli::CommandOptions options;
  const int parsed = dgmf_cli::ParseCommandLine(argc, argv, filter, options);
  if (parsed != ExitSuccess)
  {
    return parsed;
  }

  // The input: a mesh file, or an OpenFOAM case read with its patches (selected by name).
  const std::string& input = options.Input;
  const bool openFOAM = dgmf_cli::IsOpenFOAMCase(input);
  if (!openFOAM && !dgmf_cli::IsMeshFileName(options.Output))
  {
    std::cerr << "dgmf-deform: the output must end in .vtu (XML) or .vtk (legacy VTK): "
              << options.Output << "\n";
    return ExitUsage;
  }
  vtkSmartPointer<vtkAlgorithm> caseReader;
  vtkSmartPointer<vtkUnstructuredGrid> mesh;
  if (openFOAM)
  {
    caseReader = dgmf_cli::ReadOpenFOAMCase(input, options.DecomposePolyhedra);
    if (!caseReader)
    {
      return ExitFailure;
    }
    if (!options.ByName && !options.MarkerGiven)
    {
      std::cerr << "dgmf-deform: name the moving patches with --moving (the case has: "
                << dgmf_cli::ListPatchNames(input) << ")\n";
      return ExitUsage;
    }
    filter->SetInputConnection(caseReader->GetOutputPort());
    filter->ComputeNonOrthogonalityOn(); // what checkMesh will say
  }
  else
  {
    mesh = dgmf_cli::ReadMeshFile(input);
    if (dgmf_cli::GetErrorCount() > 0 || !mesh || mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "dgmf-deform: error: could not read a mesh with points from " << input << "\n";
      return ExitFailure;
    }
    filter->SetInputData(mesh);
  }
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

  // The deformation: the filter's messages reach stderr through the message window.
  dgmf_cli::ResetErrorCount();
  dgmf_cli::SetStage("deforming " + input);
  dgmf_cli::ShowProgress(filter, "deforming", options.ProgressDelay);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  filter->Update();
  timer->StopTimer();
  vtkDataObject* deformed = filter->GetOutputDataObject(0);
  if (dgmf_cli::GetErrorCount() > 0 || deformed->GetNumberOfElements(vtkDataObject::POINT) == 0)
  {
    if (openFOAM && options.ByName)
    {
      std::cerr << "dgmf-deform: the case's patches: " << dgmf_cli::ListPatchNames(input) << "\n";
    }
    std::cerr << "dgmf-deform: the deformation failed; nothing was written\n";
    return ExitFailure;
  }
  const long long inverted = CountValue(deformed, "InvertedCellCount");
  if (options.FailOnInverted && inverted > 0)
  {
    std::cerr << "dgmf-deform: the deformation inverts " << inverted
              << " cells; nothing was written (--fail-on-inverted)\n";
    return ExitInvertedCells;
  }

  std::string written = options.Output;
  if (openFOAM)
  {
    dgmf_cli::SetStage("writing into " + options.Output);
    written = dgmf_cli::WriteOpenFOAMPoints(filter, options.Output, options.Time);
    if (written.empty())
    {
      std::cerr << "dgmf-deform: error: could not write the points into " << options.Output << "\n";
      return ExitFailure;
    }
  }
  else if (!dgmf_cli::WriteMeshFile(filter->GetOutput(), options.Output))
  {
    std::cerr << "dgmf-deform: error: could not write " << options.Output
              << " (any file already there is unchanged)\n";
    return ExitFailure;
  }
  PrintSummary(filter, timer->GetElapsedTime(), written);
  return ExitSuccess;
}
