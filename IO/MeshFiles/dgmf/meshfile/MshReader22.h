/**
 * @file MshReader22.h
 * @brief A version 2.2 .msh file (ASCII or binary) read without gmsh's library, into the mesh
 * gmsh's library gives (GmshFile.h's ReadGmsh): the legacy format many CFD tools still ask for
 * (OpenFOAM's gmshToFoam, SU2's converters), whose reading through gmsh took most of a .msh
 * command's time.
 */
#ifndef dgmf_meshfile_MshReader22_h
#define dgmf_meshfile_MshReader22_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string_view>

namespace dgmf
{
namespace meshfile
{

/**
 * Reads the bytes of a version 2.2 .msh file into `mesh` as ReadGmsh does through gmsh, which
 * makes the entities of a version 2 file from the elements' tags: each element belongs to the
 * entity of its dimension and elementary tag, an entity is in the physical group of each of its
 * elements (0: none), and within an entity gmsh holds the elements in increasing element number.
 * The mesh is then built as for version 4.1 (MshModel.h: nodes in increasing tag order, the
 * dimension, the volume, one boundary per physical group of the dimension below), with gmsh's
 * two rules for version 2: nodes no element uses are not nodes of the mesh, and an element listed
 * once per physical group of its entity is read once.
 *
 * Returns false, with `mesh` unspecified, for anything it leaves to gmsh, which reads it or says
 * what is wrong: a section it does not parse to its $End line, $ParametricNodes, an element with
 * other than two tags (partitions) or an elementary tag below 1 or a physical tag below 0, an
 * element number twice (gmsh keeps the last), an element type other than first-order points,
 * lines, triangles, quadrangles, tetrahedra, hexahedra, prisms and pyramids, a node tag twice or
 * an element node that is not a node, no 2D or 3D element, a 2D mesh outside z = 0, or a binary
 * file of the other byte order. Never reads outside `file`.
 */
bool ReadMsh22(std::string_view file, bool binary, NamedMesh& mesh);

} // namespace meshfile
} // namespace dgmf

#endif
