#include "dgmf/meshfile/CGNSFile.h"

#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/LibraryIsolation.h"

#include <vtkcgns/src/cgnslib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <system_error>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
using ElementType = CGNS_ENUMT(ElementType_t);
using DataType = CGNS_ENUMT(DataType_t);

/// What the library says about its last error, as " (...)".
std::string LastError()
{
  const char* message = cg_get_error();
  return message && *message ? std::string(" (") + message + ")" : std::string();
}

/// An open CGNS file, closed when it goes out of scope; every call's error becomes a FileError
/// naming the file, the node of the tree being read, and what the library said.
class CGNSHandle
{
public:
  CGNSHandle(const std::string& path, int mode)
    : Path(path)
  {
    if (cg_open(path.c_str(), mode, &this->Id) != CG_OK)
    {
      this->Id = -1;
      throw FileError(path + ": not a CGNS file that can be opened" + LastError());
    }
  }
  ~CGNSHandle()
  {
    if (this->Id >= 0)
    {
      cg_close(this->Id);
    }
  }
  CGNSHandle(const CGNSHandle&) = delete;
  CGNSHandle& operator=(const CGNSHandle&) = delete;

  /// Throws FileError when `status` is not CG_OK.
  void Check(int status, const std::string& what) const
  {
    if (status != CG_OK)
    {
      throw FileError(this->Path + ": cannot read " + what + LastError());
    }
  }

  /// Throws FileError("<file>: <what>").
  [[noreturn]] void Fail(const std::string& what) const
  {
    throw FileError(this->Path + ": " + what);
  }

  /// Closes the file, with its error (a write that could not be flushed) as a FileError.
  void Close()
  {
    const int status = cg_close(this->Id);
    this->Id = -1;
    if (status != CG_OK)
    {
      throw FileError(this->Path + ": cannot be written" + LastError());
    }
  }

  int Id = -1;
  std::string Path;
};

/// One coordinate array of the zone, as the file stores it.
struct Coordinate
{
  std::string Name; ///< CoordinateX, CoordinateY, CoordinateZ
  DataType Type;    ///< RealSingle or RealDouble
};

/// The node the reader uses: the first base, its zone, and its coordinate arrays.
struct ZoneLayout
{
  std::string Base, Zone; ///< names, for the messages
  int CellDimension = 0;
  int PhysicalDimension = 0;
  cgsize_t Vertices = 0;
  std::vector<Coordinate> Coordinates; ///< X, Y (, Z when the physical dimension is 3)
};

/// The most entries (of 8 bytes) an array read from the file may have: a count the file cannot
/// back is refused before it drives an allocation. A compressed (HDF5) file holds its arrays in at
/// least 1/64 of their size, with 64 MiB allowed for any file.
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

/// The elements of one section: element numbers First..First + Size() - 1 of the zone.
struct Section
{
  std::string Name; ///< "section '<name>'", for the messages
  cgsize_t First = 0;
  Cells Elements; ///< on 0-based nodes
};

/// The elements of the zone's sections, with their element numbers.
class ZoneElements
{
public:
  /// Reads every section, checking node indices; sections ordered by element number.
  void Read(const CGNSHandle& file, const ZoneLayout& layout);

  /// The section holding element `number`, or nullptr.
  const Section* Find(cgsize_t number) const;

  std::vector<Section> Sections; ///< in the file's order
  cgsize_t Total = 0;            ///< the number of elements of all sections

private:
  std::vector<const Section*> ByNumber;
};

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

/// The boundary condition `bc` of the zone as a NamedBoundary: faces or Vertex cells.
NamedBoundary ReadBoundaryCondition(const CGNSHandle& file, const ZoneLayout& layout,
  const ZoneElements& elements, int dimension, int bc)
{
  char name[33] = { 0 };
  CGNS_ENUMT(BCType_t) type = CGNS_ENUMV(BCTypeNull);
  CGNS_ENUMT(PointSetType_t) pointSet = CGNS_ENUMV(PointSetTypeNull);
  cgsize_t count = 0, normalSize = 0;
  int normalIndex[3] = { 0, 0, 0 };
  DataType normalType = CGNS_ENUMV(DataTypeNull);
  int dataSets = 0;
  file.Check(cg_boco_info(file.Id, 1, 1, bc, name, &type, &pointSet, &count, normalIndex,
               &normalSize, &normalType, &dataSets),
    "boundary condition " + std::to_string(bc) + " of " + layout.Zone);
  NamedBoundary boundary;
  boundary.Name = name;
  const std::string where = "boundary condition '" + boundary.Name + "' of " + layout.Zone;
  CGNS_ENUMT(GridLocation_t) location = CGNS_ENUMV(GridLocationNull);
  file.Check(cg_boco_gridlocation_read(file.Id, 1, 1, bc, &location), "the location of " + where);

  const bool range = pointSet == CGNS_ENUMV(PointRange) || pointSet == CGNS_ENUMV(ElementRange);
  const bool list = pointSet == CGNS_ENUMV(PointList) || pointSet == CGNS_ENUMV(ElementList);
  const bool onElements = pointSet == CGNS_ENUMV(ElementRange) ||
    pointSet == CGNS_ENUMV(ElementList) || location == CGNS_ENUMV(FaceCenter) ||
    location == CGNS_ENUMV(EdgeCenter);
  if (!range && !list)
  {
    file.Fail(where + " is given as " + cg_PointSetTypeName(pointSet) +
      "; PointRange, PointList, ElementRange or ElementList are read");
  }
  if (!onElements && location != CGNS_ENUMV(Vertex))
  {
    file.Fail(where + " is located at " + cg_GridLocationName(location) +
      "; Vertex, FaceCenter or EdgeCenter are read");
  }
  // What the numbers count: the zone's elements, or its vertices.
  const cgsize_t limit = onElements ? elements.Total : layout.Vertices;
  if ((range && count != 2) || (list && (count < 0 || count > limit)))
  {
    file.Fail(where + " declares " + std::to_string(count) + " points");
  }
  std::vector<cgsize_t> numbers(static_cast<std::size_t>(count));
  if (count > 0)
  {
    file.Check(cg_boco_read(file.Id, 1, 1, bc, numbers.data(), nullptr), "the points of " + where);
  }
  if (range)
  {
    const cgsize_t first = numbers[0], last = numbers[1];
    if (first < 1 || last < first || last - first >= limit)
    {
      file.Fail(where + " has the range " + std::to_string(first) + ".." + std::to_string(last) +
        ", not within the zone's " + std::to_string(limit) +
        (onElements ? " elements" : " vertices"));
    }
    numbers.clear();
    for (cgsize_t n = first; n <= last; ++n)
    {
      numbers.push_back(n);
    }
  }
  if (!onElements)
  {
    // A set of nodes: sorted, each once.
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
    for (const cgsize_t node : numbers)
    {
      if (node < 1 || node > layout.Vertices)
      {
        file.Fail(where + " holds vertex " + std::to_string(node) + ", outside 1.." +
          std::to_string(layout.Vertices));
      }
      const std::int64_t index = node - 1;
      boundary.Faces.Add(Vertex, &index, 1);
    }
    return boundary;
  }
  // Faces: the elements in the file's order, each once.
  std::set<cgsize_t> seen;
  for (const cgsize_t number : numbers)
  {
    if (!seen.insert(number).second)
    {
      continue;
    }
    const Section* section = elements.Find(number);
    if (!section)
    {
      file.Fail(where + " names element " + std::to_string(number) + ", which no section holds");
    }
    const Cells& cells = section->Elements;
    const auto e = static_cast<std::size_t>(number - section->First);
    if (DimensionOfCellType(cells.Types[e]) != dimension - 1)
    {
      file.Fail(where + " names element " + std::to_string(number) + " of " + section->Name +
        ", which is not a face of the " + std::to_string(dimension) + "D mesh");
    }
    boundary.Faces.Add(cells.Types[e], cells.Connectivity.data() + cells.Offsets[e],
      static_cast<std::size_t>(cells.Offsets[e + 1] - cells.Offsets[e]));
  }
  return boundary;
}

/// Reads the mesh of an open file (see ReadCGNS), and the layout of its zone.
NamedMesh ReadMesh(const CGNSHandle& file, ZoneLayout& layout)
{
  layout = ReadLayout(file);
  NamedMesh mesh;
  mesh.Dimension = layout.CellDimension;
  const auto n = static_cast<std::size_t>(layout.Vertices);
  mesh.Points.assign(3 * n, 0.0);
  std::vector<double> values(n);
  for (std::size_t k = 0; k < layout.Coordinates.size(); ++k)
  {
    const cgsize_t first = 1, last = layout.Vertices;
    file.Check(cg_coord_read(file.Id, 1, 1, layout.Coordinates[k].Name.c_str(),
                 CGNS_ENUMV(RealDouble), &first, &last, values.data()),
      layout.Coordinates[k].Name + " of " + layout.Zone);
    for (std::size_t i = 0; i < n; ++i)
    {
      mesh.Points[3 * i + k] = values[i];
    }
  }
  if (mesh.Dimension == 2 && layout.PhysicalDimension == 3)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      if (mesh.Points[3 * i + 2] != 0.0)
      {
        file.Fail(layout.Zone + ": a mesh of 2D elements must lie in the plane z = 0 (node " +
          std::to_string(i + 1) + ")");
      }
    }
  }
  mesh.NodeIds.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    mesh.NodeIds[i] = static_cast<std::int64_t>(i + 1);
  }

  ZoneElements elements;
  elements.Read(file, layout);
  for (const Section& section : elements.Sections)
  {
    const Cells& cells = section.Elements;
    for (std::size_t e = 0; e < cells.Size(); ++e)
    {
      const int dimension = DimensionOfCellType(cells.Types[e]);
      if (dimension > mesh.Dimension)
      {
        file.Fail(section.Name + " of " + layout.Zone + " has elements of dimension " +
          std::to_string(dimension) + " in a base of cell dimension " +
          std::to_string(mesh.Dimension));
      }
      if (dimension == mesh.Dimension)
      {
        mesh.Volume.Add(cells.Types[e], cells.Connectivity.data() + cells.Offsets[e],
          static_cast<std::size_t>(cells.Offsets[e + 1] - cells.Offsets[e]));
      }
    }
  }

  int conditions = 0;
  file.Check(cg_nbocos(file.Id, 1, 1, &conditions), "the boundary conditions of " + layout.Zone);
  for (int bc = 1; bc <= conditions; ++bc)
  {
    NamedBoundary boundary = ReadBoundaryCondition(file, layout, elements, mesh.Dimension, bc);
    if (boundary.Faces.Size() > 0) // an empty point list names nothing
    {
      mesh.Boundaries.push_back(std::move(boundary));
    }
  }
  ValidateNamedMesh(mesh, file.Path);
  return mesh;
}
} // namespace

/// ReadCGNS in this process (ReadCGNS runs it in a child).
static NamedMesh ReadCGNSInThisProcess(const std::string& path)
{
  CGNSHandle file(path, CG_MODE_READ);
  ZoneLayout layout;
  return ReadMesh(file, layout);
}

NamedMesh ReadCGNS(const std::string& path)
{
  return ReadMeshIsolated(path, "the CGNS library", [&]() { return ReadCGNSInThisProcess(path); });
}

/// WriteCGNSWithPoints in this process (WriteCGNSWithPoints runs it in a child).
static void WriteCGNSWithPointsInThisProcess(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  ZoneLayout layout;
  NamedMesh mesh;
  {
    CGNSHandle file(source, CG_MODE_READ);
    mesh = ReadMesh(file, layout);
  }
  if (count != mesh.NumberOfNodes())
  {
    throw FileError(target + ": " + std::to_string(count) + " points given for the " +
      std::to_string(mesh.NumberOfNodes()) + " nodes of " + source + "; nothing was written");
  }
  // The coordinates written: x, y, and z in 3D (a 2D mesh keeps the file's z, 0, if it has one).
  const std::size_t written = static_cast<std::size_t>(mesh.Dimension);
  std::vector<std::vector<double>> values(written, std::vector<double>(count));
  for (std::size_t k = 0; k < written; ++k)
  {
    const bool single = layout.Coordinates[k].Type == CGNS_ENUMV(RealSingle);
    for (std::size_t i = 0; i < count; ++i)
    {
      const double value = points[3 * i + k];
      if (!std::isfinite(value) || (single && !std::isfinite(static_cast<float>(value))))
      {
        throw FileError(target + ": point " + std::to_string(i) + " has a coordinate that is " +
          (single ? "not finite as a float" : "not finite") + "; nothing was written");
      }
      values[k][i] = value;
    }
  }
  WriteModifiedCopy(source, target,
    [&](const std::string& temporary)
    {
      CGNSHandle file(temporary, CG_MODE_MODIFY);
      const ZoneLayout copy = ReadLayout(file);
      if (copy.Vertices != layout.Vertices)
      {
        file.Fail("the copy of " + source + " has another zone");
      }
      for (std::size_t k = 0; k < written; ++k)
      {
        const Coordinate& coordinate = copy.Coordinates[k];
        std::vector<float> singles;
        const void* data = values[k].data();
        if (coordinate.Type == CGNS_ENUMV(RealSingle))
        {
          singles.assign(values[k].begin(), values[k].end());
          data = singles.data();
        }
        // Over the whole range of the existing array: its data are replaced in place, the node
        // and its children (units, data class) kept.
        const cgsize_t first = 1, last = copy.Vertices;
        int index = 0;
        file.Check(cg_coord_partial_write(file.Id, 1, 1, coordinate.Type, coordinate.Name.c_str(),
                     &first, &last, data, &index),
          "(writing) " + coordinate.Name + " of " + copy.Zone);
      }
      file.Close();
    });
}

void WriteCGNSWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  WriteIsolated(source, target, "the CGNS library",
    [&]() { WriteCGNSWithPointsInThisProcess(source, target, points, count); });
}

} // namespace meshfile
} // namespace dgmf
