#include "PeriodicMotion.h"

#include "vtkDGMFDeformFilter.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>

namespace dgmf_bench
{

FrameRate TimePeriodicMotion(vtkUnstructuredGrid* mesh, int threads, int frames)
{
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point since)
  { return std::chrono::duration<double>(Clock::now() - since).count(); };
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetNumberOfThreads(threads);
  filter->ComputeQualityOff();
  filter->SetRotationAxis(0.0, 1.0, 0.0);
  filter->SetRotationLaw(vtkDGMFDeformFilter::HARMONIC);
  filter->SetRotationLawParameters(0.0, 15.0, 1.0, 0.0);
  filter->SetTimeRange(0.0, 1.0);
  filter->SetNumberOfTimeSteps(frames);
  FrameRate rate;
  Clock::time_point start = Clock::now();
  filter->UpdateTimeStep(0.0);
  rate.FirstFrame = seconds(start);
  rate.Graph = filter->GetLastGraphSeconds();
  start = Clock::now();
  for (int k = 1; k < frames; ++k)
  {
    filter->UpdateTimeStep(static_cast<double>(k) / (frames - 1));
  }
  rate.OtherFrames = seconds(start);
  rate.FramesPerSecond = (frames - 1) / rate.OtherFrames;
  rate.CycleFramesPerSecond = frames / (rate.FirstFrame + rate.OtherFrames);
  return rate;
}

} // namespace dgmf_bench
