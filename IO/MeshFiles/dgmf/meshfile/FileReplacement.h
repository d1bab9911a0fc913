/**
 * @file FileReplacement.h
 * @brief Writing a solver's file as a modified copy of its source, never half a file at the target:
 * for the formats written through their own library (Exodus II, CGNS), which changes a file in
 * place.
 */
#ifndef dgmf_meshfile_FileReplacement_h
#define dgmf_meshfile_FileReplacement_h

#include <functional>
#include <string>

namespace dgmf
{
namespace meshfile
{

/**
 * Copies `source` to a temporary file beside `target` (".<target name>.dgmf-writing<extension>"),
 * calls `modify` with the temporary file's path, and renames the temporary file over `target`.
 * `target` may be `source` (it is read whole before anything changes). If copying, `modify` (by
 * throwing) or the rename fails, the temporary file is removed, `target` is unchanged, and a
 * FileError (or what `modify` threw) propagates.
 */
void WriteModifiedCopy(const std::string& source, const std::string& target,
  const std::function<void(const std::string& temporary)>& modify);

/**
 * The bytes of the file `path`, read at its size in one call. Throws FileError ("<path>: cannot be
 * opened", "... cannot be read").
 */
std::string ReadFileBytes(const std::string& path);

/**
 * Writes `bytes` to `temporary` (a file beside `target`) and renames it over `target`, so that
 * `target` is never half written; on failure the temporary file is removed, `target` is unchanged
 * and FileError is thrown.
 */
void WriteFileAtomically(
  const std::string& target, const std::string& temporary, const std::string& bytes);

/// The temporary file WriteModifiedCopy writes beside `target`.
std::string TemporaryBeside(const std::string& target);

} // namespace meshfile
} // namespace dgmf

#endif
