/**
 * @file PointsFile.h
 * @brief An OpenFOAM `polyMesh/points` file, read and written in any of the forms OpenFOAM writes:
 * ascii or binary, compressed (`points.gz`) or not (VTK-free; namespace dgmf::openfoam).
 */
#ifndef dgmf_openfoam_PointsFile_h
#define dgmf_openfoam_PointsFile_h

#include <filesystem>
#include <string>
#include <vector>

namespace dgmf
{
namespace openfoam
{

/// How the body of an OpenFOAM file is written (the header's `format` entry).
enum class Format
{
  Ascii,
  Binary
};

/**
 * The contents of a points file: the coordinates as doubles, and what is needed to write new
 * coordinates in the same form (the text before and after the list, the format, compression).
 */
struct PointsFile
{
  std::vector<double> Points; ///< x, y, z of each point, in OpenFOAM's order
  Format BodyFormat = Format::Ascii;
  bool Compressed = false; ///< read from (and written as) points.gz
  std::string Preamble;    ///< the banner, the FoamFile header and comments before the count
  std::string Epilogue;    ///< what follows the list's closing parenthesis

  std::size_t NumberOfPoints() const { return this->Points.size() / 3; }
};

/**
 * The points file of the polyMesh directory `polyMesh`: `points` if it exists (OpenFOAM reads it
 * before `points.gz`), else `points.gz`; an empty path when there is neither.
 */
std::filesystem::path FindPointsFile(const std::filesystem::path& polyMesh);

/**
 * Reads `file` (a `points` or `points.gz` file). Binary bodies must hold 64-bit scalars (the
 * header's `arch`, "scalar=64" when absent, as OpenFOAM assumes). Throws std::runtime_error with
 * the file's name and what is wrong.
 */
PointsFile ReadPointsFile(const std::filesystem::path& file);

/**
 * Writes `numberOfPoints` points (`xyz`, 3 doubles each) into the polyMesh directory `polyMesh`
 * in the form of `like` (format, compression, header), with the header's `location` set to
 * `location` (e.g. "constant/polyMesh"). ASCII numbers are the shortest text that reads back as
 * the same double. The file is written beside its final name and renamed over it, so a reader
 * never sees half a file; the other variant (`points.gz` beside `points`, or the reverse), which
 * would shadow or be shadowed by the new file, is removed. Returns the path written. Throws
 * std::runtime_error when the directory cannot be written.
 */
std::filesystem::path WritePointsFile(const std::filesystem::path& polyMesh, const PointsFile& like,
  const double* xyz, std::size_t numberOfPoints, const std::string& location);

} // namespace openfoam
} // namespace dgmf

#endif
