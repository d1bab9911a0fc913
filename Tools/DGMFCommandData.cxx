#include "DGMFCommandData.h"

#include "vtkDGMFMeshFileReader.h"
#include "vtkDGMFMeshFileWriter.h"
#include "vtkDGMFOpenFOAMWriter.h"

#include "dgmf/ResultNames.h"
#include "dgmf/openfoam/CaseDirectory.h"

#include "DGMFBoundaryNameParts.h"
#include "DGMFCommandMessages.h"
#include "DGMFVTUReader.h"
#include "DGMFVTUWriter.h"
#include "vtkSMPTools.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkLongArray.h"
#include "vtkNew.h"
#include "vtkOpenFOAMReader.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridWriter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace dgmf_cli
{
namespace fs = std::filesystem;

namespace
{
/// True when `s` ends with `suffix` in any case (file extensions: "MESH.VTU").
bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()),
      [](char a, char b)
      {
        return std::tolower(static_cast<unsigned char>(a)) ==
          std::tolower(static_cast<unsigned char>(b));
      });
}

bool IsFoamFile(const std::string& path)
{
  return EndsWith(path, ".foam") || EndsWith(path, ".OpenFOAM");
}

/// A leaf of a composite data set with its block name.
struct NamedLeaf
{
  std::string Name;
  vtkDataObject* Data;
};

/// The named leaves of `data` (none when it is not composite), in order.
std::vector<NamedLeaf> NamedLeavesOf(vtkDataObject* data)
{
  std::vector<NamedLeaf> leaves;
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return leaves;
  }
  auto iterator = vtk::TakeSmartPointer(composite->NewIterator());
  for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
  {
    vtkInformation* metaData =
      iterator->HasCurrentMetaData() ? iterator->GetCurrentMetaData() : nullptr;
    if (metaData && metaData->Has(vtkCompositeDataSet::NAME()))
    {
      leaves.push_back(
        { metaData->Get(vtkCompositeDataSet::NAME()), iterator->GetCurrentDataObject() });
    }
  }
  return leaves;
}

/// The file to give vtkOpenFOAMReader for the case `path`.
std::string ReaderFileOf(const std::string& path)
{
  return IsFoamFile(path)
    ? path
    : (dgmf::openfoam::CaseDirectoryOf(path) / "system" / "controlDict").string();
}
} // namespace

bool IsOpenFOAMCase(const std::string& path)
{
  return IsFoamFile(path) || dgmf::openfoam::IsCase(dgmf::openfoam::CaseDirectoryOf(path));
}

vtkSmartPointer<vtkUnstructuredGrid> ReadMeshFile(const std::string& path)
{
  SetStage("reading " + path); // (an empty file is said before: InputProblem)
  if (EndsWith(path, ".vtk"))
  {
    vtkNew<vtkUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllFieldsOn();
    reader->Update();
    return reader->GetOutput();
  }
  // dgmf-deform's own files (appended raw data) on all threads; other .vtu files by VTK.
  std::string notTaken;
  if (vtkSmartPointer<vtkUnstructuredGrid> grid = ReadAppendedVTU(path, notTaken))
  {
    return grid;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

bool IsSolverMeshFile(const std::string& path)
{
  return vtkDGMFMeshFileReader::CanReadFileName(path.c_str());
}

vtkSmartPointer<vtkAlgorithm> ReadSolverMeshFile(const std::string& path)
{
  SetStage("reading " + path);
  auto reader = vtkSmartPointer<vtkDGMFMeshFileReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  if (GetErrorCount() > 0 ||
    reader->GetOutputDataObject(0)->GetNumberOfElements(vtkDataObject::POINT) == 0)
  {
    std::cerr << "dgmf-deform: error: could not read a mesh from " << path << "\n";
    return nullptr;
  }
  return reader;
}

std::vector<std::string> ExpandPatchGroups(
  const std::string& path, const std::vector<std::string>& names)
{
  std::vector<dgmf::openfoam::PatchEntry> patches;
  try
  {
    patches = dgmf::openfoam::ReadPatches(dgmf::openfoam::CaseDirectoryOf(path));
  }
  catch (const std::exception&)
  {
    return names; // the reader says what is wrong with the case
  }
  std::vector<std::string> expanded;
  for (const std::string& name : names)
  {
    const bool patch = std::any_of(patches.begin(), patches.end(),
      [&name](const dgmf::openfoam::PatchEntry& entry) { return entry.Name == name; });
    std::string members;
    for (const dgmf::openfoam::PatchEntry& entry : patches)
    {
      if (!patch && std::find(entry.Groups.begin(), entry.Groups.end(), name) != entry.Groups.end())
      {
        members += (members.empty() ? "" : "|") + entry.Name;
      }
    }
    expanded.push_back(members.empty() ? name : members);
  }
  return expanded;
}

bool IsVTUFileName(const std::string& path)
{
  return EndsWith(path, ".vtu");
}

std::vector<std::string> BoundaryNamesOf(vtkDataObject* blocks)
{
  std::vector<std::string> names;
  for (const NamedLeaf& leaf : NamedLeavesOf(blocks))
  {
    if (leaf.Name != "internalMesh")
    {
      names.push_back(leaf.Name);
    }
  }
  return names;
}

std::vector<std::string> BoundaryFamiliesOf(vtkDataObject* blocks)
{
  std::vector<std::string> families;
  for (const NamedLeaf& leaf : NamedLeavesOf(blocks))
  {
    if (leaf.Name != "internalMesh")
    {
      families.push_back(dgmf_vtk::FamilyOfBlock(leaf.Data));
    }
  }
  return families;
}

bool WriteSolverMeshFile(
  vtkAlgorithm* deformer, const std::string& source, const std::string& target)
{
  SetStage("writing " + target);
  const int errorsBefore = GetErrorCount();
  vtkNew<vtkDGMFMeshFileWriter> writer;
  writer->SetInputConnection(deformer->GetOutputPort());
  writer->SetSourceFileName(source.c_str());
  writer->SetFileName(target.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0 && GetErrorCount() == errorsBefore;
}

vtkUnstructuredGrid* VolumeOf(vtkDataObject* data)
{
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    return grid;
  }
  for (const NamedLeaf& leaf : NamedLeavesOf(data))
  {
    if (leaf.Name == "internalMesh")
    {
      return vtkUnstructuredGrid::SafeDownCast(leaf.Data);
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkUnstructuredGrid> VolumeToWrite(vtkDataObject* data)
{
  vtkUnstructuredGrid* volume = VolumeOf(data);
  if (!volume || volume == data)
  {
    return volume;
  }
  auto written = vtkSmartPointer<vtkUnstructuredGrid>::New();
  written->ShallowCopy(volume);
  vtkNew<vtkFieldData> fieldData;
  fieldData->PassData(volume->GetFieldData());
  // The composite's numeric arrays: the filter's summary and results, and the reader's own (the
  // OpenFOAM reader's CasePath, characters). The filter's Method string WriteMeshFile leaves out.
  vtkFieldData* summary = data->GetFieldData();
  for (int k = 0; summary && k < summary->GetNumberOfArrays(); ++k)
  {
    if (vtkDataArray* values = summary->GetArray(k))
    {
      fieldData->AddArray(values); // replaces an array of the same name
    }
  }
  written->SetFieldData(fieldData);
  return written;
}

namespace
{
/// Replaces each vtkIdTypeArray of the point, cell and field data of `grid` (a copy about to be
/// written) by a vtkLongArray of the same name and values: legacy files name the first type
/// `vtkIdType`, which readers other than VTK's do not know. Attributes (global or pedigree ids)
/// stay vtkIdTypeArray: VTK code asks for them as such.
void WriteIdTypeArraysAsLong(vtkUnstructuredGrid* grid)
{
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(grid->GetPointData()),
         static_cast<vtkFieldData*>(grid->GetCellData()), grid->GetFieldData() })
  {
    auto* attributes = vtkDataSetAttributes::SafeDownCast(data);
    for (int k = 0; data && k < data->GetNumberOfArrays(); ++k)
    {
      auto* ids = vtkIdTypeArray::SafeDownCast(data->GetAbstractArray(k));
      const int attribute = attributes ? attributes->IsArrayAnAttribute(k) : -1;
      if (!ids || !ids->GetName() || attribute == vtkDataSetAttributes::GLOBALIDS ||
        attribute == vtkDataSetAttributes::PEDIGREEIDS)
      {
        continue;
      }
      vtkNew<vtkLongArray> values;
      values->SetName(ids->GetName());
      values->SetNumberOfComponents(ids->GetNumberOfComponents());
      values->SetNumberOfTuples(ids->GetNumberOfTuples());
      std::copy_n(ids->GetPointer(0), ids->GetNumberOfValues(), values->GetPointer(0));
      data->AddArray(values); // in the place of the array of that name (an attribute stays one)
    }
  }
}
} // namespace

bool IsMeshFileName(const std::string& path)
{
  return EndsWith(path, ".vtu") || EndsWith(path, ".vtk");
}

bool IsCompression(const std::string& name)
{
  return name == "lz4" || name == "zlib" || name == "lzma" || name == "none";
}

bool WriteMeshFile(vtkUnstructuredGrid* mesh, const std::string& path, const VTUEncoding& encoding)
{
  if (!IsMeshFileName(path))
  {
    std::cerr << "dgmf-deform: error: cannot write " << path
              << ": the output must end in .vtu (XML) or .vtk (legacy VTK)\n";
    return false;
  }
  // Written beside its final name, then renamed over it: the final path holds the old file or the
  // whole new one, never half of one (an interruption, a full disk), and the output may be the
  // input (read completely before).
  const fs::path target(path);
  const fs::path temporary = target.parent_path() /
    ("." + target.filename().string() + ".dgmf-" + std::to_string(getpid()) + ".tmp");
  SetTemporaryFile(temporary.string());
  SetStage("writing " + path);
  const int errorsBefore = GetErrorCount();
  unsigned long errorCode = 0;
  // The filter's own string, its Method field, is left out: meshio 7 cannot read a file with a
  // string array ("Illegal data type 'String'"), nor can every VTK reader. String arrays the
  // input had are the user's data and are written, like every other input array (such a file
  // was not meshio's to read anyway).
  vtkNew<vtkUnstructuredGrid> written;
  written->ShallowCopy(mesh);
  if (vtkStringArray::SafeDownCast(written->GetFieldData()->GetAbstractArray(dgmf::names::Method)))
  {
    written->GetFieldData()->RemoveArray(dgmf::names::Method);
  }
  mesh = written;
  if (EndsWith(path, ".vtk"))
  {
    vtkNew<vtkUnstructuredGridWriter> legacy;
    // Version 4.2, not VTK 9's default 5.1, and 64-bit ids as `long`: the form every reader
    // takes (meshio 5 reads neither 5.1's `unsigned_char` nor the `vtkIdType` of the filter's
    // counts; VTK and ParaView read both versions).
    legacy->SetFileVersion(vtkDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    WriteIdTypeArraysAsLong(written);
    legacy->SetFileName(temporary.c_str());
    legacy->SetFileTypeToBinary();
    legacy->SetInputData(mesh);
    legacy->Write();
    errorCode = legacy->GetErrorCode();
  }
  else
  {
    vtkNew<DGMFVTUWriter> xml; // VTK's writer, same bytes, without its serial scans
    xml->SkipCellTypeScan(written);
    xml->SetFileName(temporary.c_str());
    xml->SetInputData(mesh);
    // Compressed blocks of 1 MiB instead of VTK's 32 KiB: 0.2 - 0.35 s less on an 8M-node grid
    // and a file 5 % smaller (speed.md).
    xml->SetBlockSize(1 << 20);
    // Appended raw, not compressed, by default: faster to write than LZ4 and than inline binary
    // (speed.md); ParaView on Debian 12 reads appended files with the expat work-around only
    // (README), inline binary without it.
    encoding.Appended ? xml->SetDataModeToAppended() : xml->SetDataModeToBinary();
    xml->SetEncodeAppendedData(0);
    const std::string compression = !encoding.Compression.empty() ? encoding.Compression
      : encoding.Appended                                         ? "none"
                                                                  : "lz4";
    compression == "zlib"     ? xml->SetCompressorTypeToZLib()
      : compression == "lzma" ? xml->SetCompressorTypeToLZMA()
      : compression == "none" ? xml->SetCompressorTypeToNone()
                              : xml->SetCompressorTypeToLZ4();
    // VTK compresses block after block on its one thread, between its writes: the next 8 MiB
    // of blocks are compressed on worker threads while it writes (same bytes).
    xml->CompressAhead(vtkSMPTools::GetEstimatedNumberOfThreads());
    // What was read compressed and did not change (the cells, as a rule) is written with the
    // blocks it was read from, in their block size, instead of being compressed again.
    xml->PreferReadBlockSize(written);
    xml->Write();
    errorCode = xml->GetErrorCode();
  }
  std::error_code error;
  // vtkXMLWriter::Write() returns 1 even when it fails: its error code and messages tell.
  bool ok = errorCode == 0 && GetErrorCount() == errorsBefore && fs::exists(temporary, error);
  if (ok)
  {
    fs::rename(temporary, target, error);
    ok = !error;
    if (!ok)
    {
      std::cerr << "dgmf-deform: error: cannot rename " << temporary << " to " << path << ": "
                << error.message() << "\n";
    }
  }
  else if (errorCode != 0)
  {
    std::cerr << "dgmf-deform: error: writing " << path << " failed: "
              << (errorCode < vtkErrorCode::FirstVTKErrorCode
                     ? std::strerror(static_cast<int>(errorCode))
                     : vtkErrorCode::GetStringFromErrorCode(errorCode))
              << "\n";
  }
  if (!ok)
  {
    fs::remove(temporary, error);
  }
  SetTemporaryFile("");
  return ok;
}

vtkSmartPointer<vtkAlgorithm> ReadOpenFOAMCase(const std::string& path, bool decomposePolyhedra)
{
  auto reader = vtkSmartPointer<vtkOpenFOAMReader>::New();
  reader->SetFileName(ReaderFileOf(path).c_str());
  reader->UpdateInformation();
  // The internal mesh and every patch (the names the options select); no zones, no fields.
  reader->DisableAllPatchArrays();
  for (int k = 0; k < reader->GetNumberOfPatchArrays(); ++k)
  {
    const std::string name = reader->GetPatchArrayName(k);
    if (name == "internalMesh" || name.rfind("patch/", 0) == 0)
    {
      reader->SetPatchArrayStatus(name.c_str(), 1);
    }
  }
  reader->DisableAllCellArrays();
  reader->DisableAllPointArrays();
  reader->DisableAllLagrangianArrays();
  reader->SetDecomposePolyhedra(decomposePolyhedra ? 1 : 0);
  reader->SetCreateCellToPoint(0);
  const int errorsBefore = GetErrorCount();
  reader->Update();
  // A points file that does not parse leaves the reader's error and no internal mesh: that is
  // what to say, not that the named patches are missing.
  vtkUnstructuredGrid* volume = VolumeOf(reader->GetOutputDataObject(0));
  if (reader->GetNumberOfPatchArrays() == 0 || !reader->GetOutputDataObject(0) ||
    GetErrorCount() > errorsBefore || !volume || volume->GetNumberOfPoints() == 0)
  {
    std::cerr << "dgmf-deform: error: could not read an OpenFOAM mesh from " << path << "\n";
    return nullptr;
  }
  return reader;
}

std::string ListPatchNames(const std::string& path)
{
  std::string names;
  try
  {
    for (const std::string& name :
      dgmf::openfoam::ReadPatchNames(dgmf::openfoam::CaseDirectoryOf(path)))
    {
      names += (names.empty() ? "" : ", ") + name;
    }
  }
  catch (const std::exception& e)
  {
    names = e.what();
  }
  return names;
}

std::string WriteOpenFOAMPoints(vtkAlgorithm* deformer, const std::string& outputCase,
  const std::string& time, const std::vector<std::string>& seriesTimes)
{
  vtkNew<vtkDGMFOpenFOAMWriter> writer;
  writer->SetSeriesTimes(seriesTimes);
  writer->SetInputConnection(deformer->GetOutputPort());
  writer->SetFileName(outputCase.c_str());
  writer->SetTimeDirectory(time.c_str());
  return writer->Write() ? writer->GetLastWrittenFile() : std::string();
}
} // namespace dgmf_cli
