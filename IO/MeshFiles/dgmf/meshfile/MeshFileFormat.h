/**
 * @file MeshFileFormat.h
 * @brief The solver mesh formats the library reads and writes back, told by the file name's
 * extension, and one entry point for each of reading and writing.
 */
#ifndef dgmf_meshfile_MeshFileFormat_h
#define dgmf_meshfile_MeshFileFormat_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string>

namespace dgmf
{
namespace meshfile
{

/// A solver mesh format.
enum class MeshFileFormat
{
  None,   ///< not a format of this library
  Gmsh,   ///< .msh (GmshFile.h)
  SU2,    ///< .su2 (SU2File.h)
  Exodus, ///< .exo, .e, .ex2 (ExodusFile.h)
  CGNS    ///< .cgns (CGNSFile.h)
};

/// The format of a file named `path`, by its extension (case-sensitive, as ParaView's).
MeshFileFormat FormatOfFileName(const std::string& path);

/// The extensions of the formats, separated by spaces, without dots ("msh su2 exo e ex2 cgns").
const char* MeshFileExtensions();

/// Reads `path` with the reader of its format. Throws FileError (also for an unknown extension).
NamedMesh ReadMeshFile(const std::string& path);

/**
 * Writes a copy of `source` to `target` with the node coordinates `points` (3 per node, in the
 * reader's order; `count` nodes), with the writer of their format: both must be of one format.
 * Throws FileError; the target is then unchanged.
 */
void WriteMeshFileWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
