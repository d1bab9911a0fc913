/**
 * @file SU2TestFiles.h
 * @brief What the SU2 tests share: the hand-made files, a temporary folder per test, reading and
 * writing whole files, and the error message of a read.
 */
#ifndef dgmf_meshfile_SU2TestFiles_h
#define dgmf_meshfile_SU2TestFiles_h

#include "dgmf/meshfile/SU2File.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace su2test
{
namespace fs = std::filesystem;
namespace mf = dgmf::meshfile;

/**
 * 2D: a quad and two triangles on [0,2]x[0,1]; comments, blank lines, spaces around '=', tabs,
 * point and element lines with and without their index, a marker name with spaces. The last
 * line ends in a one-digit node index (the truncation test relies on it).
 */
inline const char* const Hand2D = R"(% a hand-made 2D SU2 mesh
%
NDIME = 2

NELEM= 3
9 0 1 4 3 0
5	1	2	5	1
5 1 5 4
% the points
NPOIN=6
0 0 0
1.0 0.0 1
2 0e0
0 1 3
1   1	4
+2 1.0 5
NMARK= 3
MARKER_TAG= lower wall
MARKER_ELEMS= 2
3 0 1
3 1 2
MARKER_TAG =outlet
MARKER_ELEMS =1
3 2 5
MARKER_TAG=  upper & left (#2)  
MARKER_ELEMS= 3
3 5 4
3 4 3
3 3 0
)";

/**
 * 3D: a unit cube (hexahedron 0-7) with a pyramid on top (apex 8), a wedge beside it (nodes
 * 1 9 2 and 5 10 6) and a tetrahedron on the wedge (9 11 2 10).
 */
inline const char* const Hand3D = R"(NDIME= 3
NELEM= 4
12 0 1 2 3 4 5 6 7 0
14 4 5 6 7 8 1
13 1 9 2 5 10 6 2
10 9 11 2 10 3
NPOIN= 12 12
0 0 0 0
1 0 0 1
1 1 0 2
0 1 0 3
0 0 1 4
1 0 1 5
1 1 1 6
0 1 1 7
0.5 0.5 1.5 8
2 0 0 9
2 0 1 10
2 1 0 11
NMARK= 2
MARKER_TAG= bottom
MARKER_ELEMS= 3
9 0 3 2 1
5 1 2 9
5 9 2 11
MARKER_TAG= apex
MARKER_ELEMS= 4
5 4 5 8
5 5 6 8
5 6 7 8
5 7 4 8
)";

/// A fresh folder for the running test, removed at the end.
class TemporaryFolder
{
public:
  TemporaryFolder()
  {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    this->Path = fs::temp_directory_path() /
      ("dgmf-su2-" + std::string(test->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(this->Path);
    fs::create_directories(this->Path);
  }
  ~TemporaryFolder()
  {
    std::error_code ignored;
    fs::remove_all(this->Path, ignored);
  }
  std::string File(const std::string& name) const { return (this->Path / name).string(); }
  fs::path Path;
};

inline void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

inline std::string ReadText(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The message of the FileError that reading `path` throws ("" if it reads).
inline std::string ReadError(const std::string& path)
{
  try
  {
    mf::ReadSU2(path);
  }
  catch (const mf::FileError& e)
  {
    return e.what();
  }
  return "";
}

/// `text` with every "\n" made "\r\n".
inline std::string WithCRLF(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  }
  return out;
}

/// True if `a` and `b` hold the same doubles bit for bit (so -0 differs from 0).
inline bool SameBits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() &&
    (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

} // namespace su2test

#endif
