#include "vtkDGMFMeshFileReader.h"

#include "DGMFNamedMeshBlocks.h"

#include "dgmf/meshfile/GmshFile.h"
#include "dgmf/meshfile/SU2File.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"

#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkDGMFMeshFileReader);

namespace
{
bool EndsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
    text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}
} // namespace

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
  const std::string name = fileName ? fileName : "";
  return EndsWith(name, ".msh") || EndsWith(name, ".su2");
}

int vtkDGMFMeshFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  const std::string name = this->FileName ? this->FileName : "";
  if (!CanReadFileName(name.c_str()))
  {
    vtkErrorMacro("Cannot read '" << name << "': give a gmsh .msh or an SU2 .su2 file.");
    return 0;
  }
  try
  {
    const dgmf::meshfile::NamedMesh mesh =
      EndsWith(name, ".su2") ? dgmf::meshfile::ReadSU2(name) : dgmf::meshfile::ReadGmsh(name);
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
