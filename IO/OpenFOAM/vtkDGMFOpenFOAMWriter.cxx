#include "vtkDGMFOpenFOAMWriter.h"

#include "dgmf/openfoam/CaseDirectory.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkOpenFOAMReader.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <set>
#include <vector>

vtkStandardNewMacro(vtkDGMFOpenFOAMWriter);

namespace
{
/// The block named internalMesh of a composite dataset, else its first unstructured grid; or the
/// point set itself.
vtkPointSet* InternalMeshOf(vtkDataObject* data)
{
  if (auto* points = vtkPointSet::SafeDownCast(data))
  {
    return points;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return nullptr;
  }
  vtkPointSet* first = nullptr;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* grid = vtkUnstructuredGrid::SafeDownCast(it->GetCurrentDataObject());
    if (!grid)
    {
      continue;
    }
    vtkInformation* meta = it->HasCurrentMetaData() ? it->GetCurrentMetaData() : nullptr;
    if (meta && meta->Has(vtkCompositeDataSet::NAME()) &&
      std::string(meta->Get(vtkCompositeDataSet::NAME())) == "internalMesh")
    {
      return grid;
    }
    first = first ? first : grid;
  }
  return first;
}

/// The first OpenFOAM reader upstream of `algorithm`'s inputs (breadth first), or null.
vtkOpenFOAMReader* FindUpstreamReader(vtkAlgorithm* algorithm)
{
  std::vector<vtkAlgorithm*> queue{ algorithm };
  std::set<vtkAlgorithm*> seen{ algorithm };
  for (std::size_t k = 0; k < queue.size(); ++k)
  {
    if (auto* reader = vtkOpenFOAMReader::SafeDownCast(queue[k]))
    {
      return reader;
    }
    for (int port = 0; port < queue[k]->GetNumberOfInputPorts(); ++port)
    {
      for (int c = 0; c < queue[k]->GetNumberOfInputConnections(port); ++c)
      {
        vtkAlgorithm* upstream = queue[k]->GetInputAlgorithm(port, c);
        if (upstream && seen.insert(upstream).second)
        {
          queue.push_back(upstream);
        }
      }
    }
  }
  return nullptr;
}

/// The points of `mesh` as doubles.
std::vector<double> PointsOf(vtkPointSet* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    mesh->GetPoint(i, xyz.data() + 3 * i);
  }
  return xyz;
}
} // namespace

vtkDGMFOpenFOAMWriter::vtkDGMFOpenFOAMWriter()
{
  this->SetNumberOfInputPorts(2);
  this->SetTimeDirectory("constant");
}

vtkDGMFOpenFOAMWriter::~vtkDGMFOpenFOAMWriter()
{
  this->SetFileName(nullptr);
  this->SetSourceCase(nullptr);
  this->SetTimeDirectory(nullptr);
}

void vtkDGMFOpenFOAMWriter::SetReferenceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkDGMFOpenFOAMWriter::SetReferenceData(vtkDataObject* reference)
{
  this->SetInputData(1, reference);
}

int vtkDGMFOpenFOAMWriter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkDGMFOpenFOAMWriter::WriteData()
{
  namespace fs = std::filesystem;
  namespace of = dgmf::openfoam;
  this->LastWrittenFile.clear();
  const auto fail = [this](const std::string& message)
  {
    vtkErrorMacro(<< message);
    this->SetErrorCode(vtkErrorCode::UserError);
  };
  if (!this->FileName || !*this->FileName)
  {
    fail("No FileName: give the case to write (a directory, or a .foam file in it).");
    return;
  }
  vtkPointSet* deformed = InternalMeshOf(this->GetInput(0));
  if (!deformed)
  {
    fail("The input has no unstructured grid (the OpenFOAM reader's internalMesh).");
    return;
  }
  vtkOpenFOAMReader* reader = FindUpstreamReader(this);
  vtkDataObject* referenceData = this->GetNumberOfInputConnections(1) > 0
    ? this->GetInput(1)
    : (reader ? reader->GetOutputDataObject(0) : nullptr);
  vtkPointSet* reference = InternalMeshOf(referenceData);
  std::string source = this->SourceCase ? this->SourceCase : "";
  if (source.empty() && reader && reader->GetFileName())
  {
    source = reader->GetFileName();
  }
  if (!reference || source.empty())
  {
    fail("No undeformed mesh or no source case: read the case with an OpenFOAM reader upstream, "
         "or set SourceCase and connect the Reference input (the mesh as read).");
    return;
  }
  if (reference->GetNumberOfPoints() != deformed->GetNumberOfPoints())
  {
    fail("The input has " + std::to_string(deformed->GetNumberOfPoints()) +
      " points and the undeformed mesh " + std::to_string(reference->GetNumberOfPoints()) +
      ": they must be the same mesh.");
    return;
  }
  const fs::path target(this->FileName);
  try
  {
    const std::vector<double> before = PointsOf(reference), after = PointsOf(deformed);
    const fs::path caseDirectory = of::CaseDirectoryOf(target);
    this->LastWrittenFile = of::WriteDeformedPoints(of::CaseDirectoryOf(fs::path(source)),
      caseDirectory, this->TimeDirectory ? this->TimeDirectory : "constant", before.data(),
      after.data(), static_cast<std::size_t>(deformed->GetNumberOfPoints()))
                              .string();
    if (target != caseDirectory && !fs::exists(target))
    {
      std::ofstream(target.string()).flush(); // the empty file ParaView opens a case with
    }
  }
  catch (const std::bad_alloc&)
  {
    fail("Out of memory while writing the points; nothing was written.");
  }
  catch (const std::exception& e)
  {
    fail(e.what());
  }
}

void vtkDGMFOpenFOAMWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SourceCase: "
     << (this->SourceCase && *this->SourceCase ? this->SourceCase : "(the reader's)") << "\n";
  os << indent << "TimeDirectory: " << (this->TimeDirectory ? this->TimeDirectory : "") << "\n";
}
