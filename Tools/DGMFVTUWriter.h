/**
 * @file DGMFVTUWriter.h
 * @brief dgmf-deform's .vtu writer: VTK's XML writer (vtkXMLUnstructuredGridWriter), writing the
 * same bytes, without the two serial passes that took most of a large grid's write.
 *
 * VTK 9.2's writer, on an 8.2M-hexahedron grid (2 threads, appended raw, LZ4): 2.5 s, of which
 * 0.6 s choosing the file version from the distinct cell types (a std::set insertion per cell)
 * and 0.9 s the RangeMin/RangeMax of every point and cell array (vtkDataArray::GetRange, about
 * 0.16 s for each 8M-value array, no faster with threads). Here the ranges are computed with
 * vtkSMPTools and left where GetRange finds them (the array's information, as GetRange itself
 * caches them), and the cell types are scanned in parallel to choose the version VTK would
 * choose. See Documentation/speed.md.
 */
#ifndef DGMFVTUWriter_h
#define DGMFVTUWriter_h

#include "vtkUnsignedCharArray.h" // for the weak pointers
#include "vtkUnstructuredGrid.h"  // for the weak pointers
#include "vtkWeakPointer.h"       // for the added ghost arrays
#include "vtkXMLUnstructuredGridWriter.h"

#include <cstddef>

class vtkDataArray;

namespace dgmf_cli
{

/**
 * @class DGMFVTUWriter
 * @brief vtkXMLUnstructuredGridWriter with the array ranges computed in parallel (appended mode),
 * with SkipCellTypeScan the file version chosen without VTK's serial cell-type scan, and with
 * CompressAhead the blocks compressed on worker threads while VTK writes.
 *
 * Writes the same bytes as vtkXMLUnstructuredGridWriter with the same settings (tested).
 */
class DGMFVTUWriter : public vtkXMLUnstructuredGridWriter
{
public:
  static DGMFVTUWriter* New();
  vtkTypeMacro(DGMFVTUWriter, vtkXMLUnstructuredGridWriter);

  /**
   * Prepares `grid`, a shallow copy the caller owns and is about to write with this writer, so
   * that VTK skips its cell-type scan: when the grid has no array named vtkGhostType and only
   * linear cells (VTK's types up to the hexagonal prism, where VTK keeps its previous file
   * version), zero-filled ghost arrays are added (with them VTK does not scan) and this writer
   * removes them again before anything is written, if its input is still that grid with those
   * arrays, and keeps the previous version, as the scan would have. Other grids are left as they
   * are. Returns true when the grid was prepared.
   */
  bool SkipCellTypeScan(vtkUnstructuredGrid* grid);

  /**
   * Computes the range of `array` as vtkDataArray::GetRange(-1) does (component 0 of a
   * one-component array, else the tuples' Euclidean norm; NaN skipped), with vtkSMPTools, and
   * caches it in the array's information where GetRange looks first (not for an array with no
   * value other than NaN, or only +inf or -inf, whose range is left to VTK).
   */
  static void CacheRange(vtkDataArray* array);

  /**
   * Replaces the compressor set (LZ4, zlib or LZMA, with its level) by the same class compressing
   * an array's next blocks on `threads` worker threads while VTK writes, up to `windowBytes`
   * ahead (default 8 MiB; DGMFLookAheadCompressor.h): the same bytes. Call after choosing the
   * compressor type; nothing happens for another compressor.
   */
  void CompressAhead(int threads, std::size_t windowBytes = std::size_t(8) << 20);

  /**
   * Takes the block size of the arrays of `grid` that were read with their compressed blocks
   * (CompressedArray: DGMFVTUReader's arrays, unmodified), when blocks of that size made by
   * this writer's compressor class hold at least half the bytes to write: those blocks are then
   * written as they were read instead of being compressed again (with CompressAhead). Call after
   * choosing the compressor type and block size; returns true when the block size was changed.
   * A file whose arrays were compressed in blocks of VTK's 32 KiB then gets blocks of 32 KiB.
   */
  bool PreferReadBlockSize(vtkUnstructuredGrid* grid);

protected:
  DGMFVTUWriter();
  ~DGMFVTUWriter() override;
  int StartFile() override;
  int EndFile() override;
  void WriteAppendedPieceData(int index) override;

private:
  DGMFVTUWriter(const DGMFVTUWriter&) = delete;
  void operator=(const DGMFVTUWriter&) = delete;
  /// The grid SkipCellTypeScan prepared and the ghost arrays it added (removed in StartFile
  /// only if the input is still that grid with those arrays).
  vtkWeakPointer<vtkUnstructuredGrid> PreparedGrid;
  vtkWeakPointer<vtkUnsignedCharArray> AddedPointGhosts;
  vtkWeakPointer<vtkUnsignedCharArray> AddedCellGhosts;
};

} // namespace dgmf_cli

#endif
