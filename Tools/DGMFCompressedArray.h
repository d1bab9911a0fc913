/**
 * @file DGMFCompressedArray.h
 * @brief The compressed blocks an array was read from (DGMFVTUReader), remembered for the array
 * so that DGMFVTUWriter writes them again instead of compressing the same values again.
 *
 * dgmf-deform writes most of what it read unchanged: the cells (connectivity, offsets, types:
 * about 600 MB at 8.26M nodes) and the input's point and cell arrays. Compressing them again with
 * LZ4 took about 0.4 s of the write on two threads. For an array read by DGMFVTUReader from a
 * compressed file, the file's compressed blocks are remembered (the file stays mapped while they
 * are) with the array's modification time; the writer hands them to VTK's writer when the array
 * is still alive, unmodified, and the file's compressor and block size are the writer's
 * (DGMFLookAheadCompressor: RegisterCompressed). Nothing is stored in the array itself: VTK's
 * writer would write an array's information into the file. See Documentation/speed.md.
 */
#ifndef DGMFCompressedArray_h
#define DGMFCompressedArray_h

#include "vtkType.h"

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkAbstractArray;

namespace dgmf_cli
{

/**
 * The compressed form of an array's values as a file holds them: the blocks (each of BlockSize
 * bytes of values but the last), made by the compressor class CompressorClass, of the values that
 * start Offset bytes into the array's memory (VTK's cell offsets: after the leading 0), Bytes
 * bytes in all.
 */
struct CompressedArray
{
  /// A compressed block: where its bytes lie (in the mapped file) and how many there are.
  using Block = std::pair<const unsigned char*, std::size_t>;

  std::shared_ptr<const void> Keep; ///< holds the memory the blocks lie in
  std::string CompressorClass;
  std::size_t BlockSize = 0;
  std::size_t Offset = 0;
  std::size_t Bytes = 0;
  std::vector<Block> Blocks;

  /**
   * Remembers `blocks` for `array`'s values as they are now (its modification time). The entries
   * of arrays that no longer exist are dropped on the way (and their files unmapped).
   */
  static void Remember(vtkAbstractArray* array, CompressedArray blocks);

  /// The blocks remembered for `array`, if it is unmodified since; else null. Valid until the next
  /// Remember.
  static const CompressedArray* Of(vtkAbstractArray* array);
};

} // namespace dgmf_cli

#endif
