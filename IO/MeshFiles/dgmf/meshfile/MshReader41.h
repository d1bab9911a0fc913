/**
 * @file MshReader41.h
 * @brief A version 4.1 .msh file (ASCII or binary) read without gmsh's library, into the mesh
 * gmsh's library gives (GmshFile.h's ReadGmsh): for the files gmsh writes by default, whose
 * reading through gmsh (a child process, the library's load and its parse) took most of a
 * .msh command's time.
 */
#ifndef dgmf_meshfile_MshReader41_h
#define dgmf_meshfile_MshReader41_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string_view>

namespace dgmf
{
namespace meshfile
{

/**
 * Reads the bytes of a version 4.1 .msh file into `mesh` as ReadGmsh does through gmsh: the nodes
 * in increasing tag order; the dimension the highest of the entities with elements (2 or 3); the
 * volume the elements of the entities of that dimension, entity by entity in increasing tag, the
 * types of an entity in increasing gmsh type, each in the file's order; one boundary per physical
 * group of the dimension below, in increasing group tag, named by $PhysicalNames or "group N",
 * its entities in increasing tag, their elements in the same order. First-order points, lines,
 * triangles, quadrangles, tetrahedra, hexahedra, prisms (each triangle reversed for VTK) and
 * pyramids.
 *
 * Returns false, with `mesh` unspecified, for anything it leaves to gmsh, which reads it or says
 * what is wrong: a section it does not parse to its $End line, parametric nodes, partitioned
 * entities, ghost elements or parametrizations, an element type other than those, an element of
 * an entity $Entities does not list or of another dimension than its entity, a node tag twice or
 * an element node that is not a node, a physical tag below 1, no 2D or 3D element, a 2D mesh
 * outside z = 0, or a binary file of the other byte order. Never reads outside `file`.
 */
bool ReadMsh41(std::string_view file, bool binary, NamedMesh& mesh);

} // namespace meshfile
} // namespace dgmf

#endif
