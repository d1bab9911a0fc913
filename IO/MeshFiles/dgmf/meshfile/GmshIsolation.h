/**
 * @file GmshIsolation.h
 * @brief Private to GmshFile.cxx: gmsh's work on a file runs in a child process, so that a crash
 * or a hang of gmsh on a hostile file is a FileError, not the end of the caller's process.
 */
#ifndef dgmf_meshfile_GmshIsolation_h
#define dgmf_meshfile_GmshIsolation_h

#include "dgmf/meshfile/NamedMesh.h"

#include <functional>
#include <string>

namespace dgmf
{
namespace meshfile
{

/**
 * Runs `work` in a forked child and returns the bytes it returned. A FileError thrown by `work`
 * is thrown again here with its message; a child that dies (gmsh 4.8.4 corrupts its heap on some
 * malformed files and aborts), exits without an answer, or takes longer than `seconds` (then
 * killed) is a FileError("<file>: ..."). The child leaves with _exit: no atexit handlers, no
 * flushing of the parent's streams.
 */
std::string RunIsolated(
  const std::string& file, double seconds, const std::function<std::string()>& work);

/// A mesh as bytes, from gmsh's process to the caller's (MeshFromBytes reads them back; it throws
/// FileError on a short answer).
std::string MeshToBytes(const NamedMesh& mesh);
NamedMesh MeshFromBytes(const std::string& bytes);

} // namespace meshfile
} // namespace dgmf

#endif
