/**
 * @file PeriodicMotion.h
 * @brief The benchmark's frames per second of a periodic motion (issue 19): a pitching body
 * played frame after frame, the graph built once.
 */
#ifndef dgmf_bench_PeriodicMotion_h
#define dgmf_bench_PeriodicMotion_h

class vtkUnstructuredGrid;

namespace dgmf_bench
{

/// What the frames of one period took.
struct FrameRate
{
  double FirstFrame = 0.0;           ///< the first frame: graph, location and mapping
  double Graph = 0.0;                ///< of which the graph
  double OtherFrames = 0.0;          ///< the other frames together
  double FramesPerSecond = 0.0;      ///< of the other frames (the graph reused)
  double CycleFramesPerSecond = 0.0; ///< of the whole period, the first frame included
};

/**
 * Plays one period of a harmonic pitch (15 degrees of amplitude about the y axis through the
 * origin) on `mesh` (with its BoundaryMarker) in `frames` frames, through vtkDGMFDeformFilter's
 * RotationLaw and UpdateTimeStep, quality off, on `threads` threads.
 */
FrameRate TimePeriodicMotion(vtkUnstructuredGrid* mesh, int threads, int frames);

} // namespace dgmf_bench

#endif
