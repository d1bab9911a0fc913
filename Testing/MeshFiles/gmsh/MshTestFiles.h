/**
 * @file MshTestFiles.h
 * @brief The gmsh tests' files: a fresh directory per test, a file's bytes read and written.
 */
#ifndef dgmf_meshfile_test_MshTestFiles_h
#define dgmf_meshfile_test_MshTestFiles_h

#include "dgmf/meshfile/NamedMesh.h"

#include <filesystem>
#include <fstream>
#include <random>
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

/**
 * Reads `trials` seeded mutants of `bytes` (1 to 3 changes each: a byte changed, up to 16 bytes
 * erased, or the end cut) with `read(mutant, mesh)`; a mesh it accepts goes through the readers'
 * checks (ValidateNamedMesh), which may refuse it, as ReadGmsh does. Returns how many it
 * accepted. Each read must return (the sanitizer build checks that no byte outside the mutant is
 * read).
 */
template <typename Read>
std::size_t ReadMutants(const std::string& bytes, std::mt19937& random, int trials, Read read)
{
  std::size_t accepted = 0;
  for (int trial = 0; trial < trials; ++trial)
  {
    std::string mutant = bytes;
    for (int c = 0, changes = 1 + static_cast<int>(random() % 3); c < changes; ++c)
    {
      const std::size_t at = random() % mutant.size();
      switch (random() % 3)
      {
        case 0:
          mutant[at] = static_cast<char>(random());
          break;
        case 1:
          mutant.erase(at, 1 + random() % 16);
          break;
        default:
          mutant.resize(at);
      }
    }
    NamedMesh mesh;
    if (read(mutant, mesh))
    {
      ++accepted;
      try
      {
        ValidateNamedMesh(mesh, "mutant.msh");
      }
      catch (const FileError&)
      {
      }
    }
  }
  return accepted;
}

} // namespace test
} // namespace meshfile
} // namespace dgmf

#endif
