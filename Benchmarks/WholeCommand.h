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
 * Writes `mesh` to `directory`/mesh.vtu (appended raw, LZ4: a compressed input, read on both
 * threads; not timed), then runs `command` (dgmf-deform) on it `repeats` times with the benchmark's
 * motion and `threads` threads, writing `directory`/deformed.vtu, and returns the times of the run
 * whose wall time is the median. Throws std::runtime_error when the command fails or prints no
 * timings.
 *
 * One run alone is not representative on a virtual machine: the first command after the
 * benchmark has freed gigabytes took twice as long on this project's VM (its page faults, 5.4
 * s of system time against 2.2 s in the next run), the host providing the freed memory again.
 */
CommandTimes TimeWholeCommand(vtkUnstructuredGrid* mesh, const std::string& command,
  const std::string& directory, int threads, int repeats);

} // namespace dgmf_bench

#endif
