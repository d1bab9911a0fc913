#include "FirstAndRepeated.h"

#include "vtkDGMFDeformFilter.h"

#include <algorithm>
#include <chrono>

namespace dgmf_bench
{

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

FirstAndRepeated TimeFirstAndRepeated(vtkDGMFDeformFilter* filter, int repeats)
{
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point since)
  { return std::chrono::duration<double>(Clock::now() - since).count(); };
  std::vector<double> first, graph, location, mapping, repeated;
  FirstAndRepeated result;
  for (int r = 0; r < std::max(repeats, 1); ++r)
  {
    filter->ReleaseCache();
    filter->SetRotationAngles(5.0, 10.0, 15.0 + r);
    Clock::time_point start = Clock::now();
    filter->Update();
    first.push_back(seconds(start));
    graph.push_back(filter->GetLastGraphSeconds());
    location.push_back(filter->GetLastLocationSeconds());
    mapping.push_back(filter->GetLastDeformationSeconds());
    // A new motion: only the mapping runs again.
    filter->SetRotationAngles(5.0, 10.0, 20.0 + r);
    start = Clock::now();
    filter->Update();
    repeated.push_back(seconds(start));
    result.GraphAlwaysReused = result.GraphAlwaysReused && filter->GetLastExecutionReusedGraph();
  }
  result.First = Median(first);
  result.Graph = Median(graph);
  result.Location = Median(location);
  result.Mapping = Median(mapping);
  result.Repeated = Median(repeated);
  return result;
}

} // namespace dgmf_bench
