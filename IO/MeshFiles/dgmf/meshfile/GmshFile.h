/**
 * @file GmshFile.h
 * @brief gmsh's .msh files (versions 2.2 and 4.x, ASCII and binary), read and written through
 * gmsh's own library: physical groups of dimension d - 1 are the boundary names.
 */
#ifndef dgmf_meshfile_GmshFile_h
#define dgmf_meshfile_GmshFile_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string>

namespace dgmf
{
namespace meshfile
{

/**
 * Reads the .msh file `path` with gmsh's library. The dimension is the highest of its elements;
 * Volume holds the elements of that dimension (first-order types only: others are a FileError);
 * each physical group of the dimension below is a NamedBoundary (its name, or "group N" for an
 * unnamed group N). Points are in the order gmsh gives its nodes, NodeIds their tags. Throws
 * FileError naming the file.
 */
NamedMesh ReadGmsh(const std::string& path);

/**
 * Writes `source` again to `target` with the node coordinates `points` (3 per node, in ReadGmsh's
 * order; `count` must be the number of nodes ReadGmsh gives): node tags, elements, entities and
 * physical groups unchanged, in the version and mode (ASCII or binary) of `source`. Written beside
 * `target` and renamed over it; `target` may be `source`. Throws FileError.
 */
void WriteGmshWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
