// dgmf-deform's .vtu reader (Tools/DGMFVTUReader): the grid VTK's own reader gives, for every
// compressor and header size it takes, and null (VTK's reader then) for the files it does not.
#include "DGMFVTUReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkShortArray.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace
{
constexpr int Side = 14; // points per side: Side^3 points

/// Hexahedra and tetrahedra on a Side^3 grid of points, with point, cell and field arrays of
/// several types and component counts, component names and active attributes.
vtkSmartPointer<vtkUnstructuredGrid> Grid()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k < Side; ++k)
    for (int j = 0; j < Side; ++j)
      for (int i = 0; i < Side; ++i)
        points->InsertNextPoint(i + 0.01 * j, j - 0.02 * k, k + 0.003 * i * i);
  grid->SetPoints(points);
  const auto id = [](int i, int j, int k)
  { return static_cast<vtkIdType>(i + Side * (j + Side * k)); };
  for (int k = 0; k + 1 < Side; ++k)
    for (int j = 0; j + 1 < Side; ++j)
      for (int i = 0; i + 1 < Side; ++i)
      {
        if ((i + j) % 2 == 0)
        {
          const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
            id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
            id(i, j + 1, k + 1) };
          grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
        }
        else
        {
          const vtkIdType tet[4] = { id(i, j, k), id(i + 1, j, k), id(i, j + 1, k),
            id(i, j, k + 1) };
          grid->InsertNextCell(VTK_TETRA, 4, tet);
        }
      }
  const vtkIdType n = grid->GetNumberOfPoints();
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetComponentName(0, "u");
  velocity->SetComponentName(2, "w");
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("GlobalNodeIds");
  vtkNew<vtkShortArray> small;
  small->SetName("Small");
  small->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < n; ++i)
  {
    velocity->InsertNextTuple3(0.5 * i, -1.0 / (i + 1), i % 7);
    marker->InsertNextValue(static_cast<int>(i % 3));
    ids->InsertNextValue(1000000000000 + i);
    small->InsertNextTuple2(static_cast<double>(i % 100), -static_cast<double>(i % 50));
  }
  grid->GetPointData()->AddArray(velocity);
  grid->GetPointData()->AddArray(marker);
  grid->GetPointData()->AddArray(ids);
  grid->GetPointData()->AddArray(small);
  grid->GetPointData()->SetActiveVectors("Velocity");
  grid->GetPointData()->SetActiveScalars("BoundaryMarker");
  vtkNew<vtkDoubleArray> quality;
  quality->SetName("SizeSkew");
  vtkNew<vtkUnsignedCharArray> flags;
  flags->SetName("Inverted");
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    quality->InsertNextValue(1.0 / (c + 2));
    flags->InsertNextValue(static_cast<unsigned char>(c % 2));
  }
  grid->GetCellData()->AddArray(quality);
  grid->GetCellData()->AddArray(flags);
  grid->GetCellData()->SetActiveScalars("SizeSkew");
  vtkNew<vtkIdTypeArray> count;
  count->SetName("InvertedCellCount");
  count->InsertNextValue(3);
  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  time->InsertNextValue(0.25);
  time->InsertNextValue(0.5);
  grid->GetFieldData()->AddArray(count);
  grid->GetFieldData()->AddArray(time);
  return grid;
}

std::string Write(vtkUnstructuredGrid* grid, const std::string& name,
  const std::function<void(vtkXMLUnstructuredGridWriter*)>& settings)
{
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToAppended();
  writer->SetEncodeAppendedData(0);
  writer->SetBlockSize(1024); // many blocks, read on both threads
  settings(writer);
  EXPECT_EQ(writer->Write(), 1);
  return path;
}

vtkSmartPointer<vtkUnstructuredGrid> ReadByVtk(const std::string& path)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

/// Every value of `b` is `a`'s, bit for bit, with the same name, type and components.
void ExpectSameArray(vtkDataArray* a, vtkDataArray* b, const std::string& where)
{
  ASSERT_NE(a, nullptr) << where;
  ASSERT_NE(b, nullptr) << where;
  EXPECT_STREQ(a->GetName(), b->GetName()) << where;
  EXPECT_EQ(a->GetDataType(), b->GetDataType()) << where << " " << a->GetName();
  ASSERT_EQ(a->GetNumberOfComponents(), b->GetNumberOfComponents()) << where;
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples()) << where;
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
  {
    const char* na = a->GetComponentName(c);
    const char* nb = b->GetComponentName(c);
    EXPECT_EQ(std::string(na ? na : ""), std::string(nb ? nb : "")) << where << " component " << c;
  }
  // The information keys (VTK's writer stores cached ranges with the arrays).
  EXPECT_EQ(a->GetInformation()->GetNumberOfKeys(), b->GetInformation()->GetNumberOfKeys())
    << where << " " << a->GetName();
  if (a->GetInformation()->Has(vtkDataArray::L2_NORM_RANGE()))
  {
    ASSERT_TRUE(b->GetInformation()->Has(vtkDataArray::L2_NORM_RANGE())) << where;
    EXPECT_EQ(a->GetInformation()->Get(vtkDataArray::L2_NORM_RANGE(), 1),
      b->GetInformation()->Get(vtkDataArray::L2_NORM_RANGE(), 1))
      << where;
  }
  const std::size_t bytes = static_cast<std::size_t>(a->GetNumberOfValues()) * a->GetDataTypeSize();
  EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes), 0)
    << where << " " << a->GetName();
}

void ExpectSameFields(vtkFieldData* a, vtkFieldData* b, const std::string& where)
{
  ASSERT_EQ(a->GetNumberOfArrays(), b->GetNumberOfArrays()) << where;
  for (int k = 0; k < a->GetNumberOfArrays(); ++k)
  {
    ExpectSameArray(a->GetArray(k), b->GetArray(k), where);
  }
}

/// The grid VTK's reader gives: points, cells, arrays and active attributes.
void ExpectSameGrid(vtkUnstructuredGrid* vtk, vtkUnstructuredGrid* ours, const std::string& where)
{
  ASSERT_EQ(vtk->GetNumberOfPoints(), Side * Side * Side) << where; // VTK's reader read it all
  ASSERT_EQ(ours->GetNumberOfPoints(), vtk->GetNumberOfPoints()) << where;
  ASSERT_EQ(ours->GetNumberOfCells(), vtk->GetNumberOfCells()) << where;
  ExpectSameArray(vtk->GetPoints()->GetData(), ours->GetPoints()->GetData(), where + " points");
  ExpectSameArray(vtk->GetCellTypesArray(), ours->GetCellTypesArray(), where + " types");
  vtkNew<vtkIdTypeArray> offsetsVtk, connectivityVtk, offsetsOurs, connectivityOurs;
  vtk->GetCells()->ExportLegacyFormat(connectivityVtk);
  ours->GetCells()->ExportLegacyFormat(connectivityOurs);
  ExpectSameArray(connectivityVtk, connectivityOurs, where + " cells");
  ExpectSameFields(vtk->GetPointData(), ours->GetPointData(), where + " point data");
  ExpectSameFields(vtk->GetCellData(), ours->GetCellData(), where + " cell data");
  ExpectSameFields(vtk->GetFieldData(), ours->GetFieldData(), where + " field data");
  for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
  {
    vtkAbstractArray* pv = vtk->GetPointData()->GetAbstractAttribute(a);
    vtkAbstractArray* po = ours->GetPointData()->GetAbstractAttribute(a);
    EXPECT_EQ(pv ? std::string(pv->GetName()) : "", po ? std::string(po->GetName()) : "")
      << where << " point attribute " << a;
    vtkAbstractArray* cv = vtk->GetCellData()->GetAbstractAttribute(a);
    vtkAbstractArray* co = ours->GetCellData()->GetAbstractAttribute(a);
    EXPECT_EQ(cv ? std::string(cv->GetName()) : "", co ? std::string(co->GetName()) : "")
      << where << " cell attribute " << a;
  }
}
} // namespace

TEST(VTUReader, ReadsWhatVtksReaderReadsWithEveryCompressorAndHeader)
{
  const vtkSmartPointer<vtkUnstructuredGrid> grid = Grid();
  for (int compressor :
    { vtkXMLWriter::NONE, vtkXMLWriter::LZ4, vtkXMLWriter::ZLIB, vtkXMLWriter::LZMA })
  {
    for (int header : { vtkXMLWriter::UInt32, vtkXMLWriter::UInt64 })
    {
      const std::string where =
        "compressor " + std::to_string(compressor) + ", header " + std::to_string(header);
      const std::string path = Write(grid, "dgmf_reader_test.vtu",
        [&](vtkXMLUnstructuredGridWriter* writer)
        {
          writer->SetCompressorType(compressor);
          writer->SetHeaderType(header);
        });
      std::string whyNot;
      const vtkSmartPointer<vtkUnstructuredGrid> ours = dgmf_cli::ReadAppendedVTU(path, whyNot);
      ASSERT_NE(ours, nullptr) << where << ": " << whyNot;
      ExpectSameGrid(ReadByVtk(path), ours, where);
      std::remove(path.c_str());
    }
  }
}

TEST(VTUReader, LeavesOtherFilesToVtksReader)
{
  const vtkSmartPointer<vtkUnstructuredGrid> grid = Grid();
  const auto notTaken =
    [&](const std::string& what, const std::function<void(vtkXMLUnstructuredGridWriter*)>& settings)
  {
    const std::string path = Write(grid, "dgmf_reader_other.vtu", settings);
    std::string whyNot;
    EXPECT_EQ(dgmf_cli::ReadAppendedVTU(path, whyNot), nullptr) << what;
    EXPECT_FALSE(whyNot.empty()) << what;
    std::remove(path.c_str());
  };
  notTaken("base64", [](vtkXMLUnstructuredGridWriter* w) { w->SetEncodeAppendedData(1); });
  notTaken("inline binary", [](vtkXMLUnstructuredGridWriter* w) { w->SetDataModeToBinary(); });
  notTaken("ascii", [](vtkXMLUnstructuredGridWriter* w) { w->SetDataModeToAscii(); });
  // A string array: not numeric.
  auto withNames = vtkSmartPointer<vtkUnstructuredGrid>::New();
  withNames->DeepCopy(grid);
  vtkNew<vtkStringArray> names;
  names->SetName("Names");
  names->InsertNextValue("wing");
  withNames->GetFieldData()->AddArray(names);
  const std::string path = Write(withNames, "dgmf_reader_strings.vtu",
    [](vtkXMLUnstructuredGridWriter* w) { w->SetCompressorTypeToLZ4(); });
  std::string whyNot;
  EXPECT_EQ(dgmf_cli::ReadAppendedVTU(path, whyNot), nullptr);
  EXPECT_FALSE(whyNot.empty());
  std::remove(path.c_str());
  EXPECT_EQ(dgmf_cli::ReadAppendedVTU("/nonexistent/mesh.vtu", whyNot), nullptr);
}

TEST(VTUReader, ATruncatedOrDamagedFileIsRefusedNotRead)
{
  const std::string path = Write(Grid(), "dgmf_reader_damaged.vtu",
    [](vtkXMLUnstructuredGridWriter* w) { w->SetCompressorTypeToLZ4(); });
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string whyNot;
  // Cut in the middle of the appended data: an array runs past the end.
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() * 3 / 4));
  }
  EXPECT_EQ(dgmf_cli::ReadAppendedVTU(path, whyNot), nullptr);
  EXPECT_FALSE(whyNot.empty());
  // Damaged blocks: the compressed bytes of the second half overwritten.
  {
    std::string damaged = bytes;
    for (std::size_t k = damaged.size() / 2; k + 8 < damaged.size(); k += 97)
    {
      damaged[k] = static_cast<char>(damaged[k] ^ 0x5a);
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(damaged.data(), static_cast<std::streamsize>(damaged.size()));
  }
  const vtkSmartPointer<vtkUnstructuredGrid> damaged = dgmf_cli::ReadAppendedVTU(path, whyNot);
  // LZ4 may decompress damaged bytes to the right size; then the grid is whatever they hold, but
  // no point id may lie outside the points.
  if (damaged)
  {
    const vtkIdType n = damaged->GetNumberOfPoints();
    vtkNew<vtkIdTypeArray> legacy;
    damaged->GetCells()->ExportLegacyFormat(legacy);
    for (vtkIdType k = 0; k < legacy->GetNumberOfValues();)
    {
      const vtkIdType count = legacy->GetValue(k++);
      for (vtkIdType m = 0; m < count; ++m, ++k)
      {
        ASSERT_LT(legacy->GetValue(k), n);
        ASSERT_GE(legacy->GetValue(k), 0);
      }
    }
  }
  else
  {
    EXPECT_FALSE(whyNot.empty());
  }
  std::remove(path.c_str());
}

TEST(VTUReader, HeadersThatDoNotHoldTogetherAreRefused)
{
  const std::string path = Write(Grid(), "dgmf_reader_lies.vtu",
    [](vtkXMLUnstructuredGridWriter* w)
    {
      w->SetCompressorTypeToLZ4();
      w->SetHeaderTypeToUInt64();
    });
  std::string original;
  {
    std::ifstream in(path, std::ios::binary);
    original.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto refused = [&](const std::string& what, const std::function<void(std::string&)>& edit)
  {
    std::string bytes = original;
    edit(bytes);
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    std::string whyNot;
    EXPECT_EQ(dgmf_cli::ReadAppendedVTU(path, whyNot), nullptr) << what;
    EXPECT_FALSE(whyNot.empty()) << what;
  };
  const auto replace = [](std::string& bytes, const std::string& from, const std::string& to)
  {
    const std::size_t at = bytes.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bytes.replace(at, from.size(), to);
  };
  // 2^61 points: their bytes do not fit in 64 bits.
  refused("2^61 points",
    [&](std::string& b)
    {
      replace(b, "NumberOfPoints=\"" + std::to_string(Side * Side * Side) + "\"",
        "NumberOfPoints=\"2305843009213693952\"");
    });
  // Blocks whose sizes wrap around to the array's size: 2 blocks of 2^64 - 8 and B + 8 bytes.
  refused("wrapping block sizes",
    [&](std::string& b)
    {
      const std::size_t appended = b.find('_', b.find("<AppendedData")) + 1;
      const std::size_t name = b.find("Name=\"Points\"");
      const std::size_t offsetAt = b.find("offset=\"", name) + 8;
      const std::size_t offset = std::stoull(b.substr(offsetAt, 20));
      const std::uint64_t words[3] = { 2, ~std::uint64_t(0) - 7,
        static_cast<std::uint64_t>(Side * Side * Side) * 3 * 8 + 8 };
      std::memcpy(&b[appended + offset], words, sizeof words);
    });
  // Two point arrays of one name (VTK keeps the first: left to it), points of 2 components.
  refused("two arrays named Velocity",
    [&](std::string& b) { replace(b, "Name=\"Small\"", "Name=\"Velocity\""); });
  refused("points of 2 components",
    [&](std::string& b)
    {
      const std::size_t name = b.find("Name=\"Points\"");
      const std::size_t components = b.find("NumberOfComponents=\"3\"", name);
      b.replace(components, 22, "NumberOfComponents=\"2\"");
    });
  refused(
    "offsets twice", [&](std::string& b) { replace(b, "Name=\"types\"", "Name=\"offsets\""); });
  std::remove(path.c_str());
}
