#include "DGMFInputNodes.h"

#include "DGMFSlipFitting.h"

#include "DGMFBoundaryNodes.h"
#include "DGMFMeshConversion.h"
#include "DGMFSMPTools.h"
#include "dgmf/Finite.h"
#include "dgmf/HugePages.h"

#include "vtkAlgorithm.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellTypes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <iterator>
#include <stdexcept>
#include <unordered_map>

namespace dgmf_vtk
{
namespace
{
/// True when `input` (a data set, or a leaf of a composite one) has the point array `name` with
/// `components` components.
bool HasPointArray(vtkDataObject* input, const char* name, int components)
{
  const auto has = [&](vtkDataObject* object)
  {
    auto* set = vtkDataSet::SafeDownCast(object);
    vtkDataArray* array = set ? set->GetPointData()->GetArray(name) : nullptr;
    return array && array->GetNumberOfComponents() == components;
  };
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto iterator = vtk::TakeSmartPointer(composite->NewIterator());
    for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
    {
      if (has(iterator->GetCurrentDataObject()))
      {
        return true;
      }
    }
    return false;
  }
  return input && has(input);
}

/// The array selected at `index` ("" for None); `defaultName` when none was ever selected (C++
/// without SetInputArrayToProcess) and `input` has a point array of that name with `components`.
std::string SelectedArrayName(vtkAlgorithm* algorithm, int index, vtkDataObject* input = nullptr,
  const char* defaultName = nullptr, int components = 0)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(index);
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    const char* name = info->Get(vtkDataObject::FIELD_NAME());
    const std::string selected = name ? name : "";
    return selected == "None" ? std::string() : selected;
  }
  return defaultName && HasPointArray(input, defaultName, components) ? defaultName : "";
}

/// The point array `name` of `mesh` with `components` components (what it is, in `what`).
vtkDataArray* FindPointArray(
  vtkUnstructuredGrid* mesh, const std::string& name, int components, const std::string& what)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name.c_str());
  if (!array && mesh->GetPointData()->GetAbstractArray(name.c_str()))
  {
    throw std::invalid_argument("The " + what + " array '" + name + "' is a point array of " +
      mesh->GetPointData()->GetAbstractArray(name.c_str())->GetDataTypeAsString() +
      " values, not of numbers.");
  }
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
  // A malformed input (pipelines check this, hand-made grids may not): its values per node are
  // read by index.
  if (array->GetNumberOfTuples() != mesh->GetNumberOfPoints())
  {
    throw std::invalid_argument("The " + what + " array '" + name + "' has " +
      std::to_string(array->GetNumberOfTuples()) + " tuples; the mesh has " +
      std::to_string(mesh->GetNumberOfPoints()) + " points.");
  }
  return array;
}

/// dgmf::MarkerToNodeKinds over any array type (vtkArrayDispatch: no virtual call per value).
struct MarkerToKinds
{
  /// Nodes per block of the conversion on the threads.
  static constexpr vtkIdType Block = 1 << 16;

  /// The blocks' conversions on the threads; the error of the first block that has one (its
  /// first bad value, so the first of all), whatever the threads.
  template <typename ArrayType>
  void operator()(ArrayType* array, dgmf::NodeKind* kinds) const
  {
    const vtkIdType n = array->GetNumberOfTuples();
    const auto blocks = static_cast<std::size_t>((n + Block - 1) / Block);
    std::vector<std::exception_ptr> failures(blocks);
    dgmf::ForEachBlock(MakeSMPParallelFor(), blocks,
      [&](std::size_t block)
      {
        const vtkIdType begin = static_cast<vtkIdType>(block) * Block;
        try
        {
          dgmf::MarkerToNodeKinds(
            vtk::DataArrayValueRange<1>(array, begin, std::min(n, begin + Block)), kinds + begin,
            static_cast<std::size_t>(begin));
        }
        catch (...)
        {
          failures[block] = std::current_exception();
        }
      });
    for (const std::exception_ptr& failure : failures)
    {
      if (failure)
      {
        std::rethrow_exception(failure);
      }
    }
  }
};
} // namespace

bool PatchesKey::Matches(vtkUnstructuredGrid* patches)
{
  if (!patches || this->None)
  {
    return this->Valid && !patches && this->None;
  }
  return this->Cells.Matches(patches->GetCells(), [patches]() { return HashCells(patches); });
}

void PatchesKey::Set(vtkUnstructuredGrid* patches)
{
  this->Valid = true;
  this->None = patches == nullptr;
  if (patches)
  {
    this->Cells.Set(patches->GetCells(), [patches]() { return HashCells(patches); });
  }
}

SelectedArrays GetSelectedArrays(vtkAlgorithm* algorithm, vtkDataObject* input)
{
  SelectedArrays arrays;
  arrays.Displacement =
    SelectedArrayName(algorithm, DisplacementArrayIndex, input, "Displacement", 3);
  arrays.Marker = SelectedArrayName(algorithm, MarkerArrayIndex, input, "BoundaryMarker", 1);
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
  problem.Slip = this->Slip;
  problem.FitDistinctPositions = this->Distributed;
  return problem;
}

void InputGatherer::Gather(
  vtkUnstructuredGrid* mesh, const GatherOptions& options, InputNodes& nodes)
{
  this->Deferred.clear();
  const SelectedArrays& arrays = options.Arrays;
  const auto n = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  if (n == 0 && options.Distributed)
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
  nodes.Patches = options.Patches;
  this->Searched = false;
  this->DistinctPoints = options.DistinctPoints;
  nodes.Points = PointsAsDouble(mesh->GetPoints(), nodes.PointCopy);
  if (options.Distributed && dgmf::FirstOutOfRange(nodes.Points, 3 * n) < 3 * n)
  {
    // Said by the piece that has it, with its own point number (once the pieces' boundary nodes
    // are exchanged, another process would say it of a number its piece does not have).
    throw std::invalid_argument(
      dgmf::OutOfRangePointsMessage(dgmf::FirstOutOfRange(nodes.Points, 3 * n)));
  }
  nodes.Dimension =
    options.Dimension != 0 ? options.Dimension : DetectDimension(mesh, nodes.Points, n);
  if (nodes.Dimension < 0)
  {
    vtkUnsignedCharArray* types = mesh->GetDistinctCellTypesArray();
    bool surfaceCells = false;
    for (vtkIdType t = 0; types && t < types->GetNumberOfValues(); ++t)
    {
      surfaceCells = surfaceCells || vtkCellTypes::GetDimension(types->GetValue(t)) == 2;
    }
    if (!surfaceCells)
    {
      throw std::invalid_argument("The mesh has no 2D or 3D cell (only lines or vertices): there "
                                  "is no area or volume to deform.");
    }
    throw std::invalid_argument(
      "The mesh has no 3D cell but its points do not all have the same z: 2D meshes must lie in a "
      "plane z = constant (up to 1e-6 of their extent in x and y). Turn a mesh in another plane "
      "into one (ParaView's Transform filter); a surface mesh (polygons on a curved or closed "
      "surface) is no volume to deform.");
  }
  if (nodes.Dimension == 3 && options.OneCellThick != OneCellThickOff && !options.Distributed)
  {
    // Named boundaries found the planes already, on the same points.
    if (options.Roles)
    {
      nodes.Layers = options.Roles->Layers;
    }
    else
    {
      const auto hash = [&]() { return HashBytes(nodes.Points, 3 * n * sizeof(double)); };
      if (!this->LayerPoints.Matches(mesh->GetPoints()->GetData(), hash))
      {
        this->Layers = dgmf::FindExtrudedLayers(nodes.Points, n, MakeSMPParallelFor());
        // No layers (a volume mesh): kept for the same points object only, as finding that again
        // costs one streaming pass, about what a hash of the points would.
        if (this->Layers.Found())
        {
          this->LayerPoints.Set(mesh->GetPoints()->GetData(), hash);
        }
        else
        {
          this->LayerPoints.SetObjectOnly(mesh->GetPoints()->GetData());
        }
      }
      nodes.Layers = this->Layers;
    }
  }
  if (options.OneCellThick == OneCellThickOn && !nodes.Layers.Found())
  {
    throw std::invalid_argument(
      "The one-cell-thick mode is On, but the mesh is not one cell thick: its nodes do not lie on "
      "two planes normal to x, y or z, in pairs with the same other coordinates" +
      std::string(options.Distributed ? " (or the run is distributed)." : "."));
  }
  vtkDataArray* displacement = arrays.Displacement.empty()
    ? nullptr
    : FindPointArray(mesh, arrays.Displacement, 3, "displacement");
  vtkDataArray* marker = arrays.Marker.empty() || options.Roles
    ? nullptr
    : FindPointArray(mesh, arrays.Marker, 1, "boundary-marker");
  if (!displacement && !marker && !options.Roles)
  {
    throw std::invalid_argument(
      "Select a boundary-marker array (0 = interior, 1 = static, 2 = moving, 3 = slip), a "
      "displacement array (boundary nodes with a non-zero displacement move), or the moving "
      "boundaries by name.");
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
  this->GatherKinds(mesh, options, marker, nodes);
  if (options.Roles)
  {
    nodes.Warnings.insert(
      nodes.Warnings.end(), options.Roles->Warnings.begin(), options.Roles->Warnings.end());
    nodes.BodyIds = options.Roles->BodyIds;
    nodes.NumberOfBodies =
      nodes.BodyIds.empty() ? 0 : *std::max_element(nodes.BodyIds.begin(), nodes.BodyIds.end());
  }
  else if (!arrays.BodyIds.empty())
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
  this->GatherSlipPlanes(options, nodes);
}

void InputGatherer::GatherSlipPlanes(const GatherOptions& options, InputNodes& nodes)
{
  std::vector<std::vector<std::int32_t>> groups;
  std::vector<std::string> names;
  if (options.Roles)
  {
    groups = options.Roles->SlipNodes;
    names = options.Roles->SlipNames;
  }
  else
  {
    // The marker's value 3: one plane. Most meshes have none: a byte search says so at once.
    const dgmf::NodeKind slip = dgmf::NodeKind::SlipBoundary;
    static_assert(sizeof(dgmf::NodeKind) == 1, "node kinds are bytes");
    unsigned char slipByte;
    std::memcpy(&slipByte, &slip, 1);
    const bool any = nodes.NumberOfNodes > 0 &&
      std::memchr(nodes.Kinds.data(), slipByte, nodes.NumberOfNodes) != nullptr;
    if (!any && !options.Distributed) // (the other pieces of a distributed mesh may have some)
    {
      return;
    }
    groups.resize(1);
    names.push_back("boundary-marker value 3");
    for (std::size_t i = 0; any && i < nodes.NumberOfNodes; ++i)
    {
      if (nodes.Kinds[i] == dgmf::NodeKind::SlipBoundary)
      {
        groups[0].push_back(static_cast<std::int32_t>(i));
      }
    }
  }
  if (options.Distributed)
  {
    // Fitted to the nodes of every piece once they have met (AgreeOnSlipPlanes): a piece may
    // hold too few of a plane's nodes, or noisy ones, to fit it alone.
    nodes.SlipGroups = std::move(groups);
    nodes.SlipNames = std::move(names);
    return;
  }
  FitSlipPlanes(groups, names, options.Roles, nodes);
}

std::vector<std::function<void()>> InputGatherer::TakeDeferredJobs()
{
  std::vector<std::function<void()>> jobs;
  jobs.swap(this->Deferred);
  return jobs;
}

void InputGatherer::GatherKinds(
  vtkUnstructuredGrid* mesh, const GatherOptions& options, vtkDataArray* marker, InputNodes& nodes)
{
  const std::size_t n = nodes.NumberOfNodes;
  if (options.Roles)
  {
    dgmf::AssignOnHugePages(nodes.Kinds, options.Roles->Kinds.begin(), options.Roles->Kinds.end());
    // The mesh's own boundary where no block was read (a reader asked for the moving patch only)
    // is static: it must not follow the body. Pieces of a distributed mesh need ghost cells.
    if ((!options.Distributed || mesh->GetCellGhostArray()) &&
      !this->RolesCoverTheBoundary(mesh, nodes))
    {
      const std::vector<std::uint8_t> flags = this->FlagMeshBoundary(mesh, nodes);
      std::vector<std::uint8_t> unread(n, 0); // on the boundary no block was read for
      for (std::size_t i = 0; i < n; ++i)
      {
        if (flags[i] && nodes.Kinds[i] == dgmf::NodeKind::Interior)
        {
          nodes.Kinds[i] = dgmf::NodeKind::StaticBoundary;
          unread[i] = 1;
        }
      }
      this->MakeSlipEdgesStatic(mesh, unread, nodes);
    }
    return;
  }
  // 8 MB at 8M nodes, three times (the kinds, the marker's kept copy, the mapping's). The marker
  // is converted on the threads into the kept copy, whose storage (whole huge pages, not
  // zero-filled: UninitializedVector) stays while the marker does; the nodes' kinds are a copy
  // of it (new storage on huge pages: each 4 KiB fault is costly on a virtual machine,
  // HugePages.h).
  if (marker &&
    !(this->Marker == marker && this->MarkerMTime == marker->GetMTime() &&
      !DistrustedObjects::Active() && this->MarkerKinds.size() == n))
  {
    this->Marker = nullptr;      // until the conversion succeeds
    this->MarkerKinds.resize(n); // every kind written by the conversion
    try
    {
      MarkerToKinds worker;
      if (!vtkArrayDispatch::Dispatch::Execute(marker, worker, this->MarkerKinds.data()))
      {
        worker(marker, this->MarkerKinds.data()); // an array type outside the dispatch list
      }
    }
    catch (const std::invalid_argument& e)
    {
      throw std::invalid_argument(
        "The boundary-marker array '" + options.Arrays.Marker + "' " + e.what());
    }
    this->Marker = marker;
    this->MarkerMTime = marker->GetMTime();
  }
  if (marker)
  {
    dgmf::AssignOnHugePages(nodes.Kinds, this->MarkerKinds.begin(), this->MarkerKinds.end());
    return;
  }
  dgmf::AssignOnHugePages(nodes.Kinds, n, dgmf::NodeKind::Interior);
  // No marker: the nodes of the mesh's boundary, moving where their displacement is non-zero.
  if (options.Distributed && !mesh->GetCellGhostArray())
  {
    throw std::invalid_argument(
      "In a distributed run without a boundary-marker array, the pieces need ghost "
      "cells (e.g. ParaView's Ghost Cells Generator), or the faces between pieces "
      "would be taken for the mesh's boundary. Add ghost cells or select a marker.");
  }
  const std::vector<std::uint8_t> flags = this->FlagMeshBoundary(mesh, nodes);
  std::size_t boundary = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (flags[i])
    {
      ++boundary;
      const double* d = nodes.Displacement + 3 * i;
      nodes.Kinds[i] = (d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0) ? dgmf::NodeKind::MovingBoundary
                                                                   : dgmf::NodeKind::StaticBoundary;
    }
  }
  if (boundary == n)
  {
    nodes.Warnings.push_back("Every node of the mesh lies on its boundary, so every node is a "
                             "boundary node and none can follow the motion. Select a "
                             "boundary-marker array or the boundaries by name.");
  }
}

std::size_t InputGatherer::GetMemorySize() const
{
  std::size_t bytes = this->MarkerKinds.capacity() * sizeof(dgmf::NodeKind);
  if (this->Facets)
  {
    bytes += (this->Facets->Offsets.capacity() + this->Facets->Ids.capacity()) * sizeof(vtkIdType);
  }
  bytes += this->ClosingPolygons.capacity() * sizeof(vtkIdType);
  bytes += (this->Layers.Front.capacity() + this->Layers.Layer.capacity()) * sizeof(std::int32_t);
  return bytes;
}

} // namespace dgmf_vtk
