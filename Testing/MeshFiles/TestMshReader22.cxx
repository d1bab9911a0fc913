// Version 2.2 .msh files read without gmsh (MshReader22.h): the mesh gmsh's library gives, on every
// generated test mesh and on hand-made files with what gmsh's own writer never does (unused
// nodes, elements out of number order, an element in two groups of a volume); the files it leaves
// to gmsh; mutated files.
#include "dgmf/meshfile/GmshFile.h"
#include "dgmf/meshfile/MshReader22.h"

#include "gmsh/GmshTestMeshes.h"
#include "gmsh/MshTestFiles.h"
#include "gmsh/SameMesh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <sstream>

namespace mf = dgmf::meshfile;
namespace mt = dgmf::meshfile::test;
namespace fs = std::filesystem;

namespace
{
/// The number of nodes of the gmsh types the hand-made files use.
int GmshNodes(int type)
{
  switch (type)
  {
    case 15:
      return 1;
    case 1:
      return 2;
    case 2:
      return 3;
    case 3:
    case 4:
      return 4;
    case 5:
      return 8;
    case 6:
      return 6;
    default:
      return 5;
  }
}

template <typename T>
void Put(std::string& out, T value)
{
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

/**
 * The binary file of a hand-made ASCII one (two tags per element): the same nodes and elements
 * in the same order, consecutive elements of one type in one block.
 */
std::string Binary(const std::string& ascii)
{
  std::istringstream in(ascii);
  std::string out, line;
  while (std::getline(in, line))
  {
    if (line == "2.2 0 8")
    {
      out += "2.2 1 8\n";
      Put<std::int32_t>(out, 1);
      out += "\n";
    }
    else if (line == "$Nodes")
    {
      std::size_t count = 0;
      in >> count;
      out += "$Nodes\n" + std::to_string(count) + "\n";
      for (std::size_t k = 0; k < count; ++k)
      {
        int tag = 0;
        double x = 0, y = 0, z = 0;
        in >> tag >> x >> y >> z;
        Put<std::int32_t>(out, tag);
        Put(out, x);
        Put(out, y);
        Put(out, z);
      }
      std::getline(in, line);
      out += "\n";
    }
    else if (line == "$Elements")
    {
      std::size_t count = 0;
      in >> count;
      out += "$Elements\n" + std::to_string(count) + "\n";
      std::vector<std::vector<int>> elements(count);
      for (auto& element : elements)
      {
        int number = 0, type = 0, tags = 0;
        in >> number >> type >> tags;
        element = { type, number };
        for (int k = 0; k < tags + GmshNodes(type); ++k)
        {
          int value = 0;
          in >> value;
          element.push_back(value);
        }
      }
      for (std::size_t e = 0; e < count;)
      {
        std::size_t end = e;
        while (end < count && elements[end][0] == elements[e][0])
        {
          ++end;
        }
        Put<std::int32_t>(out, elements[e][0]);
        Put<std::int32_t>(out, static_cast<std::int32_t>(end - e));
        Put<std::int32_t>(out, 2);
        for (; e < end; ++e)
        {
          for (std::size_t k = 1; k < elements[e].size(); ++k)
          {
            Put<std::int32_t>(out, elements[e][k]);
          }
        }
      }
      std::getline(in, line);
      out += "\n";
    }
    else
    {
      out += line + "\n";
    }
  }
  return out;
}

/// Hand-made: a tetrahedron (number 20) and a hexahedron (10) in volume 4 of group 9 "fluid",
/// a tetrahedron (30) in volume 2 outside any group, triangles of surface 3 in group 7 "wall"
/// and (elements 12 and 13, the same triangle) in an unnamed group 8, a quadrangle (14) of
/// surface 3 outside any group (in both groups all the same), a point element (15); nodes 9
/// (unused) and 2 out of tag order.
const char* const HandMade = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                             "$PhysicalNames\n2\n2 7 \"wall\"\n3 9 \"fluid\"\n$EndPhysicalNames\n"
                             "$Nodes\n10\n1 0 0 0\n9 5 5 5\n3 0 1 0\n2 1 0 0\n4 0 0 1\n5 1 1 0\n"
                             "6 1 0 1\n8 1 1 1\n7 0 1 1\n10 2 2 2\n$EndNodes\n"
                             "$Elements\n8\n"
                             "20 4 2 9 4 1 2 3 4\n"
                             "10 5 2 9 4 1 2 5 3 4 6 8 7\n"
                             "30 4 2 0 2 2 5 8 10\n"
                             "13 2 2 8 3 1 3 2\n"
                             "12 2 2 7 3 1 3 2\n"
                             "14 3 2 0 3 2 5 8 6\n"
                             "16 2 2 7 3 1 4 3\n"
                             "15 15 2 0 1 7\n"
                             "$EndElements\n";

std::string WriteFile(const fs::path& dir, const std::string& name, const std::string& bytes)
{
  const std::string path = (dir / name).string();
  mt::WriteBytes(path, bytes);
  return path;
}

std::string Replaced(std::string text, const std::string& from, const std::string& to)
{
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}
} // namespace

TEST(MshReader22, EveryTestMeshReadsAsGmshReadsIt)
{
  const fs::path dir = mt::FreshDirectory("dgmf-msh22-same");
  const std::string path = (dir / "m.msh").string();
  const int checked = mt::ForEachTestMesh(2.2, path,
    [&](bool binary)
    {
      mf::NamedMesh mesh;
      ASSERT_TRUE(mf::ReadMsh22(mt::Bytes(path), binary, mesh));
      mt::ExpectIdentical(mesh, mf::ReadGmshWithGmsh(path));
      mt::ExpectIdentical(mf::ReadGmsh(path), mesh);
    });
  EXPECT_EQ(checked, 16);
}

TEST(MshReader22, WhatGmshsWriterNeverWritesIsReadAsGmshReadsIt)
{
  // The entities gmsh makes of the tags, elements by number, unused nodes dropped, an element in
  // two groups read once; each variant in both modes.
  const fs::path dir = mt::FreshDirectory("dgmf-msh22-hand-made");
  const std::string handMade = HandMade;
  const std::vector<std::pair<std::string, std::string>> variants = {
    { "as made", handMade },
    // The tetrahedron also in a second volume group: the volume's copies read once.
    { "volume in two groups",
      Replaced(Replaced(handMade, "$Elements\n8\n", "$Elements\n9\n"), "$EndElements",
        "21 4 2 11 4 1 2 3 4\n$EndElements") },
    // The elements in increasing number: the same mesh.
    { "in number order",
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
      "$EndNodes\n$Elements\n3\n1 2 2 5 1 1 3 2\n2 2 2 5 1 1 4 3\n3 4 2 6 2 1 2 3 4\n"
      "$EndElements\n" },
    // A 2D mesh with an unused node off the plane z = 0: gmsh drops it, so the mesh is 2D.
    { "2D, an unused node off the plane",
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n"
      "5 0 0 3\n$EndNodes\n$Elements\n4\n4 2 2 3 1 1 2 3\n3 2 2 3 1 2 4 3\n1 1 2 4 2 1 2\n"
      "2 1 2 0 3 2 4\n$EndElements\n" },
  };
  int checked = 0;
  for (const auto& variant : variants)
  {
    for (bool binary : { false, true })
    {
      SCOPED_TRACE(variant.first + (binary ? " binary" : " ASCII"));
      const std::string bytes = binary ? Binary(variant.second) : variant.second;
      const std::string path = WriteFile(dir, "h.msh", bytes);
      mf::NamedMesh mesh;
      ASSERT_TRUE(mf::ReadMsh22(bytes, binary, mesh));
      mt::ExpectIdentical(mesh, mf::ReadGmshWithGmsh(path));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8);
  // What the hand-made file holds, field by field.
  mf::NamedMesh mesh;
  ASSERT_TRUE(mf::ReadMsh22(handMade, false, mesh));
  EXPECT_EQ(mesh.NodeIds, (std::vector<std::int64_t>{ 1, 2, 3, 4, 5, 6, 7, 8, 10 })); // not 9
  EXPECT_EQ(mesh.Volume.Types,
    (std::vector<std::uint8_t>{ mf::Tetra, mf::Tetra, mf::Hexahedron })); // entity 2, then 4
  ASSERT_EQ(mesh.Boundaries.size(), 2u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "wall");
  EXPECT_EQ(mesh.Boundaries[1].Name, "group 8");
  // Surface 3 in both groups: its triangles (12 and 13 once, then 16) and its quadrangle.
  for (const mf::NamedBoundary& boundary : mesh.Boundaries)
  {
    EXPECT_EQ(boundary.Faces.Types,
      (std::vector<std::uint8_t>{ mf::Triangle, mf::Triangle, mf::Quad })); // gmsh type 2 before 3
    EXPECT_EQ(
      boundary.Faces.Connectivity, (std::vector<std::int64_t>{ 0, 2, 1, 0, 3, 2, 1, 4, 7, 5 }));
  }
}

TEST(MshReader22, WhatItLeavesToGmshIsReadOrRefusedByGmsh)
{
  const fs::path dir = mt::FreshDirectory("dgmf-msh22-left");
  mf::NamedMesh mesh;
  const std::string handMade = HandMade;
  const std::vector<std::pair<std::string, std::string>> left = {
    { "an element number twice (gmsh keeps the last)",
      Replaced(handMade, "16 2 2 7 3 1 4 3", "20 2 2 7 3 1 4 3") },
    { "three tags (a partition)", Replaced(handMade, "15 15 2 0 1 7", "15 15 3 0 1 1 7") },
    { "one tag", Replaced(handMade, "15 15 2 0 1 7", "15 15 1 0 7") },
    { "elementary tag 0", Replaced(handMade, "15 15 2 0 1 7", "15 15 2 0 0 7") },
    { "negative physical tag", Replaced(handMade, "15 15 2 0 1 7", "15 15 2 -1 1 7") },
    { "a second-order type", Replaced(handMade, "15 15 2 0 1 7", "15 8 2 0 1 1 2 3") },
    { "no node 11", Replaced(handMade, "1 2 3 4\n", "1 2 3 11\n") },
    { "a node tag twice", Replaced(handMade, "9 5 5 5", "2 5 5 5") },
    { "parametric nodes",
      Replaced(handMade, "$Elements", "$ParametricNodes\n$EndParametricNodes\n$Elements") },
    { "text after the sections", handMade + "trailing\n" },
    { "a wrong end", Replaced(handMade, "$EndElements", "$EndNodes") },
    { "no elements", handMade.substr(0, handMade.find("$Elements")) },
  };
  for (const auto& file : left)
  {
    SCOPED_TRACE(file.first);
    EXPECT_FALSE(mf::ReadMsh22(file.second, false, mesh));
    // gmsh reads it (the duplicated number, the tags), or says what is wrong.
    const std::string path = WriteFile(dir, "l.msh", file.second);
    try
    {
      mt::ExpectIdentical(mf::ReadGmsh(path), mf::ReadGmshWithGmsh(path));
    }
    catch (const mf::FileError&)
    {
      EXPECT_THROW(mf::ReadGmshWithGmsh(path), mf::FileError);
    }
  }
  // Binary: an element number twice, or the other byte order.
  const std::string twice = Binary(Replaced(handMade, "16 2 2 7 3 1 4 3", "20 2 2 7 3 1 4 3"));
  EXPECT_FALSE(mf::ReadMsh22(twice, true, mesh));
  std::string swapped = Binary(handMade);
  const std::size_t one = swapped.find("2.2 1 8\n") + 8;
  std::swap(swapped[one], swapped[one + 3]);
  EXPECT_FALSE(mf::ReadMsh22(swapped, true, mesh));
  // Sections it does not need are read past, a $Nodes line in a comment too.
  EXPECT_TRUE(mf::ReadMsh22(
    Replaced(handMade, "$Nodes", "$Comments\n$Nodes\n$EndComments\n$Nodes"), false, mesh));
  EXPECT_EQ(mesh.NodeIds.size(), 9u);
}

TEST(MshReader22, RandomMutationsNeverReadOutsideTheFile)
{
  // Seeded byte mutations of both modes: each read returns (the sanitizer build checks that no
  // byte outside the file is read); a mesh it accepts passes the readers' checks or is refused
  // by them, as ReadGmsh does.
  const fs::path dir = mt::FreshDirectory("dgmf-msh22-mutations");
  std::mt19937 random(22);
  for (bool binary : { false, true })
  {
    const std::string path = (dir / "r.msh").string();
    mt::WriteRectangleWithHole(path, { 2.2, binary, false });
    for (const std::string& bytes : { mt::Bytes(path), binary ? Binary(HandMade) : HandMade })
    {
      const std::size_t accepted = mt::ReadMutants(bytes, random, 400,
        [binary](const std::string& mutant, mf::NamedMesh& mesh)
        { return mf::ReadMsh22(mutant, binary, mesh); });
      EXPECT_LT(accepted, 400u);
    }
  }
}
