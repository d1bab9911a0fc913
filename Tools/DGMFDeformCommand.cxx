/**
 * dgmf-deform: deforms a mesh file with vtkDGMFDeformFilter from the command line.
 *
 *   dgmf-deform INPUT OUTPUT.vtu [options]
 *
 * INPUT is a .vtu (XML) or .vtk (legacy) unstructured grid. The output is written as an XML
 * unstructured grid in inline binary mode. The quality summary is printed on one line. The exit
 * code is 0 on success, 1 on a filter or I/O error, 2 on a usage error.
 */
#include "vtkDGMFDeformFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
std::string Usage()
{
  std::string usage =
    "usage: dgmf-deform INPUT OUTPUT.vtu [options]\n"
    "  INPUT                   .vtu or .vtk unstructured grid\n"
    "  --rotate AX AY AZ       rotation angles in degrees about x, y, z (2D: AZ)\n"
    "  --center X Y Z          rotation centre (default 0 0 0)\n"
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
    "  --no-quality            skip the SizeSkew quality metric\n";
  return usage;
}

bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
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

vtkSmartPointer<vtkUnstructuredGrid> ReadMesh(const std::string& path)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh;
  if (EndsWith(path, ".vtk"))
  {
    vtkNew<vtkUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllFieldsOn();
    reader->Update();
    mesh = reader->GetOutput();
  }
  else
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  return mesh;
}

double FieldValue(vtkUnstructuredGrid* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : 0.0;
}

/// Counts the error events of the filter, so a failure gives a non-zero exit code.
void CountError(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<int*>(clientData);
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
  for (int i = 3; i < argc; ++i)
  {
    const std::string option = argv[i];
    double v[3];
    if (option == "--rotate" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationAngles(v);
    }
    else if (option == "--center" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationCenter(v);
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

  vtkSmartPointer<vtkUnstructuredGrid> mesh = ReadMesh(inputPath);
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    std::cerr << "dgmf-deform: could not read a mesh with points from " << inputPath << "\n";
    return 1;
  }
  // Defaults: use the conventional array names when the input has them.
  if (markerGiven || mesh->GetPointData()->GetArray(marker.c_str()))
  {
    filter->SetBoundaryMarkerArrayName(marker.c_str());
  }
  if (displacementGiven || mesh->GetPointData()->GetArray(displacement.c_str()))
  {
    filter->SetDisplacementArrayName(displacement.c_str());
  }

  int errors = 0;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(CountError);
  onError->SetClientData(&errors);
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  filter->SetInputData(mesh);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  filter->Update();
  timer->StopTimer();
  vtkUnstructuredGrid* deformed = filter->GetOutput();
  if (errors > 0 || deformed->GetNumberOfPoints() == 0)
  {
    std::cerr << "dgmf-deform: the deformation failed (see the error above)\n";
    return 1;
  }

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(outputPath.c_str());
  writer->SetInputData(deformed);
  writer->SetDataModeToBinary(); // inline binary: appended mode breaks with Debian 12's expat
  if (!writer->Write())
  {
    std::cerr << "dgmf-deform: could not write " << outputPath << "\n";
    return 1;
  }

  std::cout << "dgmf-deform: " << deformed->GetNumberOfPoints() << " points, "
            << deformed->GetNumberOfCells() << " cells, " << timer->GetElapsedTime() << " s";
  if (filter->GetComputeQuality())
  {
    std::cout << "; SizeSkew mean " << FieldValue(deformed, "SizeSkewMean") << ", minimum "
              << FieldValue(deformed, "SizeSkewMinimum") << ", inverted cells "
              << static_cast<long long>(FieldValue(deformed, "InvertedCellCount"));
  }
  if (filter->GetSubSteps() != 1 || filter->GetRepairThreshold() > 0)
  {
    std::cout << "; sub-steps " << static_cast<long long>(FieldValue(deformed, "SubStepsUsed"))
              << ", cells repaired "
              << static_cast<long long>(FieldValue(deformed, "RepairedCellCount"))
              << ", left unrepaired "
              << static_cast<long long>(FieldValue(deformed, "UnrepairedCellCount"));
  }
  std::cout << "; wrote " << outputPath << std::endl;
  return 0;
}
