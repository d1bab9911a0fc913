/**
 * @file SU2File.h
 * @brief SU2's native mesh format (.su2, ASCII; one zone): read with its MARKER_TAGs as boundary
 * names, and written back with every section but the point coordinates unchanged.
 */
#ifndef dgmf_meshfile_SU2File_h
#define dgmf_meshfile_SU2File_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string>

namespace dgmf
{
namespace meshfile
{

/**
 * Reads the .su2 file `path`. Throws FileError, naming the file and the line, for anything it
 * cannot read: truncated files, counts that do not match, indices out of range, non-finite
 * coordinates, unknown element types, several zones. No allocation follows an unchecked count.
 *
 * What it takes: blank lines, and comment lines (first non-blank character '%') anywhere; "KEY=
 * value" with or without spaces around '='; "\r\n" line ends. NDIME= (2 or 3) first, then
 * NELEM=, NPOIN= (an optional second number, nDomain, is ignored) and NMARK= in any order;
 * other keywords before them are skipped (NZONE= or IZONE= must be 1), and after them other
 * keyword sections (FFD boxes) are skipped. An element or point line may end with one integer
 * (its index), which is not used: NodeIds are 0..NPOIN-1. NELEM holds elements of the mesh's
 * dimension (2D: 5, 9; 3D: 10, 12, 13, 14), markers one dimension lower (2D: 3; 3D: 5, 9). A
 * marker's name is its MARKER_TAG= value trimmed (spaces and other characters inside are kept);
 * names must be non-empty and unique. 2D points get z = 0. Numbers are read whole ("1.5abc",
 * "nan", "inf" and values beyond a double's range are errors).
 */
NamedMesh ReadSU2(const std::string& path);

/**
 * Writes a copy of the .su2 file `source` to `target` in which only the coordinates of the
 * NPOIN section change: `points` holds 3 per node (z ignored in 2D), `count` must be the file's
 * number of points. The coordinates are written with 17 significant digits; every other line is
 * copied byte for byte. The file is written beside `target` and renamed over it. `target` may be
 * `source`. Throws FileError.
 *
 * Each coordinate token of a point line is replaced (C locale, std::to_chars); the spaces between
 * them, a point's index and the line end stay. `source` is read and checked as ReadSU2 does
 * first; a wrong `count` or a non-finite coordinate (of the dimension written) writes nothing.
 * When its bytes are those ReadSU2 parsed last in this process (the same size and hash: the
 * command and ParaView write back the file they read), the point lines found then are used
 * instead of a second parse.
 * The temporary file is ".<target name>.dgmf-writing" in the target's folder.
 */
void WriteSU2WithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
