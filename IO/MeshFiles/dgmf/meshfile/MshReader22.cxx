// A version 2.2 .msh file read without gmsh (MshReader22.h). The layout: gmsh's reference manual,
// "Legacy formats", "MSH file format version 2"; the entities gmsh makes of the elements' tags:
// gmsh 4.8's GModel::_readMSH2, checked through its API (gmsh.MshReader22.*); the mesh made of
// them: MshModel.h.
#include "dgmf/meshfile/MshReader22.h"

#include "dgmf/HugePages.h"
#include "dgmf/meshfile/MshElementTypes.h"
#include "dgmf/meshfile/MshModel.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
using namespace msh;

/// $Nodes: `tag x y z` per node (binary: a 4-byte tag and three doubles).
bool ParseNodes(Cursor& cursor, bool binary, MshModel& model)
{
  std::uint64_t count = 0;
  if (!model.NodeTags.empty() || !ToInteger(cursor.Line(), count) ||
    count > (cursor.File.size() - cursor.At) / (binary ? 28 : 8))
  {
    return false; // a second $Nodes, or more nodes than the file can hold
  }
  const auto n = static_cast<std::size_t>(count);
  ResizeOnHugePages(model.NodeTags, n);
  ResizeOnHugePages(model.Coordinates, 3 * n);
  Values values(cursor, binary);
  for (std::size_t k = 0; k < n; ++k)
  {
    int tag = 0;
    const bool tagRead = binary ? values.Int(tag) && tag >= 1 : values.Size(model.NodeTags[k]);
    if (!tagRead || !values.Real(model.Coordinates[3 * k]) ||
      !values.Real(model.Coordinates[3 * k + 1]) || !values.Real(model.Coordinates[3 * k + 2]))
    {
      return false;
    }
    if (binary)
    {
      model.NodeTags[k] = static_cast<std::uint64_t>(tag);
    }
  }
  return EndsSection(cursor, "Nodes");
}

/**
 * The elements as they are read, in the file's order: blocks of consecutive elements of one
 * entity and type, each element's number, and the entities' physical groups.
 */
class ElementsInFileOrder
{
public:
  /**
   * `count` elements announced, in `bytes` of the file: room reserved for as many tetrahedra (a
   * volume mesh's elements, as a rule) as the file can hold (an element takes 16 bytes at least),
   * so that they are not copied as they are read; other meshes grow as they are read.
   */
  ElementsInFileOrder(MshModel& model, std::uint64_t count, std::size_t bytes)
    : Model(model)
  {
    const std::size_t elements = std::min<std::size_t>(count, bytes / 16);
    ReserveOnHugePages(this->Numbers, elements);
    ReserveOnHugePages(this->Model.ElementNodes, 4 * elements);
  }

  /// An element of gmsh type `type` whose node tags end at `end` in Model.ElementNodes.
  void Add(std::uint64_t number, const CellMapping& mapping, int type, int physical, int elementary,
    std::size_t end)
  {
    this->Increasing = this->Increasing && (this->Numbers.empty() || number > this->Numbers.back());
    this->Numbers.push_back(number);
    std::vector<ElementBlock>& blocks = this->Model.Blocks;
    if (blocks.empty() || blocks.back().Type != type || blocks.back().Entity != elementary)
    {
      ElementBlock block;
      block.Dimension = mapping.Dimension;
      block.Entity = elementary;
      block.Type = type;
      block.First = end - static_cast<std::size_t>(mapping.Nodes);
      blocks.push_back(block);
    }
    ++blocks.back().Count;
    // The entity of the element's dimension and elementary tag is in the element's group.
    if (mapping.Dimension != this->LastDimension || elementary != this->LastEntity ||
      physical != this->LastPhysical)
    {
      std::vector<int>& groups = this->Model.Entities[mapping.Dimension][elementary];
      if (physical > 0 && std::find(groups.begin(), groups.end(), physical) == groups.end())
      {
        groups.push_back(physical);
      }
      this->LastDimension = mapping.Dimension;
      this->LastEntity = elementary;
      this->LastPhysical = physical;
    }
  }

  /**
   * Puts the blocks in the order gmsh holds the elements: by increasing element number (already
   * so in the files gmsh writes). False when a number is there twice (gmsh keeps the last).
   */
  bool SortByNumber()
  {
    if (this->Increasing)
    {
      return true;
    }
    const std::size_t count = this->Numbers.size();
    std::vector<std::size_t> block(count), first(count);
    for (std::size_t b = 0, e = 0; b < this->Model.Blocks.size(); ++b)
    {
      const ElementBlock& from = this->Model.Blocks[b];
      CellMapping mapping;
      MapGmshType(from.Type, mapping);
      for (std::size_t i = 0; i < from.Count; ++i, ++e)
      {
        block[e] = b;
        first[e] = from.First + i * static_cast<std::size_t>(mapping.Nodes);
      }
    }
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(),
      [&](std::size_t a, std::size_t b) { return this->Numbers[a] < this->Numbers[b]; });
    std::vector<ElementBlock> blocks;
    std::vector<std::uint64_t> nodes;
    nodes.reserve(this->Model.ElementNodes.size());
    for (std::size_t k = 0; k < count; ++k)
    {
      if (k > 0 && this->Numbers[order[k]] == this->Numbers[order[k - 1]])
      {
        return false;
      }
      const ElementBlock& from = this->Model.Blocks[block[order[k]]];
      if (blocks.empty() || blocks.back().Type != from.Type || blocks.back().Entity != from.Entity)
      {
        blocks.push_back(from);
        blocks.back().First = nodes.size();
        blocks.back().Count = 0;
      }
      ++blocks.back().Count;
      CellMapping mapping;
      MapGmshType(from.Type, mapping);
      const std::uint64_t* element = this->Model.ElementNodes.data() + first[order[k]];
      nodes.insert(nodes.end(), element, element + mapping.Nodes);
    }
    this->Model.Blocks = std::move(blocks);
    this->Model.ElementNodes = std::move(nodes);
    return true;
  }

private:
  MshModel& Model;
  std::vector<std::uint64_t> Numbers;
  bool Increasing = true;
  int LastDimension = -1, LastEntity = 0, LastPhysical = -1;
};

/// The tags of an element: two (physical >= 0, elementary >= 1); partitions are left to gmsh.
bool ValidTags(int tags, int physical, int elementary)
{
  return tags == 2 && physical >= 0 && elementary >= 1;
}

/// $Elements in ASCII: `number type tags physical elementary nodes...` per element.
bool ParseAsciiElements(Cursor& cursor, std::uint64_t count, MshModel& model)
{
  ElementsInFileOrder elements(model, count, cursor.File.size() - cursor.At);
  for (std::uint64_t e = 0; e < count; ++e)
  {
    std::uint64_t number = 0;
    int type = 0, tags = 0, physical = 0, elementary = 0;
    CellMapping mapping;
    if (!ToInteger(cursor.Token(), number) || !ToInteger(cursor.Token(), type) ||
      !MapGmshType(type, mapping) || !ToInteger(cursor.Token(), tags) ||
      (tags >= 1 && !ToInteger(cursor.Token(), physical)) ||
      (tags >= 2 && !ToInteger(cursor.Token(), elementary)) ||
      !ValidTags(tags, physical, elementary))
    {
      return false;
    }
    for (int k = 0; k < mapping.Nodes; ++k)
    {
      std::uint64_t node = 0;
      if (!ToInteger(cursor.Token(), node))
      {
        return false;
      }
      model.ElementNodes.push_back(node);
    }
    elements.Add(number, mapping, type, physical, elementary, model.ElementNodes.size());
  }
  return elements.SortByNumber();
}

/// $Elements in binary: blocks of a header (type, elements, tags), then per element its number,
/// tags and nodes, all 4-byte integers.
bool ParseBinaryElements(Cursor& cursor, std::uint64_t count, MshModel& model)
{
  ElementsInFileOrder elements(model, count, cursor.File.size() - cursor.At);
  for (std::uint64_t read = 0; read < count;)
  {
    std::int32_t header[3] = { 0, 0, 0 };
    CellMapping mapping;
    if (!cursor.Binary(header[0]) || !cursor.Binary(header[1]) || !cursor.Binary(header[2]) ||
      !MapGmshType(header[0], mapping) || header[1] < 1 ||
      static_cast<std::uint64_t>(header[1]) > count - read || header[2] != 2 ||
      static_cast<std::uint64_t>(header[1]) >
        (cursor.File.size() - cursor.At) / (4 * (3 + static_cast<std::size_t>(mapping.Nodes))))
    {
      return false;
    }
    // (The block's size was checked against the file's: every read below succeeds.)
    std::size_t at = model.ElementNodes.size();
    ResizeOnHugePages(model.ElementNodes, at + static_cast<std::size_t>(header[1]) * mapping.Nodes);
    for (std::int32_t e = 0; e < header[1]; ++e)
    {
      std::int32_t number = 0, physical = 0, elementary = 0, node = 0;
      cursor.Binary(number);
      cursor.Binary(physical);
      cursor.Binary(elementary);
      if (number < 0 || !ValidTags(header[2], physical, elementary))
      {
        return false;
      }
      for (int k = 0; k < mapping.Nodes; ++k, ++at)
      {
        cursor.Binary(node);
        if (node < 1)
        {
          return false;
        }
        model.ElementNodes[at] = static_cast<std::uint64_t>(node);
      }
      elements.Add(
        static_cast<std::uint64_t>(number), mapping, header[0], physical, elementary, at);
    }
    read += static_cast<std::uint64_t>(header[1]);
  }
  return elements.SortByNumber();
}

bool ParseElements(Cursor& cursor, bool binary, MshModel& model)
{
  std::uint64_t count = 0;
  if (!model.Blocks.empty() || !ToInteger(cursor.Line(), count))
  {
    return false;
  }
  const bool parsed =
    binary ? ParseBinaryElements(cursor, count, model) : ParseAsciiElements(cursor, count, model);
  return parsed && EndsSection(cursor, "Elements");
}
} // namespace

bool ReadMsh22(std::string_view file, bool binary, NamedMesh& mesh)
{
  Cursor cursor{ file };
  if (!ReadMeshFormat(cursor, binary))
  {
    return false;
  }
  MshModel model;
  bool nodes = false, elements = false;
  const auto parsed = [](bool ok) { return ok ? SectionRead::Parsed : SectionRead::Refused; };
  const bool walked = WalkSections(cursor,
    [&](std::string_view name)
    {
      if (name == "PhysicalNames")
      {
        return parsed(ParsePhysicalNames(cursor, model));
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
      return name == "ParametricNodes" || name == "NOD" || name == "ELM" ? SectionRead::Refused
                                                                         : SectionRead::Unknown;
    });
  if (!walked || !nodes || !elements)
  {
    return false;
  }
  Version2Rules rules;
  rules.DropUnusedNodes = true;
  rules.ReadRepeatedElementsOnce = true;
  return BuildMeshAsGmshDoes(model, rules, mesh);
}

} // namespace meshfile
} // namespace dgmf
