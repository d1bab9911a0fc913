/**
 * @file WholeCommand.h
 * @brief The benchmark's whole-command figure: dgmf-deform on a .vtu of the benchmark mesh, its
 * wall time beside the filter's (issue 18).
 */
#ifndef dgmf_bench_WholeCommand_h
#define dgmf_bench_WholeCommand_h

#include <string>

class vtkUnstructuredGrid;

namespace dgmf_bench
{

/// What one run of the command took.
struct CommandTimes
{
  double Wall = 0.0;   ///< the whole command, as the user waits for it
  double Read = 0.0;   ///< as the command reports them
  double Filter = 0.0; ///< deformation and quality
  double Write = 0.0;
};

/**
 * Writes `mesh` to `directory`/mesh.vtu (appended raw, LZ4: the command's own default; not
 * timed), then runs `command` (dgmf-deform) on it with the benchmark's motion and `threads`
 * threads, writing `directory`/deformed.vtu, and returns its times. Throws std::runtime_error when
 * the command fails or prints no timings.
 */
CommandTimes TimeWholeCommand(
  vtkUnstructuredGrid* mesh, const std::string& command, const std::string& directory, int threads);

} // namespace dgmf_bench

#endif
