// The check of a .msh file's first two lines before gmsh sees the file (MshHeader.h).
#include "dgmf/meshfile/MshHeader.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace dgmf
{
namespace meshfile
{
namespace
{
std::string Trimmed(const std::string& line)
{
  const std::size_t first = line.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
  {
    return std::string();
  }
  return line.substr(first, line.find_last_not_of(" \t\r\n") - first + 1);
}
} // namespace

MshFormat CheckMshHeader(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw FileError(path + ": cannot be opened");
  }
  // Both lines are short: read at most 256 bytes each, so that a binary file without newlines is
  // not read whole.
  std::string first, second;
  char c = 0;
  while (first.size() < 256 && in.get(c) && c != '\n')
  {
    first += c;
  }
  while (second.size() < 256 && in.get(c) && c != '\n')
  {
    second += c;
  }
  if (Trimmed(first) != "$MeshFormat")
  {
    throw FileError(path +
      ": not a gmsh .msh file of version 2 or 4 (the first line is not "
      "$MeshFormat)");
  }
  std::istringstream line(second);
  MshFormat format;
  int fileType = -1, dataSize = -1;
  std::string rest;
  line >> format.Version >> fileType >> dataSize;
  const bool known = std::fabs(format.Version - 2.0) < 1e-9 ||
    std::fabs(format.Version - 2.1) < 1e-9 || std::fabs(format.Version - 2.2) < 1e-9 ||
    std::fabs(format.Version - 4.0) < 1e-9 || std::fabs(format.Version - 4.1) < 1e-9;
  if (!line || !known || (fileType != 0 && fileType != 1) || dataSize != 8 || (line >> rest))
  {
    throw FileError(path + ": unsupported $MeshFormat line '" + Trimmed(second) +
      "' (versions 2.0-2.2 and 4.0-4.1, ASCII (0) or binary (1), 8-byte reals)");
  }
  format.Binary = fileType == 1;
  return format;
}

} // namespace meshfile
} // namespace dgmf
