// The CGNS files of the CGNS tests, written with the CGNS library itself (ParaView's vtkcgns), and
// the checks the tests share (TestCGNSFile.cxx, TestCGNSHostileFiles.cxx).
#ifndef dgmf_test_CGNSTestFiles_h
#define dgmf_test_CGNSTestFiles_h

#include "dgmf/meshfile/CGNSFile.h"

#include "NamedMeshTestHelpers.h"

#include <vtkcgns/src/cgnslib.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgnstest
{
using Numbers = std::vector<cgsize_t>;

inline std::filesystem::path WorkDirectory()
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
    std::string Family; // its FamilyName (a family of the base of that name), or none
  };
  std::vector<BoundaryCondition> BoundaryConditions;
  bool DataClassOnCoordinateX = false; // a child node under CoordinateX, kept by the writer
  bool StructuredSecondZone = false;   // a structured zone after the unstructured one
  bool UnstructuredSecondZone = false; // a copy of the zone as a second zone
};

inline void Check(int status, const std::string& what)
{
  if (status != CG_OK)
  {
    throw std::runtime_error("the test could not write " + what + ": " + cg_get_error());
  }
}

/// Writes the unstructured zone of `c` as zone `name` of base 1.
inline void WriteZone(int fn, const CGNSContent& c, const char* name)
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
    if (!bc.Family.empty())
    {
      Check(cg_goto(fn, 1, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", index, "end"), "(going to) a BC");
      Check(cg_famname_write(bc.Family.c_str()), bc.Name + "'s family");
    }
  }
}

/// Writes `c` with the CGNS library.
inline void WriteCGNS(const std::filesystem::path& path, const CGNSContent& c)
{
  int fn = 0;
  Check(cg_open(path.c_str(), CG_MODE_WRITE, &fn), "the file");
  int base = 0;
  Check(cg_base_write(fn, "Base", c.CellDimension, c.PhysicalDimension, &base), "the base");
  std::vector<std::string> families;
  for (const auto& bc : c.BoundaryConditions)
  {
    if (!bc.Family.empty() && bc.Family[0] != '/' &&
      std::find(families.begin(), families.end(), bc.Family) == families.end())
    {
      int family = 0;
      Check(cg_family_write(fn, 1, bc.Family.c_str(), &family), "the family " + bc.Family);
      families.push_back(bc.Family);
    }
  }
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
inline CGNSContent SplitCube()
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
inline CGNSContent TwoDimensional()
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

inline std::string ErrorOf(const std::filesystem::path& path)
{
  return dgmf_test::ErrorOf(dgmf::meshfile::ReadCGNS, path);
}

inline bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

inline std::string Bytes(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

inline std::size_t FilesIn(const std::filesystem::path& directory)
{
  return static_cast<std::size_t>(std::distance(
    std::filesystem::directory_iterator(directory), std::filesystem::directory_iterator()));
}

/// The data type of each coordinate array of the file's zone.
inline std::vector<CGNS_ENUMT(DataType_t)> CoordinateTypes(const std::filesystem::path& path)
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

inline void ExpectSameExceptPoints(
  const dgmf::meshfile::NamedMesh& a, const dgmf::meshfile::NamedMesh& b)
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
} // namespace cgnstest

#endif
