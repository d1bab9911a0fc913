/**
 * @file MeshBytes.h
 * @brief A NamedMesh as bytes and back: how a library's child process (LibraryIsolation.h) and the
 * gmsh module (GmshModule.h) hand a mesh to the caller.
 */
#ifndef dgmf_meshfile_MeshBytes_h
#define dgmf_meshfile_MeshBytes_h

#include "dgmf/meshfile/NamedMesh.h"

#include <cstddef>
#include <string>

namespace dgmf
{
namespace meshfile
{

/// A mesh as bytes, from a library's process to the caller's (MeshFromBytes reads them back; it
/// throws FileError on a short answer). Each array starts at a multiple of 8 bytes from the
/// start. MeshBytes is the length MeshToBytes writes into `out`.
std::size_t MeshBytes(const NamedMesh& mesh);
void MeshToBytes(const NamedMesh& mesh, char* out);
std::string MeshToBytes(const NamedMesh& mesh);
/// Read in place when `bytes` is 8-byte aligned (a mapping's, a string's heap buffer), from an
/// aligned copy otherwise.
NamedMesh MeshFromBytes(const char* bytes, std::size_t size);
NamedMesh MeshFromBytes(const std::string& bytes);

} // namespace meshfile
} // namespace dgmf

#endif
