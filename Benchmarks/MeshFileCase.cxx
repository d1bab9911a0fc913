#include "MeshFileCase.h"

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
namespace
{
double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}
} // namespace

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
  std::vector<double> first, graph, location, mapping, repeated;
  vtkNew<vtkDGMFDeformFilter> filter;
  for (int r = 0; r < std::max(repeats, 1); ++r)
  {
    filter->ReleaseCache();
    filter->SetInputData(mesh);
    filter->SetBoundaryMarkerArrayName(marker.c_str());
    filter->SetNumberOfThreads(threads);
    filter->ComputeQualityOff();
    filter->SetRotationAngles(5.0, 10.0, 15.0 + r);
    Clock::time_point start = Clock::now();
    filter->Update();
    first.push_back(seconds(start));
    graph.push_back(filter->GetLastGraphSeconds());
    location.push_back(filter->GetLastLocationSeconds());
    mapping.push_back(filter->GetLastDeformationSeconds());
    filter->SetRotationAngles(5.0, 10.0, 20.0 + r);
    start = Clock::now();
    filter->Update();
    repeated.push_back(seconds(start));
  }
  times.First = Median(first);
  times.Graph = Median(graph);
  times.Location = Median(location);
  times.Mapping = Median(mapping);
  times.Overhead = times.First - times.Graph - times.Location - times.Mapping;
  times.Repeated = Median(repeated);
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
