/**
 * @file MshTestFiles.h
 * @brief The gmsh tests' files: a fresh directory per test, a file's bytes read and written.
 */
#ifndef dgmf_meshfile_test_MshTestFiles_h
#define dgmf_meshfile_test_MshTestFiles_h

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace dgmf
{
namespace meshfile
{
namespace test
{

/// The empty directory `name` in the temporary directory (removed first if it exists).
inline std::filesystem::path FreshDirectory(const std::string& name)
{
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

inline std::string Bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

inline void WriteBytes(const std::string& path, const std::string& bytes)
{
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

} // namespace test
} // namespace meshfile
} // namespace dgmf

#endif
