#include "vtkDGMFMeshFileWriter.h"

#include "DGMFWriterInputs.h"
#include "vtkDGMFMeshFileReader.h"

#include "dgmf/meshfile/MeshFileFormat.h"
#include "dgmf/meshfile/NamedMesh.h"

#include "vtkDataObject.h"
#include "vtkErrorCode.h"
#include "vtkExodusIIReader.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
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
  auto* reader = dgmf_vtk::FindUpstream<vtkDGMFMeshFileReader>(this);
  // ParaView's own Exodus reader upstream instead: its points are placed by node id.
  auto* exodusReader = reader ? nullptr : dgmf_vtk::FindUpstream<vtkExodusIIReader>(this);
  if (source.empty())
  {
    source = reader && reader->GetFileName()        ? reader->GetFileName()
      : exodusReader && exodusReader->GetFileName() ? exodusReader->GetFileName()
                                                    : "";
  }
  if (target.empty() || !vtkDGMFMeshFileReader::CanReadFileName(target.c_str()))
  {
    fail("FileName must end in .msh, .su2, .exo, .e, .ex2 or .cgns (got '" + target + "').");
    return;
  }
  if (source.empty())
  {
    fail("No source file: read the mesh with vtkDGMFMeshFileReader (or an Exodus file with "
         "vtkExodusIIReader) upstream, or set SourceFileName.");
    return;
  }
  vtkPointSet* nodes = dgmf_vtk::InternalMeshOf(this->GetInput());
  if (!reader && !(nodes && nodes->GetPointData()->GetArray("FileNodeId")))
  {
    this->WriteByNodeId(source, target);
    return;
  }
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

void vtkDGMFMeshFileWriter::WriteByNodeId(const std::string& source, const std::string& target)
{
  try
  {
    // Every node of the source at its own position, then the input's points by their ids: the
    // nodes no block holds keep their coordinates.
    const dgmf::meshfile::NamedMesh mesh = dgmf::meshfile::ReadMeshFile(source);
    std::vector<double> points = mesh.Points;
    long long placed = 0;
    const char* ids = nullptr;
    for (const char* name : { "GlobalNodeId", "ids" })
    {
      ids = name;
      placed = dgmf_vtk::PlacePointsByNodeId(this->GetInput(), ids, mesh.NodeIds, points);
      if (placed != 0)
      {
        break;
      }
    }
    // The undeformed mesh, the output of the reader (the first algorithm upstream without
    // inputs), when it has the same ids: the file gets its own coordinates plus the displacement,
    // so that nodes that did not move keep every bit even when the reader gave single precision
    // (ExodusIIReader).
    vtkAlgorithm* origin = dgmf_vtk::FindUpstreamIf(
      this, [](vtkAlgorithm* a) { return a->GetNumberOfInputPorts() == 0; });
    vtkDataObject* undeformed = origin ? origin->GetOutputDataObject(0) : nullptr;
    std::vector<double> before = mesh.Points;
    if (placed > 0 && undeformed &&
      dgmf_vtk::PlacePointsByNodeId(undeformed, ids, mesh.NodeIds, before) == placed)
    {
      for (std::size_t k = 0; k < points.size(); ++k)
      {
        points[k] =
          points[k] == before[k] ? mesh.Points[k] : mesh.Points[k] + (points[k] - before[k]);
      }
    }
    if (placed <= 0)
    {
      vtkErrorMacro(<< "The input's points cannot be matched to the nodes of " << source
                    << (placed < 0 ? ": a node id is not in the file."
                                   : ": no GlobalNodeId or ids point array (read the file with "
                                     "the DGMF Mesh File Reader, or ParaView's Exodus reader).")
                    << " Nothing was written.");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    dgmf::meshfile::WriteMeshFileWithPoints(source, target, points.data(), mesh.NumberOfNodes());
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "Out of memory while writing " << target << "; nothing was written.");
    this->SetErrorCode(vtkErrorCode::UserError);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    this->SetErrorCode(vtkErrorCode::UserError);
  }
}

void vtkDGMFMeshFileWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SourceFileName: " << (this->SourceFileName ? this->SourceFileName : "(upstream)")
     << "\n";
}
