/**
 * @file DGMFCommandBoundaries.h
 * @brief dgmf-deform's boundaries chosen by name: what it gives the filter for an OpenFOAM case
 * (patch groups as the alternatives of their patches) and what it says it took from a mesh file.
 */
#ifndef DGMFCommandBoundaries_h
#define DGMFCommandBoundaries_h

#include "DGMFCommandOptions.h"

#include <string>
#include <vector>

class vtkDGMFDeformFilter;

namespace dgmf_cli
{
/// "a, b, c", or "(none)".
std::string Listed(const std::vector<std::string>& names);

/**
 * Says which boundaries the run uses: the names given, and every other boundary of the file
 * (`fileNames`), which stays static, as the filter reads the names (wildcards, alternatives,
 * selectors, region prefixes, the families `families` of the boundaries in fileNames' order, ""
 * for none). The file's names win over any detection of the mesh boundary. Nothing is printed
 * when a name reaches no boundary (the filter's error says so).
 */
void PrintBoundaries(const CommandOptions& options, const std::vector<std::string>& fileNames,
  const std::vector<std::string>& families);

/**
 * Gives `filter` the boundaries of `options` for the OpenFOAM case `input`: a patch group
 * ("wall", "motorBikeGroup") is the alternatives of its patches, one boundary (a slip group whose
 * patches are not one plane, as "wedge", is a plane per patch: FitSlipPlanes), and messages name
 * a group of several patches as the user did.
 */
/**
 * Why the slip boundaries of `options` cannot be used on the OpenFOAM case `input`, or "": a
 * cyclic patch (cyclic, cyclicAMI, cyclicACMI, cyclicSlip) named as slip, alone or through a
 * group. A slip plane's nodes slide within it apart from any other plane's, so the two planes of
 * a cyclic pair would no longer match (checkMesh: "face area does not match neighbour").
 */
std::string CyclicSlipProblem(const std::string& input, const CommandOptions& options);

void GiveOpenFOAMBoundaries(
  vtkDGMFDeformFilter* filter, const std::string& input, const CommandOptions& options);
} // namespace dgmf_cli

#endif
