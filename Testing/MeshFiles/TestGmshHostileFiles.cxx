// Hostile .msh files: each one a FileError naming the file, never a crash, a hang, or a .geo
// script run by gmsh.
#include "dgmf/meshfile/GmshFile.h"

#include "gmsh/GmshTestMeshes.h"
#include "gmsh/MshTestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace mf = dgmf::meshfile;
namespace mt = dgmf::meshfile::test;
namespace fs = std::filesystem;
using mt::Bytes;
using mt::WriteBytes;

namespace
{
fs::path TestDirectory(const std::string& name)
{
  return mt::FreshDirectory("dgmf-gmsh-hostile-" + name);
}

/// "" when ReadGmsh gives a mesh (ValidateNamedMesh passed), the message of its FileError
/// otherwise; any other exception fails the test.
std::string Outcome(const std::string& path)
{
  try
  {
    mf::ReadGmsh(path);
  }
  catch (const mf::FileError& e)
  {
    return e.what();
  }
  return "";
}

void ExpectFileError(const std::string& path, const std::string& what)
{
  const std::string error = Outcome(path);
  EXPECT_NE(error, "") << what;
  EXPECT_EQ(error.rfind(path, 0), 0u) << what << ": " << error;
  // gmsh reads the file through a link in a private temporary directory: its messages name the
  // user's file, not the link.
  const std::string rest = error.substr(std::min(error.size(), path.size()));
  EXPECT_EQ(rest.find("/mesh.msh"), std::string::npos) << what << ": " << error;
  EXPECT_EQ(rest.find("Error: "), std::string::npos) << what << ": " << error;
}
} // namespace

TEST(GmshHostileFiles, MissingEmptyAndGarbage)
{
  const fs::path dir = TestDirectory("basic");
  ExpectFileError((dir / "missing.msh").string(), "missing");
  const std::string path = (dir / "f.msh").string();
  WriteBytes(path, "");
  ExpectFileError(path, "empty");
  WriteBytes(path, "$MeshFormat\n");
  ExpectFileError(path, "header line only");
  WriteBytes(path, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  ExpectFileError(path, "header only");
  WriteBytes(path, "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n");
  ExpectFileError(path, "version 3");
  WriteBytes(path, "$MeshFormat\n4.1 0 4\n$EndMeshFormat\n");
  ExpectFileError(path, "4-byte reals");
  std::mt19937 random(7);
  std::string garbage(4096, '\0');
  for (char& c : garbage)
  {
    c = static_cast<char>(random() & 0xff);
  }
  WriteBytes(path, garbage);
  ExpectFileError(path, "garbage");
  WriteBytes(path, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + garbage);
  ExpectFileError(path, "garbage after a header");
  ExpectFileError(dir.string(), "a directory");
}

TEST(GmshHostileFiles, AGeoScriptIsNeverRun)
{
  // gmsh parses a .msh-named file that does not start with $MeshFormat as a .geo script, and
  // merges <file>.opt (.geo syntax) after any file: neither may reach gmsh.
  const fs::path dir = TestDirectory("geo");
  const fs::path witness = dir / "ran";
  const std::string script =
    "SystemCall \"touch " + witness.string() + "\";\nPoint(1) = {0,0,0};\n";
  WriteBytes((dir / "script.msh").string(), script);
  ExpectFileError((dir / "script.msh").string(), "a .geo script");
  mt::WriteRectangleWithHole((dir / "r.msh").string(), {});
  WriteBytes((dir / "r.msh.opt").string(), script);
  EXPECT_EQ(Outcome((dir / "r.msh").string()), "");
  EXPECT_FALSE(fs::exists(witness));
}

TEST(GmshHostileFiles, TruncatedAnywhere)
{
  const fs::path dir = TestDirectory("truncated");
  for (const mt::MshFlavour& f :
    { mt::MshFlavour{ 2.2, false, false }, mt::MshFlavour{ 2.2, true, false },
      mt::MshFlavour{ 4.1, false, false }, mt::MshFlavour{ 4.1, true, false } })
  {
    const std::string whole = (dir / "whole.msh").string(), cut = (dir / "cut.msh").string();
    mt::WriteRectangleWithHole(whole, f);
    const std::string bytes = Bytes(whole);
    for (std::size_t k = 1; k < 40; ++k)
    {
      const std::size_t size = bytes.size() * k / 40;
      WriteBytes(cut, bytes.substr(0, size));
      ExpectFileError(cut,
        "truncated to " + std::to_string(size) + " bytes, version " + std::to_string(f.Version) +
          (f.Binary ? " binary" : " ASCII"));
    }
  }
}

TEST(GmshHostileFiles, AHugeDeclaredNodeCount)
{
  const fs::path dir = TestDirectory("huge");
  const std::string path = (dir / "h.msh").string();
  WriteBytes(path,
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n9000000000000000000\n1 0 0 0\n$EndNodes\n");
  ExpectFileError(path, "version 2, 9e18 nodes");
  WriteBytes(path,
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n"
    "1 0 0 0 1 1 0 0 0\n$EndEntities\n$Nodes\n1 4000000000000 1 4000000000000\n"
    "2 1 0 4000000000000\n1\n0 0 0\n$EndNodes\n");
  ExpectFileError(path, "version 4, 4e12 nodes");
}

TEST(GmshHostileFiles, RandomMutationsOfASCIIFiles)
{
  // A few hundred mutants of small ASCII files (bytes replaced, lines dropped or repeated, digits
  // changed): each either reads as a valid mesh or is a FileError. Seeded: the same mutants on
  // every run.
  const fs::path dir = TestDirectory("mutants");
  const auto start = std::chrono::steady_clock::now();
  std::mt19937 random(20261123);
  int valid = 0, errors = 0;
  for (double version : { 2.2, 4.1 })
  {
    const std::string whole = (dir / "whole.msh").string(), mutant = (dir / "mutant.msh").string();
    mt::WritePrismAndPyramid(whole, { version, false, false });
    const std::string bytes = Bytes(whole);
    std::vector<std::string> lines;
    std::istringstream in(bytes);
    for (std::string line; std::getline(in, line);)
    {
      lines.push_back(line);
    }
    for (int m = 0; m < 150; ++m)
    {
      std::string text;
      const int kind = static_cast<int>(random() % 4);
      if (kind == 0 || kind == 1)
      {
        const std::size_t drop = random() % lines.size(), repeat = random() % lines.size();
        for (std::size_t k = 0; k < lines.size(); ++k)
        {
          if (!(kind == 0 && k == drop))
          {
            text += lines[k] + "\n";
          }
          if (kind == 1 && k == repeat)
          {
            text += lines[k] + "\n";
          }
        }
      }
      else
      {
        text = bytes;
        const char* alphabet = kind == 2 ? "0123456789-+.e " : "0123456789-$\n x\t";
        const std::size_t changes = 1 + random() % 3, length = std::strlen(alphabet);
        for (std::size_t c = 0; c < changes; ++c)
        {
          text[random() % text.size()] = alphabet[random() % length];
        }
      }
      WriteBytes(mutant, text);
      const std::string outcome = Outcome(mutant);
      (outcome.empty() ? valid : errors) += 1;
      if (!outcome.empty())
      {
        ASSERT_EQ(outcome.rfind(mutant, 0), 0u) << outcome;
      }
    }
  }
  EXPECT_GT(valid, 0);
  EXPECT_GT(errors, 0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
}
