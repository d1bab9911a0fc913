#include "DGMFCommandData.h"

#include "vtkDGMFOpenFOAMWriter.h"

#include "dgmf/openfoam/CaseDirectory.h"

#include "vtkAlgorithmOutput.h"
#include "vtkNew.h"
#include "vtkOpenFOAMReader.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <filesystem>
#include <iostream>

namespace dgmf_cli
{
namespace fs = std::filesystem;

namespace
{
bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool IsFoamFile(const std::string& path)
{
  return EndsWith(path, ".foam") || EndsWith(path, ".OpenFOAM");
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
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

bool WriteMeshFile(vtkUnstructuredGrid* mesh, const std::string& path)
{
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(mesh);
  writer->SetDataModeToBinary(); // inline binary: appended mode breaks with Debian 12's expat
  return writer->Write() != 0;
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
  reader->Update();
  if (reader->GetNumberOfPatchArrays() == 0 || !reader->GetOutputDataObject(0))
  {
    std::cerr << "dgmf-deform: could not read an OpenFOAM mesh from " << path << "\n";
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

std::string WriteOpenFOAMPoints(
  vtkAlgorithm* deformer, const std::string& outputCase, const std::string& time)
{
  vtkNew<vtkDGMFOpenFOAMWriter> writer;
  writer->SetInputConnection(deformer->GetOutputPort());
  writer->SetFileName(outputCase.c_str());
  writer->SetTimeDirectory(time.c_str());
  return writer->Write() ? writer->GetLastWrittenFile() : std::string();
}
} // namespace dgmf_cli
