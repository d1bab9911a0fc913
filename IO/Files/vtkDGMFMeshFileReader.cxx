#include "vtkDGMFMeshFileReader.h"

#include "DGMFNamedMeshBlocks.h"

#include "dgmf/meshfile/MeshFileFormat.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"

#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkDGMFMeshFileReader);

vtkDGMFMeshFileReader::vtkDGMFMeshFileReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkDGMFMeshFileReader::~vtkDGMFMeshFileReader()
{
  this->SetFileName(nullptr);
}

bool vtkDGMFMeshFileReader::CanReadFileName(const char* fileName)
{
  return dgmf::meshfile::FormatOfFileName(fileName ? fileName : "") !=
    dgmf::meshfile::MeshFileFormat::None;
}

int vtkDGMFMeshFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  const std::string name = this->FileName ? this->FileName : "";
  if (!CanReadFileName(name.c_str()))
  {
    vtkErrorMacro("Cannot read '" << name
                                  << "': give a gmsh .msh, SU2 .su2, Exodus II .exo/.e/.ex2 or "
                                     "CGNS .cgns file.");
    return 0;
  }
  try
  {
    const dgmf::meshfile::NamedMesh mesh = dgmf::meshfile::ReadMeshFile(name);
    output->ShallowCopy(dgmf_vtk::ToBlocks(mesh));
    return 1;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory while reading " << name << ".");
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
  }
  output->Initialize();
  return 0;
}

void vtkDGMFMeshFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
