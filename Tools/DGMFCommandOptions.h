/**
 * @file DGMFCommandOptions.h
 * @brief The command line of dgmf-deform: its usage text, and its options read into the filter
 * and into what the program itself needs.
 */
#ifndef DGMFCommandOptions_h
#define DGMFCommandOptions_h

#include <string>
#include <utility>
#include <vector>

class vtkDGMFDeformFilter;

namespace dgmf_cli
{
/// The exit codes of dgmf-deform (Documentation/robustness.md).
enum ExitCode
{
  ExitSuccess = 0,      ///< deformed and written
  ExitFailure = 1,      ///< the input could not be read, deformed or the output written
  ExitUsage = 2,        ///< a bad option or value
  ExitInvertedCells = 3 ///< --fail-on-inverted and the deformation inverts cells: nothing written
};

/// What the program does beyond the filter's properties.
struct CommandOptions
{
  std::string Input;
  std::string Output;
  std::string Marker = "BoundaryMarker";
  std::string Displacement = "Displacement";
  bool MarkerGiven = false;
  bool DisplacementGiven = false;
  bool BodyIdGiven = false;      ///< --body-id NAME
  std::string Time = "constant"; ///< OpenFOAM: the time directory written
  bool DecomposePolyhedra = false;
  bool ByName = false; ///< boundaries chosen by name (--moving, --static, --slip)
  std::vector<std::string> Moving, Static, Slip; ///< the names given
  /// The values of --moving, --static and --slip as given ('m', 's', 'l'), before the split at
  /// commas (KeepWholeNames)
  std::vector<std::pair<char, std::string>> NameValues;
  bool FailOnInverted = false; ///< exit 3, writing nothing, when cells are inverted
  double ProgressDelay = 2.0;  ///< seconds before the progress is shown (--progress: 0)
  bool NoWrite = false;        ///< --no-write: read and deform only (the timings show)
  bool VTUAppended = true;     ///< --vtu-mode appended (default) or binary
  std::string Compression;     ///< --compression (empty: VTUEncoding's default)
  std::string Trajectory;      ///< --trajectory: a CSV table of body motions in time
  std::vector<double> Times;   ///< --times START:END:COUNT (empty: the filter's own)
  bool Series = false;         ///< the motion depends on time: one output per time (a series)
  /// OpenFOAM: the time directories of the series a write is a frame of (empty: one time)
  std::vector<std::string> SeriesTimes;
};

/// The usage text.
std::string Usage();

/**
 * A value of --moving, --static or --slip, or a run of its comma-separated parts, that is one of
 * the file's boundary names (`fileNames`: a gmsh group "Flap, inner", also in "farfield,Flap,
 * inner") is that name, not parts split at its commas: the options' lists and the filter's
 * boundaries are made again so.
 */
void KeepWholeNames(
  CommandOptions& options, const std::vector<std::string>& fileNames, vtkDGMFDeformFilter* filter);

/**
 * Reads the command line into `filter`'s properties and `options`. Returns ExitSuccess, or
 * ExitUsage after printing what is wrong and the usage. Integers must be integers ("1.5" is
 * refused), numbers must be finite and in their range.
 */
int ParseCommandLine(int argc, char* argv[], vtkDGMFDeformFilter* filter, CommandOptions& options);
} // namespace dgmf_cli

#endif
