#include "DGMFCompositeMesh.h"

#include "DGMFArrayAllocation.h"

#include "dgmf/ResultNames.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cstring>
#include <map>
#include <string>
#include <unordered_map>

namespace dgmf_vtk
{
namespace
{
/// Exact coordinates as a hashable key.
struct CoordinateKey
{
  std::array<std::uint64_t, 3> Bits;
  bool operator==(const CoordinateKey& other) const { return this->Bits == other.Bits; }
};

struct CoordinateHash
{
  std::size_t operator()(const CoordinateKey& key) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint64_t b : key.Bits)
    {
      h = (h ^ b) * 1099511628211ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
};

CoordinateKey KeyOf(const double p[3])
{
  CoordinateKey key;
  for (int c = 0; c < 3; ++c)
  {
    const double value = p[c] == 0.0 ? 0.0 : p[c]; // -0 and +0 are the same node
    std::memcpy(&key.Bits[c], &value, sizeof(double));
  }
  return key;
}
/**
 * The names of the partitions of a partitioned data set collection (ParaView's IOSS reader gives
 * one for Exodus files): each partition is named after its partitioned data set. Empty for other
 * composite data.
 */
std::map<unsigned int, std::string> PartitionNames(vtkCompositeDataSet* input)
{
  std::map<unsigned int, std::string> names;
  auto* collection = vtkPartitionedDataSetCollection::SafeDownCast(input);
  if (!collection)
  {
    return names;
  }
  vtkNew<vtkDataObjectTreeIterator> iterator;
  iterator->SetDataSet(collection);
  iterator->VisitOnlyLeavesOff();
  iterator->TraverseSubTreeOn();
  iterator->SkipEmptyNodesOn();
  std::string current;
  for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
  {
    vtkDataObject* node = iterator->GetCurrentDataObject();
    vtkInformation* metaData =
      iterator->HasCurrentMetaData() ? iterator->GetCurrentMetaData() : nullptr;
    if (vtkPartitionedDataSet::SafeDownCast(node))
    {
      current = metaData && metaData->Has(vtkCompositeDataSet::NAME())
        ? metaData->Get(vtkCompositeDataSet::NAME())
        : "";
    }
    else if (vtkDataSet::SafeDownCast(node) && !current.empty())
    {
      names[iterator->GetCurrentFlatIndex()] = current;
    }
  }
  return names;
}
/// The tuples `nodeOf[i]` of `values`, in a new array of the same type and name.
vtkSmartPointer<vtkDataArray> Gathered(vtkDataArray* values, const std::vector<vtkIdType>& nodeOf)
{
  vtkSmartPointer<vtkDataArray> gathered = vtk::TakeSmartPointer(values->NewInstance());
  gathered->SetName(values->GetName());
  gathered->SetNumberOfComponents(values->GetNumberOfComponents());
  const auto n = static_cast<vtkIdType>(nodeOf.size());
  AllocateTuples(gathered, n);
  auto* from = vtkDoubleArray::SafeDownCast(values);
  auto* to = vtkDoubleArray::SafeDownCast(gathered);
  if (from && to) // the deformed points and the filter's arrays
  {
    const int m = values->GetNumberOfComponents();
    const double* source = from->GetPointer(0);
    double* target = to->GetPointer(0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      std::memcpy(target + m * i, source + m * nodeOf[static_cast<std::size_t>(i)],
        static_cast<std::size_t>(m) * sizeof(double));
    }
    return gathered;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    gathered->SetTuple(i, nodeOf[static_cast<std::size_t>(i)], values);
  }
  return gathered;
}

/// The tuples [first, first + count) of `values`, in a new array of the same type and name.
vtkSmartPointer<vtkDataArray> Range(vtkDataArray* values, vtkIdType first, vtkIdType count)
{
  vtkSmartPointer<vtkDataArray> range = vtk::TakeSmartPointer(values->NewInstance());
  range->SetName(values->GetName());
  range->SetNumberOfComponents(values->GetNumberOfComponents());
  AllocateTuples(range, count);
  range->InsertTuples(0, count, first, values);
  return range;
}
} // namespace

CompositeMesh::CompositeMesh(
  vtkCompositeDataSet* input, const std::string& displacementName, const std::string& markerName)
  : Input(input)
  , Merged(vtkSmartPointer<vtkUnstructuredGrid>::New())
{
  // The merge grows VTK arrays one insertion at a time, and VTK aborts when that fails: make sure
  // first that twice what it may need is there (points, their hash, the arrays, the cells).
  const auto blockPoints = static_cast<std::size_t>(input->GetNumberOfPoints());
  const auto blockCells = static_cast<std::size_t>(input->GetNumberOfCells());
  EnsureAvailableMemory(2 * (blockPoints * (24 + 64 + 24 * 2) + blockCells * 8 * 10));
  std::vector<std::string> arrays;
  for (const std::string& name : { displacementName, markerName })
  {
    if (!name.empty())
    {
      arrays.push_back(name);
    }
  }
  std::unordered_map<CoordinateKey, vtkIdType, CoordinateHash> nodeAt;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<vtkSmartPointer<vtkDoubleArray>> merged(arrays.size());
  vtkNew<vtkIdList> cellPoints;
  this->Merged->Allocate(1024);

  const std::map<unsigned int, std::string> partitionNames = PartitionNames(input);
  auto iterator = vtk::TakeSmartPointer(input->NewIterator());
  iterator->SkipEmptyNodesOn();
  for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
  {
    auto* block = vtkPointSet::SafeDownCast(iterator->GetCurrentDataObject());
    if (!block)
    {
      ++this->Skipped;
      continue;
    }
    Leaf leaf;
    leaf.FlatIndex = iterator->GetCurrentFlatIndex();
    leaf.CellDimension = 0;
    vtkInformation* metaData =
      iterator->HasCurrentMetaData() ? iterator->GetCurrentMetaData() : nullptr;
    leaf.Name = metaData && metaData->Has(vtkCompositeDataSet::NAME())
      ? metaData->Get(vtkCompositeDataSet::NAME())
      : "";
    const auto partition = partitionNames.find(leaf.FlatIndex);
    if (leaf.Name.empty() && partition != partitionNames.end())
    {
      leaf.Name = partition->second; // a partition of a named partitioned data set (IOSS reader)
    }
    leaf.NodeOf.resize(static_cast<std::size_t>(block->GetNumberOfPoints()));
    std::vector<vtkDataArray*> sources(arrays.size());
    for (std::size_t a = 0; a < arrays.size(); ++a)
    {
      sources[a] = block->GetPointData()->GetArray(arrays[a].c_str());
    }
    for (vtkIdType i = 0; i < block->GetNumberOfPoints(); ++i)
    {
      double p[3];
      block->GetPoint(i, p);
      auto found = nodeAt.emplace(KeyOf(p), points->GetNumberOfPoints());
      if (found.second)
      {
        points->InsertNextPoint(p);
      }
      const vtkIdType node = found.first->second;
      leaf.NodeOf[static_cast<std::size_t>(i)] = node;
      for (std::size_t a = 0; a < arrays.size(); ++a)
      {
        vtkDataArray* source = sources[a];
        if (!merged[a])
        {
          // Sized by the first block that has the array; later blocks define it too.
          if (!source)
          {
            continue;
          }
          merged[a] = vtkSmartPointer<vtkDoubleArray>::New();
          merged[a]->SetName(arrays[a].c_str());
          merged[a]->SetNumberOfComponents(source->GetNumberOfComponents());
        }
        vtkDoubleArray* target = merged[a];
        const int components = target->GetNumberOfComponents();
        while (target->GetNumberOfTuples() <= node)
        {
          const std::vector<double> zeros(static_cast<std::size_t>(components), 0.0);
          target->InsertNextTuple(zeros.data());
        }
        if (!source || source->GetNumberOfComponents() != components)
        {
          continue;
        }
        if (arrays[a] == markerName)
        {
          target->SetComponent(
            node, 0, std::max(target->GetComponent(node, 0), source->GetComponent(i, 0)));
        }
        else
        {
          // The first non-zero value found for the node (a block may lack it or hold zeros).
          bool unset = true;
          for (int c = 0; c < components; ++c)
          {
            unset = unset && target->GetComponent(node, c) == 0.0;
          }
          for (int c = 0; unset && c < components; ++c)
          {
            target->SetComponent(node, c, source->GetComponent(i, c));
          }
        }
      }
    }
    leaf.FirstCell = this->Merged->GetNumberOfCells();
    for (vtkIdType c = 0; c < block->GetNumberOfCells(); ++c)
    {
      block->GetCellPoints(c, cellPoints);
      for (vtkIdType k = 0; k < cellPoints->GetNumberOfIds(); ++k)
      {
        cellPoints->SetId(k, leaf.NodeOf[static_cast<std::size_t>(cellPoints->GetId(k))]);
      }
      const int type = block->GetCellType(c);
      leaf.CellDimension =
        std::max(leaf.CellDimension, vtkCellTypes::GetDimension(static_cast<unsigned char>(type)));
      auto* grid = vtkUnstructuredGrid::SafeDownCast(block);
      if (type == VTK_POLYHEDRON && grid)
      {
        // Polyhedra need their faces, renumbered like their points.
        vtkNew<vtkIdList> faces;
        grid->GetFaceStream(c, faces);
        std::vector<vtkIdType> stream(
          faces->GetPointer(0), faces->GetPointer(0) + faces->GetNumberOfIds());
        vtkIdType nfaces = stream.empty() ? 0 : stream[0];
        for (std::size_t k = 1; k < stream.size();)
        {
          const vtkIdType count = stream[k++];
          for (vtkIdType m = 0; m < count; ++m, ++k)
          {
            stream[k] = leaf.NodeOf[static_cast<std::size_t>(stream[k])];
          }
        }
        std::vector<vtkIdType> faceList(stream.begin() + (stream.empty() ? 0 : 1), stream.end());
        this->Merged->InsertNextCell(
          type, cellPoints->GetNumberOfIds(), cellPoints->GetPointer(0), nfaces, faceList.data());
      }
      else
      {
        this->Merged->InsertNextCell(type, cellPoints);
      }
    }
    leaf.Cells = this->Merged->GetNumberOfCells() - leaf.FirstCell;
    leaf.SameNumbering = true;
    for (std::size_t i = 0; i < leaf.NodeOf.size() && leaf.SameNumbering; ++i)
    {
      leaf.SameNumbering = leaf.NodeOf[i] == static_cast<vtkIdType>(i);
    }
    this->Leaves.push_back(std::move(leaf));
  }
  this->Merged->SetPoints(points);
  for (auto& array : merged)
  {
    if (array)
    {
      const int components = array->GetNumberOfComponents();
      const std::vector<double> zeros(static_cast<std::size_t>(components), 0.0);
      while (array->GetNumberOfTuples() < points->GetNumberOfPoints())
      {
        array->InsertNextTuple(zeros.data());
      }
      this->Merged->GetPointData()->AddArray(array);
    }
  }
}

void CompositeMesh::ScatterResult(vtkUnstructuredGrid* deformed, vtkCompositeDataSet* output) const
{
  namespace names = dgmf::names;
  output->Initialize();
  this->Scatter(deformed, { names::R, names::F }, { names::SizeSkew, names::Inverted }, output);
  vtkNew<vtkFieldData> fieldData;
  fieldData->PassData(this->Input->GetFieldData());
  for (int k = 0; k < deformed->GetFieldData()->GetNumberOfArrays(); ++k)
  {
    fieldData->AddArray(deformed->GetFieldData()->GetAbstractArray(k));
  }
  output->SetFieldData(fieldData);
}

void CompositeMesh::Scatter(vtkUnstructuredGrid* deformed,
  const std::vector<std::string>& pointArrays, const std::vector<std::string>& cellArrays,
  vtkCompositeDataSet* output) const
{
  output->CopyStructure(this->Input);
  auto iterator = vtk::TakeSmartPointer(this->Input->NewIterator());
  iterator->SkipEmptyNodesOn();
  std::size_t next = 0;
  for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
  {
    vtkDataObject* block = iterator->GetCurrentDataObject();
    if (next >= this->Leaves.size() ||
      this->Leaves[next].FlatIndex != iterator->GetCurrentFlatIndex())
    {
      output->SetDataSet(iterator, block); // not merged: passed as it is
      continue;
    }
    const Leaf& leaf = this->Leaves[next++];
    auto* source = vtkPointSet::SafeDownCast(block);
    vtkSmartPointer<vtkPointSet> copy = vtk::TakeSmartPointer(source->NewInstance());
    copy->ShallowCopy(source);
    const auto n = static_cast<vtkIdType>(leaf.NodeOf.size());
    // A leaf whose points are the merged grid's, in its order (the volume of a CFD reader's
    // output, as a rule), shares the deformed points and arrays; the others get copies.
    const bool allPoints = leaf.SameNumbering && n == deformed->GetNumberOfPoints();
    const bool allCells = leaf.FirstCell == 0 && leaf.Cells == deformed->GetNumberOfCells();
    if (allPoints)
    {
      copy->SetPoints(deformed->GetPoints());
    }
    else
    {
      vtkNew<vtkPoints> points;
      points->SetData(Gathered(deformed->GetPoints()->GetData(), leaf.NodeOf));
      copy->SetPoints(points);
    }
    for (const std::string& name : pointArrays)
    {
      if (vtkDataArray* result = deformed->GetPointData()->GetArray(name.c_str()))
      {
        copy->GetPointData()->AddArray(allPoints ? result : Gathered(result, leaf.NodeOf).Get());
      }
    }
    for (const std::string& name : cellArrays)
    {
      if (vtkDataArray* result = deformed->GetCellData()->GetArray(name.c_str()))
      {
        copy->GetCellData()->AddArray(
          allCells ? result : Range(result, leaf.FirstCell, leaf.Cells).Get());
      }
    }
    output->SetDataSet(iterator, copy);
  }
}

} // namespace dgmf_vtk
