#include "vtkDGMFMeshFileWriter.h"

#include "DGMFWriterInputs.h"
#include "vtkDGMFMeshFileReader.h"

#include "dgmf/meshfile/MeshFileFormat.h"

#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"

#include <exception>
#include <new>
#include <string>

vtkStandardNewMacro(vtkDGMFMeshFileWriter);

vtkDGMFMeshFileWriter::vtkDGMFMeshFileWriter() = default;

vtkDGMFMeshFileWriter::~vtkDGMFMeshFileWriter()
{
  this->SetFileName(nullptr);
  this->SetSourceFileName(nullptr);
}

int vtkDGMFMeshFileWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

void vtkDGMFMeshFileWriter::WriteData()
{
  const auto fail = [this](const std::string& message)
  {
    vtkErrorMacro(<< message);
    this->SetErrorCode(vtkErrorCode::UserError);
  };
  const std::string target = this->FileName ? this->FileName : "";
  std::string source = this->SourceFileName ? this->SourceFileName : "";
  if (source.empty())
  {
    auto* reader = dgmf_vtk::FindUpstream<vtkDGMFMeshFileReader>(this);
    source = reader && reader->GetFileName() ? reader->GetFileName() : "";
  }
  if (target.empty() || !vtkDGMFMeshFileReader::CanReadFileName(target.c_str()))
  {
    fail("FileName must end in .msh, .su2, .exo, .e, .ex2 or .cgns (got '" + target + "').");
    return;
  }
  if (source.empty())
  {
    fail("No source file: read the mesh with vtkDGMFMeshFileReader upstream, or set "
         "SourceFileName.");
    return;
  }
  vtkPointSet* nodes = dgmf_vtk::InternalMeshOf(this->GetInput());
  if (!nodes)
  {
    fail("The input has no unstructured grid (the reader's internalMesh).");
    return;
  }
  try
  {
    const std::vector<double> points = dgmf_vtk::PointsOf(nodes);
    const std::size_t count = static_cast<std::size_t>(nodes->GetNumberOfPoints());
    // The format checks (one format for source and target) are the library's.
    dgmf::meshfile::WriteMeshFileWithPoints(source, target, points.data(), count);
  }
  catch (const std::bad_alloc&)
  {
    fail("Out of memory while writing " + target + "; nothing was written.");
  }
  catch (const std::exception& e)
  {
    fail(e.what());
  }
}

void vtkDGMFMeshFileWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SourceFileName: " << (this->SourceFileName ? this->SourceFileName : "(upstream)")
     << "\n";
}
