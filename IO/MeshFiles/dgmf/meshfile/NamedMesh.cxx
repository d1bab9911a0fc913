#include "dgmf/meshfile/NamedMesh.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace dgmf
{
namespace meshfile
{

int NodesOfCellType(std::uint8_t type)
{
  switch (type)
  {
    case Vertex:
      return 1;
    case Line:
      return 2;
    case Triangle:
      return 3;
    case Quad:
    case Tetra:
      return 4;
    case Pyramid:
      return 5;
    case Wedge:
      return 6;
    case Hexahedron:
      return 8;
    default:
      return 0;
  }
}

int DimensionOfCellType(std::uint8_t type)
{
  switch (type)
  {
    case Vertex:
      return 0;
    case Line:
      return 1;
    case Triangle:
    case Quad:
      return 2;
    case Tetra:
    case Hexahedron:
    case Wedge:
    case Pyramid:
      return 3;
    default:
      return -1;
  }
}

namespace
{
void CheckCells(const Cells& cells, std::size_t nodes, int dimension, const std::string& where)
{
  if (cells.Offsets.size() != cells.Types.size() + 1 || cells.Offsets.front() != 0 ||
    cells.Offsets.back() != static_cast<std::int64_t>(cells.Connectivity.size()))
  {
    throw FileError(where + ": inconsistent cell offsets");
  }
  for (std::size_t c = 0; c < cells.Types.size(); ++c)
  {
    const std::int64_t count = cells.Offsets[c + 1] - cells.Offsets[c];
    if (DimensionOfCellType(cells.Types[c]) != dimension ||
      count != NodesOfCellType(cells.Types[c]))
    {
      throw FileError(where + ": cell " + std::to_string(c) + " has type " +
        std::to_string(cells.Types[c]) + " with " + std::to_string(count) + " nodes, not a " +
        std::to_string(dimension) + "D cell type the reader gives");
    }
  }
  for (std::int64_t node : cells.Connectivity)
  {
    if (node < 0 || static_cast<std::size_t>(node) >= nodes)
    {
      throw FileError(where + ": node index " + std::to_string(node) + " is outside 0.." +
        std::to_string(nodes == 0 ? 0 : nodes - 1));
    }
  }
}
} // namespace

void MergeBoundariesOfOneName(NamedMesh& mesh)
{
  std::vector<NamedBoundary> merged;
  for (NamedBoundary& boundary : mesh.Boundaries)
  {
    auto first = std::find_if(merged.begin(), merged.end(),
      [&boundary](const NamedBoundary& kept) { return kept.Name == boundary.Name; });
    if (first == merged.end())
    {
      merged.push_back(std::move(boundary));
      continue;
    }
    Cells& faces = first->Faces;
    const Cells& more = boundary.Faces;
    const auto shift = static_cast<std::int64_t>(faces.Connectivity.size());
    faces.Types.insert(faces.Types.end(), more.Types.begin(), more.Types.end());
    for (std::size_t k = 1; k < more.Offsets.size(); ++k)
    {
      faces.Offsets.push_back(more.Offsets[k] + shift);
    }
    faces.Connectivity.insert(
      faces.Connectivity.end(), more.Connectivity.begin(), more.Connectivity.end());
  }
  mesh.Boundaries = std::move(merged);
}

void ValidateNamedMesh(const NamedMesh& mesh, const std::string& file)
{
  if (mesh.Dimension != 2 && mesh.Dimension != 3)
  {
    throw FileError(file + ": the mesh dimension must be 2 or 3");
  }
  if (mesh.Points.size() % 3 != 0 || mesh.NodeIds.size() != mesh.NumberOfNodes())
  {
    throw FileError(file + ": the points and node ids do not match");
  }
  for (std::size_t k = 0; k < mesh.Points.size(); ++k)
  {
    if (!std::isfinite(mesh.Points[k]))
    {
      throw FileError(file + ": node " + std::to_string(k / 3) + " has a non-finite coordinate");
    }
  }
  if (mesh.Volume.Size() == 0)
  {
    throw FileError(file + ": no cell of dimension " + std::to_string(mesh.Dimension));
  }
  CheckCells(mesh.Volume, mesh.NumberOfNodes(), mesh.Dimension, file + ": the volume cells");
  std::set<std::string> names;
  for (const NamedBoundary& boundary : mesh.Boundaries)
  {
    if (boundary.Name.empty() || !names.insert(boundary.Name).second)
    {
      throw FileError(
        file + ": boundary names must be non-empty and unique ('" + boundary.Name + "')");
    }
    // Faces, or a set of nodes (Vertex cells only).
    const bool nodeSet = !boundary.Faces.Types.empty() && boundary.Faces.Types.front() == Vertex;
    CheckCells(boundary.Faces, mesh.NumberOfNodes(), nodeSet ? 0 : mesh.Dimension - 1,
      file + ": boundary '" + boundary.Name + "'");
  }
}

} // namespace meshfile
} // namespace dgmf
