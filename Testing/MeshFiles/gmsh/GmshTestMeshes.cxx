#include "GmshTestMeshes.h"

#include <gmsh.h>

#include <algorithm>
#include <fstream>

namespace dgmf
{
namespace meshfile
{
namespace test
{
namespace
{
bool& Initialized()
{
  static bool initialized = false;
  return initialized;
}

void Start(const std::string& name)
{
  if (!Initialized())
  {
    gmsh::initialize(0, nullptr, false);
    Initialized() = true;
  }
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add(name);
}

/// The model removed and gmsh finalized: the tests' own use of gmsh leaves nothing allocated
/// (LeakSanitizer checks this process; gmsh's own reading and writing runs in children).
void End()
{
  gmsh::model::remove();
  gmsh::finalize();
  Initialized() = false;
}

void Finish(const std::string& path, const MshFlavour& flavour)
{
  gmsh::option::setNumber("Mesh.MshFileVersion", flavour.Version);
  gmsh::option::setNumber("Mesh.Binary", flavour.Binary ? 1 : 0);
  gmsh::option::setNumber("Mesh.SaveAll", flavour.SaveAll ? 1 : 0);
  gmsh::write(path);
  End();
}

std::size_t CountElements(int dim, int tag)
{
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, dim, tag);
  std::size_t count = 0;
  for (const auto& t : tags)
  {
    count += t.size();
  }
  return count;
}

std::size_t CountGroup(int dim, const std::vector<int>& entities)
{
  std::size_t count = 0;
  for (int entity : entities)
  {
    count += CountElements(dim, entity);
  }
  return count;
}
} // namespace

GeneratedCounts WriteBoxWithHole(const std::string& path, const MshFlavour& flavour)
{
  Start("box");
  const int box = gmsh::model::occ::addBox(0, 0, 0, 4, 3, 2);
  const int hole = gmsh::model::occ::addBox(1.5, 1, 0.5, 1, 1, 1);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::cut({ { 3, box } }, { { 3, hole } }, out, map);
  gmsh::model::occ::synchronize();
  std::vector<int> outer, inner;
  gmsh::vectorpair faces;
  gmsh::model::getEntities(faces, 2);
  for (const auto& face : faces)
  {
    double x = 0, y = 0, z = 0;
    gmsh::model::occ::getCenterOfMass(2, face.second, x, y, z);
    const bool onHole = x > 1.4 && x < 2.6 && y > 0.9 && y < 2.1 && z > 0.4 && z < 1.6;
    (onHole ? inner : outer).push_back(face.second);
  }
  gmsh::model::addPhysicalGroup(2, outer, 1);
  gmsh::model::setPhysicalName(2, 1, "outer");
  gmsh::model::addPhysicalGroup(2, inner, 2);
  gmsh::model::setPhysicalName(2, 2, "hole");
  gmsh::model::addPhysicalGroup(3, { out[0].second }, 3);
  gmsh::model::setPhysicalName(3, 3, "fluid");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.6);
  gmsh::model::mesh::generate(3);
  GeneratedCounts counts;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
  counts.Nodes = tags.size();
  counts.VolumeElements = CountElements(3, -1);
  counts.BoundaryElements["outer"] = CountGroup(2, outer);
  counts.BoundaryElements["hole"] = CountGroup(2, inner);
  Finish(path, flavour);
  return counts;
}

GeneratedCounts WriteRectangleWithHole(
  const std::string& path, const MshFlavour& flavour, bool overlapping)
{
  Start("rectangle");
  const int rectangle = gmsh::model::occ::addRectangle(0, 0, 0, 4, 2);
  const int disk = gmsh::model::occ::addDisk(2, 1, 0, 0.5, 0.5);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::cut({ { 2, rectangle } }, { { 2, disk } }, out, map);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  std::vector<int> outer, inner;
  for (const auto& curve : curves)
  {
    double x = 0, y = 0, z = 0;
    gmsh::model::occ::getCenterOfMass(1, curve.second, x, y, z);
    const bool onHole = x > 1.4 && x < 2.6 && y > 0.4 && y < 1.6;
    (onHole ? inner : outer).push_back(curve.second);
  }
  gmsh::model::addPhysicalGroup(1, outer, 1);
  gmsh::model::setPhysicalName(1, 1, "outer");
  gmsh::model::addPhysicalGroup(1, inner, 5); // unnamed: "group 5"
  if (overlapping)
  {
    gmsh::model::addPhysicalGroup(1, { outer[0] }, 6);
    gmsh::model::setPhysicalName(1, 6, "left");
  }
  gmsh::model::addPhysicalGroup(2, { out[0].second }, 7);
  gmsh::model::setPhysicalName(2, 7, "fluid");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.25);
  gmsh::model::mesh::generate(2);
  GeneratedCounts counts;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
  counts.Nodes = tags.size();
  counts.VolumeElements = CountElements(2, -1);
  counts.BoundaryElements["outer"] = CountGroup(1, outer);
  counts.BoundaryElements["group 5"] = CountGroup(1, inner);
  Finish(path, flavour);
  return counts;
}

void WritePrismAndPyramid(const std::string& path, const MshFlavour& flavour)
{
  Start("prism");
  gmsh::model::addDiscreteEntity(3, 1);
  gmsh::model::addDiscreteEntity(2, 1);
  // gmsh's reference prism (0,0,0) (1,0,0) (0,1,0) / z = 1, and a pyramid on the square below.
  gmsh::model::mesh::addNodes(3, 1, { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 },
    { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, //
      0, 0, -1, 1, 0, -1, 1, 1, -1, 0, 1, -1, 0.5, 0.5, -2 });
  // Pyramid base 7 8 9 10 counter-clockwise seen from below, apex 11 below: gmsh's orientation.
  gmsh::model::mesh::addElements(
    3, 1, { 6, 7 }, { { 1 }, { 2 } }, { { 1, 2, 3, 4, 5, 6 }, { 7, 10, 9, 8, 11 } });
  gmsh::model::mesh::addElements(2, 1, { 2 }, { { 3 } }, { { 4, 5, 6 } });
  gmsh::model::addPhysicalGroup(2, { 1 }, 1);
  gmsh::model::setPhysicalName(2, 1, "wall");
  gmsh::model::addPhysicalGroup(3, { 1 }, 2);
  Finish(path, flavour);
}

void WriteSecondOrder(const std::string& path)
{
  Start("second");
  gmsh::model::occ::addRectangle(0, 0, 0, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.5);
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  Finish(path, MshFlavour());
}

GmshView ViewWithGmsh(const std::string& path)
{
  Start("view");
  gmsh::merge(path);
  GmshView view;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
  for (std::size_t k = 0; k < tags.size(); ++k)
  {
    view.At[tags[k]] = { xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2] };
    view.NodeTags.push_back(tags[k]);
  }
  std::sort(view.NodeTags.begin(), view.NodeTags.end());
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elementTags, nodeTags;
  gmsh::model::mesh::getElements(types, elementTags, nodeTags, -1, -1);
  for (std::size_t t = 0; t < types.size(); ++t)
  {
    const std::size_t per = elementTags[t].empty() ? 0 : nodeTags[t].size() / elementTags[t].size();
    for (std::size_t e = 0; e < elementTags[t].size(); ++e)
    {
      view.Elements[{ types[t], elementTags[t][e] }].assign(
        nodeTags[t].begin() + e * per, nodeTags[t].begin() + (e + 1) * per);
    }
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& group : groups)
  {
    std::string name;
    gmsh::model::getPhysicalName(group.first, group.second, name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(group.first, group.second, entities);
    view.GroupEntities[std::to_string(group.first) + ":" + name] = entities.size();
  }
  End();
  return view;
}

std::string MeshFormatLines(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  return first + "\n" + second;
}

} // namespace test
} // namespace meshfile
} // namespace dgmf
