/**
 * @file ExodusFile.h
 * @brief Exodus II files (.exo, .e, .ex2, .g), read with their node sets and side sets as boundary
 * names and written back with new coordinates, through the Exodus library ParaView's own Exodus
 * reader uses (ParaView's vtkexodusII: its symbols prefixed).
 *
 * What is read: the nodes in the file's order (NodeIds: the node number map, 1..N without one);
 * the element blocks of the mesh's dimension (the file's num_dim, or 2 for a 3D file whose
 * blocks are all 2D and lie in z = 0) with the linear types (TETRA/TET4, HEX/HEX8, WEDGE,
 * PYRAMID, TRI/TRI3, QUAD/QUAD4/SHELL4 in 2D), Exodus's node order being VTK's for these; every
 * side set as a NamedBoundary of the faces (edges in 2D) it names, and every node set as one of
 * Vertex cells. A set's name is its name in the file, or "sideset_ID" / "nodeset_ID" (ParaView's
 * ExodusIIReader names unnamed sets by their id); a side set and a node set of one name are one
 * boundary under that name only when they hold the same nodes, else the node set is
 * "NAME (node set)". Higher-order element types are a FileError.
 */
#ifndef dgmf_meshfile_ExodusFile_h
#define dgmf_meshfile_ExodusFile_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string>

namespace dgmf
{
namespace meshfile
{

/// Reads the Exodus II file `path` (see the file's comment). Throws FileError naming the file
/// and the block or set it could not read.
NamedMesh ReadExodus(const std::string& path);

/**
 * Writes a copy of the Exodus II file `source` to `target` in which only the nodal coordinates
 * change: `points` holds 3 per node in ReadExodus's order (z ignored in 2D), `count` must be the
 * file's number of nodes, every coordinate finite. The coordinates keep the file's word size
 * (float or double); blocks, sets, maps, names, variables and time steps are the source's.
 * Written beside `target` and renamed over it; `target` may be `source`. Throws FileError; the
 * target is then unchanged.
 */
void WriteExodusWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
