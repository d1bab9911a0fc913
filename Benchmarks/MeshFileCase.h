/**
 * @file MeshFileCase.h
 * @brief The benchmark on a mesh file of the user's (issue 18: the wing-body mesh of
 * Reproduction/): the first run's phases, a repeated run and the quality.
 */
#ifndef dgmf_bench_MeshFileCase_h
#define dgmf_bench_MeshFileCase_h

#include <string>

namespace dgmf_bench
{

/// One configuration's times (medians over the repeats).
struct MeshFileTimes
{
  long long Nodes = 0, Cells = 0;
  double First = 0.0;    ///< a fresh filter's Update: everything below
  double Graph = 0.0;    ///< the Delaunay graph of the boundary nodes
  double Location = 0.0; ///< every node located in it
  double Mapping = 0.0;  ///< the method's pass over the nodes
  double Overhead = 0.0; ///< First minus the three: gathering, checks, outputs (VTK)
  double Repeated = 0.0; ///< a new motion, the graph kept
  double Quality = 0.0;  ///< the SizeSkew quality filter alone on the output
};

/**
 * Reads `path` (.vtu with the point array `marker`) and times DGMF on it with `threads` threads:
 * a fresh filter rotating the moving boundary by (5, 10, 15) degrees, quality off, `repeats` times.
 * Throws std::runtime_error when the file has no points or no such array.
 */
MeshFileTimes TimeMeshFile(
  const std::string& path, const std::string& marker, int threads, int repeats);

} // namespace dgmf_bench

#endif
