// The CGNS reader and writer (CGNSFile.h): files made in the test with the CGNS library itself
// (ParaView's vtkcgns), read back field by field; write-back. Files the reader refuses:
// TestCGNSHostileFiles.cxx.
#include "CGNSTestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace mf = dgmf::meshfile;
namespace fs = std::filesystem;
using namespace cgnstest;
using dgmf_test::Find;
using dgmf_test::NodesOf;

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

TEST(CGNSFile, ReadsTheFamiliesOfTheBoundaryConditions)
{
  // A boundary condition's FamilyName is its family, by name or by a path to it (CGNS 4): the
  // name the filter chooses the family's boundaries by. Without one, none.
  const fs::path file = WorkDirectory() / "families.cgns";
  CGNSContent c = SplitCube();
  c.BoundaryConditions[0].Family = "walls";
  c.BoundaryConditions[1].Family = "/Base/walls";
  c.BoundaryConditions[2].Family = "inlet";
  WriteCGNS(file, c);
  const mf::NamedMesh mesh = mf::ReadCGNS(file.string());
  ASSERT_EQ(mesh.Boundaries.size(), 4u);
  EXPECT_EQ(mesh.Boundaries[0].Family, "walls");
  EXPECT_EQ(mesh.Boundaries[1].Family, "walls");
  EXPECT_EQ(mesh.Boundaries[2].Family, "inlet");
  EXPECT_EQ(mesh.Boundaries[3].Family, "");
  EXPECT_EQ(mesh.Boundaries[0].Name, "floor");
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
