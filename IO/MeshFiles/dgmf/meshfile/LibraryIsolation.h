/**
 * @file LibraryIsolation.h
 * @brief Private to the readers that go through a format's library (gmsh, Exodus II, CGNS): the
 * library's work on a file runs in a child process, so that a crash, a hang or a runaway
 * allocation of the library on a hostile file is a FileError, not the end of the caller's process.
 * (gmsh 4.8.4 corrupts its heap on some malformed files; netCDF allocates what a corrupted Exodus
 * header declares, and the Exodus library reads out of bounds on corrupted side sets.)
 */
#ifndef dgmf_meshfile_LibraryIsolation_h
#define dgmf_meshfile_LibraryIsolation_h

#include "dgmf/meshfile/NamedMesh.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace dgmf
{
namespace meshfile
{

/// What a child's work writes its answer into: `room(bytes)` gives that many writable bytes
/// (asked for once), shared with the caller's process without a copy. Throws when the memory
/// cannot be had, or when asked twice (the caller then gets FileError("<file>: <why>")).
using AnswerRoom = std::function<char*(std::size_t bytes)>;

/// A child's answer as the caller sees it: the bytes the child wrote into its AnswerRoom, mapped
/// read-only (no copy), until this object goes.
class IsolatedAnswer
{
public:
  IsolatedAnswer() = default;
  IsolatedAnswer(IsolatedAnswer&& other) noexcept;
  IsolatedAnswer& operator=(IsolatedAnswer&& other) noexcept;
  IsolatedAnswer(const IsolatedAnswer&) = delete;
  IsolatedAnswer& operator=(const IsolatedAnswer&) = delete;
  ~IsolatedAnswer();

  const char* Data() const { return this->Bytes; }
  std::size_t Size() const { return this->Length; }

private:
  friend IsolatedAnswer MapIsolatedAnswer(
    int memory, std::uint64_t length, const std::string& file, const std::string& library);
  /// Takes a mapping of `size` bytes (unmapped when this goes).
  IsolatedAnswer(const char* data, std::size_t size);

  const char* Bytes = nullptr;
  std::size_t Length = 0;
};

/// The first `length` bytes of the memory file `memory`, mapped (RunIsolatedInPlace's last step);
/// FileError("<file>: <library>'s process gave a broken answer ...") if it holds fewer.
IsolatedAnswer MapIsolatedAnswer(
  int memory, std::uint64_t length, const std::string& file, const std::string& library);

/**
 * Runs `work` in a forked child and returns the bytes it wrote into its AnswerRoom (none if it
 * asked for no room). The answer travels in a memory file shared by the two processes
 * (`memfd_create`): the caller maps it, nothing is copied through a pipe; only the answer's kind
 * and length (or an error's message) go through one. A FileError thrown by `work` is thrown
 * again here with its message; a child that dies, exits without an answer, announces more bytes
 * than it wrote, or takes longer than `seconds` (then killed) is a FileError("<file>: <library>
 * ..."). With `memoryBudget` > 0 the child's address space may grow by that many bytes only
 * (RLIMIT_AS), so that an allocation a corrupted count drives fails instead of taking the
 * machine's memory. The child leaves with _exit: no atexit handlers, no flushing of the parent's
 * streams.
 */
IsolatedAnswer RunIsolatedInPlace(const std::string& file, const std::string& library,
  double seconds, std::size_t memoryBudget, const std::function<void(const AnswerRoom&)>& work);

/// RunIsolatedInPlace for a `work` that returns its answer as a string (copied into the room),
/// the answer copied into a string.
std::string RunIsolated(const std::string& file, const std::string& library, double seconds,
  std::size_t memoryBudget, const std::function<std::string()>& work);

/// The time a library may take on `path`: 2 minutes plus 10 s per MiB.
double TimeAllowed(const std::string& path);

/**
 * The mesh `read` gives, read in a child process (RunIsolated) with TimeAllowed(path) and an
 * address space that may grow by 1 GiB plus 64 times the file's size: for the readers whose
 * library allocates what a corrupted header declares (netCDF, HDF5).
 */
NamedMesh ReadMeshIsolated(
  const std::string& path, const std::string& library, const std::function<NamedMesh()>& read);

/**
 * Runs `write` (which reads `source` and writes `target` through WriteModifiedCopy) in a child
 * process with the same time and memory budget: the library's state after a file it fails on
 * (HDF5 keeps objects open) stays in the child. When it fails, the temporary file beside
 * `target` is removed and the FileError thrown here.
 */
void WriteIsolated(const std::string& source, const std::string& target, const std::string& library,
  const std::function<void()>& write);

} // namespace meshfile
} // namespace dgmf

#endif
