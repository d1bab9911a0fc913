// A version 4.1 .msh file read without gmsh (MshReader41.h). The layout: gmsh's reference manual,
// "MSH file format"; the order of everything: what gmsh's library gives (GmshModel.cxx's
// ReadModel), checked against it on every test mesh (gmsh.MshReader41.*).
#include "dgmf/meshfile/MshReader41.h"

#include "dgmf/meshfile/MshElementTypes.h"
#include "dgmf/meshfile/MshNodeIndex.h"
#include "dgmf/meshfile/MshText.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
using namespace msh;

/// Numbers in the file's mode: tokens (ASCII), or binary values of this machine's order (int 4
/// bytes, size_t 8, double 8: the "8" of the format line).
class Values
{
public:
  Values(Cursor& cursor, bool binary)
    : At(cursor)
    , Binary(binary)
  {
  }

  bool Int(int& value)
  {
    if (this->Binary)
    {
      std::int32_t read = 0;
      const bool ok = this->At.Binary(read);
      value = read;
      return ok;
    }
    return ToInteger(this->At.Token(), value);
  }

  bool Size(std::uint64_t& value)
  {
    return this->Binary ? this->At.Binary(value) : ToInteger(this->At.Token(), value);
  }

  bool Real(double& value)
  {
    if (this->Binary)
    {
      return this->At.Binary(value);
    }
    const std::string_view token = this->At.Token();
    const char* end = token.data() + token.size();
    const std::from_chars_result read = std::from_chars(token.data(), end, value);
    return !token.empty() && read.ec == std::errc() && read.ptr == end;
  }

  /// Bytes left in the file.
  std::size_t Left() const { return this->At.File.size() - this->At.At; }

private:
  Cursor& At;
  bool Binary;
};

/// A block of elements of $Elements: the entity, the type, where its node tags start, how many.
struct ElementBlock
{
  int Dimension = 0, Entity = 0, Type = 0;
  std::size_t First = 0, Count = 0;
};

/// What the sections give.
struct Model
{
  std::map<int, std::vector<int>> Entities[4];      ///< by dimension: entity tag -> physical tags
  std::map<std::pair<int, int>, std::string> Names; ///< (dimension, physical tag) -> name
  std::vector<std::uint64_t> NodeTags;
  std::vector<double> Coordinates;
  std::vector<ElementBlock> Blocks;
  std::vector<std::uint64_t> ElementNodes; ///< the blocks' node tags, one block after the other
};

bool EndsSection(Cursor& cursor, std::string_view name)
{
  const std::string_view token = cursor.Token();
  return token.size() == name.size() + 4 && token.substr(0, 4) == "$End" && token.substr(4) == name;
}

/// $PhysicalNames (text in binary files too): `dimension tag "name"` per line.
bool ParsePhysicalNames(Cursor& cursor, Model& model)
{
  std::uint64_t count = 0;
  if (!ToInteger(cursor.Token(), count))
  {
    return false;
  }
  for (std::uint64_t k = 0; k < count; ++k)
  {
    int dimension = 0, tag = 0;
    if (!ToInteger(cursor.Token(), dimension) || !ToInteger(cursor.Token(), tag))
    {
      return false;
    }
    const std::string_view quoted = cursor.Line();
    if (quoted.size() < 2 || quoted.front() != '"' || quoted.back() != '"' ||
      !model.Names.emplace(std::make_pair(dimension, tag), quoted.substr(1, quoted.size() - 2))
         .second)
    {
      return false;
    }
  }
  return EndsSection(cursor, "PhysicalNames");
}

/// $Entities: points, curves, surfaces, volumes with their physical tags (bounding boxes and
/// bounding entities read past).
bool ParseEntities(Cursor& cursor, bool binary, Model& model)
{
  Values values(cursor, binary);
  std::uint64_t counts[4];
  for (std::uint64_t& count : counts)
  {
    if (!values.Size(count))
    {
      return false;
    }
  }
  for (int dimension = 0; dimension < 4; ++dimension)
  {
    for (std::uint64_t k = 0; k < counts[dimension]; ++k)
    {
      int tag = 0;
      double box = 0.0;
      std::uint64_t physicals = 0;
      if (!values.Int(tag))
      {
        return false;
      }
      for (int c = 0; c < (dimension == 0 ? 3 : 6); ++c)
      {
        if (!values.Real(box))
        {
          return false;
        }
      }
      if (!values.Size(physicals))
      {
        return false;
      }
      std::vector<int> tags;
      for (std::uint64_t p = 0; p < physicals; ++p) // (each read takes a byte at least)
      {
        int physical = 0;
        if (!values.Int(physical) || physical < 1)
        {
          return false;
        }
        if (std::find(tags.begin(), tags.end(), physical) == tags.end())
        {
          tags.push_back(physical);
        }
      }
      std::uint64_t bounding = 0;
      int boundingTag = 0;
      if (dimension > 0 && !values.Size(bounding))
      {
        return false;
      }
      for (std::uint64_t b = 0; b < bounding; ++b)
      {
        if (!values.Int(boundingTag))
        {
          return false;
        }
      }
      if (!model.Entities[dimension].emplace(tag, std::move(tags)).second)
      {
        return false; // an entity twice
      }
    }
  }
  return EndsSection(cursor, "Entities");
}

bool ParseNodes(Cursor& cursor, bool binary, Model& model)
{
  Values values(cursor, binary);
  std::uint64_t blocks = 0, count = 0, minimum = 0, maximum = 0;
  if (!values.Size(blocks) || !values.Size(count) || !values.Size(minimum) ||
    !values.Size(maximum) || !model.NodeTags.empty())
  {
    return false;
  }
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    int dimension = 0, entity = 0, parametric = 0;
    std::uint64_t inBlock = 0;
    // A node takes 8 bytes at least (a tag and three numbers in ASCII; 32 in binary).
    if (!values.Int(dimension) || !values.Int(entity) || !values.Int(parametric) ||
      parametric != 0 || !values.Size(inBlock) || inBlock > count - model.NodeTags.size() ||
      inBlock > values.Left() / 8)
    {
      return false;
    }
    const std::size_t first = model.NodeTags.size();
    model.NodeTags.resize(first + static_cast<std::size_t>(inBlock));
    for (std::size_t k = first; k < model.NodeTags.size(); ++k)
    {
      if (!values.Size(model.NodeTags[k]))
      {
        return false;
      }
    }
    model.Coordinates.resize(3 * model.NodeTags.size());
    for (std::size_t k = 3 * first; k < model.Coordinates.size(); ++k)
    {
      if (!values.Real(model.Coordinates[k]))
      {
        return false;
      }
    }
  }
  return model.NodeTags.size() == count && EndsSection(cursor, "Nodes");
}

bool ParseElements(Cursor& cursor, bool binary, Model& model)
{
  Values values(cursor, binary);
  std::uint64_t blocks = 0, count = 0, minimum = 0, maximum = 0, read = 0;
  if (!values.Size(blocks) || !values.Size(count) || !values.Size(minimum) ||
    !values.Size(maximum) || !model.Blocks.empty())
  {
    return false;
  }
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    ElementBlock block;
    std::uint64_t inBlock = 0;
    CellMapping mapping;
    if (!values.Int(block.Dimension) || !values.Int(block.Entity) || !values.Int(block.Type) ||
      !values.Size(inBlock) || !MapGmshType(block.Type, mapping) ||
      mapping.Dimension != block.Dimension || inBlock > count - read ||
      inBlock > values.Left() / (2 * static_cast<std::size_t>(mapping.Nodes + 1)))
    {
      return false;
    }
    block.First = model.ElementNodes.size();
    block.Count = static_cast<std::size_t>(inBlock);
    model.ElementNodes.resize(block.First + block.Count * static_cast<std::size_t>(mapping.Nodes));
    std::uint64_t* nodes = model.ElementNodes.data() + block.First;
    for (std::size_t e = 0; e < block.Count; ++e)
    {
      std::uint64_t tag = 0;
      if (!values.Size(tag))
      {
        return false;
      }
      for (int k = 0; k < mapping.Nodes; ++k)
      {
        if (!values.Size(*nodes++))
        {
          return false;
        }
      }
    }
    read += inBlock;
    model.Blocks.push_back(block);
  }
  return read == count && EndsSection(cursor, "Elements");
}

/// The blocks of each (dimension, entity), in the file's order.
using BlocksByEntity = std::map<std::pair<int, int>, std::vector<std::size_t>>;

/**
 * Appends the elements of entity (dimension, entity) to `cells`: its types in increasing gmsh
 * type, each type's blocks in the file's order. False when an element's node is not a node.
 */
bool AppendEntity(const Model& model, const BlocksByEntity& blocks, const NodeIndex& index,
  int dimension, int entity, Cells& cells)
{
  const auto found = blocks.find({ dimension, entity });
  if (found == blocks.end())
  {
    return true;
  }
  std::vector<int> types;
  for (const std::size_t b : found->second)
  {
    types.push_back(model.Blocks[b].Type);
  }
  std::sort(types.begin(), types.end());
  types.erase(std::unique(types.begin(), types.end()), types.end());
  for (const int type : types)
  {
    CellMapping mapping;
    MapGmshType(type, mapping);
    for (const std::size_t b : found->second)
    {
      const ElementBlock& block = model.Blocks[b];
      if (block.Type != type)
      {
        continue;
      }
      const std::uint64_t* nodes = model.ElementNodes.data() + block.First;
      std::int64_t cell[8];
      for (std::size_t e = 0; e < block.Count; ++e, nodes += mapping.Nodes)
      {
        for (int k = 0; k < mapping.Nodes; ++k)
        {
          cell[k] = index.Find(nodes[mapping.Order[k]]);
          if (cell[k] < 0)
          {
            return false;
          }
        }
        cells.Add(mapping.Type, cell, static_cast<std::size_t>(mapping.Nodes));
      }
    }
  }
  return true;
}

/// The model's mesh as ReadGmsh gives it (MshReader41.h); false for what it leaves to gmsh.
bool BuildMesh(const Model& model, NamedMesh& mesh)
{
  // The nodes in increasing tag order, each once.
  const std::size_t n = model.NodeTags.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  if (!std::is_sorted(model.NodeTags.begin(), model.NodeTags.end()))
  {
    std::sort(order.begin(), order.end(),
      [&](std::size_t a, std::size_t b) { return model.NodeTags[a] < model.NodeTags[b]; });
  }
  std::vector<std::size_t> tags(n);
  mesh.Points.resize(3 * n);
  mesh.NodeIds.resize(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    tags[k] = static_cast<std::size_t>(model.NodeTags[order[k]]);
    if ((k > 0 && tags[k] == tags[k - 1]) || tags[k] > static_cast<std::size_t>(INT64_MAX))
    {
      return false;
    }
    mesh.NodeIds[k] = static_cast<std::int64_t>(tags[k]);
    std::copy_n(&model.Coordinates[3 * order[k]], 3, &mesh.Points[3 * k]);
  }
  // The dimension: the highest of the entities with elements; every block's entity listed.
  BlocksByEntity blocks;
  mesh.Dimension = 0;
  for (std::size_t b = 0; b < model.Blocks.size(); ++b)
  {
    const ElementBlock& block = model.Blocks[b];
    if (block.Dimension < 0 || block.Dimension > 3 ||
      model.Entities[block.Dimension].count(block.Entity) == 0)
    {
      return false;
    }
    blocks[{ block.Dimension, block.Entity }].push_back(b);
    if (block.Count > 0 && block.Dimension >= 2)
    {
      mesh.Dimension = std::max(mesh.Dimension, block.Dimension);
    }
  }
  if (mesh.Dimension == 0)
  {
    return false;
  }
  if (mesh.Dimension == 2)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      if (mesh.Points[3 * k + 2] != 0.0)
      {
        return false;
      }
    }
  }
  const NodeIndex index(tags);
  const int dimension = mesh.Dimension;
  for (const auto& entity : model.Entities[dimension])
  {
    if (!AppendEntity(model, blocks, index, dimension, entity.first, mesh.Volume))
    {
      return false;
    }
  }
  // The physical groups one dimension lower, their entities in increasing tag.
  std::map<int, std::vector<int>> groups;
  for (const auto& entity : model.Entities[dimension - 1])
  {
    for (const int physical : entity.second)
    {
      groups[physical].push_back(entity.first);
    }
  }
  for (const auto& group : groups)
  {
    NamedBoundary boundary;
    const auto name = model.Names.find({ dimension - 1, group.first });
    boundary.Name = name != model.Names.end() && !name->second.empty()
      ? name->second
      : "group " + std::to_string(group.first);
    for (const int entity : group.second)
    {
      if (!AppendEntity(model, blocks, index, dimension - 1, entity, boundary.Faces))
      {
        return false;
      }
    }
    mesh.Boundaries.push_back(std::move(boundary));
  }
  return true;
}
} // namespace

bool ReadMsh41(std::string_view file, bool binary, NamedMesh& mesh)
{
  Cursor cursor{ file };
  if (NextSection(cursor) != "MeshFormat")
  {
    return false;
  }
  if (binary)
  {
    cursor.Line(); // "4.1 1 8"
    std::int32_t one = 0;
    if (!cursor.Binary(one) || one != 1)
    {
      return false; // the other byte order
    }
  }
  if (!SkipSection(cursor, "MeshFormat"))
  {
    return false;
  }
  Model model;
  bool entities = false, nodes = false, elements = false;
  for (std::string_view name = NextSection(cursor); !name.empty(); name = NextSection(cursor))
  {
    bool parsed = true;
    if (name == "PhysicalNames")
    {
      parsed = ParsePhysicalNames(cursor, model);
    }
    else if (name == "Entities")
    {
      parsed = !entities && ParseEntities(cursor, binary, model);
      entities = true;
    }
    else if (name == "Nodes")
    {
      parsed = ParseNodes(cursor, binary, model);
      nodes = true;
    }
    else if (name == "Elements")
    {
      parsed = ParseElements(cursor, binary, model);
      elements = true;
    }
    else if (name == "PartitionedEntities" || name == "GhostElements" || name == "Parametrizations")
    {
      return false;
    }
    else
    {
      parsed = SkipSection(cursor, name); // comments, periodicity, post-processing data
    }
    if (!parsed)
    {
      return false;
    }
  }
  while (cursor.At < file.size() && IsBlank(file[cursor.At]))
  {
    ++cursor.At;
  }
  if (cursor.At < file.size() || !entities || !nodes || !elements)
  {
    return false; // a line outside any section, or a section missing
  }
  mesh = NamedMesh();
  return BuildMesh(model, mesh);
}

} // namespace meshfile
} // namespace dgmf
