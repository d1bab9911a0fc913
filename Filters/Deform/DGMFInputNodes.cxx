#include "DGMFInputNodes.h"

#include "DGMFMeshConversion.h"

#include "vtkAlgorithm.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <stdexcept>

namespace dgmf_vtk
{
namespace
{
std::string SelectedArrayName(vtkAlgorithm* algorithm, int index)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(index);
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    const char* name = info->Get(vtkDataObject::FIELD_NAME());
    const std::string selected = name ? name : "";
    return selected == "None" ? std::string() : selected;
  }
  return "";
}

/// The point array `name` of `mesh` with `components` components (what it is, in `what`).
vtkDataArray* FindPointArray(
  vtkUnstructuredGrid* mesh, const std::string& name, int components, const std::string& what)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    throw std::invalid_argument(
      "The " + what + " array '" + name + "' is not a point array of the input.");
  }
  if (array->GetNumberOfComponents() != components)
  {
    throw std::invalid_argument("The " + what + " array '" + name + "' has " +
      std::to_string(array->GetNumberOfComponents()) + " components; it must have " +
      std::to_string(components) + ".");
  }
  return array;
}

/// dgmf::MarkerToNodeKinds over any array type (vtkArrayDispatch: no virtual call per value).
struct MarkerToKinds
{
  template <typename ArrayType>
  void operator()(ArrayType* array, dgmf::NodeKind* kinds) const
  {
    dgmf::MarkerToNodeKinds(vtk::DataArrayValueRange<1>(array), kinds);
  }
};
} // namespace

SelectedArrays GetSelectedArrays(vtkAlgorithm* algorithm)
{
  SelectedArrays arrays;
  arrays.Displacement = SelectedArrayName(algorithm, DisplacementArrayIndex);
  arrays.Marker = SelectedArrayName(algorithm, MarkerArrayIndex);
  arrays.BodyIds = SelectedArrayName(algorithm, BodyIdArrayIndex);
  return arrays;
}

dgmf::DeformationProblem InputNodes::ToProblem() const
{
  dgmf::DeformationProblem problem;
  problem.Dimension = this->Dimension;
  problem.NumberOfNodes = this->NumberOfNodes;
  problem.Points = this->Points;
  problem.Kinds = this->Kinds.data();
  problem.Displacement = this->Displacement;
  problem.BodyIds = this->BodyIds.empty() ? nullptr : this->BodyIds.data();
  problem.NumberOfBodies = this->NumberOfBodies;
  return problem;
}

void InputGatherer::Gather(vtkUnstructuredGrid* mesh, const SelectedArrays& arrays, int dimension,
  bool distributed, InputNodes& nodes)
{
  const auto n = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  if (n == 0 && distributed)
  {
    return; // an empty piece: it still takes part in the exchanges
  }
  if (n == 0 || mesh->GetNumberOfCells() == 0)
  {
    throw std::invalid_argument("The input mesh is empty (" + std::to_string(n) + " points, " +
      std::to_string(mesh->GetNumberOfCells()) + " cells).");
  }
  nodes.NumberOfNodes = n;
  nodes.LocalNodes = n;
  nodes.Points = PointsAsDouble(mesh->GetPoints(), nodes.PointCopy);
  nodes.Dimension = dimension != 0 ? dimension : DetectDimension(mesh, nodes.Points, n);
  if (nodes.Dimension < 0)
  {
    throw std::invalid_argument(
      "The mesh has no 3D cell but its points do not all have the same z: 2D meshes must lie in a "
      "plane z = constant.");
  }
  dimension = nodes.Dimension;
  vtkDataArray* displacement = arrays.Displacement.empty()
    ? nullptr
    : FindPointArray(mesh, arrays.Displacement, 3, "displacement");
  vtkDataArray* marker =
    arrays.Marker.empty() ? nullptr : FindPointArray(mesh, arrays.Marker, 1, "boundary-marker");
  if (!displacement && !marker)
  {
    throw std::invalid_argument(
      "Select a boundary-marker array (0 = interior, 1 = static, 2 = moving) or a "
      "displacement array (boundary nodes with a non-zero displacement move).");
  }
  if (auto* doubles = vtkDoubleArray::SafeDownCast(displacement))
  {
    nodes.Displacement = doubles->GetPointer(0);
  }
  else if (displacement)
  {
    nodes.DisplacementCopy.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      displacement->GetTuple(static_cast<vtkIdType>(i), nodes.DisplacementCopy.data() + 3 * i);
    }
    nodes.Displacement = nodes.DisplacementCopy.data();
  }
  this->GatherKinds(mesh, arrays, marker, dimension, distributed, nodes);
  if (!arrays.BodyIds.empty())
  {
    vtkDataArray* ids = FindPointArray(mesh, arrays.BodyIds, 1, "body-id");
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      values[i] = ids->GetTuple1(static_cast<vtkIdType>(i));
    }
    nodes.BodyIds.resize(n);
    try
    {
      nodes.NumberOfBodies = dgmf::ResolveBodyIds(
        values.data(), n, marker != nullptr, nodes.Kinds.data(), nodes.BodyIds.data());
    }
    catch (const std::invalid_argument& e)
    {
      throw std::invalid_argument("The body-id array '" + arrays.BodyIds + "' " + e.what());
    }
  }
}

void InputGatherer::GatherKinds(vtkUnstructuredGrid* mesh, const SelectedArrays& arrays,
  vtkDataArray* marker, int dimension, bool distributed, InputNodes& nodes)
{
  const std::size_t n = nodes.NumberOfNodes;
  nodes.Kinds.assign(n, dgmf::NodeKind::Interior);
  if (marker && this->Marker == marker && this->MarkerMTime == marker->GetMTime() &&
    this->MarkerKinds.size() == n)
  {
    nodes.Kinds = this->MarkerKinds; // converted and checked before
    return;
  }
  if (marker)
  {
    try
    {
      MarkerToKinds worker;
      if (!vtkArrayDispatch::Dispatch::Execute(marker, worker, nodes.Kinds.data()))
      {
        worker(marker, nodes.Kinds.data()); // an array type outside the dispatch list
      }
    }
    catch (const std::invalid_argument& e)
    {
      throw std::invalid_argument("The boundary-marker array '" + arrays.Marker + "' " + e.what());
    }
    this->Marker = marker;
    this->MarkerMTime = marker->GetMTime();
    this->MarkerKinds = nodes.Kinds;
    return;
  }
  // No marker: the nodes of the mesh's boundary, moving where their displacement is non-zero.
  if (distributed && !mesh->GetCellGhostArray())
  {
    throw std::invalid_argument(
      "In a distributed run without a boundary-marker array, the pieces need ghost "
      "cells (e.g. ParaView's Ghost Cells Generator), or the faces between pieces "
      "would be taken for the mesh's boundary. Add ghost cells or select a marker.");
  }
  const std::vector<std::uint8_t> flags =
    FlagBoundaryNodes(this->GetBoundaryFacets(mesh, dimension), static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i)
  {
    if (flags[i])
    {
      const double* d = nodes.Displacement + 3 * i;
      nodes.Kinds[i] = (d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0) ? dgmf::NodeKind::MovingBoundary
                                                                   : dgmf::NodeKind::StaticBoundary;
    }
  }
}

const BoundaryFacets& InputGatherer::GetBoundaryFacets(vtkUnstructuredGrid* mesh, int dimension)
{
  vtkCellArray* cells = mesh->GetCells();
  auto hashCells = [&]()
  {
    std::uint64_t h = HashArray(cells->GetConnectivityArray());
    h = HashArray(cells->GetOffsetsArray(), h);
    return HashArray(mesh->GetCellTypesArray(), h);
  };
  if (!this->Facets || !this->Cells.Matches(cells, hashCells))
  {
    this->Facets = std::make_unique<BoundaryFacets>(FindBoundaryFacets(mesh, dimension));
    this->Cells.Set(cells, hashCells);
  }
  return *this->Facets;
}

std::size_t InputGatherer::GetMemorySize() const
{
  std::size_t bytes = this->MarkerKinds.capacity() * sizeof(dgmf::NodeKind);
  if (this->Facets)
  {
    bytes += (this->Facets->Offsets.capacity() + this->Facets->Ids.capacity()) * sizeof(vtkIdType);
  }
  return bytes;
}

} // namespace dgmf_vtk
