#include "dgmf/meshfile/CGNSFile.h"

#include "dgmf/meshfile/CGNSZone.h"

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
using namespace cgns;

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
  // Its family (FamilyName_t), if it has one: a name, or a path to the family in CGNS 4
  // ("/Base/wing"), whose last part is the family's name.
  // (The library's room for one: CG_MAX_GOTO_DEPTH names of 32 characters and their slashes.)
  char family[4096] = { 0 };
  file.Check(cg_goto(file.Id, 1, "Zone_t", 1, "ZoneBC_t", 1, "BC_t", bc, "end"), where);
  const int familyRead = cg_famname_read(family);
  if (familyRead != CG_NODE_NOT_FOUND)
  {
    file.Check(familyRead, "the family name of " + where);
    family[sizeof(family) - 1] = '\0';
    const std::string path = family;
    boundary.Family = path.substr(path.rfind('/') + 1);
  }
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
  std::size_t cellsAtMost = 0, nodesAtMost = 0;
  for (const Section& section : elements.Sections)
  {
    cellsAtMost += section.Elements.Size();
    nodesAtMost += section.Elements.Connectivity.size();
  }
  mesh.Volume.Reserve(cellsAtMost, nodesAtMost); // (no copy as the cells are added)
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
  // What the write needs of the source: its zone's layout (the node count, the coordinates'
  // names and types) and the cell dimension. A 2D mesh in a 3D base is read whole, which checks
  // that its z, kept as it is, is 0.
  ZoneLayout layout;
  {
    CGNSHandle file(source, CG_MODE_READ);
    layout = ReadLayout(file);
    if (layout.CellDimension == 2 && layout.PhysicalDimension == 3)
    {
      ReadMesh(file, layout);
    }
  }
  const auto vertices = static_cast<std::size_t>(layout.Vertices);
  if (count != vertices)
  {
    throw FileError(target + ": " + std::to_string(count) + " points given for the " +
      std::to_string(vertices) + " nodes of " + source + "; nothing was written");
  }
  // The coordinates written: x, y, and z in 3D (a 2D mesh keeps the file's z, 0, if it has one).
  const std::size_t written = static_cast<std::size_t>(layout.CellDimension);
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
