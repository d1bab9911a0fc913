// A .msh file's sections as the mesh gmsh's library gives (MshModel.h). The order of everything:
// GmshModel.cxx's ReadModel, checked against it on every test mesh (gmsh.MshReader41.*,
// gmsh.MshReader22.*).
#include "dgmf/meshfile/MshModel.h"

#include "dgmf/HugePages.h"
#include "dgmf/meshfile/MshElementTypes.h"
#include "dgmf/meshfile/MshNodeIndex.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <numeric>
#include <unordered_set>

namespace dgmf
{
namespace meshfile
{
namespace
{
using namespace msh;

/// A cell's VTK type and its sorted node indices (the rest -1): equal for the copies of an element.
using CellKey = std::array<std::int64_t, 9>;

struct CellKeyHash
{
  std::size_t operator()(const CellKey& key) const
  {
    std::size_t hash = 0;
    for (const std::int64_t value : key)
    {
      hash = hash * 1000003u ^ std::hash<std::int64_t>()(value);
    }
    return hash;
  }
};

/// The cells already read (Version2Rules::ReadRepeatedElementsOnce), or nullptr for none.
using SeenCells = std::unordered_set<CellKey, CellKeyHash>;

/// The blocks of each (dimension, entity), in the model's order.
using BlocksByEntity = std::map<std::pair<int, int>, std::vector<std::size_t>>;

/**
 * Appends the elements of entity (dimension, entity) to `cells`: its types in increasing gmsh
 * type, each type's blocks in the model's order; with `seen`, an element whose copy is already
 * there is skipped. False when an element's node is not a node.
 */
bool AppendEntity(const MshModel& model, const BlocksByEntity& blocks, const NodeIndex& index,
  int dimension, int entity, SeenCells* seen, Cells& cells)
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
        if (seen)
        {
          CellKey key;
          key.fill(-1);
          std::copy_n(cell, mapping.Nodes, key.begin());
          std::sort(key.begin(), key.begin() + mapping.Nodes);
          key[8] = mapping.Type;
          if (!seen->insert(key).second)
          {
            continue;
          }
        }
        cells.Add(mapping.Type, cell, static_cast<std::size_t>(mapping.Nodes));
      }
    }
  }
  return true;
}

/// Reserves in `cells` the room of the elements of `entities` of `dimension` (no copy as it grows).
void Reserve(const MshModel& model, const BlocksByEntity& blocks, int dimension,
  const std::vector<int>& entities, Cells& cells)
{
  std::size_t count = 0, nodes = 0;
  for (const int entity : entities)
  {
    const auto found = blocks.find({ dimension, entity });
    if (found == blocks.end())
    {
      continue;
    }
    for (const std::size_t b : found->second)
    {
      CellMapping mapping;
      MapGmshType(model.Blocks[b].Type, mapping);
      count += model.Blocks[b].Count;
      nodes += model.Blocks[b].Count * static_cast<std::size_t>(mapping.Nodes);
    }
  }
  cells.Reserve(count, nodes);
}

/// Whether an entity of `dimension` is in several physical groups.
bool AnEntityInSeveralGroups(const MshModel& model, int dimension)
{
  return std::any_of(model.Entities[dimension].begin(), model.Entities[dimension].end(),
    [](const auto& entity) { return entity.second.size() > 1; });
}

/**
 * Keeps only the nodes some element uses (`tags` sorted, `index` theirs, the mesh's nodes the
 * same); false when an element node is not a node. Nothing is copied, and `index` stays, when
 * every node is used.
 */
bool DropUnusedNodes(
  const MshModel& model, std::vector<std::size_t>& tags, NodeIndex& index, NamedMesh& mesh)
{
  std::vector<char> used(tags.size(), 0);
  for (const std::uint64_t tag : model.ElementNodes)
  {
    const std::int64_t k = index.Find(static_cast<std::size_t>(tag));
    if (k < 0)
    {
      return false;
    }
    used[static_cast<std::size_t>(k)] = 1;
  }
  if (std::find(used.begin(), used.end(), 0) == used.end())
  {
    return true;
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < tags.size(); ++k)
  {
    if (used[k])
    {
      tags[kept] = tags[k];
      mesh.NodeIds[kept] = mesh.NodeIds[k];
      std::memmove(&mesh.Points[3 * kept], &mesh.Points[3 * k], 3 * sizeof(double));
      ++kept;
    }
  }
  tags.resize(kept);
  mesh.NodeIds.resize(kept);
  mesh.Points.resize(3 * kept);
  index = NodeIndex(tags);
  return true;
}
} // namespace

bool ParsePhysicalNames(Cursor& cursor, MshModel& model)
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

bool BuildMeshAsGmshDoes(const MshModel& model, const Version2Rules& rules, NamedMesh& mesh)
{
  mesh = NamedMesh();
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
  ResizeOnHugePages(mesh.Points, 3 * n);
  ResizeOnHugePages(mesh.NodeIds, n);
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
  NodeIndex index(tags);
  if (rules.DropUnusedNodes && !DropUnusedNodes(model, tags, index, mesh))
  {
    return false;
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
    for (std::size_t k = 0; k < mesh.NodeIds.size(); ++k)
    {
      if (mesh.Points[3 * k + 2] != 0.0)
      {
        return false;
      }
    }
  }
  const int dimension = mesh.Dimension;
  SeenCells seen;
  SeenCells* volumeSeen =
    rules.ReadRepeatedElementsOnce && AnEntityInSeveralGroups(model, dimension) ? &seen : nullptr;
  std::vector<int> volumeEntities;
  for (const auto& entity : model.Entities[dimension])
  {
    volumeEntities.push_back(entity.first);
  }
  Reserve(model, blocks, dimension, volumeEntities, mesh.Volume);
  for (const auto& entity : model.Entities[dimension])
  {
    if (!AppendEntity(model, blocks, index, dimension, entity.first, volumeSeen, mesh.Volume))
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
  const bool facesOnce =
    rules.ReadRepeatedElementsOnce && AnEntityInSeveralGroups(model, dimension - 1);
  for (const auto& group : groups)
  {
    NamedBoundary boundary;
    const auto name = model.Names.find({ dimension - 1, group.first });
    boundary.Name = name != model.Names.end() && !name->second.empty()
      ? name->second
      : "group " + std::to_string(group.first);
    seen.clear();
    Reserve(model, blocks, dimension - 1, group.second, boundary.Faces);
    for (const int entity : group.second)
    {
      if (!AppendEntity(model, blocks, index, dimension - 1, entity, facesOnce ? &seen : nullptr,
            boundary.Faces))
      {
        return false;
      }
    }
    mesh.Boundaries.push_back(std::move(boundary));
  }
  for (const auto& named : model.Names)
  {
    if (named.first.first != dimension - 1 && !named.second.empty())
    {
      mesh.OtherGroups.emplace_back(named.second, named.first.first);
    }
  }
  return true;
}

} // namespace meshfile
} // namespace dgmf
