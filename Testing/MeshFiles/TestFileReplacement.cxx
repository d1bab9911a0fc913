// A solver's file written whole or not at all (FileReplacement.h): pieces of every size through the
// buffered output, and a failure in the middle.
#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/NamedMesh.h"

#include "NamedMeshTestHelpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace mf = dgmf::meshfile;
namespace fs = std::filesystem;

TEST(FileReplacement, PiecesOfEverySizeGiveTheFileTheyMakeTogether)
{
  // Small pieces that fill the 1 MiB buffer across its end, pieces larger than the buffer (written
  // past it), empty pieces: the file is their concatenation, byte for byte.
  const fs::path dir = dgmf_test::WorkDirectory("file-replacement");
  const std::string target = (dir / "out.txt").string();
  std::mt19937 random(7);
  std::string expected;
  std::vector<std::string> pieces;
  for (const std::size_t size : { std::size_t(0), std::size_t(1), std::size_t(3) << 20,
         std::size_t(1) << 20, std::size_t(5), (std::size_t(1) << 20) - 3 })
  {
    std::string piece(size, '\0');
    for (char& c : piece)
    {
      c = static_cast<char>(random());
    }
    pieces.push_back(piece);
  }
  for (int k = 0; k < 300000; ++k) // 300,000 small pieces: several flushes
  {
    pieces.push_back(std::to_string(random()) + (k % 10 == 0 ? "\n" : " "));
  }
  for (const std::string& piece : pieces)
  {
    expected += piece;
  }
  mf::WriteFileAtomically(target, (dir / ".out.tmp").string(),
    [&](mf::BufferedOutput& out)
    {
      for (const std::string& piece : pieces)
      {
        out.Append(piece.data(), piece.size());
      }
    });
  const std::string written = mf::ReadFileBytes(target);
  EXPECT_EQ(written.size(), expected.size());
  EXPECT_TRUE(written == expected); // (not EXPECT_EQ: 9 MB would be printed)
  EXPECT_FALSE(fs::exists(dir / ".out.tmp"));
}

TEST(FileReplacement, AFailureWhileWritingLeavesTheTargetAsItWas)
{
  const fs::path dir = dgmf_test::WorkDirectory("file-replacement");
  const std::string target = (dir / "out.txt").string();
  mf::WriteFileAtomically(target, (dir / ".out.tmp").string(), std::string("before"));
  const std::string big(std::size_t(3) << 20, 'x');
  EXPECT_THROW(mf::WriteFileAtomically(target, (dir / ".out.tmp").string(),
                 [&](mf::BufferedOutput& out)
                 {
                   out.Append(big.data(), big.size());
                   throw mf::FileError("stopped half way");
                 }),
    mf::FileError);
  EXPECT_EQ(mf::ReadFileBytes(target), "before");
  EXPECT_FALSE(fs::exists(dir / ".out.tmp"));
  // A temporary file that cannot be made: FileError, the target unchanged.
  EXPECT_THROW(mf::WriteFileAtomically(
                 target, (dir / "no" / "such" / ".out.tmp").string(), std::string("after")),
    mf::FileError);
  EXPECT_EQ(mf::ReadFileBytes(target), "before");
}
