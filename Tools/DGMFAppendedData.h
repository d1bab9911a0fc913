/**
 * @file DGMFAppendedData.h
 * @brief The raw appended section of a VTK XML file, mapped, and its arrays' bytes decompressed
 * on all threads (the lower layer of DGMFVTUReader).
 */
#ifndef DGMFAppendedData_h
#define DGMFAppendedData_h

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dgmf_cli
{

/// Why DGMFVTUReader does not read a file (the caller then reads it with VTK's reader).
struct NotTaken
{
  std::string Why;
};

/**
 * The appended section of the file `path`, which starts at byte `position` (after the `_`),
 * with headers of `headerBytes` (4 or 8) bytes, compressed by VTK's class `compressorName` ("":
 * not compressed). Arrays are queued by their offset in the section (Queue) and their bytes
 * written by Run, every compressed block decompressed by VTK's class on the vtkSMPTools threads
 * (a compressor per thread). Every header word, size and offset is checked against the file
 * before it is used; what does not hold together throws NotTaken.
 */
class AppendedData
{
public:
  AppendedData(const std::string& path, std::size_t position, int headerBytes,
    const std::string& compressorName);
  AppendedData(const AppendedData&) = delete;
  AppendedData& operator=(const AppendedData&) = delete;

  /// Whether `compressorName` is "" or a compressor class Run can use.
  static bool CanDecompress(const std::string& compressorName);

  /// An array's compressed blocks in the mapped file (where each lies, how many bytes), each of
  /// BlockSize bytes of values but the last; none when the file is not compressed.
  struct CompressedBlocks
  {
    std::size_t BlockSize = 0;
    std::vector<std::pair<const unsigned char*, std::size_t>> Blocks;
  };

  /// Queues the `bytes` of the array at `offset` in the section, to be written at `target`;
  /// returns its compressed blocks.
  CompressedBlocks Queue(std::size_t offset, unsigned char* target, std::size_t bytes);

  /// Writes the arrays queued so far (their targets must be alive) and forgets them.
  void Run();

  /// The mapped file, held for as long as the result is (the blocks of Queue lie in it).
  std::shared_ptr<const void> GetFile() const { return this->File; }

  /// The compressor class of the file ("": not compressed).
  const std::string& GetCompressorName() const { return this->CompressorName; }

private:
  /// A piece of work: bytes of the file into an array (decompressed, or copied).
  struct Job
  {
    const unsigned char* Source;
    std::size_t SourceBytes;
    unsigned char* Target;
    std::size_t TargetBytes;
  };

  std::uint64_t Word(std::size_t at) const;
  void Check(std::size_t at, std::size_t bytes) const;

  std::shared_ptr<const void> File;    ///< the mapping (unmapped when the last holder goes)
  const unsigned char* Data = nullptr; ///< the mapped file
  std::size_t Size = 0;
  std::size_t Position;
  std::size_t HeaderBytes;
  std::string CompressorName;
  std::vector<Job> Jobs;
};

} // namespace dgmf_cli

#endif
