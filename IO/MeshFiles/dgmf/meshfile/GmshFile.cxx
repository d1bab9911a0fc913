// gmsh .msh files (GmshFile.h): checked here, read and written by gmsh's library in the gmsh
// module (GmshModule.h), which runs in a child process (LibraryIsolation.h).
#include "dgmf/meshfile/GmshFile.h"

#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/GmshModule.h"
#include "dgmf/meshfile/LibraryIsolation.h"
#include "dgmf/meshfile/MappedFile.h"
#include "dgmf/meshfile/MeshBytes.h"
#include "dgmf/meshfile/MshHeader.h"
#include "dgmf/meshfile/MshNodes.h"
#include "dgmf/meshfile/MshReader22.h"
#include "dgmf/meshfile/MshReader41.h"

#include <cmath>
#include <cstring>
#include <filesystem>

namespace dgmf
{
namespace meshfile
{
namespace fs = std::filesystem;

namespace
{
/// ReadGmshWithGmsh of a file whose header says `format`.
NamedMesh ReadThroughGmsh(const std::string& path, const MshFormat& format)
{
  // Loaded here, before the fork: the child only calls it.
  const GmshModule gmsh = LoadGmshModule(path);
  // The mesh's bytes go into the shared answer and are read from its mapping (no copy of them
  // through a string on either side but the module's own).
  const IsolatedAnswer answer = RunIsolatedInPlace(path, "gmsh", TimeAllowed(path), 0,
    [&](const AnswerRoom& room)
    {
      std::string bytesOrMessage;
      if (!gmsh.Read(path, format, bytesOrMessage))
      {
        throw FileError(bytesOrMessage);
      }
      if (!bytesOrMessage.empty())
      {
        std::memcpy(room(bytesOrMessage.size()), bytesOrMessage.data(), bytesOrMessage.size());
      }
    });
  NamedMesh mesh;
  try
  {
    mesh = MeshFromBytes(answer.Data(), answer.Size());
  }
  catch (const FileError& e)
  {
    throw FileError(path + ": " + e.what());
  }
  MergeBoundariesOfOneName(mesh);
  ValidateNamedMesh(mesh, path);
  return mesh;
}
} // namespace

NamedMesh ReadGmsh(const std::string& path)
{
  const MshFormat format = CheckMshHeader(path);
  // Versions 4.1 and 2.2 without gmsh (MshReader41.h, MshReader22.h), the same mesh; anything
  // they leave, through gmsh.
  const bool version41 = std::fabs(format.Version - 4.1) < 1e-9;
  const bool version22 = std::fabs(format.Version - 2.2) < 1e-9;
  if (version41 || version22)
  {
    const MappedFile file(path);
    NamedMesh mesh;
    if (version41 ? ReadMsh41(file.Bytes(), format.Binary, mesh)
                  : ReadMsh22(file.Bytes(), format.Binary, mesh))
    {
      MergeBoundariesOfOneName(mesh);
      ValidateNamedMesh(mesh, path);
      return mesh;
    }
  }
  return ReadThroughGmsh(path, format);
}

NamedMesh ReadGmshWithGmsh(const std::string& path)
{
  return ReadThroughGmsh(path, CheckMshHeader(path));
}

namespace
{
/// `target`'s temporary: beside it, hidden, with the .msh extension gmsh picks its writer by.
fs::path MshTemporaryBeside(const fs::path& target)
{
  return target.parent_path() / ("." + target.filename().string() + ".dgmf-writing.msh");
}
} // namespace

void WriteGmshWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  if (count > 0 && !points)
  {
    throw FileError(target + ": no points given");
  }
  for (std::size_t k = 0; k < 3 * count; ++k)
  {
    if (!std::isfinite(points[k]))
    {
      throw FileError(target + ": node " + std::to_string(k / 3) +
        " has a non-finite coordinate; nothing written");
    }
  }
  const MshFormat format = CheckMshHeader(source);
  const fs::path temporary = MshTemporaryBeside(target);
  // Versions 2.2 and 4.1 without parametric nodes: the source's own bytes with the coordinates
  // replaced (MshNodes.h), every other byte kept, without gmsh. Any other file through gmsh.
  {
    const MappedFile file(source);
    if (WriteMshWithMovedNodes(file.Bytes(), format, points, count, target, temporary.string()))
    {
      return;
    }
    // A version 2.2 file with nodes no element uses: read as gmsh reads it, without them; the
    // points are then the nodes of the tags read, and the others keep their bytes.
    NamedMesh read;
    if (std::fabs(format.Version - 2.2) < 1e-9 && ReadMsh22(file.Bytes(), format.Binary, read) &&
      read.NodeIds.size() == count &&
      WriteMshWithMovedNodesByTag(
        file.Bytes(), format, points, read.NodeIds.data(), count, target, temporary.string()))
    {
      return;
    }
  }
  const GmshModule gmsh = LoadGmshModule(source);
  try
  {
    RunIsolated(source, "gmsh", TimeAllowed(source), 0,
      [&]()
      {
        std::string message;
        if (!gmsh.Write(source, temporary.string(), format, points, count, message))
        {
          throw FileError(message);
        }
        return std::string();
      });
  }
  catch (...)
  {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error)
  {
    fs::remove(temporary, error);
    throw FileError(target + ": cannot be replaced: " + error.message());
  }
}

} // namespace meshfile
} // namespace dgmf
