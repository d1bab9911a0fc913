/**
 * @file CaseDirectory.h
 * @brief An OpenFOAM case on disk: where its mesh's points are, a new case made from it, and
 * deformed points written into it (VTK-free; namespace dgmf::openfoam).
 */
#ifndef dgmf_openfoam_CaseDirectory_h
#define dgmf_openfoam_CaseDirectory_h

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace dgmf
{
namespace openfoam
{

/// True when `directory` holds an OpenFOAM case (a `system/controlDict` file).
bool IsCase(const std::filesystem::path& directory);

/**
 * `directory` itself, or the directory of a file inside a case: a `.foam` or `.OpenFOAM` file
 * (what ParaView opens), or `system/controlDict`.
 */
std::filesystem::path CaseDirectoryOf(const std::filesystem::path& path);

/// True when `path` lies strictly inside `directory` (both made absolute, with the symbolic links
/// of their existing parts resolved); false when either cannot be resolved.
bool IsInside(const std::filesystem::path& directory, const std::filesystem::path& path);

/// The value of an OpenFOAM time name ("0", "0.05", "2e-4") in `value`; false for other names
/// ("constant", "processor0", "inf", " 1").
bool TimeValue(const std::string& name, double& value);

/// True for "constant" and for an OpenFOAM time name (a number such as "0", "1", "0.05").
bool IsTimeName(const std::string& time);

/// The earliest time of the case's time directories, in `first`; false when it has none.
bool FirstTimeOf(const std::filesystem::path& caseDirectory, double& first);

/**
 * The time a solver run of the case starts from once the times `written` are in it, by its
 * controlDict's startFrom: startTime (its startTime), firstTime or latestTime (of the time
 * directories and `written`). With `copied`, the case is the source of a new case (CopyCase),
 * which gets its first time directory only. False when the controlDict cannot be read or says
 * something else.
 */
bool SolverStartTime(const std::filesystem::path& caseDirectory, const std::vector<double>& written,
  bool copied, double& start);

/// `caseDirectory`/constant/polyMesh for "constant", else `caseDirectory`/`time`/polyMesh.
std::filesystem::path PolyMeshDirectory(
  const std::filesystem::path& caseDirectory, const std::string& time);

/// A patch of a case's boundary file: its name, its type and the groups it is in (`inGroups`).
struct PatchEntry
{
  std::string Name;
  std::vector<std::string> Groups;
  std::string Type; ///< "wall", "cyclic", "empty", ...; "" when the entry has none
};

/// The patches in `caseDirectory`/constant/polyMesh/boundary, in order.
std::vector<PatchEntry> ReadPatches(const std::filesystem::path& caseDirectory);

/// The names of the patches in `caseDirectory`/constant/polyMesh/boundary, in order.
std::vector<std::string> ReadPatchNames(const std::filesystem::path& caseDirectory);

/// Why `target` cannot take a copy of the case `source` (CopyCase): it lies inside `source`, or
/// it holds files already; "" when it can.
std::string CopyTargetProblem(
  const std::filesystem::path& source, const std::filesystem::path& target);

/**
 * Copies the case `source` into `target` (created; it must not hold anything yet): every file and
 * directory of the case except the time directories after the first one (the fields to start
 * from are kept), `processor*` directories and `postProcessing`. Throws std::runtime_error, before
 * anything is copied, when `target` cannot take the copy (CopyTargetProblem).
 */
void CopyCase(const std::filesystem::path& source, const std::filesystem::path& target);

/**
 * Writes deformed points into an OpenFOAM case.
 *
 * The case's own points P (`source`/constant/polyMesh) are read in double precision, and the
 * deformation is added to them: P + (deformed - reference), where `reference` are the undeformed
 * points the deformation started from (VTK's OpenFOAM reader gives them rounded to single
 * precision). Points that did not move are written exactly as they were, and the rounding of the
 * reader does not reach the case. Only the first P.size() points of `reference` and `deformed`
 * are used (the reader appends one point per polyhedron when it decomposes polyhedra).
 *
 * `target` is `source` itself (the case is then modified on purpose), an existing case made from
 * it, or a new or empty directory, which gets a copy of `source` (CopyCase). The points go into
 * `target`/`time`/polyMesh ("constant", or a time name: OpenFOAM then takes the faces from
 * constant), in the format of the case's points file (ascii or binary, compressed or not).
 *
 * Throws std::runtime_error when the counts differ, when `reference` is not the case's points
 * (another case, or another time), when a deformed point is not finite, or when a file cannot be
 * read or written; nothing is written then. Returns the file written. `replaced`, when given, is
 * set to whether a time directory's points were there before (in `target`, or in the copy of
 * `source` just made: a mesh a solver moved), which the new ones replace; false for "constant".
 */
std::filesystem::path WriteDeformedPoints(const std::filesystem::path& source,
  const std::filesystem::path& target, const std::string& time, const double* reference,
  const double* deformed, std::size_t numberOfPoints, bool* replaced = nullptr);

} // namespace openfoam
} // namespace dgmf

#endif
