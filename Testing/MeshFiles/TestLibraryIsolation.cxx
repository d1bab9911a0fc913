// A format library's work in a child process (LibraryIsolation.h): what comes back, whole, and
// what each way of failing gives.
#include "dgmf/meshfile/LibraryIsolation.h"

#include <gtest/gtest.h>

#include <csignal>
#include <functional>
#include <signal.h>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace mf = dgmf::meshfile;

namespace
{
/// The message of the FileError `run` throws, or "" if it throws none.
template <typename Run>
std::string FailureOf(Run run)
{
  try
  {
    run();
  }
  catch (const mf::FileError& e)
  {
    return e.what();
  }
  return "";
}

std::string Isolated(const std::function<std::string()>& work)
{
  return mf::RunIsolated("mesh.test", "testlib", 60.0, 0, work);
}
} // namespace

TEST(LibraryIsolation, ALargeAnswerComesBackWholeByteForByte)
{
  // 40 MB: many times the pipe's capacity, so the reads and the child's writes take turns.
  std::string expected(40u << 20, '\0');
  for (std::size_t k = 0; k < expected.size(); ++k)
  {
    expected[k] = static_cast<char>((k * 2654435761u) >> 13);
  }
  EXPECT_EQ(Isolated([&]() { return expected; }), expected);
  EXPECT_EQ(Isolated([]() { return std::string(); }), "");
  // An answer that starts like the header of an error is still the answer.
  EXPECT_EQ(Isolated([]() { return std::string("Ebody"); }), "Ebody");
}

TEST(LibraryIsolation, AMeshGoesThroughTheBytesUnchanged)
{
  mf::NamedMesh mesh;
  mesh.Dimension = 3;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  mesh.NodeIds = { 7, 8, 9, 12 };
  const std::int64_t tetra[4] = { 0, 1, 2, 3 };
  mesh.Volume.Add(mf::Tetra, tetra, 4);
  for (const char* name : { "wall", "", "far field" })
  {
    mf::NamedBoundary boundary;
    boundary.Name = name;
    const std::int64_t face[3] = { 0, 2, 1 };
    boundary.Faces.Add(mf::Triangle, face, 3);
    mesh.Boundaries.push_back(boundary);
  }
  const mf::NamedMesh back = mf::MeshFromBytes(Isolated([&]() { return mf::MeshToBytes(mesh); }));
  EXPECT_EQ(back.Dimension, 3);
  EXPECT_EQ(back.Points, mesh.Points);
  EXPECT_EQ(back.NodeIds, mesh.NodeIds);
  EXPECT_EQ(back.Volume.Types, mesh.Volume.Types);
  EXPECT_EQ(back.Volume.Offsets, mesh.Volume.Offsets);
  EXPECT_EQ(back.Volume.Connectivity, mesh.Volume.Connectivity);
  ASSERT_EQ(back.Boundaries.size(), 3u);
  for (std::size_t b = 0; b < 3; ++b)
  {
    EXPECT_EQ(back.Boundaries[b].Name, mesh.Boundaries[b].Name);
    EXPECT_EQ(back.Boundaries[b].Faces.Connectivity, mesh.Boundaries[b].Faces.Connectivity);
  }
  // Bytes cut short are refused, not read past.
  const std::string bytes = mf::MeshToBytes(mesh);
  EXPECT_NE(FailureOf([&]() { mf::MeshFromBytes(bytes.substr(0, bytes.size() - 1)); }), "");
}

TEST(LibraryIsolation, EachWayOfFailingIsAFileErrorNamingTheFileOrTheLibrary)
{
  EXPECT_EQ(
    FailureOf([]() { Isolated([]() -> std::string { throw mf::FileError("bad cell 3"); }); }),
    "bad cell 3");
  EXPECT_EQ(
    FailureOf([]() { Isolated([]() -> std::string { throw std::runtime_error("no memory"); }); }),
    "mesh.test: no memory");
  // (SIGKILL: a sanitizer's handler would turn a SIGSEGV into an exit.)
  const std::string crashed = FailureOf(
    []()
    {
      Isolated(
        []() -> std::string
        {
          ::kill(::getpid(), SIGKILL);
          return "";
        });
    });
  EXPECT_NE(crashed.find("mesh.test: testlib crashed on it (signal 9"), std::string::npos)
    << crashed;
  EXPECT_EQ(FailureOf([]() { Isolated([]() -> std::string { ::_exit(0); }); }),
    "mesh.test: testlib's process ended without an answer");
  const std::string slow = FailureOf(
    []()
    {
      mf::RunIsolated("mesh.test", "testlib", 0.2, 0,
        []()
        {
          ::sleep(30);
          return std::string();
        });
    });
  EXPECT_NE(slow.find("did not finish within"), std::string::npos) << slow;
}
