// The checks every mesh-file reader's result passes (ValidateNamedMesh).
#include "dgmf/meshfile/NamedMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace mf = dgmf::meshfile;

namespace
{
/// Two triangles on a unit square, its four edges named "wall".
mf::NamedMesh Square()
{
  mf::NamedMesh mesh;
  mesh.Dimension = 2;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  mesh.NodeIds = { 1, 2, 3, 4 };
  const std::int64_t a[3] = { 0, 1, 2 }, b[3] = { 0, 2, 3 };
  mesh.Volume.Add(mf::Triangle, a, 3);
  mesh.Volume.Add(mf::Triangle, b, 3);
  mf::NamedBoundary wall;
  wall.Name = "wall";
  for (std::int64_t k = 0; k < 4; ++k)
  {
    const std::int64_t edge[2] = { k, (k + 1) % 4 };
    wall.Faces.Add(mf::Line, edge, 2);
  }
  mesh.Boundaries.push_back(wall);
  return mesh;
}

std::string ErrorOf(const mf::NamedMesh& mesh)
{
  try
  {
    mf::ValidateNamedMesh(mesh, "square.msh");
  }
  catch (const mf::FileError& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(NamedMesh, AValidMeshPasses)
{
  EXPECT_EQ(ErrorOf(Square()), "");
}

TEST(NamedMesh, EachViolationIsAnErrorNamingTheFile)
{
  mf::NamedMesh outOfRange = Square();
  outOfRange.Volume.Connectivity[4] = 4;
  EXPECT_NE(
    ErrorOf(outOfRange).find("square.msh: the volume cells: node index 4"), std::string::npos);

  mf::NamedMesh negative = Square();
  negative.Boundaries[0].Faces.Connectivity[0] = -1;
  EXPECT_NE(ErrorOf(negative).find("boundary 'wall': node index -1"), std::string::npos);

  mf::NamedMesh nan = Square();
  nan.Points[4] = std::nan("");
  EXPECT_NE(ErrorOf(nan).find("node 1 has a non-finite coordinate"), std::string::npos);

  mf::NamedMesh wrongCount = Square();
  wrongCount.Volume.Offsets[1] = 2;
  EXPECT_NE(ErrorOf(wrongCount).find("cell 0 has type 5 with 2 nodes"), std::string::npos);

  mf::NamedMesh wrongDimension = Square();
  wrongDimension.Boundaries[0].Faces.Types[0] = mf::Triangle;
  EXPECT_NE(ErrorOf(wrongDimension), "");

  mf::NamedMesh duplicate = Square();
  duplicate.Boundaries.push_back(duplicate.Boundaries[0]);
  EXPECT_NE(ErrorOf(duplicate).find("unique ('wall')"), std::string::npos);

  mf::NamedMesh empty = Square();
  empty.Volume = mf::Cells();
  EXPECT_NE(ErrorOf(empty).find("no cell of dimension 2"), std::string::npos);

  mf::NamedMesh ids = Square();
  ids.NodeIds.pop_back();
  EXPECT_NE(ErrorOf(ids).find("node ids"), std::string::npos);
}

TEST(NamedMesh, BoundariesOfOneNameAreJoinedInOrder)
{
  // gmsh lets two physical groups share a name: one boundary, the first's faces then the
  // second's (refused as a name given twice until 2026-11-30).
  mf::NamedMesh mesh = Square();
  mf::NamedBoundary inlet;
  inlet.Name = "inlet";
  const std::int64_t diagonal[2] = { 0, 2 };
  inlet.Faces.Add(mf::Line, diagonal, 2);
  mesh.Boundaries.push_back(inlet);
  mf::NamedBoundary more = mesh.Boundaries[0]; // a second "wall": its first two edges
  more.Faces = mf::Cells();
  const std::int64_t first[2] = { 0, 1 }, second[2] = { 1, 2 };
  more.Faces.Add(mf::Line, first, 2);
  more.Faces.Add(mf::Line, second, 2);
  mesh.Boundaries.push_back(more);
  EXPECT_NE(ErrorOf(mesh).find("unique"), std::string::npos);
  mf::MergeBoundariesOfOneName(mesh);
  EXPECT_EQ(ErrorOf(mesh), "");
  ASSERT_EQ(mesh.Boundaries.size(), 2u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "wall");
  EXPECT_EQ(mesh.Boundaries[1].Name, "inlet");
  const mf::Cells& wall = mesh.Boundaries[0].Faces;
  ASSERT_EQ(wall.Size(), 6u);
  EXPECT_EQ(wall.Offsets, (std::vector<std::int64_t>{ 0, 2, 4, 6, 8, 10, 12 }));
  EXPECT_EQ(std::vector<std::int64_t>(wall.Connectivity.begin() + 8, wall.Connectivity.end()),
    (std::vector<std::int64_t>{ 0, 1, 1, 2 }));
}
