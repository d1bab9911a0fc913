/**
 * @file MshModel.h
 * @brief Private to the .msh readers that work without gmsh (MshReader41.cxx, MshReader22.cxx):
 * what a file's sections give (entities with their physical groups, nodes, blocks of elements),
 * and the mesh gmsh's library makes of it (GmshFile.h's ReadGmsh), built the same way for both
 * versions.
 */
#ifndef dgmf_meshfile_MshModel_h
#define dgmf_meshfile_MshModel_h

#include "dgmf/meshfile/MshText.h"
#include "dgmf/meshfile/NamedMesh.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dgmf
{
namespace meshfile
{

/// Elements of one entity and one gmsh type, their node tags one after the other in the model's
/// ElementNodes from First (Count elements).
struct ElementBlock
{
  int Dimension = 0, Entity = 0, Type = 0;
  std::size_t First = 0, Count = 0;
};

/// What the sections give.
struct MshModel
{
  std::map<int, std::vector<int>> Entities[4];      ///< by dimension: entity tag -> physical tags
  std::map<std::pair<int, int>, std::string> Names; ///< (dimension, physical tag) -> name
  std::vector<std::uint64_t> NodeTags;
  std::vector<double> Coordinates;
  std::vector<ElementBlock> Blocks; ///< in the order gmsh holds them within an entity and type
  std::vector<std::uint64_t> ElementNodes;
};

/// $PhysicalNames (text in binary files too, the same in both versions): `dimension tag "name"`
/// per line, then the "$EndPhysicalNames" token.
bool ParsePhysicalNames(msh::Cursor& cursor, MshModel& model);

/// How gmsh's library holds a version 2 file (checked against it: gmsh.MshReader22.*).
struct Version2Rules
{
  /// Nodes no element uses are not nodes of the mesh.
  bool DropUnusedNodes = false;
  /// An element is listed once per physical group of its entity, and gmsh keeps each copy:
  /// where an entity of a dimension has several groups, that dimension's elements are read once
  /// (GmshModel.cxx's AddElements: in the volume, and in each boundary).
  bool ReadRepeatedElementsOnce = false;
};

/**
 * `model` as ReadGmsh gives it: the nodes in increasing tag order; the dimension the highest of
 * the entities with elements (2 or 3); the volume the elements of the entities of that dimension,
 * entity by entity in increasing tag, the types of an entity in increasing gmsh type, each type's
 * blocks in the model's order; one boundary per physical group of the dimension below, in
 * increasing group tag, named by $PhysicalNames or "group N", its entities in increasing tag.
 * False, with `mesh` unspecified, for what the readers leave to gmsh: a block of an entity the
 * model does not list, a node tag twice, an element node that is not a node, no 2D or 3D element,
 * a 2D mesh outside z = 0.
 */
bool BuildMeshAsGmshDoes(const MshModel& model, const Version2Rules& rules, NamedMesh& mesh);

} // namespace meshfile
} // namespace dgmf

#endif
