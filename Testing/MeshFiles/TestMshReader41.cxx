// Version 4.1 .msh files read without gmsh (MshReader41.h): the mesh gmsh's library gives, on every
// test mesh; the files it leaves to gmsh; mutated files.
#include "dgmf/meshfile/GmshFile.h"
#include "dgmf/meshfile/MshReader41.h"

#include "gmsh/GmshTestMeshes.h"
#include "gmsh/MshTestFiles.h"
#include "gmsh/SameMesh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace mf = dgmf::meshfile;
namespace mt = dgmf::meshfile::test;
namespace fs = std::filesystem;

namespace
{
bool ReadWithoutGmsh(const std::string& path, bool binary, mf::NamedMesh& mesh)
{
  return mf::ReadMsh41(mt::Bytes(path), binary, mesh);
}
} // namespace

TEST(MshReader41, EveryTestMeshReadsAsGmshReadsIt)
{
  const fs::path dir = mt::FreshDirectory("dgmf-msh41-same");
  const std::string path = (dir / "m.msh").string();
  const int checked = mt::ForEachTestMesh(4.1, path,
    [&](bool binary)
    {
      mf::NamedMesh mesh;
      ASSERT_TRUE(ReadWithoutGmsh(path, binary, mesh));
      mt::ExpectIdentical(mesh, mf::ReadGmshWithGmsh(path));
      mt::ExpectIdentical(mf::ReadGmsh(path), mesh);
    });
  EXPECT_EQ(checked, 16);
}

TEST(MshReader41, WhatItLeavesToGmshIsReadOrRefusedByGmsh)
{
  const fs::path dir = mt::FreshDirectory("dgmf-msh41-left");
  const std::string path = (dir / "m.msh").string();
  mf::NamedMesh mesh;
  // Second-order elements: gmsh's path names the type.
  mt::WriteSecondOrder(path);
  EXPECT_FALSE(ReadWithoutGmsh(path, false, mesh));
  EXPECT_THROW(mf::ReadGmsh(path), mf::FileError);
  // Hand-made: a tetrahedron of entity 1, a triangle group "wall" on surface 2.
  const std::string tetra =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 5 \"wall\"\n"
    "$EndPhysicalNames\n$Entities\n0 0 1 1\n2 0 0 0 1 1 0 1 5 0\n"
    "1 0 0 0 1 1 1 0 1 2\n$EndEntities\n$Nodes\n1 4 1 4\n3 1 0 4\n4\n2\n3\n1\n"
    "0 0 1\n1 0 0\n0 1 0\n0 0 0\n$EndNodes\n$Elements\n2 2 1 2\n"
    "2 2 2 1\n1 1 2 3\n3 1 4 1\n2 1 2 3 4\n$EndElements\n";
  ASSERT_TRUE(mf::ReadMsh41(tetra, false, mesh));
  EXPECT_EQ(mesh.NodeIds, (std::vector<std::int64_t>{ 1, 2, 3, 4 }));
  EXPECT_EQ(mesh.Points, (std::vector<double>{ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 }));
  EXPECT_EQ(mesh.Volume.Connectivity, (std::vector<std::int64_t>{ 0, 1, 2, 3 }));
  ASSERT_EQ(mesh.Boundaries.size(), 1u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "wall");
  EXPECT_EQ(mesh.Boundaries[0].Faces.Connectivity, (std::vector<std::int64_t>{ 0, 1, 2 }));
  const auto variant = [&](const std::string& from, const std::string& to)
  {
    std::string changed = tetra;
    const std::size_t at = changed.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return changed.replace(at, from.size(), to);
  };
  EXPECT_FALSE(mf::ReadMsh41(variant("3 1 0 4", "3 1 1 4"), false, mesh)) << "parametric";
  EXPECT_FALSE(mf::ReadMsh41(variant("3 1 4 1\n", "3 9 4 1\n"), false, mesh)) << "no entity 9";
  EXPECT_FALSE(mf::ReadMsh41(variant("3 1 4 1\n", "3 1 11 1\n"), false, mesh)) << "type 11";
  EXPECT_FALSE(mf::ReadMsh41(variant("2 1 2 3 4", "2 1 2 3 7"), false, mesh)) << "no node 7";
  EXPECT_FALSE(mf::ReadMsh41(variant("4\n2\n3\n1\n", "4\n2\n3\n2\n"), false, mesh)) << "tag twice";
  EXPECT_FALSE(mf::ReadMsh41(variant("$EndElements", "$EndNodes"), false, mesh)) << "wrong end";
  EXPECT_FALSE(mf::ReadMsh41(variant("1 5 0\n", "1 0 0\n"), false, mesh)) << "physical tag 0";
  EXPECT_FALSE(mf::ReadMsh41(tetra + "trailing\n", false, mesh)) << "text after the sections";
  EXPECT_FALSE(mf::ReadMsh41(
    variant("$Nodes", "$PartitionedEntities\n$EndPartitionedEntities\n$Nodes"), false, mesh))
    << "partitioned";
  // Sections it does not need are read past.
  EXPECT_TRUE(
    mf::ReadMsh41(variant("$Nodes", "$Comments\n$Nodes\n$EndComments\n$Nodes"), false, mesh));
  EXPECT_EQ(mesh.Volume.Connectivity, (std::vector<std::int64_t>{ 0, 1, 2, 3 }));
}

TEST(MshReader41, RandomMutationsNeverReadOutsideTheFile)
{
  // Seeded byte mutations of both modes: each read returns (the sanitizer build checks that no
  // byte outside the file is read); a mesh it accepts passes the readers' checks or is refused
  // by them, as ReadGmsh does.
  const fs::path dir = mt::FreshDirectory("dgmf-msh41-mutations");
  std::mt19937 random(411);
  for (bool binary : { false, true })
  {
    const std::string path = (dir / "r.msh").string();
    mt::WriteRectangleWithHole(path, { 4.1, binary, false });
    const std::size_t accepted = mt::ReadMutants(mt::Bytes(path), random, 400,
      [binary](const std::string& mutant, mf::NamedMesh& mesh)
      { return mf::ReadMsh41(mutant, binary, mesh); });
    EXPECT_LT(accepted, 400u);
  }
}
