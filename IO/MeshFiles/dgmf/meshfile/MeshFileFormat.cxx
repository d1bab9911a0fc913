#include "dgmf/meshfile/MeshFileFormat.h"

#include "dgmf/meshfile/CGNSFile.h"
#include "dgmf/meshfile/ExodusFile.h"
#include "dgmf/meshfile/GmshFile.h"
#include "dgmf/meshfile/SU2File.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace dgmf
{
namespace meshfile
{

MeshFileFormat FormatOfFileName(const std::string& path)
{
  // In any case ("BOX.MSH", as some tools and file systems write them).
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".msh")
    return MeshFileFormat::Gmsh;
  if (extension == ".su2")
    return MeshFileFormat::SU2;
  if (extension == ".exo" || extension == ".e" || extension == ".ex2")
    return MeshFileFormat::Exodus;
  if (extension == ".cgns")
    return MeshFileFormat::CGNS;
  return MeshFileFormat::None;
}

const char* MeshFileExtensions()
{
  return "msh su2 exo e ex2 cgns";
}

NamedMesh ReadMeshFile(const std::string& path)
{
  switch (FormatOfFileName(path))
  {
    case MeshFileFormat::Gmsh:
      return ReadGmsh(path);
    case MeshFileFormat::SU2:
      return ReadSU2(path);
    case MeshFileFormat::Exodus:
      return ReadExodus(path);
    case MeshFileFormat::CGNS:
      return ReadCGNS(path);
    case MeshFileFormat::None:
      break;
  }
  throw FileError("Cannot read '" + path +
    "': give a gmsh .msh, SU2 .su2, Exodus II .exo/.e/.ex2 or CGNS .cgns file.");
}

void WriteMeshFileWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  const MeshFileFormat format = FormatOfFileName(target);
  if (format == MeshFileFormat::None)
  {
    throw FileError("Cannot write '" + target +
      "': the file must end in .msh, .su2, .exo, .e, .ex2 or .cgns, as the file it was read from.");
  }
  if (FormatOfFileName(source) != format)
  {
    throw FileError("The source file " + source + " and the file to write " + target +
      " must have the same format: each format is written as a copy of its source.");
  }
  switch (format)
  {
    case MeshFileFormat::Gmsh:
      return WriteGmshWithPoints(source, target, points, count);
    case MeshFileFormat::SU2:
      return WriteSU2WithPoints(source, target, points, count);
    case MeshFileFormat::Exodus:
      return WriteExodusWithPoints(source, target, points, count);
    case MeshFileFormat::CGNS:
      return WriteCGNSWithPoints(source, target, points, count);
    case MeshFileFormat::None:
      break;
  }
}

} // namespace meshfile
} // namespace dgmf
