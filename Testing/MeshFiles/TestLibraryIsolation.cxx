// A format library's work in a child process (LibraryIsolation.h): what comes back, whole, and
// what each way of failing gives.
#include "dgmf/meshfile/LibraryIsolation.h"
#include "dgmf/meshfile/MeshBytes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <functional>
#include <signal.h>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

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
    boundary.Family = std::string(name) == "wall" ? "body" : "";
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
    EXPECT_EQ(back.Boundaries[b].Family, mesh.Boundaries[b].Family);
    EXPECT_EQ(back.Boundaries[b].Faces.Connectivity, mesh.Boundaries[b].Faces.Connectivity);
  }
  // The length announced is the length written, and every array starts 8-byte aligned (the
  // names of 4, 0 and 9 characters are padded), so the caller reads them in place.
  const std::string bytes = mf::MeshToBytes(mesh);
  EXPECT_EQ(bytes.size(), mf::MeshBytes(mesh));
  EXPECT_EQ(bytes.size() % 8, 0u);
  // Bytes that are not 8-byte aligned are read too (from an aligned copy).
  std::vector<char> shifted(bytes.size() + 1);
  std::copy(bytes.begin(), bytes.end(), shifted.begin() + 1);
  const mf::NamedMesh unaligned = mf::MeshFromBytes(shifted.data() + 1, bytes.size());
  EXPECT_EQ(unaligned.Points, mesh.Points);
  EXPECT_EQ(unaligned.Volume.Connectivity, mesh.Volume.Connectivity);
  ASSERT_EQ(unaligned.Boundaries.size(), 3u);
  EXPECT_EQ(unaligned.Boundaries[2].Name, "far field");
  // Bytes cut short anywhere are refused, not read past (each cut in a buffer of its own, so
  // that the sanitizers see a read past its end).
  for (std::size_t length = 0; length < bytes.size(); ++length)
  {
    const std::string cut = bytes.substr(0, length);
    EXPECT_NE(FailureOf([&]() { mf::MeshFromBytes(cut); }), "") << length;
  }
}

TEST(LibraryIsolation, AnAnswerWrittenInPlaceIsMappedWholeWithoutAPipe)
{
  constexpr std::size_t size = 24u << 20;
  const mf::IsolatedAnswer answer = mf::RunIsolatedInPlace("mesh.test", "testlib", 60.0, 0,
    [&](const mf::AnswerRoom& room)
    {
      char* bytes = room(size);
      for (std::size_t k = 0; k < size; ++k)
      {
        bytes[k] = static_cast<char>((k * 2654435761u) >> 13);
      }
    });
  ASSERT_EQ(answer.Size(), size);
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < size; ++k)
  {
    wrong += answer.Data()[k] != static_cast<char>((k * 2654435761u) >> 13) ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u);
  // A moved answer keeps its bytes; the one moved from has none.
  mf::IsolatedAnswer moved;
  moved = mf::RunIsolatedInPlace(
    "mesh.test", "testlib", 60.0, 0, [](const mf::AnswerRoom& room) { room(3)[2] = 'z'; });
  mf::IsolatedAnswer kept(std::move(moved));
  ASSERT_EQ(kept.Size(), 3u);
  EXPECT_EQ(kept.Data()[2], 'z');
  EXPECT_EQ(moved.Size(), 0u);
  // No room asked for: an empty answer.
  const mf::IsolatedAnswer none =
    mf::RunIsolatedInPlace("mesh.test", "testlib", 60.0, 0, [](const mf::AnswerRoom&) {});
  EXPECT_EQ(none.Size(), 0u);
  EXPECT_EQ(none.Data(), nullptr);
}

TEST(LibraryIsolation, AnAnswerRoomBeyondTheChildsMemoryIsAFileError)
{
  EXPECT_EQ(FailureOf(
              []()
              {
                mf::RunIsolatedInPlace("mesh.test", "testlib", 60.0, 0,
                  [](const mf::AnswerRoom& room)
                  {
                    room(8);
                    room(8);
                  });
              }),
    "mesh.test: a child's answer room is asked for twice");
#if !defined(__SANITIZE_ADDRESS__) // (no address-space budget under AddressSanitizer)
  const std::string tooLarge = FailureOf(
    []()
    {
      mf::RunIsolatedInPlace("mesh.test", "testlib", 60.0, std::size_t(64) << 20,
        [](const mf::AnswerRoom& room) { room(std::size_t(8) << 30); });
    });
  EXPECT_EQ(tooLarge.rfind("mesh.test: no memory for an answer of 8589934592 bytes", 0), 0u)
    << tooLarge;
#endif
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
