#include "MeshFileCase.h"

#include "FirstAndRepeated.h"

#include "vtkDGMFDeformFilter.h"
#include "vtkSizeSkewQualityFilter.h"

#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace dgmf_bench
{

MeshFileTimes TimeMeshFile(
  const std::string& path, const std::string& marker, int threads, int repeats)
{
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point since)
  { return std::chrono::duration<double>(Clock::now() - since).count(); };
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* mesh = reader->GetOutput();
  // Debian 12's expat can make VTK read a file as empty: count what was read.
  if (mesh->GetNumberOfPoints() == 0 || !mesh->GetPointData()->GetArray(marker.c_str()))
  {
    throw std::runtime_error(path + ": no points, or no point array " + marker);
  }
  MeshFileTimes times;
  times.Nodes = mesh->GetNumberOfPoints();
  times.Cells = mesh->GetNumberOfCells();
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName(marker.c_str());
  filter->SetNumberOfThreads(threads);
  filter->ComputeQualityOff();
  const FirstAndRepeated timed = TimeFirstAndRepeated(filter, repeats);
  times.First = timed.First;
  times.Graph = timed.Graph;
  times.Location = timed.Location;
  times.Mapping = timed.Mapping;
  times.Repeated = timed.Repeated;
  times.Overhead = times.First - times.Graph - times.Location - times.Mapping;
  vtkNew<vtkSizeSkewQualityFilter> quality;
  quality->SetInputData(filter->GetOutput());
  quality->SetReferenceData(mesh);
  quality->SetNumberOfThreads(threads);
  const Clock::time_point start = Clock::now();
  quality->Update();
  times.Quality = seconds(start);
  return times;
}

} // namespace dgmf_bench
