/**
 * @file GmshModule.h
 * @brief gmsh's library, loaded when a .msh file is first read or written, not when a program
 * starts. libgmsh (with OpenCASCADE, FLTK and about 70 libraries in all) took 0.1 - 0.15 s to load
 * in every process that linked it, dgmf-deform on a .vtu and ParaView loading the plugin included
 * (Documentation/speed.md, "Starting without gmsh"). The gmsh calls are in a module of their own,
 * libDGMFGmshFile.so (GmshModel.cxx, GmshSession.cxx), opened with dlopen: the file the
 * environment variable DGMF_GMSH_MODULE names if it is set and not empty (and only it), else
 * first beside the library or program that holds this code (an install tree: beside
 * libDGMFIO.so), then, for code inside the build tree, at the module's place in the build tree,
 * then by the dynamic loader's search (LD_LIBRARY_PATH).
 */
#ifndef dgmf_meshfile_GmshModule_h
#define dgmf_meshfile_GmshModule_h

#include "dgmf/meshfile/MshHeader.h"

#include <cstddef>
#include <string>

namespace dgmf
{
namespace meshfile
{

/// The module's entry points. Each returns true on success; on failure `message` holds the
/// FileError's message ("<file>: <what>"), as exceptions do not cross the module's boundary.
struct GmshModule
{
  /// Reads the checked .msh file `path` into a NamedMesh, as bytes (MeshToBytes).
  bool (*Read)(const std::string& path, const MshFormat& format, std::string& bytesOrMessage);
  /// Writes `source` with its nodes moved to `points` (3 x `count`) to `target`.
  bool (*Write)(const std::string& source, const std::string& target, const MshFormat& format,
    const double* points, std::size_t count, std::string& message);
};

/// The entry points' names.
constexpr const char* kGmshModuleReadSymbol = "dgmf_meshfile_gmsh_read";
constexpr const char* kGmshModuleWriteSymbol = "dgmf_meshfile_gmsh_write";
constexpr const char* kGmshModuleIdentitySymbol = "dgmf_meshfile_gmsh_build_identity";

/// This build's identity (made once per build tree by CMake): a module of another build, whose
/// NamedMesh or entry points may differ, is refused.
#ifdef DGMF_GMSH_MODULE_IDENTITY
constexpr const char* kGmshModuleIdentity = DGMF_GMSH_MODULE_IDENTITY;
#else
constexpr const char* kGmshModuleIdentity = "unknown";
#endif

/**
 * The gmsh module's entry points, loaded on the first call (thread-safe) and kept for the
 * process's life. Throws FileError("<file>: gmsh's library cannot be loaded: <where it looked and
 * why>") when no module loads (tried again on the next call); `file` only names the file in that
 * message.
 */
GmshModule LoadGmshModule(const std::string& file);

} // namespace meshfile
} // namespace dgmf

#endif
