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
 */
NamedMesh ReadSU2(const std::string& path);

/**
 * Writes a copy of the .su2 file `source` to `target` in which only the coordinates of the
 * NPOIN section change: `points` holds 3 per node (z ignored in 2D), `count` must be the file's
 * number of points. The coordinates are written with 17 significant digits; every other line is
 * copied byte for byte. The file is written beside `target` and renamed over it. `target` may be
 * `source`. Throws FileError.
 */
void WriteSU2WithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
