/**
 * @file MshNodes.h
 * @brief A gmsh .msh file written back with its nodes moved, without gmsh's library: the bytes of
 * the source with the coordinates in its $Nodes section replaced, every other byte kept. For the
 * versions 2.2 and 4.1, ASCII and binary, without parametric coordinates; GmshFile.h leaves any
 * other file to gmsh's writer.
 */
#ifndef dgmf_meshfile_MshNodes_h
#define dgmf_meshfile_MshNodes_h

#include "dgmf/meshfile/MshHeader.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace dgmf
{
namespace meshfile
{

/**
 * `file` (the bytes of a .msh file whose first lines say `format`) with the coordinates of the
 * node of the k-th smallest tag replaced by points[3 k], points[3 k + 1], points[3 k + 2] (the
 * order in which ReadGmsh gives the nodes): true, and the result in `patched`. False, and
 * `patched` unspecified, when the file is not one this can rewrite in place: a version other than
 * 2.2 and 4.1, a binary file of the other byte order, parametric coordinates, a $Nodes section
 * that does not parse to its $EndNodes (counts past the end of the file included), a repeated
 * tag, or a number of nodes other than `count`. ASCII coordinates are written as the shortest
 * decimal that reads back as the same double. Never reads outside `file`.
 */
bool ReplaceMshNodeCoordinates(std::string_view file, const MshFormat& format, const double* points,
  std::size_t count, std::string& patched);

} // namespace meshfile
} // namespace dgmf

#endif
