/**
 * @file DGMFCommandChecks.h
 * @brief dgmf-deform's checks before the work: what the input is, whether the output can be
 * written from it, options that would be ignored, and a mesh whose nodes could not move.
 */
#ifndef DGMFCommandChecks_h
#define DGMFCommandChecks_h

#include "DGMFCommandOptions.h"

#include <string>

class vtkDGMFDeformFilter;
class vtkUnstructuredGrid;

namespace dgmf_cli
{
/// What the input is.
enum class InputKind
{
  VTKFile,      ///< .vtu or .vtk, boundaries by marker array
  SolverFile,   ///< .msh, .su2, .exo/.e/.ex2 or .cgns, boundaries by name
  OpenFOAMCase, ///< a case directory, its controlDict or a .foam file, patches by name
};

/// The kind of `input` (by its name, or its being a case directory).
InputKind KindOf(const std::string& input);

/**
 * Why `input` cannot be read, said before anything else ("" when it may be): it does not exist; it
 * is a directory but no OpenFOAM case (no system/controlDict); it is a case without a mesh (no
 * constant/polyMesh: blockMesh not run, or a decomposed case whose processor* directories alone
 * hold the mesh). These were told as "the output must end in .vtu" or "controlDict contains no
 * meshes" until 2026-11-30.
 */
std::string InputProblem(InputKind kind, const std::string& input);

/// Why `output` cannot be written from `input` ("" when it can): .vtu and .vtk always; the
/// solver's file back in its own format; an OpenFOAM case back into a case, but not into a new
/// directory inside it (it would be copied into itself).
std::string OutputProblem(InputKind kind, const std::string& input, const std::string& output);

/**
 * Options that would be ignored for this input or output: an error for --time outside an
 * OpenFOAM case (false), a warning for the others (they were all ignored without a word until
 * 2026-11-30).
 */
bool OptionsFitTheInput(InputKind kind, const CommandOptions& options, vtkDGMFDeformFilter* filter);

/**
 * For a mesh without a boundary-marker array: says that its boundary is found from its faces,
 * moving where the displacement array is not zero; false (an error printed) when that array is
 * missing or zero everywhere, so that no node would move whatever the motion asked for (such a
 * run wrote the input's points, exit 0, until 2026-11-30).
 */
bool NodesCanMove(vtkUnstructuredGrid* mesh, const CommandOptions& options);

} // namespace dgmf_cli

#endif
