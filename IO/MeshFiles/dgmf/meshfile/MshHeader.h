/**
 * @file MshHeader.h
 * @brief A gmsh .msh file's version and mode, read and checked from its first two lines without
 * gmsh's library (which is loaded only when a .msh file is read or written: GmshModule.h).
 */
#ifndef dgmf_meshfile_MshHeader_h
#define dgmf_meshfile_MshHeader_h

#include <string>

namespace dgmf
{
namespace meshfile
{

/// What a .msh file's $MeshFormat section says.
struct MshFormat
{
  double Version = 0.0; ///< 2.0, 2.1, 2.2, 4.0 or 4.1
  bool Binary = false;
};

/**
 * Reads the first two lines of `path` and checks them: "$MeshFormat", then "<version> <0|1> 8"
 * with a version 2.x or 4.x. Throws FileError naming the file otherwise. gmsh parses a file with
 * a .msh name but another first line as a .geo script (which can run commands), so no file goes
 * to gmsh without this check.
 */
MshFormat CheckMshHeader(const std::string& path);

} // namespace meshfile
} // namespace dgmf

#endif
