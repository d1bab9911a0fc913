// dgmf-deform's .vtu writer (Tools/DGMFVTUWriter): the same bytes as VTK's own writer, with its
// shortcuts taken only where VTK would choose the same.
#include "DGMFVTUWriter.h"

#include "DGMFCompressedArray.h"
#include "DGMFLookAheadCompressor.h"
#include "DGMFVTUReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
/// A grid of hexahedra and tetrahedra (or, with `quadratic`, one quadratic tetrahedron too),
/// with point and cell arrays of several types, components, NaN and infinite values.
vtkSmartPointer<vtkUnstructuredGrid> MixedGrid(bool quadratic)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  const int n = 12;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        points->InsertNextPoint(i + 0.01 * j, j - 0.02 * k, k + 0.003 * i * i);
      }
    }
  }
  grid->SetPoints(points);
  auto id = [&](int i, int j, int k) { return static_cast<vtkIdType>(i + n * (j + n * k)); };
  for (int k = 0; k + 1 < n; ++k)
  {
    for (int j = 0; j + 1 < n; ++j)
    {
      for (int i = 0; i + 1 < n; ++i)
      {
        if ((i + j + k) % 3 == 0)
        {
          const vtkIdType tet[4] = { id(i, j, k), id(i + 1, j, k), id(i, j + 1, k),
            id(i, j, k + 1) };
          grid->InsertNextCell(VTK_TETRA, 4, tet);
          continue;
        }
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
    }
  }
  if (quadratic)
  {
    const vtkIdType tet10[10] = { 0, 2, 2 * n, 2 * n * n, 1, n + 1, n, n * n, n * n + 1,
      n * n + n };
    grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, tet10);
  }
  const vtkIdType nodes = grid->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("Displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(nodes);
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  marker->SetNumberOfTuples(nodes);
  vtkNew<vtkFloatArray> f;
  f->SetName("f");
  f->SetNumberOfTuples(nodes);
  for (vtkIdType p = 0; p < nodes; ++p)
  {
    const double x = std::sin(0.37 * p);
    displacement->SetTuple3(p, x, -2.0 * x * x, 0.5 - x);
    marker->SetValue(p, static_cast<int>(p % 7) - 3);
    f->SetValue(p, static_cast<float>(std::cos(0.11 * p)));
  }
  displacement->SetTuple3(5, std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0);
  f->SetValue(7, std::numeric_limits<float>::quiet_NaN());
  f->SetValue(9, -std::numeric_limits<float>::infinity());
  grid->GetPointData()->AddArray(displacement);
  grid->GetPointData()->AddArray(marker);
  grid->GetPointData()->AddArray(f);
  vtkNew<vtkDoubleArray> quality;
  quality->SetName("SizeSkew");
  quality->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    quality->SetValue(c, 1.0 / (1.0 + static_cast<double>(c % 13)));
  }
  grid->GetCellData()->AddArray(quality);
  return grid;
}

/// The .vtu `writer` writes for `grid` (to a string), with the given mode and compressor, and,
/// for a DGMFVTUWriter with `ahead` > 0, the compressor's blocks compressed on two worker
/// threads, a window of `ahead` blocks ahead.
std::string Written(vtkXMLUnstructuredGridWriter* writer, vtkUnstructuredGrid* grid, bool appended,
  int compressor, int ahead = 0, int blockSize = 1 << 12)
{
  writer->SetInputData(grid);
  writer->WriteToOutputStringOn();
  appended ? writer->SetDataModeToAppended() : writer->SetDataModeToBinary();
  writer->SetEncodeAppendedData(0);
  writer->SetCompressorType(compressor);
  writer->SetBlockSize(blockSize);
  if (auto* ours = dgmf_cli::DGMFVTUWriter::SafeDownCast(writer); ours && ahead > 0)
  {
    ours->CompressAhead(2, static_cast<std::size_t>(ahead) * static_cast<std::size_t>(blockSize));
  }
  EXPECT_EQ(writer->Write(), 1);
  EXPECT_EQ(writer->GetErrorCode(), 0u);
  return writer->GetOutputString();
}

/**
 * The bytes of VTK's writer and of DGMFVTUWriter (on a shallow copy, as dgmf-deform writes), each
 * on a grid of its own made by `make`: a write caches the arrays' ranges in their information,
 * and a second write of the same arrays writes that cache into the header (VTK's behaviour).
 */
void ExpectSameBytes(const std::function<vtkSmartPointer<vtkUnstructuredGrid>()>& make,
  bool expectSkip, bool appended, int compressor, int ahead = 0)
{
  vtkNew<vtkXMLUnstructuredGridWriter> stock;
  const std::string expected = Written(stock, make(), appended, compressor);
  vtkNew<vtkUnstructuredGrid> copy;
  copy->ShallowCopy(make());
  const int pointArrays = copy->GetPointData()->GetNumberOfArrays();
  vtkNew<dgmf_cli::DGMFVTUWriter> fast;
  EXPECT_EQ(fast->SkipCellTypeScan(copy), expectSkip);
  const std::string actual = Written(fast, copy, appended, compressor, ahead);
  if (ahead > 0)
  {
    // The blocks were compressed ahead (most handed to VTK from the cache).
    auto* lookAhead = dynamic_cast<dgmf_cli::LookAheadCompressor*>(fast->GetCompressor());
    ASSERT_NE(lookAhead, nullptr);
    EXPECT_GT(lookAhead->GetCacheHits(), 0u);
    if (ahead >= 5)
    {
      EXPECT_GT(lookAhead->GetCacheHits(), lookAhead->GetCacheMisses());
    }
  }
  EXPECT_EQ(copy->GetPointData()->GetNumberOfArrays(), pointArrays) << "ghost arrays left";
  EXPECT_GT(expected.size(), 1000u);
  if (expectSkip)
  {
    EXPECT_EQ(actual.find("vtkGhostType"), std::string::npos);
  }
  if (actual != expected && std::getenv("DGMF_DUMP_VTU"))
  {
    std::ofstream(std::string(std::getenv("DGMF_DUMP_VTU")) + ".expected") << expected;
    std::ofstream(std::string(std::getenv("DGMF_DUMP_VTU")) + ".actual") << actual;
  }
  EXPECT_TRUE(actual == expected) << "appended " << appended << ", compressor " << compressor
                                  << ": " << actual.size() << " against " << expected.size()
                                  << " bytes";
}
} // namespace

TEST(VTUWriter, WritesTheBytesOfVtksWriterForLinearCells)
{
  for (const bool appended : { true, false })
  {
    for (const int compressor : { vtkXMLWriterBase::LZ4, vtkXMLWriterBase::NONE })
    {
      ExpectSameBytes([]() { return MixedGrid(false); }, true, appended, compressor);
    }
  }
}

// Blocks compressed ahead on worker threads: VTK's bytes with each of its compressors, appended
// and inline, windows of 1, 2, 5 and 1000 blocks (the arrays' last blocks are shorter; 1000 is
// more than any array has).
TEST(VTUWriter, CompressingAheadWritesTheBytesOfVtksWriter)
{
  for (const bool appended : { true, false })
  {
    for (const int compressor :
      { vtkXMLWriterBase::LZ4, vtkXMLWriterBase::ZLIB, vtkXMLWriterBase::LZMA })
    {
      for (const int ahead : { 1, 2, 5, 1000 })
      {
        ExpectSameBytes([]() { return MixedGrid(false); }, true, appended, compressor, ahead);
      }
    }
  }
}

// One writer writing again: the workers stopped at the end of the first file start again for
// the second, whose bytes are VTK's too.
TEST(VTUWriter, CompressingAheadWritesAgainWithTheSameWriter)
{
  vtkNew<vtkXMLUnstructuredGridWriter> stock;
  const std::string expected = Written(stock, MixedGrid(false), true, vtkXMLWriterBase::LZ4);
  vtkNew<dgmf_cli::DGMFVTUWriter> ours;
  vtkNew<vtkUnstructuredGrid> first;
  first->ShallowCopy(MixedGrid(false));
  ours->SkipCellTypeScan(first);
  EXPECT_TRUE(Written(ours, first, true, vtkXMLWriterBase::LZ4, 3) == expected);
  vtkDataCompressor* compressor = ours->GetCompressor();
  auto* lookAhead = dynamic_cast<dgmf_cli::LookAheadCompressor*>(compressor);
  ASSERT_NE(lookAhead, nullptr);
  vtkNew<vtkUnstructuredGrid> second;
  second->ShallowCopy(MixedGrid(false));
  ours->SkipCellTypeScan(second);
  ours->SetInputData(second);
  EXPECT_EQ(ours->Write(), 1);
  EXPECT_EQ(ours->GetCompressor(), compressor);
  EXPECT_TRUE(ours->GetOutputString() == expected);
  EXPECT_GT(lookAhead->GetCacheHits(), 2 * lookAhead->GetCacheMisses());
}

// Quadratic cells and a grid's own ghost arrays: VTK's own choice of version, no shortcut.
TEST(VTUWriter, LeavesQuadraticCellsAndGhostArraysToVtk)
{
  ExpectSameBytes([]() { return MixedGrid(true); }, false, true, vtkXMLWriterBase::LZ4);
  ExpectSameBytes(
    []()
    {
      vtkSmartPointer<vtkUnstructuredGrid> grid = MixedGrid(false);
      grid->AllocateCellGhostArray();
      grid->GetCellGhostArray()->SetValue(3, 1);
      return grid;
    },
    false, true, vtkXMLWriterBase::LZ4);
}

// A grid's own vtkGhostType array of another type than VTK's, and a writer prepared for one grid
// but given another: VTK's path, nothing removed.
TEST(VTUWriter, TouchesOnlyTheGhostArraysItAdded)
{
  ExpectSameBytes(
    []()
    {
      vtkSmartPointer<vtkUnstructuredGrid> grid = MixedGrid(false);
      vtkNew<vtkIntArray> ghosts;
      ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
      ghosts->SetNumberOfTuples(grid->GetNumberOfPoints());
      ghosts->FillValue(0);
      grid->GetPointData()->AddArray(ghosts);
      return grid;
    },
    false, true, vtkXMLWriterBase::LZ4);

  vtkSmartPointer<vtkUnstructuredGrid> withGhosts = MixedGrid(false);
  withGhosts->AllocateCellGhostArray();
  withGhosts->AllocatePointGhostArray();
  vtkNew<vtkUnstructuredGrid> other;
  other->ShallowCopy(MixedGrid(false));
  vtkNew<dgmf_cli::DGMFVTUWriter> writer;
  ASSERT_TRUE(writer->SkipCellTypeScan(other));
  const std::string written = Written(writer, withGhosts, true, vtkXMLWriterBase::LZ4);
  EXPECT_NE(withGhosts->GetCellGhostArray(), nullptr) << "the input's own ghost array removed";
  EXPECT_NE(withGhosts->GetPointGhostArray(), nullptr) << "the input's own ghost array removed";
  EXPECT_NE(written.find("vtkGhostType"), std::string::npos);
}

TEST(VTUWriter, CachedRangesAreVtksRanges)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MixedGrid(false);
  vtkNew<vtkDoubleArray> infinite;
  infinite->SetName("OnlyInfinite");
  infinite->SetNumberOfTuples(grid->GetNumberOfPoints());
  infinite->FillValue(std::numeric_limits<double>::infinity());
  grid->GetPointData()->AddArray(infinite);
  std::vector<vtkDataArray*> arrays = { grid->GetPoints()->GetData(),
    grid->GetCellData()->GetArray("SizeSkew") };
  for (int k = 0; k < grid->GetPointData()->GetNumberOfArrays(); ++k)
  {
    arrays.push_back(grid->GetPointData()->GetArray(k));
  }
  for (vtkDataArray* array : arrays)
  {
    vtkSmartPointer<vtkDataArray> fresh;
    fresh.TakeReference(array->NewInstance());
    fresh->DeepCopy(array);
    dgmf_cli::DGMFVTUWriter::CacheRange(array);
    const bool cached = array->GetInformation()->Has(vtkDataArray::L2_NORM_RANGE()) ||
      array->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT());
    // An array of +inf only is left to VTK, which writes the type's largest value as its minimum.
    EXPECT_EQ(cached, array != infinite.GetPointer()) << array->GetName();
    double expected[2], actual[2];
    fresh->GetRange(expected, -1);
    array->GetRange(actual, -1);
    EXPECT_EQ(actual[0], expected[0]) << array->GetName();
    EXPECT_EQ(actual[1], expected[1]) << array->GetName();
  }
}

namespace
{
/// MixedGrid written by VTK's writer (appended, LZ4, blocks of 4 KiB) to the file `name` (one
/// per test: the tests may run at the same time).
std::string CompressedFile(const std::string& name)
{
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  std::ofstream(path, std::ios::binary)
    << Written(writer, MixedGrid(false), true, vtkXMLWriterBase::LZ4);
  return path;
}

/// The file read by dgmf-deform's reader (a new grid each time: writes cache ranges in arrays).
vtkSmartPointer<vtkUnstructuredGrid> ReadBack(const std::string& path)
{
  std::string whyNot;
  vtkSmartPointer<vtkUnstructuredGrid> grid = dgmf_cli::ReadAppendedVTU(path, whyNot);
  EXPECT_NE(grid, nullptr) << whyNot;
  return grid;
}

/// The blocks left with the arrays VTK's writer writes (points, point and cell data, cells).
std::size_t ReadBlocks(vtkUnstructuredGrid* grid)
{
  std::vector<vtkAbstractArray*> arrays = { grid->GetPoints()->GetData(),
    grid->GetCells()->GetConnectivityArray(), grid->GetCells()->GetOffsetsArray(),
    grid->GetCellTypesArray() };
  for (int k = 0; k < grid->GetPointData()->GetNumberOfArrays(); ++k)
  {
    arrays.push_back(grid->GetPointData()->GetAbstractArray(k));
  }
  for (int k = 0; k < grid->GetCellData()->GetNumberOfArrays(); ++k)
  {
    arrays.push_back(grid->GetCellData()->GetAbstractArray(k));
  }
  std::size_t blocks = 0;
  for (vtkAbstractArray* array : arrays)
  {
    const dgmf_cli::CompressedArray* read = dgmf_cli::CompressedArray::Of(array);
    blocks += read ? read->Blocks.size() : 0;
  }
  return blocks;
}

/**
 * The bytes DGMFVTUWriter writes for the file read back and changed by `change` (compressing
 * ahead, compressor `compressor`, blocks of `blockSize`) are VTK's writer's for the same grid;
 * returns the blocks it wrote as they were read.
 */
std::size_t BlocksWrittenAsRead(const std::string& path,
  const std::function<void(vtkUnstructuredGrid*)>& change, int compressor, int blockSize)
{
  vtkSmartPointer<vtkUnstructuredGrid> forVtk = ReadBack(path);
  change(forVtk);
  vtkNew<vtkXMLUnstructuredGridWriter> stock;
  const std::string expected = Written(stock, forVtk, true, compressor, 0, blockSize);
  vtkSmartPointer<vtkUnstructuredGrid> read = ReadBack(path);
  change(read);
  vtkNew<vtkUnstructuredGrid> copy; // as dgmf-deform writes: a shallow copy
  copy->ShallowCopy(read);
  vtkNew<dgmf_cli::DGMFVTUWriter> ours;
  ours->SkipCellTypeScan(copy);
  const std::string actual = Written(ours, copy, true, compressor, 3, blockSize);
  EXPECT_TRUE(actual == expected) << actual.size() << " against " << expected.size() << " bytes";
  auto* lookAhead = dynamic_cast<dgmf_cli::LookAheadCompressor*>(ours->GetCompressor());
  return lookAhead ? lookAhead->GetBlocksHandedAsRead() : 0;
}
} // namespace

// dgmf-deform writes again, as they were read, the compressed blocks of the arrays it did not
// change (the cells, as a rule): VTK's bytes, only for unmodified arrays, only with the file's
// compressor and block size.
TEST(VTUWriter, ArraysReadCompressedAreWrittenWithTheBlocksTheyWereRead)
{
  const std::string path = CompressedFile("dgmf-test-vtu-blocks-as-read.vtu");
  const auto unchanged = [](vtkUnstructuredGrid*) {};
  // Nothing is left in the arrays: VTK's writer writes a grid read back as the original.
  {
    vtkNew<vtkXMLUnstructuredGridWriter> original, readBack;
    const std::string a = Written(original, MixedGrid(false), true, vtkXMLWriterBase::LZ4);
    const std::string b = Written(readBack, ReadBack(path), true, vtkXMLWriterBase::LZ4);
    EXPECT_TRUE(a == b);
  }
  const std::size_t all = ReadBlocks(ReadBack(path));
  EXPECT_GT(all, 10u);
  EXPECT_EQ(BlocksWrittenAsRead(path, unchanged, vtkXMLWriterBase::LZ4, 1 << 12), all);
  // Points moved in place (and said so): theirs compressed again, the rest as read.
  std::size_t pointBlocks = 0;
  const auto movePoints = [&pointBlocks](vtkUnstructuredGrid* grid)
  {
    vtkDataArray* points = grid->GetPoints()->GetData();
    pointBlocks = dgmf_cli::CompressedArray::Of(points)->Blocks.size();
    for (vtkIdType p = 0; p < points->GetNumberOfTuples(); p += 3)
    {
      points->SetComponent(p, 1, points->GetComponent(p, 1) + 0.25);
    }
    points->Modified();
  };
  const std::size_t afterMove =
    BlocksWrittenAsRead(path, movePoints, vtkXMLWriterBase::LZ4, 1 << 12);
  EXPECT_EQ(afterMove, all - pointBlocks) << all << " " << pointBlocks;
  // A deep copy of an array is another array: compressed again.
  std::size_t markerBlocks = 0;
  const auto copyMarker = [&markerBlocks](vtkUnstructuredGrid* grid)
  {
    vtkDataArray* marker = grid->GetPointData()->GetArray("BoundaryMarker");
    markerBlocks = dgmf_cli::CompressedArray::Of(marker)->Blocks.size();
    vtkSmartPointer<vtkDataArray> copy = vtk::TakeSmartPointer(marker->NewInstance());
    copy->DeepCopy(marker);
    grid->GetPointData()->AddArray(copy); // replaces the array of the same name
  };
  const std::size_t afterCopy =
    BlocksWrittenAsRead(path, copyMarker, vtkXMLWriterBase::LZ4, 1 << 12);
  EXPECT_EQ(afterCopy, all - markerBlocks) << all << " " << markerBlocks;
  // Another block size or compressor: everything compressed again.
  EXPECT_EQ(BlocksWrittenAsRead(path, unchanged, vtkXMLWriterBase::LZ4, 1 << 13), 0u);
  EXPECT_EQ(BlocksWrittenAsRead(path, unchanged, vtkXMLWriterBase::ZLIB, 1 << 12), 0u);
  std::filesystem::remove(path);
}

// The writer takes the read arrays' block size when they hold at least half the bytes.
TEST(VTUWriter, PrefersTheBlockSizeOfWhatWasReadCompressed)
{
  const std::string path = CompressedFile("dgmf-test-vtu-read-block-size.vtu");
  const auto preferred = [&](int compressor, bool copyEverything)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = ReadBack(path);
    if (copyEverything)
    {
      vtkNew<vtkUnstructuredGrid> copy;
      copy->DeepCopy(grid);
      grid = copy;
    }
    vtkNew<dgmf_cli::DGMFVTUWriter> writer;
    writer->SetCompressorType(compressor);
    writer->SetBlockSize(1 << 20);
    const bool changed = writer->PreferReadBlockSize(grid);
    EXPECT_EQ(changed, writer->GetBlockSize() != (1 << 20));
    return writer->GetBlockSize();
  };
  EXPECT_EQ(preferred(vtkXMLWriterBase::LZ4, false), 1 << 12);
  EXPECT_EQ(preferred(vtkXMLWriterBase::LZ4, true), 1 << 20) << "a deep copy was taken as read";
  EXPECT_EQ(preferred(vtkXMLWriterBase::ZLIB, false), 1 << 20) << "another compressor's blocks";
  std::filesystem::remove(path);
}
