#include "dgmf/meshfile/ExodusFile.h"

#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/LibraryIsolation.h"

#include <vtkexodusII/include/exodusII.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
/// An open Exodus file, closed when it goes out of scope; every call's error becomes a FileError
/// naming the file, what was being read, and what the library said.
class ExodusHandle
{
public:
  ExodusHandle(const std::string& path, int mode)
    : Path(path)
  {
    // The library prints its errors to stderr unless told not to; they reach the user through
    // the FileError instead.
    ex_opts(EX_DEFAULT);
    int computeWordSize = 8; // doubles in memory, whatever the file stores
    int fileWordSize = 0;
    float version = 0.0f;
    this->Id = ex_open(path.c_str(), mode, &computeWordSize, &fileWordSize, &version);
    if (this->Id < 0)
    {
      throw FileError(path + ": not an Exodus II file that can be opened" + LastError());
    }
    // 64-bit integers for ids, maps and connectivity, whatever the file stores.
    ex_set_int64_status(this->Id, EX_ALL_INT64_API);
  }
  ~ExodusHandle()
  {
    if (this->Id >= 0)
    {
      ex_close(this->Id);
    }
  }
  ExodusHandle(const ExodusHandle&) = delete;
  ExodusHandle& operator=(const ExodusHandle&) = delete;

  /// Throws FileError when `status` is an error.
  void Check(int status, const std::string& what) const
  {
    if (status < 0)
    {
      throw FileError(this->Path + ": cannot read " + what + LastError());
    }
  }

  /// Closes the file, with its error (a write that could not be flushed) as a FileError.
  void Close()
  {
    const int status = ex_close(this->Id);
    this->Id = -1;
    if (status < 0)
    {
      throw FileError(this->Path + ": cannot be written" + LastError());
    }
  }

  int Id = -1;
  std::string Path;

private:
  static std::string LastError()
  {
    const char* message = nullptr;
    const char* function = nullptr;
    int code = 0;
    ex_get_err(&message, &function, &code);
    return message && *message ? std::string(" (") + message + ")" : std::string();
  }
};

/// For a node number 0, what it most often means: the file ends before its data (a copy cut
/// short reads back zeros where its arrays should be).
std::string CutShortHint(std::int64_t node)
{
  return node == 0 ? " (0: is the file cut short? Its arrays read back as zeros past its end)" : "";
}

/// The file's sizes, checked against what the file can hold before anything is allocated.
ex_init_params ReadSizes(const ExodusHandle& file)
{
  ex_init_params sizes{};
  file.Check(ex_get_init_ext(file.Id, &sizes), "the header");
  // A count the file cannot back is refused before it drives an allocation: the arrays read are
  // at most 8 bytes an entry, and a compressed (netCDF-4) file holds them in at least 1/64 of
  // that, with 64 MiB allowed for any file.
  std::error_code error;
  const auto bytes = static_cast<double>(std::filesystem::file_size(file.Path, error));
  const double budget = std::max(64.0 * 1024 * 1024, 64.0 * (error ? 0.0 : bytes)) / 8.0;
  for (const std::int64_t count : { sizes.num_nodes * 3, sizes.num_elem, sizes.num_elem_blk,
         sizes.num_node_sets, sizes.num_side_sets })
  {
    if (count < 0 || static_cast<double>(count) > budget)
    {
      throw FileError(file.Path + ": the header declares " + std::to_string(count) +
        " entries, more than the file can hold");
    }
  }
  if (sizes.num_dim < 2 || sizes.num_dim > 3)
  {
    throw FileError(file.Path + ": the mesh has " + std::to_string(sizes.num_dim) +
      " dimensions (2 or 3 are read)");
  }
  return sizes;
}

/// The ids and names of the objects of one type (names: the file's, else PREFIX_ID).
void ReadIdsAndNames(const ExodusHandle& file, ex_entity_type type, std::int64_t count,
  const std::string& prefix, std::vector<std::int64_t>& ids, std::vector<std::string>& names)
{
  ids.assign(static_cast<std::size_t>(count), 0);
  names.assign(static_cast<std::size_t>(count), std::string());
  if (count == 0)
  {
    return;
  }
  file.Check(ex_get_ids(file.Id, type, ids.data()), "the ids of the " + prefix + "s");
  const int length =
    std::max<int>(32, static_cast<int>(ex_inquire_int(file.Id, EX_INQ_DB_MAX_USED_NAME_LENGTH)));
  ex_set_max_name_length(file.Id, length);
  std::vector<std::vector<char>> storage(
    static_cast<std::size_t>(count), std::vector<char>(static_cast<std::size_t>(length) + 1, 0));
  std::vector<char*> pointers;
  for (std::vector<char>& name : storage)
  {
    pointers.push_back(name.data());
  }
  file.Check(ex_get_names(file.Id, type, pointers.data()), "the names of the " + prefix + "s");
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    std::string name(storage[k].data());
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
    {
      name.pop_back();
    }
    names[k] = name.empty() ? prefix + "_" + std::to_string(ids[k]) : name;
  }
}

/// VTK's cell type of an Exodus element type with `nodes` nodes; 0 when not a linear type.
std::uint8_t CellTypeOf(std::string type, std::int64_t nodes)
{
  std::transform(type.begin(), type.end(), type.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  const auto startsWith = [&type](const char* prefix) { return type.rfind(prefix, 0) == 0; };
  if (startsWith("TET") && nodes == 4)
    return Tetra;
  if (startsWith("HEX") && nodes == 8)
    return Hexahedron;
  if (startsWith("WEDGE") && nodes == 6)
    return Wedge;
  if (startsWith("PYRA") && nodes == 5)
    return Pyramid;
  if ((startsWith("TRI") || startsWith("SHELL")) && nodes == 3)
    return Triangle;
  if ((startsWith("QUAD") || startsWith("SHELL")) && nodes == 4)
    return Quad;
  if ((startsWith("BAR") || startsWith("BEAM") || startsWith("TRUSS") || startsWith("EDGE")) &&
    nodes == 2)
    return Line;
  return 0;
}

/// An element block's id, cell type and size (its header: no connectivity read).
struct BlockHeader
{
  std::int64_t Id = 0;
  std::string What; ///< "element block NAME"
  std::uint8_t Type = 0;
  std::int64_t Count = 0, Nodes = 0;
};

/**
 * The headers of the non-empty element blocks, each a linear type, and the mesh's dimension (the
 * highest of theirs: 2 or 3); throws FileError otherwise.
 */
std::vector<BlockHeader> ReadBlockHeaders(
  const ExodusHandle& file, const ex_init_params& sizes, int& dimension)
{
  std::vector<std::int64_t> ids;
  std::vector<std::string> names;
  ReadIdsAndNames(file, EX_ELEM_BLOCK, sizes.num_elem_blk, "block", ids, names);
  std::vector<BlockHeader> headers;
  dimension = 0;
  for (std::size_t b = 0; b < ids.size(); ++b)
  {
    char type[MAX_STR_LENGTH + 1] = { 0 };
    BlockHeader header;
    header.Id = ids[b];
    header.What = "element block " + names[b];
    std::int64_t edges = 0, faces = 0, attributes = 0;
    file.Check(ex_get_block(file.Id, EX_ELEM_BLOCK, ids[b], type, &header.Count, &header.Nodes,
                 &edges, &faces, &attributes),
      header.What);
    if (header.Count == 0)
    {
      continue;
    }
    header.Type = CellTypeOf(type, header.Nodes);
    if (header.Type == 0)
    {
      throw FileError(file.Path + ": " + header.What + " has elements of type " + type + " with " +
        std::to_string(header.Nodes) +
        " nodes; the linear types are read (tetrahedra, hexahedra, "
        "wedges, pyramids, triangles, quadrilaterals)");
    }
    if (header.Count < 0 || header.Count > sizes.num_elem)
    {
      throw FileError(file.Path + ": " + header.What + " declares " + std::to_string(header.Count) +
        " elements, the file " + std::to_string(sizes.num_elem));
    }
    dimension = std::max(dimension, DimensionOfCellType(header.Type));
    headers.push_back(std::move(header));
  }
  if (dimension < 2)
  {
    throw FileError(file.Path + ": no element block of 2D or 3D elements");
  }
  return headers;
}

/// The element blocks of the mesh's dimension, as Volume; the dimension itself.
void ReadElementBlocks(const ExodusHandle& file, const ex_init_params& sizes, NamedMesh& mesh)
{
  int dimension = 0;
  const std::vector<BlockHeader> headers = ReadBlockHeaders(file, sizes, dimension);
  struct Block
  {
    std::uint8_t Type;
    std::vector<std::int64_t> Connectivity;
  };
  std::vector<Block> blocks;
  for (const BlockHeader& header : headers)
  {
    Block block{ header.Type,
      std::vector<std::int64_t>(static_cast<std::size_t>(header.Count * header.Nodes)) };
    file.Check(
      ex_get_conn(file.Id, EX_ELEM_BLOCK, header.Id, block.Connectivity.data(), nullptr, nullptr),
      "the connectivity of " + header.What);
    blocks.push_back(std::move(block));
  }
  mesh.Dimension = dimension;
  const auto nodeCount = static_cast<std::int64_t>(mesh.NumberOfNodes());
  std::size_t volumeCells = 0, volumeNodes = 0;
  for (const Block& block : blocks)
  {
    if (DimensionOfCellType(block.Type) == dimension)
    {
      volumeCells +=
        block.Connectivity.size() / static_cast<std::size_t>(NodesOfCellType(block.Type));
      volumeNodes += block.Connectivity.size();
    }
  }
  mesh.Volume.Reserve(volumeCells, volumeNodes); // (no copy as the cells are added)
  for (const Block& block : blocks)
  {
    if (DimensionOfCellType(block.Type) != dimension)
    {
      continue; // lower-dimensional blocks (beams, shells of a 3D mesh) are not volume cells
    }
    const int n = NodesOfCellType(block.Type);
    std::vector<std::int64_t> cell(static_cast<std::size_t>(n));
    for (std::size_t first = 0; first < block.Connectivity.size(); first += cell.size())
    {
      for (std::size_t k = 0; k < cell.size(); ++k)
      {
        const std::int64_t node = block.Connectivity[first + k];
        if (node < 1 || node > nodeCount)
        {
          throw FileError(file.Path + ": an element uses node " + std::to_string(node) +
            ", outside 1.." + std::to_string(nodeCount) + CutShortHint(node));
        }
        cell[k] = node - 1;
      }
      mesh.Volume.Add(block.Type, cell.data(), cell.size());
    }
  }
}

/// The side set `id` as faces (edges in 2D) on 0-based nodes.
Cells ReadSideSet(const ExodusHandle& file, std::int64_t id, const std::string& name,
  const NamedMesh& mesh, std::int64_t elements)
{
  std::int64_t sides = 0, factors = 0;
  const std::string what = "side set " + name;
  file.Check(ex_get_set_param(file.Id, EX_SIDE_SET, id, &sides, &factors), what);
  if (sides < 0 || sides > 6 * elements)
  {
    throw FileError(file.Path + ": " + what + " declares " + std::to_string(sides) + " sides");
  }
  Cells faces;
  if (sides == 0)
  {
    return faces;
  }
  // The library checks the sides' elements and side numbers, and gives each side's nodes.
  std::int64_t length = 0;
  file.Check(ex_get_side_set_node_list_len(file.Id, id, &length), what);
  if (length < 0 || length > 8 * sides)
  {
    throw FileError(file.Path + ": " + what + " declares " + std::to_string(length) + " nodes");
  }
  std::vector<std::int64_t> counts(static_cast<std::size_t>(sides));
  std::vector<std::int64_t> nodes(static_cast<std::size_t>(length));
  file.Check(ex_get_side_set_node_list(file.Id, id, counts.data(), nodes.data()), what);
  const auto nodeCount = static_cast<std::int64_t>(mesh.NumberOfNodes());
  std::size_t next = 0;
  for (const std::int64_t count : counts)
  {
    const std::uint8_t type = mesh.Dimension == 2 ? (count == 2 ? Line : 0)
      : count == 3                                ? Triangle
      : count == 4                                ? Quad
                                                  : 0;
    if (type == 0 || next + static_cast<std::size_t>(count) > nodes.size())
    {
      throw FileError(file.Path + ": " + what + " has a side with " + std::to_string(count) +
        " nodes, not a face of the " + std::to_string(mesh.Dimension) + "D mesh");
    }
    std::int64_t face[4];
    for (std::int64_t k = 0; k < count; ++k)
    {
      const std::int64_t node = nodes[next++];
      if (node < 1 || node > nodeCount)
      {
        throw FileError(
          file.Path + ": " + what + " uses node " + std::to_string(node) + CutShortHint(node));
      }
      face[k] = node - 1;
    }
    faces.Add(type, face, static_cast<std::size_t>(count));
  }
  return faces;
}

/// The node set `id` as Vertex cells on 0-based nodes, sorted, each node once.
Cells ReadNodeSet(
  const ExodusHandle& file, std::int64_t id, const std::string& name, const NamedMesh& mesh)
{
  std::int64_t count = 0, factors = 0;
  const std::string what = "node set " + name;
  file.Check(ex_get_set_param(file.Id, EX_NODE_SET, id, &count, &factors), what);
  const auto nodeCount = static_cast<std::int64_t>(mesh.NumberOfNodes());
  if (count < 0 || count > nodeCount)
  {
    throw FileError(file.Path + ": " + what + " declares " + std::to_string(count) + " nodes");
  }
  std::vector<std::int64_t> nodes(static_cast<std::size_t>(count));
  if (count > 0)
  {
    file.Check(ex_get_set(file.Id, EX_NODE_SET, id, nodes.data(), nullptr), what);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  Cells vertices;
  for (std::int64_t node : nodes)
  {
    if (node < 1 || node > nodeCount)
    {
      throw FileError(file.Path + ": " + what + " holds node " + std::to_string(node) +
        ", outside 1.." + std::to_string(nodeCount) + CutShortHint(node));
    }
    const std::int64_t index = node - 1;
    vertices.Add(Vertex, &index, 1);
  }
  return vertices;
}

/// The sorted distinct nodes of `cells`.
std::vector<std::int64_t> NodesOf(const Cells& cells)
{
  std::vector<std::int64_t> nodes(cells.Connectivity);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}
} // namespace

/// ReadExodus in this process (ReadExodus runs it in a child).
static NamedMesh ReadExodusInThisProcess(const std::string& path)
{
  ExodusHandle file(path, EX_READ);
  const ex_init_params sizes = ReadSizes(file);
  NamedMesh mesh;
  const auto n = static_cast<std::size_t>(sizes.num_nodes);
  std::vector<double> x(n), y(n), z(n, 0.0);
  if (n > 0)
  {
    file.Check(ex_get_coord(file.Id, x.data(), y.data(), sizes.num_dim == 3 ? z.data() : nullptr),
      "the coordinates");
  }
  mesh.Points.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    mesh.Points[3 * i] = x[i];
    mesh.Points[3 * i + 1] = y[i];
    mesh.Points[3 * i + 2] = z[i];
  }
  mesh.NodeIds.resize(n);
  if (n > 0)
  {
    file.Check(ex_get_id_map(file.Id, EX_NODE_MAP, mesh.NodeIds.data()), "the node number map");
  }
  ReadElementBlocks(file, sizes, mesh);
  if (mesh.Dimension == 2 && std::any_of(z.begin(), z.end(), [](double c) { return c != 0.0; }))
  {
    throw FileError(path + ": a mesh of 2D elements must lie in the plane z = 0");
  }

  std::vector<std::int64_t> ids;
  std::vector<std::string> names;
  ReadIdsAndNames(file, EX_SIDE_SET, sizes.num_side_sets, "sideset", ids, names);
  for (std::size_t s = 0; s < ids.size(); ++s)
  {
    mesh.Boundaries.push_back(
      { names[s], ReadSideSet(file, ids[s], names[s], mesh, sizes.num_elem), std::string() });
  }
  const std::size_t sideSets = mesh.Boundaries.size();
  ReadIdsAndNames(file, EX_NODE_SET, sizes.num_node_sets, "nodeset", ids, names);
  for (std::size_t s = 0; s < ids.size(); ++s)
  {
    Cells nodes = ReadNodeSet(file, ids[s], names[s], mesh);
    const auto twin = std::find_if(mesh.Boundaries.begin(),
      mesh.Boundaries.begin() + static_cast<std::ptrdiff_t>(sideSets),
      [&](const NamedBoundary& b) { return b.Name == names[s]; });
    if (twin == mesh.Boundaries.begin() + static_cast<std::ptrdiff_t>(sideSets))
    {
      mesh.Boundaries.push_back({ names[s], std::move(nodes), std::string() });
    }
    else if (NodesOf(twin->Faces) != nodes.Connectivity)
    {
      // A node set named as a side set but holding other nodes keeps its nodes under its own name.
      mesh.Boundaries.push_back({ names[s] + " (node set)", std::move(nodes), std::string() });
    }
  }
  // Empty sets name nothing.
  mesh.Boundaries.erase(std::remove_if(mesh.Boundaries.begin(), mesh.Boundaries.end(),
                          [](const NamedBoundary& b) { return b.Faces.Size() == 0; }),
    mesh.Boundaries.end());
  ValidateNamedMesh(mesh, path);
  return mesh;
}

NamedMesh ReadExodus(const std::string& path)
{
  return ReadMeshIsolated(
    path, "the Exodus library", [&]() { return ReadExodusInThisProcess(path); });
}

/// WriteExodusWithPoints in this process (WriteExodusWithPoints runs it in a child).
static void WriteExodusWithPointsInThisProcess(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  // What the write needs of the source: its node count and the mesh's dimension (the element
  // blocks' headers, their connectivity not read), and a 2D mesh's z.
  std::vector<double> z(count, 0.0);
  int written = 0; // the coordinates given: a 2D mesh keeps the file's z (0)
  {
    ExodusHandle file(source, EX_READ);
    const ex_init_params sizes = ReadSizes(file);
    if (count != static_cast<std::size_t>(sizes.num_nodes))
    {
      throw FileError(target + ": " + std::to_string(count) + " points given for the " +
        std::to_string(sizes.num_nodes) + " nodes of " + source + "; nothing was written");
    }
    ReadBlockHeaders(file, sizes, written);
    if (written == 2 && sizes.num_dim == 3 && count > 0)
    {
      file.Check(ex_get_coord(file.Id, nullptr, nullptr, z.data()), "the coordinates");
      if (std::any_of(z.begin(), z.end(), [](double c) { return c != 0.0; }))
      {
        throw FileError(source + ": a mesh of 2D elements must lie in the plane z = 0");
      }
    }
  }
  std::vector<double> x(count), y(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < written; ++c)
    {
      if (!std::isfinite(points[3 * i + c]))
      {
        throw FileError(target + ": point " + std::to_string(i) +
          " has a non-finite coordinate; nothing was written");
      }
    }
    x[i] = points[3 * i];
    y[i] = points[3 * i + 1];
    if (written == 3)
    {
      z[i] = points[3 * i + 2];
    }
  }
  WriteModifiedCopy(source, target,
    [&](const std::string& temporary)
    {
      ExodusHandle file(temporary, EX_WRITE);
      const ex_init_params sizes = ReadSizes(file);
      const int dimensions = static_cast<int>(sizes.num_dim);
      int combined = -1;
      if (nc_inq_varid(file.Id, "coord", &combined) == NC_NOERR)
      {
        // The old layout, one variable coord[num_dim][num_nodes] (meshio writes it), which
        // ex_put_coord does not write: written through netCDF, converted to its type by it.
        std::vector<double> all(x);
        all.insert(all.end(), y.begin(), y.end());
        if (dimensions == 3)
        {
          all.insert(all.end(), z.begin(), z.end());
        }
        const int status = nc_put_var_double(file.Id, combined, all.data());
        if (status != NC_NOERR)
        {
          throw FileError(
            temporary + ": cannot write the coordinates (" + nc_strerror(status) + ")");
        }
      }
      else
      {
        file.Check(ex_put_coord(file.Id, x.data(), y.data(), dimensions == 3 ? z.data() : nullptr),
          "(writing) the coordinates");
      }
      file.Close();
    });
}

void WriteExodusWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  WriteIsolated(source, target, "the Exodus library",
    [&]() { WriteExodusWithPointsInThisProcess(source, target, points, count); });
}

} // namespace meshfile
} // namespace dgmf
