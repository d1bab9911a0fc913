/**
 * @file NamedMesh.h
 * @brief A solver's mesh as the mesh-file readers give it: the nodes in the file's order, the
 * cells of the mesh's dimension, and the named boundaries (gmsh physical groups, SU2 markers,
 * Exodus side sets and node sets, CGNS boundary conditions). VTK-free: cell types are VTK's numbers
 * (as SU2 files use them), so the VTK reader only copies.
 */
#ifndef dgmf_meshfile_NamedMesh_h
#define dgmf_meshfile_NamedMesh_h

#include "dgmf/HugePages.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dgmf
{
namespace meshfile
{

/// VTK's numbers of the linear cell types the readers give (vtkCellType.h).
enum CellType : std::uint8_t
{
  Vertex = 1,
  Line = 3,
  Triangle = 5,
  Quad = 9,
  Tetra = 10,
  Hexahedron = 12,
  Wedge = 13,
  Pyramid = 14
};

/// Cells: VTK type, and the 0-based node indices of each (Offsets has one entry more than Types).
struct Cells
{
  std::vector<std::uint8_t> Types;
  std::vector<std::int64_t> Offsets{ 0 };
  std::vector<std::int64_t> Connectivity;

  std::size_t Size() const { return this->Types.size(); }
  /// Room for `cells` more cells of `nodes` nodes in all, so that adding them copies nothing
  /// (large arrays on huge pages: dgmf/HugePages.h).
  void Reserve(std::size_t cells, std::size_t nodes)
  {
    dgmf::ReserveOnHugePages(this->Types, this->Types.size() + cells);
    dgmf::ReserveOnHugePages(this->Offsets, this->Offsets.size() + cells);
    dgmf::ReserveOnHugePages(this->Connectivity, this->Connectivity.size() + nodes);
  }
  void Add(std::uint8_t type, const std::int64_t* nodes, std::size_t count)
  {
    this->Types.push_back(type);
    this->Connectivity.insert(this->Connectivity.end(), nodes, nodes + count);
    this->Offsets.push_back(static_cast<std::int64_t>(this->Connectivity.size()));
  }
};

/// A named boundary: its faces (edges in 2D), on the mesh's nodes; or, for a set of nodes (an
/// Exodus node set, a CGNS boundary condition on vertices), one Vertex cell per node.
struct NamedBoundary
{
  std::string Name;
  Cells Faces;
  /// The group of boundaries the file puts it in (a CGNS boundary condition's FamilyName), or
  /// empty: the group's name chooses all its boundaries (docs: formats.md, "CGNS").
  std::string Family;
};

/// A mesh read from a file.
struct NamedMesh
{
  int Dimension = 3;          ///< 2 (all nodes at one z in the file; z = 0 but for gmsh) or 3
  std::vector<double> Points; ///< 3 coordinates per node, in the file's order
  /// The file's own id of each node (gmsh node tags; SU2: the index), same order as Points.
  std::vector<std::int64_t> NodeIds;
  Cells Volume; ///< the cells of the mesh's dimension (all of them, named or not)
  std::vector<NamedBoundary> Boundaries; ///< in the file's order
  /// The named groups of other dimensions (a gmsh physical curve or point of a 3D mesh, a volume
  /// group), which are not boundaries: their names and dimensions, for messages.
  std::vector<std::pair<std::string, int>> OtherGroups;

  std::size_t NumberOfNodes() const { return this->Points.size() / 3; }
};

/**
 * A file that cannot be read or written: the message names the file and, where it can, the line
 * or section.
 */
class FileError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * Joins the boundaries of one name into the first of them, their faces in order (gmsh lets
 * several physical groups share a name, and reads such a file; they were refused as names given
 * twice until 2026-11-30).
 */
void MergeBoundariesOfOneName(NamedMesh& mesh);

/**
 * Checks what every reader promises: Points a multiple of 3 and finite, NodeIds one per node,
 * Offsets consistent with Connectivity, every node index in range, node counts matching the cell
 * types, Volume of the mesh's dimension, named faces one dimension lower (or all Vertex cells, a
 * set of nodes), names non-empty and unique. Throws FileError("<file>: ...") on the first
 * violation.
 */
void ValidateNamedMesh(const NamedMesh& mesh, const std::string& file);

/// The number of nodes of a cell of VTK type `type` (0 for a type the readers do not give).
int NodesOfCellType(std::uint8_t type);

/// The dimension of a cell of VTK type `type` (-1 for a type the readers do not give).
int DimensionOfCellType(std::uint8_t type);

} // namespace meshfile
} // namespace dgmf

#endif
