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
 * Replaces, in `bytes` (a .msh file whose first lines say `format`), the coordinates of the node of
 * the k-th smallest tag by points[3 k], points[3 k + 1], points[3 k + 2] (the order in which
 * ReadGmsh gives the nodes): true (the pieces WriteMshWithMovedNodes writes, into `bytes`): a
 * binary file's doubles replaced; an ASCII file's text written anew, each coordinate as the
 * shortest decimal that reads back as the same double. False, and `bytes` unchanged, when the file
 * is not one this can rewrite in place: a version other than 2.2 and 4.1, a binary file of the
 * other byte order, parametric coordinates, a $Nodes section that does not parse to its $EndNodes
 * (counts past the end of the file included), a repeated tag, or a number of nodes other than
 * `count`. Never reads outside `bytes`.
 */
bool ReplaceMshNodeCoordinates(
  std::string& bytes, const MshFormat& format, const double* points, std::size_t count);

/**
 * What ReplaceMshNodeCoordinates makes of `file` (the source's bytes, a mapping as a rule), written
 * to `target` through `temporary` (WriteFileAtomically, FileReplacement.h) in pieces, never whole
 * in memory: the bytes between the coordinates as they are, the coordinates from `points`. False,
 * with nothing written, for a file ReplaceMshNodeCoordinates cannot rewrite; throws FileError when
 * the file cannot be written.
 */
bool WriteMshWithMovedNodes(std::string_view file, const MshFormat& format, const double* points,
  std::size_t count, const std::string& target, const std::string& temporary);

/**
 * The same for a file with more nodes than points: `tags` (increasing, one per point) are the
 * nodes the points are (a version 2.2 file read as gmsh reads it: the nodes elements use); the
 * other nodes keep their bytes. False as WriteMshWithMovedNodes, and when a tag is not a node.
 */
bool WriteMshWithMovedNodesByTag(std::string_view file, const MshFormat& format,
  const double* points, const std::int64_t* tags, std::size_t count, const std::string& target,
  const std::string& temporary);

} // namespace meshfile
} // namespace dgmf

#endif
