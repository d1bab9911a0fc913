/**
 * @file NamedMeshTestHelpers.h
 * @brief What the tests of the readers that go through a format's library (Exodus II, CGNS) share:
 * a fresh directory per test, a boundary by name and its nodes, the message of a FileError.
 */
#ifndef dgmf_test_NamedMeshTestHelpers_h
#define dgmf_test_NamedMeshTestHelpers_h

#include "dgmf/meshfile/NamedMesh.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

namespace dgmf_test
{
/// A fresh directory for the running test's files: <temp>/dgmf-<format>-<pid>-<test name>.
inline std::filesystem::path WorkDirectory(const std::string& format)
{
  const auto* test = testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path directory = std::filesystem::temp_directory_path() /
    ("dgmf-" + format + "-" + std::to_string(::getpid()) + "-" + test->name());
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

/// The boundary named `name`, or null.
inline const dgmf::meshfile::NamedBoundary* Find(
  const dgmf::meshfile::NamedMesh& mesh, const std::string& name)
{
  for (const dgmf::meshfile::NamedBoundary& b : mesh.Boundaries)
  {
    if (b.Name == name)
    {
      return &b;
    }
  }
  return nullptr;
}

/// The distinct nodes of a boundary (0-based).
inline std::set<std::int64_t> NodesOf(const dgmf::meshfile::NamedBoundary& b)
{
  return { b.Faces.Connectivity.begin(), b.Faces.Connectivity.end() };
}

/// The message of the FileError `read(path)` throws, or "" when it reads the file.
template <typename Read>
std::string ErrorOf(Read read, const std::filesystem::path& path)
{
  try
  {
    read(path.string());
  }
  catch (const dgmf::meshfile::FileError& e)
  {
    return e.what();
  }
  return "";
}
} // namespace dgmf_test

#endif
