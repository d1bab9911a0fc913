/**
 * @file DGMFLookAheadCompressor.h
 * @brief VTK's data compressors (LZ4, zlib, LZMA) compressing the blocks ahead of VTK's XML
 * writer in parallel, with the same bytes.
 *
 * vtkXMLWriter compresses an array's blocks one after the other, on one thread, between its writes
 * (about 0.5 s of LZ4 for an 8M-node grid). It hands the compressor each block where it lies in
 * the array's memory (little-endian, no conversion); this compressor, told where the arrays lie
 * (RegisterRange), queues the requested block and a window of the next ones of the same array
 * for worker threads, which compress them while VTK writes the blocks before, and hands VTK each
 * block when it asks for it. Every block is compressed by VTK's own compressor class, so the
 * bytes are VTK's; a block outside the ranges is compressed on the spot, as VTK would.
 */
#ifndef DGMFLookAheadCompressor_h
#define DGMFLookAheadCompressor_h

#include "vtkDataCompressor.h"
#include "vtkSmartPointer.h" // for New's result

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace dgmf_cli
{

/**
 * A compressor of VTK's class `className` (vtkLZ4DataCompressor, vtkZLibDataCompressor or
 * vtkLZMADataCompressor) compressing ahead on `threads` worker threads (at least one), up to
 * `windowBytes` of blocks ahead of the one VTK asks for (at least one block), in the memory
 * ranges given to RegisterRange (cast the result: LookAheadCompressor). Its class name is VTK's
 * (the file records it). Null for another class. The workers start with the first block asked
 * for in a range and stop in ClearRanges.
 */
vtkSmartPointer<vtkDataCompressor> NewLookAheadCompressor(
  const std::string& className, int threads, std::size_t windowBytes);

/// The look-ahead part of the compressors of NewLookAheadCompressor.
class LookAheadCompressor
{
public:
  virtual ~LookAheadCompressor() = default;
  /// Blocks inside [begin, begin + bytes) may be compressed ahead (the memory must not change
  /// until the write ends).
  virtual void RegisterRange(const void* begin, std::size_t bytes) = 0;
  /**
   * The values at [begin, begin + bytes) are already compressed by this compressor's class in
   * blocks of `blockSize` bytes (the last one shorter): `blocks` (where each block's bytes lie,
   * how many; they must stay until ClearRanges). A block VTK asks for at begin + k blockSize, of
   * block k's size, is handed as it is (CompressedArray: the blocks a file was read from).
   */
  virtual void RegisterCompressed(const void* begin, std::size_t bytes, std::size_t blockSize,
    const std::vector<std::pair<const unsigned char*, std::size_t>>& blocks) = 0;
  /// Forgets the ranges, the compressed blocks registered and the blocks compressed ahead, and
  /// stops the workers (none reads the ranges' memory afterwards).
  virtual void ClearRanges() = 0;
  /// Blocks handed as registered with RegisterCompressed since the compressor was made.
  virtual std::size_t GetBlocksHandedAsRead() const = 0;
  /// Blocks handed from the queue, and blocks asked for that were not the next one queued (a new
  /// queue started there when in a range, else compressed on the spot), since the compressor
  /// was made.
  virtual std::size_t GetCacheHits() const = 0;
  virtual std::size_t GetCacheMisses() const = 0;
};

} // namespace dgmf_cli

#endif
