/**
 * dgmf-deform: deforms a mesh file or an OpenFOAM case with vtkDGMFDeformFilter from the command
 * line.
 *
 *   dgmf-deform INPUT OUTPUT.vtu [options]
 *   dgmf-deform CASE_DIR OUT_CASE_DIR --moving NAME[,NAME...] [--static ...] [--slip ...] [options]
 *
 * INPUT is a .vtu (XML) or .vtk (legacy) unstructured grid; the output is written as an XML
 * unstructured grid in inline binary mode. CASE_DIR is an OpenFOAM case (its directory or a .foam
 * file); the deformed points are written into OUT_CASE_DIR (vtkDGMFOpenFOAMWriter: a new
 * directory gets a copy of the case; OUT_CASE_DIR may be CASE_DIR itself). The quality summary
 * is printed on one line. The exit code is 0 on success, 1 on a filter or I/O error, 2 on a usage
 * error.
 */
#include "DGMFCommandData.h"

#include "vtkDGMFDeformFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::string Usage()
{
  std::string usage =
    "usage: dgmf-deform INPUT OUTPUT.vtu [options]\n"
    "       dgmf-deform CASE_DIR OUT_CASE_DIR --moving NAME[,NAME...] [options]\n"
    "  INPUT                   .vtu or .vtk unstructured grid\n"
    "  CASE_DIR                OpenFOAM case (directory or .foam file); OUT_CASE_DIR gets the\n"
    "                          deformed points (a copy of the case if new; may be CASE_DIR)\n"
    "  --moving NAMES          moving boundaries by name (patches), comma-separated: one body "
    "each\n"
    "  --static NAMES          static boundaries by name (unselected patches are static anyway)\n"
    "  --slip NAMES            planar boundaries whose nodes slide in their plane (symmetry)\n"
    "  --time T                OpenFOAM: write T/polyMesh/points (default constant)\n"
    "  --decompose-polyhedra   OpenFOAM: read polyhedra as tetrahedra and pyramids\n"
    "  --one-cell-thick MODE   detect, on or off: a one-cell-thick 2D mesh (default detect)\n"
    "  --rotate AX AY AZ       rotation angles in degrees about x, y, z (2D: AZ)\n"
    "  --center X Y Z          rotation centre (default 0 0 0); --center moving: the centroid\n"
    "                          of each moving boundary\n"
    "  --translate TX TY TZ    rigid translation (default 0 0 0)\n"
    "  --marker NAME           boundary-marker point array (default "
    "BoundaryMarker if present)\n"
    "  --displacement NAME     displacement point array (default Displacement "
    "if present)\n";
  usage +=
    "  --method NAME           " + vtkDGMFDeformFilter::GetMethodKeys(", ") + " (default dgmf)\n";
  usage +=
    "  --mode 1|2              DGMF1 or DGMF2 (default 2)\n"
    "  --damping 1..7          damping function u1..u7 (default 1)\n"
    "  --r0s VALUE             static-boundary r0, >= 1 (default 1)\n"
    "  --sub-steps N           large motions: N sub-steps, 0 = automatic (default 1)\n"
    "  --repair T              quality guard: repair cells with SizeSkew below T (default 0: "
    "off)\n"
    "  --repair-layers N       layers around bad cells whose interior nodes may move "
    "(default 2)\n"
    "  --repair-passes N       most repair passes per step (default 20)\n"
    "  --threads N             number of threads, 0 = all (default 0)\n"
    "  --no-quality            skip the SizeSkew quality metric\n"
    "  --non-orthogonality     report the maximum face non-orthogonality as checkMesh does\n"
    "                          (on for OpenFOAM cases)\n";
  return usage;
}

bool ReadDoubles(int argc, char* argv[], int& i, int count, double* values)
{
  if (i + count >= argc)
  {
    return false;
  }
  for (int k = 0; k < count; ++k)
  {
    char* end = nullptr;
    values[k] = std::strtod(argv[++i], &end);
    if (!end || *end != '\0')
    {
      return false;
    }
  }
  return true;
}

/// The comma-separated names of `list`.
std::vector<std::string> SplitNames(const std::string& list)
{
  std::vector<std::string> names;
  std::stringstream stream(list);
  std::string name;
  while (std::getline(stream, name, ','))
  {
    if (!name.empty())
    {
      names.push_back(name);
    }
  }
  return names;
}

double FieldValue(vtkDataObject* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : 0.0;
}

/// Counts the error events of the filter, so a failure gives a non-zero exit code, and prints
/// their message (an observer of ErrorEvent takes the message from VTK's output window).
void CountError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  ++*static_cast<int*>(clientData);
  if (callData)
  {
    std::cerr << "dgmf-deform: " << static_cast<const char*>(callData) << "\n";
  }
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << Usage();
    return 2;
  }
  const std::string inputPath = argv[1];
  const std::string outputPath = argv[2];
  vtkNew<vtkDGMFDeformFilter> filter;
  std::string marker = "BoundaryMarker";
  std::string displacement = "Displacement";
  bool markerGiven = false;
  bool displacementGiven = false;
  std::string time = "constant";
  bool decomposePolyhedra = false;
  bool byName = false;
  for (int i = 3; i < argc; ++i)
  {
    const std::string option = argv[i];
    double v[3];
    if (option == "--rotate" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationAngles(v);
    }
    else if (option == "--center" && i + 1 < argc && std::strcmp(argv[i + 1], "moving") == 0)
    {
      filter->SetRotationCenterMode(vtkDGMFDeformFilter::BODY_CENTROID);
      ++i;
    }
    else if (option == "--center" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationCenter(v);
    }
    else if ((option == "--moving" || option == "--static" || option == "--slip") && i + 1 < argc)
    {
      for (const std::string& name : SplitNames(argv[++i]))
      {
        option == "--moving"     ? filter->AddMovingBoundary(name.c_str())
          : option == "--static" ? filter->AddStaticBoundary(name.c_str())
                                 : filter->AddSlipBoundary(name.c_str());
        byName = true;
      }
    }
    else if (option == "--time" && i + 1 < argc)
    {
      time = argv[++i];
    }
    else if (option == "--decompose-polyhedra")
    {
      decomposePolyhedra = true;
    }
    else if (option == "--one-cell-thick" && i + 1 < argc &&
      (std::strcmp(argv[i + 1], "detect") == 0 || std::strcmp(argv[i + 1], "on") == 0 ||
        std::strcmp(argv[i + 1], "off") == 0))
    {
      const std::string mode = argv[++i];
      filter->SetOneCellThickMode(mode == "on" ? vtkDGMFDeformFilter::ON
          : mode == "off"                      ? vtkDGMFDeformFilter::OFF
                                               : vtkDGMFDeformFilter::DETECT);
    }
    else if (option == "--translate" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetTranslation(v);
    }
    else if (option == "--method" && i + 1 < argc &&
      vtkDGMFDeformFilter::GetMethodFromName(argv[i + 1]) >= 0)
    {
      filter->SetMethod(vtkDGMFDeformFilter::GetMethodFromName(argv[++i]));
    }
    else if (option == "--mode" && ReadDoubles(argc, argv, i, 1, v) && (v[0] == 1 || v[0] == 2))
    {
      filter->SetDeformationMode(static_cast<int>(v[0]));
    }
    else if (option == "--damping" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 1 && v[0] <= 7)
    {
      filter->SetDampingFunction(static_cast<int>(v[0]));
    }
    else if (option == "--r0s" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 1)
    {
      filter->SetStaticBoundaryR0(v[0]);
    }
    else if (option == "--sub-steps" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 0)
    {
      filter->SetSubSteps(static_cast<int>(v[0]));
    }
    else if (option == "--repair" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 0 && v[0] <= 1)
    {
      filter->SetRepairThreshold(v[0]);
    }
    else if (option == "--repair-layers" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 0)
    {
      filter->SetRepairLayers(static_cast<int>(v[0]));
    }
    else if (option == "--repair-passes" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 0)
    {
      filter->SetRepairPasses(static_cast<int>(v[0]));
    }
    else if (option == "--threads" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 0)
    {
      filter->SetNumberOfThreads(static_cast<int>(v[0]));
    }
    else if (option == "--marker" && i + 1 < argc)
    {
      marker = argv[++i];
      markerGiven = true;
    }
    else if (option == "--displacement" && i + 1 < argc)
    {
      displacement = argv[++i];
      displacementGiven = true;
    }
    else if (option == "--non-orthogonality")
    {
      filter->ComputeNonOrthogonalityOn();
    }
    else if (option == "--no-quality")
    {
      filter->ComputeQualityOff();
    }
    else
    {
      std::cerr << "dgmf-deform: bad option or value: " << option << "\n" << Usage();
      return 2;
    }
  }

  // The input: a mesh file, or an OpenFOAM case read with its patches (selected by name).
  const bool openFOAM = dgmf_cli::IsOpenFOAMCase(inputPath);
  vtkSmartPointer<vtkAlgorithm> caseReader;
  vtkSmartPointer<vtkUnstructuredGrid> mesh;
  if (openFOAM)
  {
    caseReader = dgmf_cli::ReadOpenFOAMCase(inputPath, decomposePolyhedra);
    if (!caseReader)
    {
      return 1;
    }
    if (!byName && !markerGiven)
    {
      std::cerr << "dgmf-deform: name the moving patches with --moving (the case has: "
                << dgmf_cli::ListPatchNames(inputPath) << ")\n";
      return 2;
    }
    filter->SetInputConnection(caseReader->GetOutputPort());
    filter->ComputeNonOrthogonalityOn(); // what checkMesh will say
  }
  else
  {
    mesh = dgmf_cli::ReadMeshFile(inputPath);
    if (!mesh || mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "dgmf-deform: could not read a mesh with points from " << inputPath << "\n";
      return 1;
    }
    filter->SetInputData(mesh);
  }
  // Defaults: use the conventional array names when the input has them.
  if (markerGiven || (mesh && mesh->GetPointData()->GetArray(marker.c_str())))
  {
    filter->SetBoundaryMarkerArrayName(marker.c_str());
  }
  if (displacementGiven || (mesh && mesh->GetPointData()->GetArray(displacement.c_str())))
  {
    filter->SetDisplacementArrayName(displacement.c_str());
  }

  int errors = 0;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(CountError);
  onError->SetClientData(&errors);
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  filter->Update();
  timer->StopTimer();
  vtkDataObject* deformed = filter->GetOutputDataObject(0);
  if (errors > 0 || deformed->GetNumberOfElements(vtkDataObject::POINT) == 0)
  {
    if (openFOAM && byName)
    {
      std::cerr << "dgmf-deform: the case's patches: " << dgmf_cli::ListPatchNames(inputPath)
                << "\n";
    }
    std::cerr << "dgmf-deform: the deformation failed (see the error above)\n";
    return 1;
  }

  std::string written = outputPath;
  if (openFOAM)
  {
    written = dgmf_cli::WriteOpenFOAMPoints(filter, outputPath, time);
    if (written.empty())
    {
      std::cerr << "dgmf-deform: could not write the points into " << outputPath << "\n";
      return 1;
    }
  }
  else if (!dgmf_cli::WriteMeshFile(filter->GetOutput(), outputPath))
  {
    std::cerr << "dgmf-deform: could not write " << outputPath << "\n";
    return 1;
  }

  std::cout << "dgmf-deform: " << deformed->GetNumberOfElements(vtkDataObject::POINT) << " points, "
            << deformed->GetNumberOfElements(vtkDataObject::CELL) << " cells, "
            << timer->GetElapsedTime() << " s";
  if (filter->GetComputeQuality())
  {
    std::cout << "; SizeSkew mean " << FieldValue(deformed, "SizeSkewMean") << ", minimum "
              << FieldValue(deformed, "SizeSkewMinimum") << ", inverted cells "
              << static_cast<long long>(FieldValue(deformed, "InvertedCellCount"))
              << " (invalid in the input: "
              << static_cast<long long>(FieldValue(deformed, "InputInvalidCellCount")) << ")";
  }
  if (filter->GetComputeNonOrthogonality())
  {
    std::cout << "; non-orthogonality max " << FieldValue(deformed, "MaximumNonOrthogonality")
              << " (input " << FieldValue(deformed, "InputMaximumNonOrthogonality") << ")";
  }
  if (filter->GetSubSteps() != 1 || filter->GetRepairThreshold() > 0)
  {
    std::cout << "; sub-steps " << static_cast<long long>(FieldValue(deformed, "SubStepsUsed"))
              << ", cells repaired "
              << static_cast<long long>(FieldValue(deformed, "RepairedCellCount"))
              << ", left unrepaired "
              << static_cast<long long>(FieldValue(deformed, "UnrepairedCellCount"));
  }
  std::cout << "; wrote " << written << std::endl;
  return 0;
}
