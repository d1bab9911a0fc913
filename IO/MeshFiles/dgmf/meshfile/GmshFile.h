/**
 * @file GmshFile.h
 * @brief gmsh's .msh files (versions 2.2 and 4.x, ASCII and binary), read and written through
 * gmsh's own library: physical groups of dimension d - 1 are the boundary names.
 *
 * How gmsh is used (gmsh 4.8.4, Debian 12), and why:
 * - The file's first two lines are checked first ("$MeshFormat", then version 2.0-2.2 or
 *   4.0-4.1, ASCII or binary, 8-byte reals). gmsh parses a .msh-named file with another first line
 *   as a .geo script, which can run commands (SystemCall); it also merges a "<file>.opt" option
 *   file (.geo syntax) found beside the file. gmsh reads the file through a link named mesh.msh in
 *   a private temporary directory, so neither happens.
 * - gmsh works in a forked child process; the mesh comes back through a pipe. gmsh 4.8.4
 *   corrupts its heap and aborts on some malformed files (for example a version 4 $Nodes section
 *   whose header line is missing, so that its count is smaller than its blocks), which no check
 *   in the process could undo: a crash, or no answer within 2 minutes plus 10 s per MiB, is a
 *   FileError. The calling process never initializes gmsh (the child does, silently, without the
 *   user's gmshrc; General.AbortOnError = 0, because gmsh 4.8 leaks the open file when it throws
 *   from its readers and, in gmsh::open, stays "busy" for good).
 * - Not for a process that cannot fork (a fork of a multi-threaded process runs gmsh alone in the
 *   child; glibc's malloc supports that).
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
 * unnamed group N). Points are in increasing tag order (the file's order for files gmsh writes;
 * gmsh's own order after reading a version 2 file follows its classification of the nodes, not
 * the file), NodeIds their tags, each node once (getNodes of the whole model without
 * includeBoundary, which would repeat the nodes of shared entity boundaries). A 2D mesh (no 3D
 * element) must lie in one plane z = constant. A version 2 file lists an element once per physical
 * group of its entity and gmsh keeps each copy: those are read once. Prisms are read with each
 * triangle reversed (gmsh's corner order turns the other way round from VTK's documented wedge);
 * the other types have VTK's order. Throws FileError naming the file.
 *
 * Files of version 4.1 (what gmsh writes by default) and 2.2 (the legacy format), ASCII or binary,
 * are read without gmsh's library into the same mesh (ReadMsh41, MshReader41.h; ReadMsh22,
 * MshReader22.h, which also drops the nodes no element uses, as gmsh does with version 2 files);
 * any file they leave (other versions, partitioned or parametric files, other element types,
 * anything they do not parse, and every file with an error) is read by gmsh (ReadGmshWithGmsh),
 * which also words the errors.
 */
NamedMesh ReadGmsh(const std::string& path);

/// ReadGmsh through gmsh's library alone, whatever the version (the reference ReadMsh41 and
/// ReadMsh22 are checked against).
NamedMesh ReadGmshWithGmsh(const std::string& path);

/**
 * Writes `source` again to `target` with the node coordinates `points` (3 per node, in ReadGmsh's
 * order; `count` must be the number of nodes ReadGmsh gives): node tags, elements, entities and
 * physical groups unchanged, in the version and mode (ASCII or binary) of `source`. Written beside
 * `target` (".<name>.dgmf-writing.msh") and renamed over it; `target` may be `source`. Coordinates
 * must be finite. Throws FileError; the target is then unchanged.
 *
 * Versions 2.2 and 4.1 without parametric nodes (what gmsh writes by default): the source's own
 * bytes with the coordinates in its $Nodes section replaced (ReplaceMshNodeCoordinates,
 * MshNodes.h), every other byte kept, without gmsh's library; ASCII coordinates as the shortest
 * decimal that reads back as the same double, so both modes keep every bit. A version 2.2 file
 * with nodes no element uses (which its reading drops, as gmsh's does): the points replace the
 * nodes of the tags read (WriteMshWithMovedNodesByTag), the unused nodes keep their bytes.
 *
 * Any other file (versions 2.0, 2.1 and 4.0, parametric nodes, a binary file of the other byte
 * order, a $Nodes section that does not parse, or a number of nodes other than `count`) goes
 * through gmsh. Version 4: every node is moved in gmsh's model (setNode) and the model written
 * with Mesh.SaveAll = 1 (all elements, physical or not); entities keep their tags and groups
 * (their bounding boxes are recomputed), parametric coordinates are dropped (the nodes moved).
 * Version 2: gmsh's writer numbers nodes 1..N in the order it holds them, which after reading is
 * not the file's order, so the model is rebuilt with the nodes in tag order; files whose node tags
 * are not 1..N, whose elements are in several physical groups, in and outside groups, or that
 * have nodes no element uses, cannot be written unchanged by gmsh and are refused. ASCII
 * coordinates are written by gmsh with 16 significant digits (%.16g): they read back within
 * 1e-15 relative.
 */
void WriteGmshWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
