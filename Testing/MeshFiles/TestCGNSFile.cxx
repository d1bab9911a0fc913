// The CGNS reader and writer (CGNSFile.h): files made in the test with the CGNS library itself
// (ParaView's vtkcgns), read back field by field; write-back; files the reader refuses.
#include "dgmf/meshfile/CGNSFile.h"

#include "ByteMutations.h"
#include "NamedMeshTestHelpers.h"

#include <vtkcgns/src/cgnslib.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace mf = dgmf::meshfile;
namespace fs = std::filesystem;

namespace
{
using Numbers = std::vector<cgsize_t>;

fs::path WorkDirectory()
{
  return dgmf_test::WorkDirectory("cgns");
}

/// What the test writes as a CGNS file: one base, one unstructured zone (unless told otherwise).
struct CGNSContent
{
  int CellDimension = 3;
  int PhysicalDimension = 3;
  CGNS_ENUMT(DataType_t) CoordinateType = CGNS_ENUMV(RealDouble);
  std::vector<double> X, Y, Z;
  struct Section
  {
    std::string Name;
    CGNS_ENUMT(ElementType_t) Type;
    cgsize_t Start, End;
    Numbers Nodes;   // 1-based; for MIXED: type, nodes, type, nodes...
    Numbers Offsets; // MIXED only: where each element starts in Nodes (one more than elements)
  };
  std::vector<Section> Sections;
  struct BoundaryCondition
  {
    std::string Name;
    CGNS_ENUMT(BCType_t) Type;
    CGNS_ENUMT(PointSetType_t) PointSet;
    CGNS_ENUMT(GridLocation_t) Location;
    Numbers Points;
  };
  std::vector<BoundaryCondition> BoundaryConditions;
  bool DataClassOnCoordinateX = false; // a child node under CoordinateX, kept by the writer
  bool StructuredSecondZone = false;   // a structured zone after the unstructured one
  bool UnstructuredSecondZone = false; // a copy of the zone as a second zone
};

void Check(int status, const std::string& what)
{
  if (status != CG_OK)
  {
    throw std::runtime_error("the test could not write " + what + ": " + cg_get_error());
  }
}

/// Writes the unstructured zone of `c` as zone `name` of base 1.
void WriteZone(int fn, const CGNSContent& c, const char* name)
{
  const cgsize_t cells = std::count_if(c.Sections.begin(), c.Sections.end(),
    [](const CGNSContent::Section&) { return true; }); // NCell is not checked by the reader
  cgsize_t sizes[3] = { static_cast<cgsize_t>(c.X.size()), cells, 0 };
  int zone = 0;
  Check(cg_zone_write(fn, 1, name, sizes, CGNS_ENUMV(Unstructured), &zone), "the zone");
  const std::vector<double>* arrays[] = { &c.X, &c.Y, &c.Z };
  const char* names[] = { "CoordinateX", "CoordinateY", "CoordinateZ" };
  for (int k = 0; k < c.PhysicalDimension; ++k)
  {
    int index = 0;
    std::vector<float> singles(arrays[k]->begin(), arrays[k]->end());
    const void* data = c.CoordinateType == CGNS_ENUMV(RealSingle)
      ? static_cast<const void*>(singles.data())
      : static_cast<const void*>(arrays[k]->data());
    Check(cg_coord_write(fn, 1, zone, c.CoordinateType, names[k], data, &index), names[k]);
    if (k == 0 && c.DataClassOnCoordinateX)
    {
      Check(cg_goto(fn, 1, "Zone_t", zone, "GridCoordinates_t", 1, "DataArray_t", index, "end"),
        "(going to) CoordinateX");
      Check(cg_dataclass_write(CGNS_ENUMV(Dimensional)), "CoordinateX's data class");
    }
  }
  for (const auto& s : c.Sections)
  {
    int index = 0;
    if (s.Type == CGNS_ENUMV(MIXED))
    {
      Check(cg_poly_section_write(fn, 1, zone, s.Name.c_str(), s.Type, s.Start, s.End, 0,
              s.Nodes.data(), s.Offsets.data(), &index),
        s.Name);
    }
    else
    {
      Check(cg_section_write(
              fn, 1, zone, s.Name.c_str(), s.Type, s.Start, s.End, 0, s.Nodes.data(), &index),
        s.Name);
    }
  }
  for (const auto& bc : c.BoundaryConditions)
  {
    int index = 0;
    Check(cg_boco_write(fn, 1, zone, bc.Name.c_str(), bc.Type, bc.PointSet,
            static_cast<cgsize_t>(bc.Points.size()), bc.Points.data(), &index),
      bc.Name);
    // ElementRange and ElementList are written as PointRange and PointList at FaceCenter.
    if (bc.PointSet != CGNS_ENUMV(ElementRange) && bc.PointSet != CGNS_ENUMV(ElementList))
    {
      Check(cg_boco_gridlocation_write(fn, 1, zone, index, bc.Location), bc.Name + "'s location");
    }
  }
}

/// Writes `c` with the CGNS library.
void WriteCGNS(const fs::path& path, const CGNSContent& c)
{
  int fn = 0;
  Check(cg_open(path.c_str(), CG_MODE_WRITE, &fn), "the file");
  int base = 0;
  Check(cg_base_write(fn, "Base", c.CellDimension, c.PhysicalDimension, &base), "the base");
  WriteZone(fn, c, "Zone");
  if (c.UnstructuredSecondZone)
  {
    WriteZone(fn, c, "Zone2");
  }
  if (c.StructuredSecondZone)
  {
    cgsize_t sizes[9] = { 2, 2, 2, 1, 1, 1, 0, 0, 0 };
    int zone = 0;
    Check(cg_zone_write(fn, 1, "Block", sizes, CGNS_ENUMV(Structured), &zone), "a block");
  }
  Check(cg_close(fn), "the file (closing)");
}

/// A unit cube of 8 nodes split into 6 tetrahedra around its diagonal 1-7 (elements 1-6), and its
/// 12 boundary triangles (elements 7-18: z = 0, z = 1, x = 0, x = 1, y = 0, y = 1, two each).
/// Boundary conditions: "floor" (BCWall, PointRange 7..8, FaceCenter), "ceiling" (BCFarfield,
/// PointRange 9..10, FaceCenter), "left" (BCInflow, PointList 11 12, FaceCenter), "back"
/// (BCSymmetryPlane, vertices 4 3 7 8 4 of y = 1, Vertex).
CGNSContent SplitCube()
{
  CGNSContent c;
  c.X = { 0, 1, 1, 0, 0, 1, 1, 0 };
  c.Y = { 0, 0, 1, 1, 0, 0, 1, 1 };
  c.Z = { 0, 0, 0, 0, 1, 1, 1, 1 };
  c.Sections.push_back({ "Tetrahedra", CGNS_ENUMV(TETRA_4), 1, 6,
    { 1, 2, 3, 7, 1, 3, 4, 7, 1, 4, 8, 7, 1, 8, 5, 7, 1, 5, 6, 7, 1, 6, 2, 7 }, {} });
  c.Sections.push_back({ "Boundary", CGNS_ENUMV(TRI_3), 7, 18,
    { 1, 3, 2, 1, 4, 3, /* z = 0 */ 5, 6, 7, 5, 7, 8, /* z = 1 */ 1, 5, 8, 1, 8, 4, /* x = 0 */
      2, 3, 7, 2, 7, 6, /* x = 1 */ 1, 2, 6, 1, 6, 5, /* y = 0 */ 4, 8, 7, 4, 7, 3 /* y = 1 */ },
    {} });
  c.BoundaryConditions.push_back(
    { "floor", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointRange), CGNS_ENUMV(FaceCenter), { 7, 8 } });
  c.BoundaryConditions.push_back({ "ceiling", CGNS_ENUMV(BCFarfield), CGNS_ENUMV(PointRange),
    CGNS_ENUMV(FaceCenter), { 9, 10 } });
  c.BoundaryConditions.push_back(
    { "left", CGNS_ENUMV(BCInflow), CGNS_ENUMV(PointList), CGNS_ENUMV(FaceCenter), { 12, 11 } });
  c.BoundaryConditions.push_back({ "back", CGNS_ENUMV(BCSymmetryPlane), CGNS_ENUMV(PointList),
    CGNS_ENUMV(Vertex), { 4, 3, 7, 8, 4 } });
  return c;
}

/// A 2D mesh of 6 nodes in the plane (physical dimension 2): a quadrilateral and two triangles
/// (elements 1-3), and the 6 boundary edges (elements 4-9: bottom, bottom, top, top, left,
/// right). "bottom" (PointRange 4..5, EdgeCenter), "sides" (PointList 8 9, EdgeCenter), "corner"
/// (Vertex 1).
CGNSContent TwoDimensional()
{
  CGNSContent c;
  c.CellDimension = 2;
  c.PhysicalDimension = 2;
  c.X = { 0, 1, 2, 0, 1, 2 };
  c.Y = { 0, 0, 0, 1, 1, 1 };
  c.Z = { 0, 0, 0, 0, 0, 0 };
  c.Sections.push_back({ "Quadrilateral", CGNS_ENUMV(QUAD_4), 1, 1, { 1, 2, 5, 4 }, {} });
  c.Sections.push_back({ "Triangles", CGNS_ENUMV(TRI_3), 2, 3, { 2, 3, 6, 2, 6, 5 }, {} });
  c.Sections.push_back(
    { "Edges", CGNS_ENUMV(BAR_2), 4, 9, { 1, 2, 2, 3, 6, 5, 5, 4, 4, 1, 3, 6 }, {} });
  c.BoundaryConditions.push_back(
    { "bottom", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointRange), CGNS_ENUMV(EdgeCenter), { 4, 5 } });
  c.BoundaryConditions.push_back(
    { "sides", CGNS_ENUMV(BCFarfield), CGNS_ENUMV(PointList), CGNS_ENUMV(EdgeCenter), { 8, 9 } });
  c.BoundaryConditions.push_back(
    { "corner", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointList), CGNS_ENUMV(Vertex), { 1 } });
  return c;
}

using dgmf_test::Find;
using dgmf_test::NodesOf;

std::string ErrorOf(const fs::path& path)
{
  return dgmf_test::ErrorOf(mf::ReadCGNS, path);
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

std::string Bytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

std::size_t FilesIn(const fs::path& directory)
{
  return static_cast<std::size_t>(
    std::distance(fs::directory_iterator(directory), fs::directory_iterator()));
}

/// The data type of each coordinate array of the file's zone.
std::vector<CGNS_ENUMT(DataType_t)> CoordinateTypes(const fs::path& path)
{
  int fn = 0, count = 0;
  Check(cg_open(path.c_str(), CG_MODE_READ, &fn), "(opening) the file");
  Check(cg_ncoords(fn, 1, 1, &count), "(reading) the coordinates");
  std::vector<CGNS_ENUMT(DataType_t)> types;
  for (int c = 1; c <= count; ++c)
  {
    CGNS_ENUMT(DataType_t) type;
    char name[33];
    Check(cg_coord_info(fn, 1, 1, c, &type, name), "(reading) a coordinate");
    types.push_back(type);
  }
  cg_close(fn);
  return types;
}

void ExpectSameExceptPoints(const mf::NamedMesh& a, const mf::NamedMesh& b)
{
  EXPECT_EQ(a.Dimension, b.Dimension);
  EXPECT_EQ(a.NodeIds, b.NodeIds);
  EXPECT_EQ(a.Volume.Types, b.Volume.Types);
  EXPECT_EQ(a.Volume.Connectivity, b.Volume.Connectivity);
  ASSERT_EQ(a.Boundaries.size(), b.Boundaries.size());
  for (std::size_t k = 0; k < a.Boundaries.size(); ++k)
  {
    EXPECT_EQ(a.Boundaries[k].Name, b.Boundaries[k].Name);
    EXPECT_EQ(a.Boundaries[k].Faces.Types, b.Boundaries[k].Faces.Types);
    EXPECT_EQ(a.Boundaries[k].Faces.Connectivity, b.Boundaries[k].Faces.Connectivity);
  }
}
} // namespace

TEST(CGNSFile, ReadsNodesInFileOrderTetrahedraAndBoundaryConditionsAsNamedBoundaries)
{
  const fs::path file = WorkDirectory() / "cube.cgns";
  const CGNSContent c = SplitCube();
  WriteCGNS(file, c);
  const mf::NamedMesh mesh = mf::ReadCGNS(file.string());
  EXPECT_EQ(mesh.Dimension, 3);
  ASSERT_EQ(mesh.NumberOfNodes(), 8u);
  for (std::size_t i = 0; i < 8; ++i)
  {
    EXPECT_EQ(mesh.Points[3 * i], c.X[i]);
    EXPECT_EQ(mesh.Points[3 * i + 1], c.Y[i]);
    EXPECT_EQ(mesh.Points[3 * i + 2], c.Z[i]);
    EXPECT_EQ(mesh.NodeIds[i], static_cast<std::int64_t>(i + 1)); // CGNS's numbering
  }
  // The tetrahedra are the volume, in CGNS's (VTK's) node order, 0-based; the triangles are not.
  ASSERT_EQ(mesh.Volume.Size(), 6u);
  for (std::size_t k = 0; k < 24; ++k)
  {
    EXPECT_EQ(mesh.Volume.Connectivity[k], c.Sections[0].Nodes[k] - 1);
  }
  EXPECT_TRUE(std::all_of(mesh.Volume.Types.begin(), mesh.Volume.Types.end(),
    [](std::uint8_t t) { return t == mf::Tetra; }));

  ASSERT_EQ(mesh.Boundaries.size(), 4u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "floor"); // the file's order
  EXPECT_EQ(mesh.Boundaries[3].Name, "back");
  const mf::NamedBoundary* floor = Find(mesh, "floor");
  const mf::NamedBoundary* ceiling = Find(mesh, "ceiling");
  const mf::NamedBoundary* left = Find(mesh, "left");
  const mf::NamedBoundary* back = Find(mesh, "back");
  ASSERT_TRUE(floor && ceiling && left && back);
  // PointRange of faces: the triangles, with their nodes in the file's order.
  ASSERT_EQ(floor->Faces.Size(), 2u);
  EXPECT_EQ(floor->Faces.Types, (std::vector<std::uint8_t>{ mf::Triangle, mf::Triangle }));
  EXPECT_EQ(floor->Faces.Connectivity, (std::vector<std::int64_t>{ 0, 2, 1, 0, 3, 2 }));
  EXPECT_EQ(NodesOf(*ceiling), (std::set<std::int64_t>{ 4, 5, 6, 7 }));
  // PointList of faces: in the list's order.
  ASSERT_EQ(left->Faces.Size(), 2u);
  EXPECT_EQ(left->Faces.Connectivity, (std::vector<std::int64_t>{ 0, 7, 3, 0, 4, 7 }));
  // Vertex: one Vertex cell per node, sorted, each once.
  EXPECT_EQ(back->Faces.Types, std::vector<std::uint8_t>(4, mf::Vertex));
  EXPECT_EQ(back->Faces.Connectivity, (std::vector<std::int64_t>{ 2, 3, 6, 7 }));
}

TEST(CGNSFile, ReadsBoundaryConditionsGivenAsElementRangeOrElementList)
{
  // The CGNS 2 forms, which the library turns into PointRange/PointList at FaceCenter.
  const fs::path file = WorkDirectory() / "elements.cgns";
  CGNSContent c = SplitCube();
  c.BoundaryConditions.push_back({ "right", CGNS_ENUMV(BCOutflow), CGNS_ENUMV(ElementRange),
    CGNS_ENUMV(FaceCenter), { 13, 14 } });
  c.BoundaryConditions.push_back(
    { "front", CGNS_ENUMV(BCWall), CGNS_ENUMV(ElementList), CGNS_ENUMV(FaceCenter), { 15, 16 } });
  WriteCGNS(file, c);
  const mf::NamedMesh mesh = mf::ReadCGNS(file.string());
  ASSERT_TRUE(Find(mesh, "right") && Find(mesh, "front"));
  EXPECT_EQ(NodesOf(*Find(mesh, "right")), (std::set<std::int64_t>{ 1, 2, 5, 6 }));
  EXPECT_EQ(NodesOf(*Find(mesh, "front")), (std::set<std::int64_t>{ 0, 1, 4, 5 }));
  EXPECT_EQ(Find(mesh, "front")->Faces.Types[0], mf::Triangle);
}

TEST(CGNSFile, ReadsA2DMeshOfQuadrilateralsAndTrianglesWithEdgeBoundaries)
{
  const fs::path file = WorkDirectory() / "plane.cgns";
  const CGNSContent c = TwoDimensional();
  WriteCGNS(file, c);
  const mf::NamedMesh mesh = mf::ReadCGNS(file.string());
  EXPECT_EQ(mesh.Dimension, 2);
  ASSERT_EQ(mesh.NumberOfNodes(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
  {
    EXPECT_EQ(mesh.Points[3 * i], c.X[i]);
    EXPECT_EQ(mesh.Points[3 * i + 1], c.Y[i]);
    EXPECT_EQ(mesh.Points[3 * i + 2], 0.0); // no CoordinateZ: z = 0
  }
  EXPECT_EQ(mesh.Volume.Types, (std::vector<std::uint8_t>{ mf::Quad, mf::Triangle, mf::Triangle }));
  EXPECT_EQ(mesh.Volume.Connectivity, (std::vector<std::int64_t>{ 0, 1, 4, 3, 1, 2, 5, 1, 5, 4 }));
  ASSERT_EQ(mesh.Boundaries.size(), 3u);
  const mf::NamedBoundary* bottom = Find(mesh, "bottom");
  const mf::NamedBoundary* sides = Find(mesh, "sides");
  const mf::NamedBoundary* corner = Find(mesh, "corner");
  ASSERT_TRUE(bottom && sides && corner);
  EXPECT_EQ(bottom->Faces.Types, (std::vector<std::uint8_t>{ mf::Line, mf::Line }));
  EXPECT_EQ(bottom->Faces.Connectivity, (std::vector<std::int64_t>{ 0, 1, 1, 2 }));
  EXPECT_EQ(sides->Faces.Connectivity, (std::vector<std::int64_t>{ 3, 0, 2, 5 }));
  EXPECT_EQ(corner->Faces.Types, (std::vector<std::uint8_t>{ mf::Vertex }));
  EXPECT_EQ(corner->Faces.Connectivity, (std::vector<std::int64_t>{ 0 }));
}

TEST(CGNSFile, ReadsA2DMeshInA3DBaseWhenItLiesAtZZero)
{
  const fs::path directory = WorkDirectory();
  CGNSContent c = TwoDimensional();
  c.PhysicalDimension = 3;
  WriteCGNS(directory / "flat.cgns", c);
  const mf::NamedMesh mesh = mf::ReadCGNS((directory / "flat.cgns").string());
  EXPECT_EQ(mesh.Dimension, 2);
  EXPECT_EQ(mesh.Volume.Size(), 3u);

  c.Z[4] = 0.5;
  WriteCGNS(directory / "bent.cgns", c);
  EXPECT_TRUE(Contains(ErrorOf(directory / "bent.cgns"), "z = 0"));
}

TEST(CGNSFile, ReadsMixedSections)
{
  // The 2D mesh as one MIXED section: the quadrilateral, the triangles and the edges.
  const fs::path file = WorkDirectory() / "mixed.cgns";
  CGNSContent c = TwoDimensional();
  CGNSContent::Section mixed{ "Mixed", CGNS_ENUMV(MIXED), 1, 9, {}, { 0 } };
  for (const auto& s : c.Sections)
  {
    int npe = 0;
    cg_npe(s.Type, &npe);
    for (std::size_t first = 0; first < s.Nodes.size(); first += static_cast<std::size_t>(npe))
    {
      mixed.Nodes.push_back(s.Type);
      mixed.Nodes.insert(mixed.Nodes.end(), s.Nodes.begin() + static_cast<std::ptrdiff_t>(first),
        s.Nodes.begin() + static_cast<std::ptrdiff_t>(first) + npe);
      mixed.Offsets.push_back(static_cast<cgsize_t>(mixed.Nodes.size()));
    }
  }
  c.Sections = { mixed };
  WriteCGNS(file, c);
  const mf::NamedMesh mesh = mf::ReadCGNS(file.string());
  WriteCGNS(file.string() + ".separate.cgns", TwoDimensional());
  const mf::NamedMesh separate = mf::ReadCGNS(file.string() + ".separate.cgns");
  EXPECT_EQ(mesh.Volume.Types, separate.Volume.Types);
  EXPECT_EQ(mesh.Volume.Connectivity, separate.Volume.Connectivity);
  ExpectSameExceptPoints(mesh, separate);
}

TEST(CGNSFile, ReadsMixedSectionsOfTetrahedraAndTriangles)
{
  const fs::path file = WorkDirectory() / "mixed3d.cgns";
  CGNSContent c = SplitCube();
  CGNSContent::Section mixed{ "Mixed", CGNS_ENUMV(MIXED), 1, 18, {}, { 0 } };
  for (const auto& s : c.Sections)
  {
    const std::size_t npe = s.Type == CGNS_ENUMV(TETRA_4) ? 4 : 3;
    for (std::size_t first = 0; first < s.Nodes.size(); first += npe)
    {
      mixed.Nodes.push_back(s.Type);
      mixed.Nodes.insert(mixed.Nodes.end(), s.Nodes.begin() + static_cast<std::ptrdiff_t>(first),
        s.Nodes.begin() + static_cast<std::ptrdiff_t>(first + npe));
      mixed.Offsets.push_back(static_cast<cgsize_t>(mixed.Nodes.size()));
    }
  }
  c.Sections = { mixed };
  WriteCGNS(file, c);
  const mf::NamedMesh mesh = mf::ReadCGNS(file.string());
  WriteCGNS(file.string() + ".separate.cgns", SplitCube());
  ExpectSameExceptPoints(mesh, mf::ReadCGNS(file.string() + ".separate.cgns"));
}

TEST(CGNSFile, WritesACopyWithOnlyTheCoordinatesChanged)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "source.cgns";
  const fs::path target = directory / "moved.cgns";
  CGNSContent c = SplitCube();
  c.DataClassOnCoordinateX = true;
  WriteCGNS(source, c);
  const mf::NamedMesh before = mf::ReadCGNS(source.string());
  std::vector<double> moved(before.Points);
  for (std::size_t k = 0; k < moved.size(); ++k)
  {
    moved[k] = moved[k] * 1.25 + 0.1 * std::sin(static_cast<double>(k));
  }
  mf::WriteCGNSWithPoints(source.string(), target.string(), moved.data(), moved.size() / 3);
  const mf::NamedMesh after = mf::ReadCGNS(target.string());
  EXPECT_EQ(after.Points, moved); // RealDouble coordinates: bit for bit
  ExpectSameExceptPoints(after, before);
  EXPECT_EQ(
    CoordinateTypes(target), std::vector<CGNS_ENUMT(DataType_t)>(3, CGNS_ENUMV(RealDouble)));
  // The coordinate array's own children stay.
  {
    int fn = 0;
    ASSERT_EQ(cg_open(target.c_str(), CG_MODE_READ, &fn), CG_OK);
    CGNS_ENUMT(DataClass_t) dataClass = CGNS_ENUMV(DataClassNull);
    EXPECT_EQ(cg_goto(fn, 1, "Zone_t", 1, "GridCoordinates_t", 1, "DataArray_t", 1, "end"), CG_OK);
    EXPECT_EQ(cg_dataclass_read(&dataClass), CG_OK);
    EXPECT_EQ(dataClass, CGNS_ENUMV(Dimensional));
    // The boundary conditions keep their types and point sets.
    char name[33];
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) pointSet;
    cgsize_t count = 0, normalSize = 0;
    int normalIndex[3], dataSets = 0;
    CGNS_ENUMT(DataType_t) normalType;
    EXPECT_EQ(cg_boco_info(fn, 1, 1, 2, name, &type, &pointSet, &count, normalIndex, &normalSize,
                &normalType, &dataSets),
      CG_OK);
    EXPECT_EQ(std::string(name), "ceiling");
    EXPECT_EQ(type, CGNS_ENUMV(BCFarfield));
    EXPECT_EQ(pointSet, CGNS_ENUMV(PointRange));
    cg_close(fn);
  }
  // The source is untouched, and nothing is left beside the target.
  EXPECT_EQ(mf::ReadCGNS(source.string()).Points, before.Points);
  EXPECT_EQ(FilesIn(directory), 2u);

  // In place (the target is the source).
  mf::WriteCGNSWithPoints(source.string(), source.string(), moved.data(), moved.size() / 3);
  EXPECT_EQ(mf::ReadCGNS(source.string()).Points, moved);
  EXPECT_EQ(FilesIn(directory), 2u);
}

TEST(CGNSFile, SingleCoordinatesStaySingle)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "single.cgns";
  CGNSContent c = SplitCube();
  c.CoordinateType = CGNS_ENUMV(RealSingle);
  WriteCGNS(source, c);
  std::vector<double> moved = mf::ReadCGNS(source.string()).Points;
  moved[0] = 0.1;  // not a float
  moved[23] = 1.7; // z of the last node
  mf::WriteCGNSWithPoints(source.string(), source.string(), moved.data(), moved.size() / 3);
  const mf::NamedMesh after = mf::ReadCGNS(source.string());
  for (std::size_t k = 0; k < moved.size(); ++k)
  {
    EXPECT_EQ(after.Points[k], static_cast<double>(static_cast<float>(moved[k])));
  }
  EXPECT_EQ(
    CoordinateTypes(source), std::vector<CGNS_ENUMT(DataType_t)>(3, CGNS_ENUMV(RealSingle)));
  // A coordinate a float cannot hold is refused.
  moved[4] = 1e300;
  EXPECT_THROW(
    mf::WriteCGNSWithPoints(source.string(), source.string(), moved.data(), 8), mf::FileError);
}

TEST(CGNSFile, Writes2DMeshesWithoutAZ)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "plane.cgns";
  WriteCGNS(source, TwoDimensional());
  std::vector<double> moved = mf::ReadCGNS(source.string()).Points;
  for (std::size_t i = 0; i < moved.size() / 3; ++i)
  {
    moved[3 * i] += 0.25;
    moved[3 * i + 2] = 7.0; // ignored in 2D
  }
  mf::WriteCGNSWithPoints(source.string(), source.string(), moved.data(), moved.size() / 3);
  const mf::NamedMesh after = mf::ReadCGNS(source.string());
  for (std::size_t i = 0; i < moved.size() / 3; ++i)
  {
    EXPECT_EQ(after.Points[3 * i], moved[3 * i]);
    EXPECT_EQ(after.Points[3 * i + 2], 0.0);
  }
  EXPECT_EQ(CoordinateTypes(source).size(), 2u);
}

TEST(CGNSFile, AWrongPointCountOrANaNLeavesTheTargetUnchanged)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "source.cgns";
  const fs::path target = directory / "target.cgns";
  const fs::path existing = directory / "existing.cgns";
  WriteCGNS(source, SplitCube());
  WriteCGNS(existing, TwoDimensional());
  const std::string existingBytes = Bytes(existing);
  std::vector<double> points = mf::ReadCGNS(source.string()).Points;
  EXPECT_THROW(
    mf::WriteCGNSWithPoints(source.string(), target.string(), points.data(), 7), mf::FileError);
  EXPECT_THROW(
    mf::WriteCGNSWithPoints(source.string(), existing.string(), points.data(), 9), mf::FileError);
  points[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(
    mf::WriteCGNSWithPoints(source.string(), target.string(), points.data(), 8), mf::FileError);
  EXPECT_THROW(
    mf::WriteCGNSWithPoints(source.string(), existing.string(), points.data(), 8), mf::FileError);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(Bytes(existing), existingBytes);
  EXPECT_EQ(FilesIn(directory), 2u); // no temporary file left
}

TEST(CGNSFile, RefusesMissingAndNonCGNSFiles)
{
  const fs::path directory = WorkDirectory();
  EXPECT_TRUE(Contains(ErrorOf(directory / "missing.cgns"), "missing.cgns"));
  {
    std::ofstream text(directory / "text.cgns");
    text << "not a CGNS file\n";
  }
  EXPECT_TRUE(Contains(ErrorOf(directory / "text.cgns"), "text.cgns"));
  // A truncated file.
  WriteCGNS(directory / "whole.cgns", SplitCube());
  fs::copy_file(directory / "whole.cgns", directory / "truncated.cgns");
  fs::resize_file(directory / "truncated.cgns", fs::file_size(directory / "whole.cgns") / 2);
  EXPECT_NE(ErrorOf(directory / "truncated.cgns"), "");
  // Writing from a file that cannot be read writes nothing.
  std::vector<double> points(24, 0.0);
  EXPECT_THROW(mf::WriteCGNSWithPoints((directory / "text.cgns").string(),
                 (directory / "out.cgns").string(), points.data(), 8),
    mf::FileError);
  EXPECT_FALSE(fs::exists(directory / "out.cgns"));
}

TEST(CGNSFile, RefusesAStructuredZoneOrASecondZone)
{
  const fs::path directory = WorkDirectory();
  CGNSContent c = SplitCube();
  c.StructuredSecondZone = true;
  WriteCGNS(directory / "structured.cgns", c);
  EXPECT_TRUE(Contains(ErrorOf(directory / "structured.cgns"), "2 zones"));

  // A structured zone alone.
  {
    int fn = 0, base = 0, zone = 0;
    const fs::path file = directory / "block.cgns";
    ASSERT_EQ(cg_open(file.c_str(), CG_MODE_WRITE, &fn), CG_OK);
    ASSERT_EQ(cg_base_write(fn, "Base", 3, 3, &base), CG_OK);
    cgsize_t sizes[9] = { 2, 2, 2, 1, 1, 1, 0, 0, 0 };
    ASSERT_EQ(cg_zone_write(fn, base, "Block", sizes, CGNS_ENUMV(Structured), &zone), CG_OK);
    ASSERT_EQ(cg_close(fn), CG_OK);
    EXPECT_TRUE(Contains(ErrorOf(file), "not unstructured"));
  }

  c = SplitCube();
  c.UnstructuredSecondZone = true;
  WriteCGNS(directory / "two.cgns", c);
  EXPECT_TRUE(Contains(ErrorOf(directory / "two.cgns"), "2 zones"));
}

TEST(CGNSFile, RefusesAnElementOnANodeThatDoesNotExist)
{
  const fs::path directory = WorkDirectory();
  CGNSContent c = SplitCube();
  c.Sections[0].Nodes[5] = 9;
  WriteCGNS(directory / "outside.cgns", c);
  const std::string error = ErrorOf(directory / "outside.cgns");
  EXPECT_TRUE(Contains(error, "node 9")) << error;
  EXPECT_TRUE(Contains(error, "Tetrahedra")) << error;

  c = SplitCube();
  c.Sections[1].Nodes[0] = 0;
  WriteCGNS(directory / "zero.cgns", c);
  EXPECT_TRUE(Contains(ErrorOf(directory / "zero.cgns"), "node 0"));

  c = SplitCube();
  c.BoundaryConditions[3].Points[0] = 42;
  WriteCGNS(directory / "vertex.cgns", c);
  EXPECT_TRUE(Contains(ErrorOf(directory / "vertex.cgns"), "back"));
}

TEST(CGNSFile, RefusesABoundaryConditionOnElementsThatAreNotFaces)
{
  const fs::path directory = WorkDirectory();
  // A tetrahedron.
  CGNSContent c = SplitCube();
  c.BoundaryConditions[2].Points = { 11, 3 };
  WriteCGNS(directory / "volume.cgns", c);
  std::string error = ErrorOf(directory / "volume.cgns");
  EXPECT_TRUE(Contains(error, "'left'") && Contains(error, "not a face")) << error;
  // An element no section holds.
  c = SplitCube();
  c.BoundaryConditions[1].Points = { 17, 19 };
  WriteCGNS(directory / "beyond.cgns", c);
  error = ErrorOf(directory / "beyond.cgns");
  EXPECT_TRUE(Contains(error, "'ceiling'")) << error;
  // Vertices as faces of a 2D mesh: a NODE section named by an edge boundary condition.
  c = TwoDimensional();
  c.Sections.push_back({ "Nodes", CGNS_ENUMV(NODE), 10, 11, { 1, 2 }, {} });
  c.BoundaryConditions[1].Points = { 9, 10 };
  WriteCGNS(directory / "nodes.cgns", c);
  error = ErrorOf(directory / "nodes.cgns");
  EXPECT_TRUE(Contains(error, "'sides'") && Contains(error, "not a face")) << error;
}

TEST(CGNSFile, RefusesHigherOrderElements)
{
  const fs::path directory = WorkDirectory();
  CGNSContent c = SplitCube();
  c.Sections[0].Type = CGNS_ENUMV(TETRA_10);
  c.Sections[0].End = 2; // 2 elements of 10 nodes (and 4 spare)
  c.Sections[0].Nodes.resize(20);
  c.BoundaryConditions.clear();
  WriteCGNS(directory / "tetra10.cgns", c);
  const std::string error = ErrorOf(directory / "tetra10.cgns");
  EXPECT_TRUE(Contains(error, "TETRA_10")) << error;
}

TEST(CGNSFile, SeededMutantsReadAsMeshesOrFileErrors)
{
  // Bytes flipped, runs overwritten, the file cut (ByteMutations.h): each mutant reads as a valid
  // mesh (ReadCGNS validates it) that writes back, or is a FileError; HDF5's and the CGNS
  // library's failures stay in the reader's child.
  const fs::path directory = WorkDirectory();
  const fs::path valid = directory / "valid.cgns";
  WriteCGNS(valid, SplitCube());
  const fs::path mutant = directory / "mutant.cgns";
  const fs::path written = directory / "written.cgns";
  int meshes = 0, errors = 0;
  dgmf_test::ForEachMutant(valid, mutant, 150, 20261124,
    [&](int k)
    {
      try
      {
        const mf::NamedMesh mesh = mf::ReadCGNS(mutant.string());
        mf::WriteCGNSWithPoints(
          mutant.string(), written.string(), mesh.Points.data(), mesh.NumberOfNodes());
        EXPECT_EQ(mf::ReadCGNS(written.string()).Points, mesh.Points) << k;
        ++meshes;
      }
      catch (const mf::FileError&)
      {
        ++errors;
      }
    });
  EXPECT_EQ(meshes + errors, 150);
  EXPECT_GT(errors, 0);
}
