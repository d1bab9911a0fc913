#include "dgmf/meshfile/CGNSZone.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <system_error>

namespace dgmf
{
namespace meshfile
{
namespace cgns
{

/// What the library says about its last error, as " (...)".
std::string LastError()
{
  const char* message = cg_get_error();
  return message && *message ? std::string(" (") + message + ")" : std::string();
}

double EntryBudget(const std::string& path)
{
  std::error_code error;
  const auto bytes = static_cast<double>(std::filesystem::file_size(path, error));
  return std::max(64.0 * 1024 * 1024, 64.0 * (error ? 0.0 : bytes)) / 8.0;
}

/// The first base and its one unstructured zone, and the zone's Cartesian coordinate arrays.
ZoneLayout ReadLayout(const CGNSHandle& file)
{
  ZoneLayout layout;
  int bases = 0;
  file.Check(cg_nbases(file.Id, &bases), "the number of bases");
  if (bases < 1)
  {
    file.Fail("no base (CGNSBase_t)");
  }
  char name[33] = { 0 };
  file.Check(cg_base_read(file.Id, 1, name, &layout.CellDimension, &layout.PhysicalDimension),
    "the first base");
  layout.Base = "base '" + std::string(name) + "'";
  if (layout.CellDimension < 2 || layout.CellDimension > 3 ||
    layout.PhysicalDimension < layout.CellDimension || layout.PhysicalDimension > 3)
  {
    file.Fail(layout.Base + " has cell dimension " + std::to_string(layout.CellDimension) +
      " and physical dimension " + std::to_string(layout.PhysicalDimension) +
      " (2D or 3D meshes are read)");
  }
  int zones = 0;
  file.Check(cg_nzones(file.Id, 1, &zones), "the zones of " + layout.Base);
  if (zones != 1)
  {
    file.Fail(
      layout.Base + " has " + std::to_string(zones) + " zones; one unstructured zone is read");
  }
  CGNS_ENUMT(ZoneType_t) zoneType = CGNS_ENUMV(ZoneTypeNull);
  file.Check(cg_zone_type(file.Id, 1, 1, &zoneType), "the zone type in " + layout.Base);
  cgsize_t sizes[9] = { 0 }; // room for a structured zone's 3 x 3
  file.Check(cg_zone_read(file.Id, 1, 1, name, sizes), "the zone of " + layout.Base);
  layout.Zone = "zone '" + std::string(name) + "'";
  if (zoneType != CGNS_ENUMV(Unstructured))
  {
    file.Fail(layout.Zone + " is not unstructured; one unstructured zone is read");
  }
  layout.Vertices = sizes[0];
  if (layout.Vertices < 1 || static_cast<double>(layout.Vertices) * 3 > EntryBudget(file.Path))
  {
    file.Fail(layout.Zone + " declares " + std::to_string(layout.Vertices) +
      " vertices, more than the file can hold");
  }

  int count = 0;
  file.Check(cg_ncoords(file.Id, 1, 1, &count), "the coordinates of " + layout.Zone);
  const char* wanted[] = { "CoordinateX", "CoordinateY", "CoordinateZ" };
  layout.Coordinates.assign(static_cast<std::size_t>(layout.PhysicalDimension),
    { std::string(), CGNS_ENUMV(DataTypeNull) });
  for (int c = 1; c <= count; ++c)
  {
    DataType type = CGNS_ENUMV(DataTypeNull);
    file.Check(cg_coord_info(file.Id, 1, 1, c, &type, name),
      "coordinate array " + std::to_string(c) + " of " + layout.Zone);
    for (int k = 0; k < layout.PhysicalDimension; ++k)
    {
      if (name == std::string(wanted[k]))
      {
        if (type != CGNS_ENUMV(RealSingle) && type != CGNS_ENUMV(RealDouble))
        {
          file.Fail(
            std::string(wanted[k]) + " of " + layout.Zone + " is not RealSingle or RealDouble");
        }
        layout.Coordinates[k] = { name, type };
      }
    }
  }
  for (int k = 0; k < layout.PhysicalDimension; ++k)
  {
    if (layout.Coordinates[k].Name.empty())
    {
      file.Fail(layout.Zone + " has no " + wanted[k] + " (Cartesian coordinates are read)");
    }
  }
  return layout;
}

/// VTK's cell type of a linear CGNS element type; 0 for the others.
std::uint8_t CellTypeOf(cgsize_t type)
{
  switch (type)
  {
    case CGNS_ENUMV(NODE):
      return Vertex;
    case CGNS_ENUMV(BAR_2):
      return Line;
    case CGNS_ENUMV(TRI_3):
      return Triangle;
    case CGNS_ENUMV(QUAD_4):
      return Quad;
    case CGNS_ENUMV(TETRA_4):
      return Tetra;
    case CGNS_ENUMV(PYRA_5):
      return Pyramid;
    case CGNS_ENUMV(PENTA_6):
      return Wedge;
    case CGNS_ENUMV(HEXA_8):
      return Hexahedron;
    default:
      return 0;
  }
}

void ZoneElements::Read(const CGNSHandle& file, const ZoneLayout& layout)
{
  int count = 0;
  file.Check(cg_nsections(file.Id, 1, 1, &count), "the sections of " + layout.Zone);
  const double budget = EntryBudget(file.Path);
  double entries = 0; // of all sections read so far
  for (int s = 1; s <= count; ++s)
  {
    char name[33] = { 0 };
    ElementType type = CGNS_ENUMV(ElementTypeNull);
    cgsize_t start = 0, end = 0;
    int boundaries = 0, parents = 0;
    file.Check(cg_section_read(file.Id, 1, 1, s, name, &type, &start, &end, &boundaries, &parents),
      "section " + std::to_string(s) + " of " + layout.Zone);
    Section section;
    section.Name = "section '" + std::string(name) + "'";
    const std::string where = section.Name + " of " + layout.Zone;
    cgsize_t size = 0;
    file.Check(cg_ElementDataSize(file.Id, 1, 1, s, &size), "the size of " + where);
    const cgsize_t elements = end - start + 1;
    entries += static_cast<double>(size) + static_cast<double>(elements);
    if (start < 1 || end < start || size < 0 || entries > budget)
    {
      file.Fail(where + " declares elements " + std::to_string(start) + ".." + std::to_string(end) +
        " with " + std::to_string(size) + " entries, more than the file can hold");
    }
    section.First = start;
    std::vector<cgsize_t> data(static_cast<std::size_t>(size));
    std::vector<cgsize_t> offsets;
    if (type == CGNS_ENUMV(MIXED))
    {
      // Each element: its type, then its nodes; where each starts in the offsets.
      offsets.assign(static_cast<std::size_t>(elements) + 1, 0);
      file.Check(cg_poly_elements_read(file.Id, 1, 1, s, data.data(), offsets.data(), nullptr),
        "the elements of " + where);
    }
    else
    {
      const std::uint8_t cellType = CellTypeOf(type);
      if (cellType == 0)
      {
        file.Fail(where + " has elements of type " + cg_ElementTypeName(type) +
          "; the linear types are read (BAR_2, TRI_3, QUAD_4, TETRA_4, PYRA_5, PENTA_6, "
          "HEXA_8, and MIXED sections of these)");
      }
      const int nodes = NodesOfCellType(cellType);
      if (size != elements * nodes)
      {
        file.Fail(where + " holds " + std::to_string(size) + " node numbers for " +
          std::to_string(elements) + " elements of " + std::to_string(nodes) + " nodes");
      }
      file.Check(
        cg_elements_read(file.Id, 1, 1, s, data.data(), nullptr), "the elements of " + where);
      // Written as a MIXED section's: type, nodes.
      std::vector<cgsize_t> mixed;
      mixed.reserve(data.size() + static_cast<std::size_t>(elements));
      offsets.reserve(static_cast<std::size_t>(elements) + 1);
      offsets.push_back(0);
      for (std::size_t first = 0; first < data.size(); first += static_cast<std::size_t>(nodes))
      {
        mixed.push_back(type);
        mixed.insert(mixed.end(), data.begin() + static_cast<std::ptrdiff_t>(first),
          data.begin() + static_cast<std::ptrdiff_t>(first) + nodes);
        offsets.push_back(static_cast<cgsize_t>(mixed.size()));
      }
      data.swap(mixed);
    }
    if (offsets.front() != 0 || offsets.back() != static_cast<cgsize_t>(data.size()))
    {
      file.Fail(where + " has element offsets that do not match its " +
        std::to_string(data.size()) + " entries");
    }
    std::int64_t cell[8];
    section.Elements.Reserve(offsets.size() - 1, data.size());
    for (std::size_t e = 0; e + 1 < offsets.size(); ++e)
    {
      const cgsize_t begin = offsets[e], stop = offsets[e + 1];
      const std::uint8_t cellType =
        begin >= 0 && begin < stop && stop <= static_cast<cgsize_t>(data.size())
        ? CellTypeOf(data[static_cast<std::size_t>(begin)])
        : 0;
      const cgsize_t nodes = stop - begin - 1;
      if (cellType == 0 || nodes != NodesOfCellType(cellType))
      {
        file.Fail(where + ": element " + std::to_string(start + static_cast<cgsize_t>(e)) +
          " is not one of the linear types (BAR_2, TRI_3, QUAD_4, TETRA_4, PYRA_5, PENTA_6, "
          "HEXA_8) with its number of nodes");
      }
      for (cgsize_t k = 0; k < nodes; ++k)
      {
        const cgsize_t node = data[static_cast<std::size_t>(begin + 1 + k)];
        if (node < 1 || node > layout.Vertices)
        {
          file.Fail(where + ": element " + std::to_string(start + static_cast<cgsize_t>(e)) +
            " uses node " + std::to_string(node) + ", outside 1.." +
            std::to_string(layout.Vertices));
        }
        cell[k] = node - 1;
      }
      section.Elements.Add(cellType, cell, static_cast<std::size_t>(nodes));
    }
    this->Total += elements;
    this->Sections.push_back(std::move(section));
  }
  // Element numbers are the zone's, unique across its sections.
  for (const Section& section : this->Sections)
  {
    this->ByNumber.push_back(&section);
  }
  std::sort(this->ByNumber.begin(), this->ByNumber.end(),
    [](const Section* a, const Section* b) { return a->First < b->First; });
  for (std::size_t k = 1; k < this->ByNumber.size(); ++k)
  {
    const Section* before = this->ByNumber[k - 1];
    if (before->First + static_cast<cgsize_t>(before->Elements.Size()) > this->ByNumber[k]->First)
    {
      file.Fail(before->Name + " and " + this->ByNumber[k]->Name + " of " + layout.Zone +
        " share element numbers");
    }
  }
}

const Section* ZoneElements::Find(cgsize_t number) const
{
  // The last section starting at or before `number`.
  auto after = std::upper_bound(this->ByNumber.begin(), this->ByNumber.end(), number,
    [](cgsize_t n, const Section* s) { return n < s->First; });
  if (after == this->ByNumber.begin())
  {
    return nullptr;
  }
  const Section* section = *(after - 1);
  return number - section->First < static_cast<cgsize_t>(section->Elements.Size()) ? section
                                                                                   : nullptr;
}

} // namespace cgns
} // namespace meshfile
} // namespace dgmf
