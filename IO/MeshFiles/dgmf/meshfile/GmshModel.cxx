// The gmsh module (GmshModule.h): a .msh file read into a NamedMesh and written back with moved
// nodes, through gmsh's own library. Called by GmshFile.cxx in a child process
// (LibraryIsolation.h); the gmsh calls run in a GmshSession (GmshSession.h): serialized, silent,
// errors collected from gmsh's logger.
#include "dgmf/NumberText.h"
#include "dgmf/meshfile/GmshModule.h"
#include "dgmf/meshfile/GmshSession.h"
#include "dgmf/meshfile/MeshBytes.h"
#include "dgmf/meshfile/MshElementTypes.h"
#include "dgmf/meshfile/MshNodeIndex.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <set>
#include <type_traits>

namespace dgmf
{
namespace meshfile
{
namespace fs = std::filesystem;

namespace
{
std::string GmshTypeName(int gmshType)
{
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> coordinates;
  try
  {
    gmsh::model::mesh::getElementProperties(
      gmshType, name, dim, order, nodes, coordinates, primary);
  }
  catch (...)
  {
  }
  return "gmsh element type " + std::to_string(gmshType) + (name.empty() ? "" : " (" + name + ")");
}

/// All the model's nodes, sorted by tag (each once: getNodes(-1, -1) without includeBoundary).
struct ModelNodes
{
  std::vector<std::size_t> Tags;
  std::vector<double> Coordinates;
};

ModelNodes GetSortedNodes(GmshSession& session)
{
  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
  session.ThrowOnGmshError("gmsh cannot give its nodes");
  if (coordinates.size() != 3 * tags.size())
  {
    session.Fail("gmsh gives " + std::to_string(coordinates.size()) + " coordinates for " +
      std::to_string(tags.size()) + " nodes");
  }
  std::vector<std::size_t> order(tags.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
    [&tags](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  ModelNodes nodes;
  nodes.Tags.resize(tags.size());
  nodes.Coordinates.resize(coordinates.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    nodes.Tags[k] = tags[order[k]];
    std::copy_n(&coordinates[3 * order[k]], 3, &nodes.Coordinates[3 * k]);
    if (k > 0 && nodes.Tags[k] == nodes.Tags[k - 1])
    {
      session.Fail("node tag " + std::to_string(nodes.Tags[k]) + " appears twice");
    }
  }
  return nodes;
}

/**
 * The elements of entity (dim, tag) (all entities of `dim` if tag < 0), type by type, as
 * gmsh::model::mesh::getElements gives them: getElementsByType gives the same elements in the
 * same order, and took 0.15 s where getElements took 0.24 s (1.29M tetrahedra, gmsh 4.8).
 */
void GetElementsByType(int dim, int tag, std::vector<int>& types,
  std::vector<std::vector<std::size_t>>& elementTags,
  std::vector<std::vector<std::size_t>>& nodeTags)
{
  gmsh::model::mesh::getElementTypes(types, dim, tag);
  // Fresh vectors for each type: gmsh only resizes them when they are too small (its
  // preallocation for several tasks), so a second type's would keep the first's length.
  elementTags.assign(types.size(), {});
  nodeTags.assign(types.size(), {});
  for (std::size_t t = 0; t < types.size(); ++t)
  {
    gmsh::model::mesh::getElementsByType(types[t], elementTags[t], nodeTags[t], tag);
  }
}

/**
 * Appends the elements of entity (dim, tag) (all entities of `dim` if tag < 0) to `cells`. A
 * version 2 file lists an element once per physical group of its entity and gmsh keeps every
 * copy: with `unique`, an element whose type and nodes are already in `seen` is skipped.
 */
void AddElements(GmshSession& session, const NodeIndex& index, int dim, int tag, bool unique,
  std::set<std::vector<std::int64_t>>& seen, Cells& cells)
{
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elementTags, nodeTags;
  GetElementsByType(dim, tag, types, elementTags, nodeTags);
  session.ThrowOnGmshError("gmsh cannot give its elements");
  for (std::size_t t = 0; t < types.size(); ++t)
  {
    CellMapping mapping;
    if (!MapGmshType(types[t], mapping))
    {
      session.Fail(GmshTypeName(types[t]) + " is not supported (first-order points, lines, " +
        "triangles, quadrangles, tetrahedra, hexahedra, prisms and pyramids only)");
    }
    const std::vector<std::size_t>& nodes = nodeTags[t];
    if (nodes.size() != elementTags[t].size() * static_cast<std::size_t>(mapping.Nodes))
    {
      session.Fail("gmsh gives inconsistent nodes for " + GmshTypeName(types[t]));
    }
    std::int64_t cell[8];
    std::vector<std::int64_t> key;
    for (std::size_t e = 0; e < elementTags[t].size(); ++e)
    {
      for (int k = 0; k < mapping.Nodes; ++k)
      {
        const std::size_t nodeTag = nodes[e * mapping.Nodes + mapping.Order[k]];
        cell[k] = index.Find(nodeTag);
        if (cell[k] < 0)
        {
          session.Fail("element " + std::to_string(elementTags[t][e]) + " uses node tag " +
            std::to_string(nodeTag) + ", which is not a node of the file");
        }
      }
      if (unique)
      {
        key.assign(cell, cell + mapping.Nodes);
        std::sort(key.begin(), key.end());
        key.push_back(mapping.Type);
        if (!seen.insert(key).second)
        {
          continue;
        }
      }
      cells.Add(mapping.Type, cell, static_cast<std::size_t>(mapping.Nodes));
    }
  }
}

/// Whether the model has elements of dimension `dim` (the types present: nothing copied).
bool HasElements(int dim)
{
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, dim, -1);
  return !types.empty();
}

/// The number of physical groups of each entity of dimension `dim`.
std::size_t MostPhysicalGroupsOfAnEntity(int dim)
{
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  std::size_t most = 0;
  for (const auto& entity : entities)
  {
    std::vector<int> groups;
    gmsh::model::getPhysicalGroupsForEntity(entity.first, entity.second, groups);
    most = std::max(most, groups.size());
  }
  return most;
}

NamedMesh ReadModel(GmshSession& session, const MshFormat& format)
{
  NamedMesh mesh;
  const ModelNodes nodes = GetSortedNodes(session);
  mesh.NodeIds.assign(nodes.Tags.begin(), nodes.Tags.end());
  mesh.Points = nodes.Coordinates;
  const NodeIndex index(nodes.Tags);

  mesh.Dimension = HasElements(3) ? 3 : (HasElements(2) ? 2 : 0);
  session.ThrowOnGmshError("gmsh cannot give its elements");
  if (mesh.Dimension == 0)
  {
    session.Fail("no 2D or 3D element");
  }
  if (mesh.Dimension == 2 && !nodes.Tags.empty())
  {
    // A 2D mesh lies in one plane z = constant (the filter keeps that z; until 2026-11-30 only
    // z = 0 was read), up to 1e-6 of its extent in x and y, as the filter takes it (a mesh turned
    // into the plane by a transform, single precision).
    const double z = nodes.Coordinates[2];
    double low[2] = { nodes.Coordinates[0], nodes.Coordinates[1] };
    double high[2] = { low[0], low[1] };
    for (std::size_t k = 0; k < nodes.Tags.size(); ++k)
    {
      for (int c = 0; c < 2; ++c)
      {
        low[c] = std::min(low[c], nodes.Coordinates[3 * k + c]);
        high[c] = std::max(high[c], nodes.Coordinates[3 * k + c]);
      }
    }
    const double tolerance = 1e-6 * std::max(high[0] - low[0], high[1] - low[1]);
    for (std::size_t k = 0; k < nodes.Tags.size(); ++k)
    {
      if (!(std::abs(nodes.Coordinates[3 * k + 2] - z) <= tolerance))
      {
        // Also a 3D geometry saved with physical groups on its surfaces only (gmsh then keeps
        // no volume element): said, as it is the likelier mistake.
        session.Fail("the file has no 3D element, and a 2D mesh must lie in one plane z = "
                     "constant, but node " +
          std::to_string(nodes.Tags[0]) + " has z = " + NumberText(z) + " and node " +
          std::to_string(nodes.Tags[k]) + " z = " + NumberText(nodes.Coordinates[3 * k + 2]) +
          " (a 3D mesh saved with physical groups on surfaces only keeps no volume element: add "
          "a physical volume, or save with Mesh.SaveAll)");
      }
    }
  }
  const bool version2 = format.Version < 3.0;

  // The volume: every element of the mesh's dimension, entity by entity.
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, mesh.Dimension);
  std::set<std::vector<std::int64_t>> seen;
  const bool uniqueVolume = version2 && MostPhysicalGroupsOfAnEntity(mesh.Dimension) > 1;
  for (const auto& entity : entities)
  {
    AddElements(session, index, entity.first, entity.second, uniqueVolume, seen, mesh.Volume);
  }

  // The boundaries: the physical groups one dimension lower.
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, mesh.Dimension - 1);
  const bool uniqueFaces = version2 && MostPhysicalGroupsOfAnEntity(mesh.Dimension - 1) > 1;
  for (const auto& group : groups)
  {
    NamedBoundary boundary;
    gmsh::model::getPhysicalName(group.first, group.second, boundary.Name);
    if (boundary.Name.empty())
    {
      boundary.Name = "group " + std::to_string(group.second);
    }
    std::vector<int> groupEntities;
    gmsh::model::getEntitiesForPhysicalGroup(group.first, group.second, groupEntities);
    seen.clear();
    for (int entity : groupEntities)
    {
      AddElements(session, index, group.first, entity, uniqueFaces, seen, boundary.Faces);
    }
    mesh.Boundaries.push_back(std::move(boundary));
  }
  gmsh::vectorpair everyGroup;
  gmsh::model::getPhysicalGroups(everyGroup);
  for (const auto& group : everyGroup)
  {
    std::string name;
    gmsh::model::getPhysicalName(group.first, group.second, name);
    if (group.first != mesh.Dimension - 1 && !name.empty())
    {
      mesh.OtherGroups.emplace_back(name, group.first);
    }
  }
  session.ThrowOnGmshError("gmsh cannot give its physical groups");
  return mesh;
}

/// Runs `body`, turning what gmsh throws despite AbortOnError = 0 into a FileError.
template <typename Body>
auto TranslatingGmshErrors(GmshSession& session, Body body) -> decltype(body())
{
  try
  {
    return body();
  }
  catch (const FileError&)
  {
    throw;
  }
  catch (const std::bad_alloc&)
  {
    session.Fail("out of memory");
  }
  catch (const std::string& message)
  {
    session.Fail("gmsh: " + message);
  }
  catch (const std::exception& e)
  {
    session.Fail(std::string("gmsh: ") + e.what());
  }
  catch (...)
  {
    session.Fail("gmsh failed");
  }
}
} // namespace

namespace
{
/// Moves every node of the (version 4) model to the coordinates `points` (sorted tags' order).
void SetNodes(GmshSession& session, const ModelNodes& nodes, const double* points)
{
  std::vector<double> xyz(3);
  const std::vector<double> noParametric;
  for (std::size_t k = 0; k < nodes.Tags.size(); ++k)
  {
    xyz.assign(points + 3 * k, points + 3 * k + 3);
    gmsh::model::mesh::setNode(nodes.Tags[k], xyz, noParametric);
  }
  session.ThrowOnGmshError("gmsh cannot move its nodes");
}

/**
 * gmsh's version 2 writer numbers the nodes 1..N in the order it holds them, which after reading a
 * version 2 file is not the file's order. The model is rebuilt for it: the same entities, physical
 * groups and elements (element tags included), and every node on the first entity in the order
 * of its tag, so that the writer gives node k the tag k + 1 it had. Returns Mesh.SaveAll for
 * the rebuilt model: version 2 files keep the physical groups only when gmsh writes the physical
 * elements alone (an element once per group), so files whose elements are all in exactly one
 * physical group, or none in any, are the ones it can write unchanged.
 */
int RebuildForVersion2(GmshSession& session, const ModelNodes& nodes, const double* points)
{
  for (std::size_t k = 0; k < nodes.Tags.size(); ++k)
  {
    if (nodes.Tags[k] != k + 1)
    {
      session.Fail("gmsh's version 2 writer numbers the nodes 1.." +
        std::to_string(nodes.Tags.size()) + ", and this file's node tags are not those");
    }
  }
  gmsh::vectorpair entities, groups;
  gmsh::model::getEntities(entities);
  gmsh::model::getPhysicalGroups(groups);
  struct EntityMesh
  {
    int Dim, Tag;
    std::vector<int> Types;
    std::vector<std::vector<std::size_t>> ElementTags, NodeTags;
  };
  std::vector<EntityMesh> meshes;
  std::vector<char> used(nodes.Tags.size() + 1, 0);
  bool withGroup = false, withoutGroup = false;
  for (const auto& entity : entities)
  {
    EntityMesh m{ entity.first, entity.second, {}, {}, {} };
    GetElementsByType(m.Dim, m.Tag, m.Types, m.ElementTags, m.NodeTags);
    std::vector<int> entityGroups;
    gmsh::model::getPhysicalGroupsForEntity(m.Dim, m.Tag, entityGroups);
    bool any = false;
    for (const std::vector<std::size_t>& nodeTags : m.NodeTags)
    {
      any = any || !nodeTags.empty();
      for (std::size_t tag : nodeTags)
      {
        used[std::min(tag, nodes.Tags.size())] = 1; // tags are 1..N here
      }
    }
    if (any && entityGroups.size() > 1)
    {
      session.Fail("gmsh cannot write a version 2 file in which elements are in several physical "
                   "groups unchanged (entity " +
        std::to_string(m.Dim) + "D " + std::to_string(m.Tag) + ")");
    }
    withGroup = withGroup || (any && entityGroups.size() == 1);
    withoutGroup = withoutGroup || (any && entityGroups.empty());
    meshes.push_back(std::move(m));
  }
  if (withGroup && withoutGroup)
  {
    session.Fail("gmsh cannot write a version 2 file with elements both in and outside physical "
                 "groups unchanged (it drops either those elements or every group)");
  }
  if (std::find(used.begin() + 1, used.end(), 0) != used.end())
  {
    session.Fail("gmsh's version 2 writer drops the nodes no element uses, and this file has some");
  }
  std::vector<std::pair<std::vector<int>, std::string>> groupData;
  for (const auto& group : groups)
  {
    groupData.emplace_back();
    gmsh::model::getEntitiesForPhysicalGroup(group.first, group.second, groupData.back().first);
    gmsh::model::getPhysicalName(group.first, group.second, groupData.back().second);
  }
  session.ThrowOnGmshError("gmsh cannot give its model");

  session.AddModel("dgmf-meshfile-write");
  for (const EntityMesh& m : meshes)
  {
    gmsh::model::addDiscreteEntity(m.Dim, m.Tag);
  }
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    gmsh::model::addPhysicalGroup(groups[g].first, groupData[g].first, groups[g].second);
    if (!groupData[g].second.empty())
    {
      gmsh::model::setPhysicalName(groups[g].first, groups[g].second, groupData[g].second);
    }
  }
  if (!meshes.empty())
  {
    gmsh::model::mesh::addNodes(meshes.front().Dim, meshes.front().Tag, nodes.Tags,
      std::vector<double>(points, points + 3 * nodes.Tags.size()));
  }
  for (const EntityMesh& m : meshes)
  {
    gmsh::model::mesh::addElements(m.Dim, m.Tag, m.Types, m.ElementTags, m.NodeTags);
  }
  session.ThrowOnGmshError("gmsh cannot rebuild the model for writing");
  return withGroup ? 0 : 1;
}

/// Reads the merged model of `path` (GmshModule::Read).
std::string ReadGmshModel(const std::string& path, const MshFormat& format)
{
  GmshSession session(path);
  return TranslatingGmshErrors(session,
    [&]()
    {
      session.Merge(path);
      return MeshToBytes(ReadModel(session, format));
    });
}

/// Writes `source` with the nodes moved to `points` to `target` (GmshModule::Write).
void WriteGmshModel(const std::string& source, const std::string& target, const MshFormat& format,
  const double* points, std::size_t count)
{
  GmshSession session(source);
  TranslatingGmshErrors(session,
    [&]()
    {
      session.Merge(source);
      const ModelNodes nodes = GetSortedNodes(session);
      if (nodes.Tags.size() != count)
      {
        session.Fail("has " + std::to_string(nodes.Tags.size()) + " nodes, " +
          std::to_string(count) + " points given");
      }
      int saveAll = 1;
      if (format.Version < 3.0)
      {
        saveAll = RebuildForVersion2(session, nodes, points);
      }
      else
      {
        SetNodes(session, nodes, points); // version 4 keeps tags, entities and groups
      }
      session.SetOption("Mesh.MshFileVersion", format.Version);
      session.SetOption("Mesh.Binary", format.Binary ? 1 : 0);
      session.SetOption("Mesh.SaveAll", saveAll);
      session.SetOption("Mesh.SaveParametric", 0); // moved nodes: old parameters are wrong
      session.SetOption("Mesh.ScalingFactor", 1);
      gmsh::write(target);
      session.ThrowOnGmshError("gmsh cannot write " + target);
    });
}

/// Runs `body`; a FileError (or anything else) becomes `message` and false.
template <typename Body>
bool ReportingFailure(const std::string& file, std::string& message, Body body)
{
  try
  {
    body();
    return true;
  }
  catch (const FileError& e)
  {
    message = e.what();
  }
  catch (const std::exception& e)
  {
    message = file + ": gmsh: " + e.what();
  }
  catch (...)
  {
    message = file + ": gmsh failed";
  }
  return false;
}
} // namespace
} // namespace meshfile
} // namespace dgmf

// The module's entry points (GmshModule.h), found by name with dlsym.
#define DGMF_GMSH_MODULE_ENTRY extern "C" __attribute__((visibility("default")))

DGMF_GMSH_MODULE_ENTRY const char* dgmf_meshfile_gmsh_build_identity()
{
  return dgmf::meshfile::kGmshModuleIdentity;
}

DGMF_GMSH_MODULE_ENTRY bool dgmf_meshfile_gmsh_read(
  const std::string& path, const dgmf::meshfile::MshFormat& format, std::string& bytesOrMessage)
{
  return dgmf::meshfile::ReportingFailure(
    path, bytesOrMessage, [&]() { bytesOrMessage = dgmf::meshfile::ReadGmshModel(path, format); });
}

DGMF_GMSH_MODULE_ENTRY bool dgmf_meshfile_gmsh_write(const std::string& source,
  const std::string& target, const dgmf::meshfile::MshFormat& format, const double* points,
  std::size_t count, std::string& message)
{
  return dgmf::meshfile::ReportingFailure(source, message,
    [&]() { dgmf::meshfile::WriteGmshModel(source, target, format, points, count); });
}

// The entry points have the types the loader casts them to.
static_assert(
  std::is_same_v<decltype(&dgmf_meshfile_gmsh_read), decltype(dgmf::meshfile::GmshModule::Read)>);
static_assert(
  std::is_same_v<decltype(&dgmf_meshfile_gmsh_write), decltype(dgmf::meshfile::GmshModule::Write)>);
