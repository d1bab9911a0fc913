// The checks every mesh-file reader's result passes (ValidateNamedMesh).
#include "dgmf/meshfile/NamedMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

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
