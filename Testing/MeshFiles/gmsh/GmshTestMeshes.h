/**
 * @file GmshTestMeshes.h
 * @brief Test meshes made by gmsh's C++ API and written as .msh files (no shipped files), and
 * what gmsh itself reads back from a file (independent of ReadGmsh).
 */
#ifndef dgmf_meshfile_GmshTestMeshes_h
#define dgmf_meshfile_GmshTestMeshes_h

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace test
{

/// The .msh flavour to write: version 2.2 or 4.1, ASCII or binary, Mesh.SaveAll.
struct MshFlavour
{
  double Version = 4.1;
  bool Binary = false;
  bool SaveAll = false;
};

/// Node and element counts of a generated mesh, as gmsh had them before writing.
struct GeneratedCounts
{
  std::size_t Nodes = 0;
  std::size_t VolumeElements = 0;
  std::map<std::string, std::size_t> BoundaryElements; ///< per physical name
};

/**
 * A 4 x 3 x 2 box with a cubic hole, tetrahedra: physical surfaces "outer" (6 faces) and "hole"
 * (6 faces), physical volume "fluid".
 */
GeneratedCounts WriteBoxWithHole(const std::string& path, const MshFlavour& flavour);

/**
 * A 4 x 2 rectangle with a circular hole at z = 0, triangles: physical curves "outer" (4),
 * an unnamed group 5 (the hole), physical surface "fluid". With `overlapping`, the first outer
 * curve is also in a physical group "left" (an entity in two groups).
 */
GeneratedCounts WriteRectangleWithHole(
  const std::string& path, const MshFlavour& flavour, bool overlapping = false);

/// One gmsh prism and one pyramid, in gmsh's own (positive) orientation, boundary group "wall".
void WritePrismAndPyramid(const std::string& path, const MshFlavour& flavour);

/// A 2D mesh of second-order triangles.
void WriteSecondOrder(const std::string& path);

/// What gmsh reads from `path` (in a model of its own): every element and the physical groups.
struct GmshView
{
  std::vector<std::size_t> NodeTags;             ///< sorted
  std::map<std::size_t, std::vector<double>> At; ///< node tag -> coordinates
  /// (type, element tag) -> node tags, over every entity.
  std::map<std::pair<int, std::size_t>, std::vector<std::size_t>> Elements;
  std::map<std::string, std::size_t> GroupEntities; ///< "dim:name" -> number of entities
};
GmshView ViewWithGmsh(const std::string& path);

/// The first two lines of a file ("$MeshFormat" and the version line).
std::string MeshFormatLines(const std::string& path);

} // namespace test
} // namespace meshfile
} // namespace dgmf

#endif
