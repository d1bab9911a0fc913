// A file's bytes mapped for a parser (MappedFile.h): the same bytes as a read, for files that map
// and those that do not, and the errors of a read.
#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/MappedFile.h"
#include "dgmf/meshfile/NamedMesh.h"

#include "NamedMeshTestHelpers.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace mf = dgmf::meshfile;
namespace fs = std::filesystem;

namespace
{
void WriteFile(const fs::path& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}
} // namespace

TEST(MappedFile, ARegularFileIsMappedWithItsBytesWhateverItsSize)
{
  // In the temporary directory (mapped or read, depending on its file system) and in /dev/shm
  // (tmpfs, a local file system: mapped). Sizes around a page and a large one, every byte value.
  const fs::path shared = fs::path("/dev/shm") / ("dgmf-mapped-file-" + std::to_string(::getpid()));
  std::error_code error;
  fs::create_directories(shared, error);
  ASSERT_FALSE(error) << "/dev/shm: " << error.message();
  for (const fs::path& dir : { dgmf_test::WorkDirectory("mapped-file"), shared })
  {
    for (const std::size_t size : { std::size_t(1), std::size_t(4095), std::size_t(4096),
           std::size_t(4097), std::size_t(3) << 20 })
    {
      std::string bytes(size, '\0');
      for (std::size_t k = 0; k < size; ++k)
      {
        bytes[k] = static_cast<char>((k * 2654435761u) >> 11);
      }
      const fs::path path = dir / ("file" + std::to_string(size));
      WriteFile(path, bytes);
      const mf::MappedFile file(path.string());
      if (dir == shared)
      {
        EXPECT_TRUE(file.IsMapped()) << size;
      }
      ASSERT_EQ(file.Bytes().size(), size);
      EXPECT_TRUE(file.Bytes() == bytes) << dir << " " << size;
      EXPECT_EQ(mf::ReadFileBytes(path.string()), bytes);
    }
  }
  fs::remove_all(shared, error);
}

TEST(MappedFile, WhatCannotBeMappedIsReadAndWhatCannotBeReadIsAFileError)
{
  const fs::path dir = dgmf_test::WorkDirectory("mapped-file");
  // An empty file (no mapping of 0 bytes) and a character device: read, empty.
  WriteFile(dir / "empty", "");
  const mf::MappedFile empty((dir / "empty").string());
  EXPECT_FALSE(empty.IsMapped());
  EXPECT_EQ(empty.Bytes().size(), 0u);
  const mf::MappedFile device("/dev/null");
  EXPECT_FALSE(device.IsMapped());
  EXPECT_EQ(device.Bytes().size(), 0u);
  // A named pipe's bytes, read as a stream (written by a thread: each side's open waits for the
  // other's).
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer(
    [&fifo]()
    {
      std::ofstream out(fifo, std::ios::binary);
      out << "pipe bytes";
    });
  const mf::MappedFile piped(fifo.string());
  writer.join();
  EXPECT_FALSE(piped.IsMapped());
  EXPECT_EQ(std::string(piped.Bytes()), "pipe bytes");
  // Missing: the reader's error.
  try
  {
    const mf::MappedFile missing((dir / "missing.msh").string());
    ADD_FAILURE() << "a missing file gave bytes";
  }
  catch (const mf::FileError& e)
  {
    EXPECT_EQ(std::string(e.what()), (dir / "missing.msh").string() + ": cannot be opened");
  }
}

TEST(MappedFile, TheBytesStayWhenTheFileIsReplacedWhileMapped)
{
  // A mesh file written again (replaced by a rename, as this project's writers and most tools do)
  // while mapped: the mapping keeps the bytes it had.
  const fs::path dir = dgmf_test::WorkDirectory("mapped-file");
  const fs::path path = dir / "mesh.su2";
  WriteFile(path, "NDIME= 3\n");
  const mf::MappedFile file(path.string());
  // (mapped where the temporary directory is on a local file system, as a rule)
  WriteFile(dir / "new.su2", "NDIME= 2\nNPOIN= 0\n");
  fs::rename(dir / "new.su2", path);
  EXPECT_EQ(std::string(file.Bytes()), "NDIME= 3\n");
}
