/**
 * @file FileReplacement.h
 * @brief Writing a solver's file as a modified copy of its source, never half a file at the target:
 * for the formats written through their own library (Exodus II, CGNS), which changes a file in
 * place.
 */
#ifndef dgmf_meshfile_FileReplacement_h
#define dgmf_meshfile_FileReplacement_h

#include <cstddef>
#include <fstream>
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
 * A copy of the bytes of the file `path` (MappedFile's). Throws FileError ("<path>: cannot be
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

/**
 * A file written in pieces through a buffer of 1 MiB: a text file made of the source's pieces and
 * new numbers without a copy of the whole file in memory (WriteFileAtomically below).
 */
class BufferedOutput
{
public:
  void Append(const char* data, std::size_t size)
  {
    if (this->Buffer.size() + size > Capacity)
    {
      this->Flush();
      if (size > Capacity)
      {
        this->File.write(data, static_cast<std::streamsize>(size));
        return;
      }
    }
    this->Buffer.append(data, size);
  }

private:
  friend void WriteFileAtomically(
    const std::string&, const std::string&, const std::function<void(BufferedOutput&)>&);
  static constexpr std::size_t Capacity = std::size_t(1) << 20;

  explicit BufferedOutput(const std::string& path)
    : File(path, std::ios::binary | std::ios::trunc)
  {
    this->Buffer.reserve(Capacity);
  }

  void Flush()
  {
    this->File.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
    this->Buffer.clear();
  }

  std::ofstream File;
  std::string Buffer;
};

/**
 * WriteFileAtomically of what `write` appends (in the order it appends it). What `write` throws
 * propagates, the temporary file removed and `target` unchanged.
 */
void WriteFileAtomically(const std::string& target, const std::string& temporary,
  const std::function<void(BufferedOutput&)>& write);

/// The temporary file WriteModifiedCopy writes beside `target`.
std::string TemporaryBeside(const std::string& target);

} // namespace meshfile
} // namespace dgmf

#endif
