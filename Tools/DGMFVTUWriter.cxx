#include "DGMFVTUWriter.h"

#include "DGMFCompressedArray.h"
#include "DGMFLookAheadCompressor.h"
#include "DGMFTupleAllocation.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArrayRange.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>

namespace dgmf_cli
{
vtkStandardNewMacro(DGMFVTUWriter);

DGMFVTUWriter::DGMFVTUWriter() = default;
DGMFVTUWriter::~DGMFVTUWriter() = default;

namespace
{
/// The lowest and highest value (or squared norm) seen by one thread.
struct Extremes
{
  double Low = std::numeric_limits<double>::infinity();
  double High = -std::numeric_limits<double>::infinity();
};

/// GetRange(-1)'s range: component 0 of one-component arrays, the norm of longer tuples.
struct RangeWorker
{
  double Range[2] = { 0.0, 0.0 };

  template <typename ArrayType>
  void operator()(ArrayType* array)
  {
    const int components = array->GetNumberOfComponents();
    vtkSMPThreadLocal<Extremes> local;
    vtkSMPTools::For(0, array->GetNumberOfTuples(),
      [&](vtkIdType begin, vtkIdType end)
      {
        Extremes& extremes = local.Local(); // once per chunk, not per value
        double low = extremes.Low, high = extremes.High;
        for (const auto tuple : vtk::DataArrayTupleRange(array, begin, end))
        {
          double value = 0.0;
          if (components == 1)
          {
            value = static_cast<double>(tuple[0]);
          }
          else
          {
            for (int c = 0; c < components; ++c)
            {
              const double x = static_cast<double>(tuple[c]);
              value += x * x;
            }
          }
          if (!std::isnan(value))
          {
            low = std::min(low, value);
            high = std::max(high, value);
          }
        }
        extremes.Low = low;
        extremes.High = high;
      });
    Extremes all;
    for (const Extremes& extremes : local)
    {
      all.Low = std::min(all.Low, extremes.Low);
      all.High = std::max(all.High, extremes.High);
    }
    this->Range[0] = components == 1 ? all.Low : std::sqrt(all.Low);
    this->Range[1] = components == 1 ? all.High : std::sqrt(all.High);
  }
};

/// True when every cell is of a linear type up to VTK_HEXAGONAL_PRISM (checked in parallel).
bool OnlyLinearCells(vtkUnstructuredGrid* grid)
{
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (!types)
  {
    return true;
  }
  const unsigned char* type = types->GetPointer(0);
  std::atomic<bool> linear(true);
  vtkSMPTools::For(0, types->GetNumberOfValues(),
    [&](vtkIdType begin, vtkIdType end)
    {
      bool all = true;
      for (vtkIdType i = begin; i < end; ++i)
      {
        all = all && type[i] <= VTK_HEXAGONAL_PRISM;
      }
      if (!all)
      {
        linear = false;
      }
    });
  return linear;
}
} // namespace

void DGMFVTUWriter::CacheRange(vtkDataArray* array)
{
  if (!array || array->GetNumberOfTuples() == 0)
  {
    return;
  }
  RangeWorker worker;
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker))
  {
    worker(array);
  }
  if (worker.Range[0] == std::numeric_limits<double>::infinity() ||
    worker.Range[1] == -std::numeric_limits<double>::infinity())
  {
    // Only NaN, or only +inf or -inf: VTK starts from the type's largest and smallest values
    // and writes those; left to its own computation.
    return;
  }
  vtkInformation* information = array->GetInformation();
  if (array->GetNumberOfComponents() == 1)
  {
    vtkNew<vtkInformationVector> perComponent;
    perComponent->SetNumberOfInformationObjects(1);
    perComponent->GetInformationObject(0)->Set(vtkDataArray::COMPONENT_RANGE(), worker.Range, 2);
    information->Set(vtkAbstractArray::PER_COMPONENT(), perComponent);
  }
  else
  {
    information->Set(vtkDataArray::L2_NORM_RANGE(), worker.Range, 2);
  }
}

namespace
{
/**
 * Adds to `data` the array VTK's AllocatePointGhostArray and AllocateCellGhostArray make (named
 * vtkGhostType, `count` zeros), on huge pages before the zeros are written (AllocateTuples): 16
 * MB at 8.26M nodes, which VTK faults in 4 KiB pages (4,000 faults, costly on a VM).
 */
void AddZeroGhostArray(vtkDataSetAttributes* data, vtkIdType count)
{
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  dgmf_vtk::AllocateTuples(ghosts, count);
  std::fill_n(ghosts->GetPointer(0), count, static_cast<unsigned char>(0));
  data->AddArray(ghosts);
}
} // namespace

bool DGMFVTUWriter::SkipCellTypeScan(vtkUnstructuredGrid* grid)
{
  this->PreparedGrid = nullptr;
  this->AddedPointGhosts = nullptr;
  this->AddedCellGhosts = nullptr;
  // Any array named vtkGhostType (of whatever type) is the grid's own: VTK's path.
  const char* ghosts = vtkDataSetAttributes::GhostArrayName();
  if (!grid || grid->GetPointData()->HasArray(ghosts) || grid->GetCellData()->HasArray(ghosts) ||
    !OnlyLinearCells(grid))
  {
    return false;
  }
  AddZeroGhostArray(grid->GetPointData(), grid->GetNumberOfPoints());
  AddZeroGhostArray(grid->GetCellData(), grid->GetNumberOfCells());
  this->PreparedGrid = grid;
  this->AddedPointGhosts = grid->GetPointGhostArray();
  this->AddedCellGhosts = grid->GetCellGhostArray();
  return true;
}

void DGMFVTUWriter::CompressAhead(int threads, std::size_t windowBytes)
{
  vtkDataCompressor* current = this->GetCompressor();
  if (!current)
  {
    return;
  }
  vtkSmartPointer<vtkDataCompressor> ahead =
    NewLookAheadCompressor(current->GetClassName(), threads, windowBytes);
  if (ahead)
  {
    ahead->SetCompressionLevel(current->GetCompressionLevel());
    this->SetCompressor(ahead);
  }
}

namespace
{
/**
 * Registers the memory of `array` with the look-ahead compressor if VTK writes it from there,
 * and the blocks it was read from (CompressedArray) when it is unmodified and they were made
 * by the compressor's class (`compressorClass`) in blocks of the writer's `blockSize`.
 */
void RegisterArray(LookAheadCompressor* compressor, vtkAbstractArray* array,
  const std::string& compressorClass, std::size_t blockSize)
{
  if (!array || !array->HasStandardMemoryLayout() || array->GetNumberOfValues() <= 0)
  {
    return;
  }
  auto* memory = static_cast<const unsigned char*>(array->GetVoidPointer(0));
  const std::size_t bytes = static_cast<std::size_t>(array->GetNumberOfValues()) *
    static_cast<std::size_t>(array->GetDataTypeSize());
  compressor->RegisterRange(memory, bytes);
  const CompressedArray* read = CompressedArray::Of(array);
  if (read && read->CompressorClass == compressorClass && read->BlockSize == blockSize &&
    read->Offset <= bytes && read->Bytes <= bytes - read->Offset)
  {
    compressor->RegisterCompressed(memory + read->Offset, read->Bytes, blockSize, read->Blocks);
  }
}

/// Calls `visit` with the grid's point coordinates (if any) and each point and cell array.
template <typename Visit>
void ForEachPointAndCellArray(vtkUnstructuredGrid* grid, Visit visit)
{
  if (grid->GetPoints())
  {
    visit(grid->GetPoints()->GetData());
  }
  for (vtkDataSetAttributes* arrays : { static_cast<vtkDataSetAttributes*>(grid->GetPointData()),
         static_cast<vtkDataSetAttributes*>(grid->GetCellData()) })
  {
    for (int k = 0; k < arrays->GetNumberOfArrays(); ++k)
    {
      visit(arrays->GetAbstractArray(k));
    }
  }
}
} // namespace

bool DGMFVTUWriter::PreferReadBlockSize(vtkUnstructuredGrid* grid)
{
  if (!grid || !this->GetCompressor())
  {
    return false;
  }
  const std::string compressorClass = this->GetCompressor()->GetClassName();
  // The bytes of the arrays to write, and of those read in blocks of each size by this class.
  std::size_t total = 0;
  std::map<std::size_t, std::size_t> readBytes;
  const auto count = [&](vtkAbstractArray* array)
  {
    if (!array)
    {
      return;
    }
    const std::size_t bytes = static_cast<std::size_t>(array->GetNumberOfValues()) *
      static_cast<std::size_t>(array->GetDataTypeSize());
    total += bytes;
    const CompressedArray* read = CompressedArray::Of(array);
    if (read && read->CompressorClass == compressorClass && read->BlockSize > 0 &&
      read->BlockSize <= static_cast<std::size_t>(VTK_INT_MAX))
    {
      readBytes[read->BlockSize] += read->Bytes;
    }
  };
  ForEachPointAndCellArray(grid, count);
  if (vtkCellArray* cells = grid->GetCells())
  {
    count(cells->GetConnectivityArray());
    count(cells->GetOffsetsArray());
  }
  count(grid->GetCellTypesArray());
  const auto most = std::max_element(readBytes.begin(), readBytes.end(),
    [](const auto& a, const auto& b) { return a.second < b.second; });
  if (most == readBytes.end() || 2 * most->second < total)
  {
    return false;
  }
  this->SetBlockSize(most->first);
  return true;
}

int DGMFVTUWriter::EndFile()
{
  if (auto* ahead = dynamic_cast<LookAheadCompressor*>(this->GetCompressor()))
  {
    ahead->ClearRanges();
  }
  return this->Superclass::EndFile();
}

int DGMFVTUWriter::StartFile()
{
  // VTK has chosen the version (no scan: the ghost arrays were there); nothing is written yet.
  // Only the arrays this writer added, to the grid it prepared, are removed.
  auto* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
  if (grid && grid == this->PreparedGrid && this->AddedPointGhosts &&
    grid->GetPointGhostArray() == this->AddedPointGhosts && this->AddedCellGhosts &&
    grid->GetCellGhostArray() == this->AddedCellGhosts)
  {
    grid->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
    grid->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
    this->UsePreviousVersion = true; // the scan's choice for linear cells without ghosts
  }
  this->PreparedGrid = nullptr;
  this->AddedPointGhosts = nullptr;
  this->AddedCellGhosts = nullptr;
  // The arrays VTK will compress from their own memory, for the look-ahead compressor.
  if (auto* ahead = dynamic_cast<LookAheadCompressor*>(this->GetCompressor()))
  {
    ahead->ClearRanges();
    if (grid && this->GetNumberOfPieces() == 1) // pieces would need their own ranges
    {
      const std::string compressorClass = this->GetCompressor()->GetClassName();
      const auto blockSize = static_cast<std::size_t>(this->GetBlockSize());
      const auto add = [&](vtkAbstractArray* array)
      { RegisterArray(ahead, array, compressorClass, blockSize); };
      ForEachPointAndCellArray(grid, add);
      if (vtkCellArray* cells = grid->GetCells())
      {
        add(cells->GetConnectivityArray());
        add(cells->GetOffsetsArray());
      }
      add(grid->GetCellTypesArray());
    }
  }
  return this->Superclass::StartFile();
}

void DGMFVTUWriter::WriteAppendedPieceData(int index)
{
  // The header (with the ranges' placeholders) is written; the appended data's writing asks each
  // array for its range. Cached here, not before Write(): the cache would be written as
  // InformationKey elements into the header.
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput()))
  {
    ForEachPointAndCellArray(
      grid, [](vtkAbstractArray* array) { CacheRange(vtkDataArray::SafeDownCast(array)); });
  }
  this->Superclass::WriteAppendedPieceData(index);
}

} // namespace dgmf_cli
