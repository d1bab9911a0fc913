// A version 4.1 .msh file read without gmsh (MshReader41.h). The layout: gmsh's reference manual,
// "MSH file format"; the mesh made of it: MshModel.h.
#include "dgmf/meshfile/MshReader41.h"

#include "dgmf/HugePages.h"
#include "dgmf/meshfile/MshElementTypes.h"
#include "dgmf/meshfile/MshModel.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
using namespace msh;

/// $Entities: points, curves, surfaces, volumes with their physical tags (bounding boxes and
/// bounding entities read past).
bool ParseEntities(Cursor& cursor, bool binary, MshModel& model)
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

bool ParseNodes(Cursor& cursor, bool binary, MshModel& model)
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
    ResizeOnHugePages(model.NodeTags, first + static_cast<std::size_t>(inBlock));
    for (std::size_t k = first; k < model.NodeTags.size(); ++k)
    {
      if (!values.Size(model.NodeTags[k]))
      {
        return false;
      }
    }
    ResizeOnHugePages(model.Coordinates, 3 * model.NodeTags.size());
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

bool ParseElements(Cursor& cursor, bool binary, MshModel& model)
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
    ResizeOnHugePages(
      model.ElementNodes, block.First + block.Count * static_cast<std::size_t>(mapping.Nodes));
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

} // namespace

bool ReadMsh41(std::string_view file, bool binary, NamedMesh& mesh)
{
  Cursor cursor{ file };
  if (!ReadMeshFormat(cursor, binary))
  {
    return false;
  }
  MshModel model;
  bool entities = false, nodes = false, elements = false;
  const auto parsed = [](bool ok) { return ok ? SectionRead::Parsed : SectionRead::Refused; };
  const bool walked = WalkSections(cursor,
    [&](std::string_view name)
    {
      if (name == "PhysicalNames")
      {
        return parsed(ParsePhysicalNames(cursor, model));
      }
      if (name == "Entities")
      {
        const bool first = !entities;
        entities = true;
        return parsed(first && ParseEntities(cursor, binary, model));
      }
      if (name == "Nodes")
      {
        nodes = true;
        return parsed(ParseNodes(cursor, binary, model));
      }
      if (name == "Elements")
      {
        elements = true;
        return parsed(ParseElements(cursor, binary, model));
      }
      return name == "PartitionedEntities" || name == "GhostElements" || name == "Parametrizations"
        ? SectionRead::Refused
        : SectionRead::Unknown;
    });
  if (!walked || !entities || !nodes || !elements)
  {
    return false; // a section missing
  }
  return BuildMeshAsGmshDoes(model, Version2Rules(), mesh);
}

} // namespace meshfile
} // namespace dgmf
