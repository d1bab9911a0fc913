// A .msh file's node coordinates replaced in its own bytes (MshNodes.h): every other byte kept,
// the nodes in the order of their tags, and every file it cannot rewrite left to gmsh.
#include "dgmf/meshfile/GmshFile.h"
#include "dgmf/meshfile/MshNodes.h"

#include "gmsh/GmshTestMeshes.h"
#include "gmsh/MshTestFiles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>

namespace mf = dgmf::meshfile;
namespace mt = dgmf::meshfile::test;
namespace fs = std::filesystem;

namespace
{
/// The file without its $Nodes section (what must stay byte for byte).
std::string OutsideNodes(const std::string& bytes)
{
  const std::size_t begin = bytes.find("\n$Nodes");
  const std::size_t end = bytes.find("\n$EndNodes");
  return begin == std::string::npos || end == std::string::npos
    ? bytes
    : bytes.substr(0, begin) + bytes.substr(end);
}

bool Replace(const std::string& text, double version, bool binary,
  const std::vector<double>& points, std::string& patched)
{
  mf::MshFormat format;
  format.Version = version;
  format.Binary = binary;
  patched = text;
  const bool replaced =
    mf::ReplaceMshNodeCoordinates(patched, format, points.data(), points.size() / 3);
  if (!replaced)
  {
    EXPECT_EQ(patched, text) << "a file it cannot rewrite is left as it was";
  }
  return replaced;
}

/// Every coordinate changed, with full mantissas.
std::vector<double> Moved(std::vector<double> points)
{
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    points[k] = points[k] / 3.0 + 1e-3 * static_cast<double>(k % 7) - 0.1;
  }
  return points;
}

const mt::MshFlavour kFlavours[] = { { 2.2, false, false }, { 2.2, true, false },
  { 4.1, false, false }, { 4.1, true, false } };
} // namespace

TEST(MshNodes, EachFlavourGetsItsNodesMovedAndKeepsEveryOtherByte)
{
  const fs::path dir = mt::FreshDirectory("dgmf-msh-nodes-flavours");
  for (const mt::MshFlavour& f : kFlavours)
  {
    SCOPED_TRACE(std::to_string(f.Version) + (f.Binary ? " binary" : " ASCII"));
    const std::string source = (dir / "box.msh").string(), target = (dir / "moved.msh").string();
    mt::WriteBoxWithHole(source, f);
    const std::string bytes = mt::Bytes(source);
    const mf::NamedMesh mesh = mf::ReadGmsh(source);
    std::string patched;
    // The same points: a binary file comes out as it was; an ASCII one as it reads.
    ASSERT_TRUE(Replace(bytes, f.Version, f.Binary, mesh.Points, patched));
    if (f.Binary)
    {
      EXPECT_EQ(patched, bytes);
    }
    EXPECT_EQ(OutsideNodes(patched), OutsideNodes(bytes));
    // Moved points: exactly those read back (ASCII too: the shortest exact decimal), every other
    // byte the source's, and gmsh sees the same elements, tags and groups.
    const std::vector<double> moved = Moved(mesh.Points);
    ASSERT_TRUE(Replace(bytes, f.Version, f.Binary, moved, patched));
    EXPECT_EQ(OutsideNodes(patched), OutsideNodes(bytes));
    mt::WriteBytes(target, patched);
    const mf::NamedMesh back = mf::ReadGmsh(target);
    EXPECT_EQ(back.NodeIds, mesh.NodeIds);
    EXPECT_EQ(std::memcmp(back.Points.data(), moved.data(), moved.size() * sizeof(double)), 0);
    EXPECT_EQ(back.Volume.Connectivity, mesh.Volume.Connectivity);
    const mt::GmshView before = mt::ViewWithGmsh(source), after = mt::ViewWithGmsh(target);
    EXPECT_EQ(before.NodeTags, after.NodeTags);
    EXPECT_EQ(before.Elements, after.Elements);
    EXPECT_EQ(before.GroupEntities, after.GroupEntities);
  }
}

TEST(MshNodes, NodesGoInTheOrderOfTheirTagsAndLineEndsStay)
{
  // Tags out of order (5, 2, 9): the points come in tag order (2, 5, 9), as ReadGmsh gives them.
  const std::string text = "$MeshFormat\r\n2.2 0 8\r\n$EndMeshFormat\r\n$Nodes\r\n3\r\n"
                           "5 1 1 1\r\n2 2 2 2\r\n9   3\t3 3\r\n$EndNodes\r\n$Elements\r\n0\r\n"
                           "$EndElements\r\n";
  std::string patched;
  ASSERT_TRUE(Replace(text, 2.2, false, { 0.5, -2, 1e-20, 0.1, 0.25, 3, 7, 8, -0.0 }, patched));
  EXPECT_EQ(patched,
    "$MeshFormat\r\n2.2 0 8\r\n$EndMeshFormat\r\n$Nodes\r\n3\r\n"
    "5 0.1 0.25 3\r\n2 0.5 -2 1e-20\r\n9   7\t8 -0\r\n$EndNodes\r\n$Elements\r\n0\r\n"
    "$EndElements\r\n");
}

TEST(MshNodes, AVersion22NodeNoElementUsesKeepsItsBytes)
{
  // Nodes 6, 7 and 9 are used by no element (gmsh's reading, and ours, drop them) and the tags
  // are out of order: the 7 points read are written by tag, the unused nodes' lines stay as they
  // were. Until 2026-11-30 such a file went through gmsh's writer, which dropped those nodes (or
  // refused the file with gaps in its tags).
  const fs::path dir = mt::FreshDirectory("dgmf-msh-nodes-unused");
  const std::string source = (dir / "unused.msh").string(), target = (dir / "moved.msh").string();
  const std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                           "$PhysicalNames\n1\n3 9 \"fluid\"\n$EndPhysicalNames\n"
                           "$Nodes\n10\n1 0 0 0\n9 5 5 5\n3 0 1 0\n2 1 0 0\n4 0 0 1\n5 1 1 0\n"
                           "6 1 0 1\n8 1 1 1\n7 0 1 1\n10 2 2 2\n$EndNodes\n"
                           "$Elements\n2\n20 4 2 9 4 1 2 3 4\n30 4 2 9 4 2 5 8 10\n"
                           "$EndElements\n";
  mt::WriteBytes(source, text);
  const mf::NamedMesh mesh = mf::ReadGmsh(source);
  ASSERT_EQ(mesh.NumberOfNodes(), 7u);
  const std::vector<double> moved = Moved(mesh.Points);
  mf::WriteGmshWithPoints(source, target, moved.data(), mesh.NumberOfNodes());
  const std::string written = mt::Bytes(target);
  EXPECT_EQ(OutsideNodes(written), OutsideNodes(text));
  for (const char* kept : { "\n9 5 5 5\n", "\n6 1 0 1\n", "\n7 0 1 1\n" })
  {
    EXPECT_NE(written.find(kept), std::string::npos) << kept << " in\n" << written;
  }
  const mf::NamedMesh back = mf::ReadGmsh(target);
  EXPECT_EQ(back.NodeIds, mesh.NodeIds);
  EXPECT_EQ(std::memcmp(back.Points.data(), moved.data(), moved.size() * sizeof(double)), 0);
}

TEST(MshNodes, ALineNodesInsideAnotherSectionIsNotTheNodes)
{
  const std::string text = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Comments\n$Nodes\n1\n"
                           "1 0 0 0\n$EndNodes\n$EndComments\n$Nodes\n1 2 1 2\n3 7 0 2\n1\n2\n"
                           "0 0 0\n1 1 1\n$EndNodes\n";
  std::string patched;
  ASSERT_TRUE(Replace(text, 4.1, false, { 4, 5, 6, 7, 8, 9 }, patched));
  EXPECT_EQ(patched,
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Comments\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
    "$EndComments\n$Nodes\n1 2 1 2\n3 7 0 2\n1\n2\n4 5 6\n7 8 9\n$EndNodes\n");
}

TEST(MshNodes, FilesItCannotRewriteAreLeftToGmsh)
{
  std::string patched;
  const std::string v22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 1 1\n"
                          "$EndNodes\n";
  const std::vector<double> two = { 1, 2, 3, 4, 5, 6 };
  EXPECT_TRUE(Replace(v22, 2.2, false, two, patched));
  EXPECT_FALSE(Replace(v22, 2.2, false, { 1, 2, 3 }, patched)) << "another number of nodes";
  EXPECT_FALSE(Replace(v22, 2.0, false, two, patched)) << "version 2.0";
  std::string repeated = v22;
  repeated.replace(repeated.find("2 1 1 1"), 1, "1");
  EXPECT_FALSE(Replace(repeated, 2.2, false, two, patched)) << "a tag twice";
  EXPECT_FALSE(Replace(v22.substr(0, v22.find("$EndNodes")), 2.2, false, two, patched))
    << "no $EndNodes";
  EXPECT_FALSE(Replace(v22.substr(0, v22.find("2 1 1 1") + 5), 2.2, false, two, patched))
    << "cut in a node";
  const std::string parametric = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n"
                                 "1 7 1 2\n1\n2\n0 0 0 0.5\n1 1 1 0.7\n$EndNodes\n";
  EXPECT_FALSE(Replace(parametric, 4.1, false, two, patched)) << "parametric nodes";
  const std::string huge = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n"
                           "1 7 0 99999999999999\n1\n2\n0 0 0\n1 1 1\n$EndNodes\n";
  EXPECT_FALSE(Replace(huge, 4.1, false, two, patched)) << "a block larger than the file";

  // A binary file of the other byte order; and versions 4.0 and 2.2 through WriteGmshWithPoints:
  // gmsh writes what this does not.
  const fs::path dir = mt::FreshDirectory("dgmf-msh-nodes-fallback");
  const std::string source = (dir / "s.msh").string(), target = (dir / "t.msh").string();
  mt::WriteBoxWithHole(source, { 4.1, true, false });
  const mf::NamedMesh mesh = mf::ReadGmsh(source);
  std::string swapped = mt::Bytes(source);
  const std::size_t one = swapped.find("4.1 1 8\n") + 8;
  std::reverse(swapped.begin() + static_cast<std::ptrdiff_t>(one),
    swapped.begin() + static_cast<std::ptrdiff_t>(one) + 4);
  EXPECT_FALSE(Replace(swapped, 4.1, true, mesh.Points, patched)) << "big-endian";
  mt::WriteBoxWithHole(source, { 4.0, false, false });
  EXPECT_FALSE(Replace(mt::Bytes(source), 4.0, false, mesh.Points, patched)) << "version 4.0";
  const mf::NamedMesh mesh40 = mf::ReadGmsh(source);
  const std::vector<double> moved = Moved(mesh40.Points);
  mf::WriteGmshWithPoints(source, target, moved.data(), mesh40.NumberOfNodes());
  EXPECT_EQ(mf::ReadGmsh(target).NodeIds, mesh40.NodeIds);
}

TEST(MshNodes, RandomMutationsNeverReadOutsideTheFile)
{
  // Every flavour's bytes mutated at random (seeded), around the $Nodes section most: each call
  // returns, true or false (the sanitizer build checks no byte outside the file is read).
  const fs::path dir = mt::FreshDirectory("dgmf-msh-nodes-mutations");
  std::mt19937 random(20261128);
  for (const mt::MshFlavour& f : kFlavours)
  {
    const std::string source = (dir / "r.msh").string();
    mt::WriteRectangleWithHole(source, f);
    const std::string bytes = mt::Bytes(source);
    const mf::NamedMesh mesh = mf::ReadGmsh(source);
    const std::size_t nodes = bytes.find("$Nodes");
    const std::size_t span = bytes.find("$EndNodes") + 12 - nodes;
    std::size_t accepted = 0;
    for (int trial = 0; trial < 400; ++trial)
    {
      std::string mutant = bytes;
      const int changes = 1 + static_cast<int>(random() % 4);
      for (int c = 0; c < changes; ++c)
      {
        const std::size_t at = trial % 4 == 0 ? random() % mutant.size() : nodes + random() % span;
        switch (random() % 3)
        {
          case 0:
            mutant[at % mutant.size()] = static_cast<char>(random());
            break;
          case 1:
            mutant.erase(at % mutant.size(), 1 + random() % 16);
            break;
          default:
            mutant.resize(at % mutant.size());
        }
      }
      std::string patched;
      accepted += Replace(mutant, f.Version, f.Binary, mesh.Points, patched) ? 1 : 0;
    }
    EXPECT_LT(accepted, 400u); // (most mutants of the section are refused)
  }
}
