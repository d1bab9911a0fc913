// Files the CGNS reader refuses (CGNSFile.h): missing and foreign files, zones and elements it
// does not take, nodes that do not exist, and seeded byte mutants of a valid file.
#include "ByteMutations.h"
#include "CGNSTestFiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace mf = dgmf::meshfile;
namespace fs = std::filesystem;
using namespace cgnstest;

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
