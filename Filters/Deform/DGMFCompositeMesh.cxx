#include "DGMFCompositeMesh.h"

#include "DGMFArrayAllocation.h"
#include "DGMFMergedCells.h"
#include "DGMFMeshConversion.h"
#include "DGMFSMPTools.h"
#include "DGMFTupleAllocation.h"

#include "dgmf/CoincidentPoints.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/ResultNames.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <numeric>
#include <string>

namespace dgmf_vtk
{
namespace
{
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
/**
 * The merged node of every point (NumberNodes): points [0, Prefix) are all first points of
 * their places, each its own node (a CFD reader's volume, as a rule: not stored); the others'
 * nodes in Rest.
 */
struct NodeNumbers
{
  std::size_t Prefix = 0;
  dgmf::UninitializedVector<vtkIdType> Rest;

  vtkIdType NodeOf(std::size_t i) const
  {
    return i < this->Prefix ? static_cast<vtkIdType>(i) : this->Rest[i - this->Prefix];
  }
};

/**
 * The merged node of every point, numbered in the order the nodes are first met, from each
 * point's first coincident point (`first`, FirstCoincidentPoints); `nodes` gets their number. In
 * fixed blocks on the threads: the first points of each block counted, numbered from the counts
 * before, then every other point given its first point's node. The leading points that are all
 * first points are neither read again nor stored.
 */
NodeNumbers NumberNodes(const dgmf::UninitializedVector<std::int64_t>& first, vtkIdType& nodes,
  const dgmf::ParallelFor& parallelFor)
{
  constexpr std::size_t block = std::size_t(1) << 16;
  const std::size_t total = first.size();
  const std::size_t blocks = (total + block - 1) / block;
  const auto isFirst = [&](std::size_t i) { return static_cast<std::size_t>(first[i]) == i; };
  std::vector<vtkIdType> before(blocks + 1, 0);
  dgmf::ForEachBlock(parallelFor, blocks,
    [&](std::size_t b)
    {
      vtkIdType count = 0;
      for (std::size_t i = b * block; i < std::min(total, (b + 1) * block); ++i)
      {
        count += isFirst(i) ? 1 : 0;
      }
      before[b + 1] = count;
    });
  NodeNumbers numbers;
  std::size_t full = 0; // blocks of first points only, from the start
  while (full < blocks &&
    static_cast<std::size_t>(before[full + 1]) ==
      std::min(total, (full + 1) * block) - full * block)
  {
    ++full;
  }
  numbers.Prefix = std::min(total, full * block);
  while (numbers.Prefix < total && isFirst(numbers.Prefix))
  {
    ++numbers.Prefix;
  }
  std::partial_sum(before.begin(), before.end(), before.begin());
  nodes = before.back();
  numbers.Rest = dgmf::UninitializedVector<vtkIdType>(total - numbers.Prefix);
  const std::size_t prefix = numbers.Prefix;
  dgmf::ForEachBlock(parallelFor, blocks - full,
    [&](std::size_t b)
    {
      b += full;
      vtkIdType next = before[b];
      for (std::size_t i = b * block; i < std::min(total, (b + 1) * block); ++i)
      {
        if (isFirst(i))
        {
          if (i >= prefix)
          {
            numbers.Rest[i - prefix] = next;
          }
          ++next;
        }
      }
    });
  dgmf::ForEachBlock(parallelFor, blocks - full,
    [&](std::size_t b)
    {
      b += full;
      for (std::size_t i = std::max(prefix, b * block); i < std::min(total, (b + 1) * block); ++i)
      {
        if (!isFirst(i))
        {
          // A first point, numbered above.
          numbers.Rest[i - prefix] = numbers.NodeOf(static_cast<std::size_t>(first[i]));
        }
      }
    });
  return numbers;
}

/// The tuples of `values` at the leaf's nodes (leaf.Node(i)), in a new array of the same type and
/// name.
vtkSmartPointer<vtkDataArray> Gathered(vtkDataArray* values, const CompositeMesh::Leaf& leaf)
{
  vtkSmartPointer<vtkDataArray> gathered = vtk::TakeSmartPointer(values->NewInstance());
  gathered->SetName(values->GetName());
  gathered->SetNumberOfComponents(values->GetNumberOfComponents());
  const vtkIdType n = leaf.NumberOfPoints;
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
      std::memcpy(
        target + m * i, source + m * leaf.Node(i), static_cast<std::size_t>(m) * sizeof(double));
    }
    return gathered;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    gathered->SetTuple(i, leaf.Node(i), values);
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

/**
 * A block's values of a selected array into the merged nodes' (vtkArrayDispatch: no virtual call
 * per value): the boundary marker takes the largest value found for a node (moving anywhere:
 * moving), other arrays the first tuple found that is not zero.
 */
struct MergeNodeValues
{
  const CompositeMesh::Leaf& Leaf;
  double* Values;
  bool IsMarker;

  template <typename Array>
  void operator()(Array* source)
  {
    const auto tuples = vtk::DataArrayTupleRange(source);
    const int m = source->GetNumberOfComponents();
    for (vtkIdType i = 0; i < tuples.size(); ++i)
    {
      double* target = this->Values + this->Leaf.Node(i) * m;
      const auto tuple = tuples[i];
      if (this->IsMarker)
      {
        target[0] = std::max(target[0], static_cast<double>(tuple[0]));
      }
      else if (std::all_of(target, target + m, [](double v) { return v == 0.0; }))
      {
        for (int k = 0; k < m; ++k)
        {
          target[k] = static_cast<double>(tuple[k]);
        }
      }
    }
  }
};

} // namespace

CompositeMesh::CompositeMesh(
  vtkCompositeDataSet* input, const std::string& displacementName, const std::string& markerName)
  : Input(input)
  , Merged(vtkSmartPointer<vtkUnstructuredGrid>::New())
{
  // Make sure first that twice what the merge may need is there (all the points and what finds
  // the coincident ones, the merged points, ids and arrays, the cells).
  const auto blockPoints = static_cast<std::size_t>(input->GetNumberOfPoints());
  const auto blockCells = static_cast<std::size_t>(input->GetNumberOfCells());
  EnsureAvailableMemory(2 * (blockPoints * (24 + 42 + 16 + 24 * 2) + blockCells * 8 * 20));
  std::vector<std::string> arrays;
  for (const std::string& name : { displacementName, markerName })
  {
    if (!name.empty())
    {
      arrays.push_back(name);
    }
  }

  // 1. The leaves with points, and their points one after the other.
  const std::map<unsigned int, std::string> partitionNames = PartitionNames(input);
  std::vector<vtkPointSet*> blocks;
  std::vector<std::size_t> firstPoint{ 0 };
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
    blocks.push_back(block);
    firstPoint.push_back(firstPoint.back() + static_cast<std::size_t>(block->GetNumberOfPoints()));
    this->Leaves.push_back(std::move(leaf));
  }
  const std::size_t total = firstPoint.back();
  const dgmf::ParallelFor parallelFor = MakeSMPParallelFor();
  dgmf::PointPieces pieces;
  std::vector<std::vector<double>> copies(blocks.size()); // points that are not doubles
  for (std::size_t l = 0; l < blocks.size(); ++l)
  {
    pieces.Points.push_back(PointsAsDouble(blocks[l]->GetPoints(), copies[l]));
    pieces.Counts.push_back(firstPoint[l + 1] - firstPoint[l]);
  }

  // 2. Points at the same place are one node, numbered in the order they are first met.
  const dgmf::UninitializedVector<std::int64_t> first =
    dgmf::FirstCoincidentPoints(pieces, parallelFor);
  vtkIdType nodes = 0;
  NodeNumbers numbers = NumberNodes(first, nodes, parallelFor);
  for (std::size_t l = 0; l < blocks.size(); ++l)
  {
    Leaf& leaf = this->Leaves[l];
    leaf.NumberOfPoints = static_cast<vtkIdType>(firstPoint[l + 1] - firstPoint[l]);
    if (firstPoint[l] == 0 && firstPoint[l + 1] <= numbers.Prefix)
    {
      leaf.SameNumbering = true; // first points from the start: each its own node
      continue;
    }
    const auto count = static_cast<std::size_t>(leaf.NumberOfPoints);
    std::size_t same = 0; // a leaf of the first nodes in their order needs no map either
    while (same < count && numbers.NodeOf(firstPoint[l] + same) == static_cast<vtkIdType>(same))
    {
      ++same;
    }
    leaf.SameNumbering = same == count;
    if (!leaf.SameNumbering)
    {
      leaf.NodeOf.resize(count);
      for (std::size_t i = 0; i < count; ++i)
      {
        leaf.NodeOf[i] = numbers.NodeOf(firstPoint[l] + i);
      }
    }
  }
  numbers = NodeNumbers();

  // 3. The merged points: those of a leaf that has them all in their order (a CFD reader's
  //    volume, as a rule), shared; else the points where their nodes are first met.
  vtkSmartPointer<vtkPoints> mergedPoints;
  for (std::size_t l = 0; l < blocks.size() && !mergedPoints; ++l)
  {
    vtkPoints* points = blocks[l]->GetPoints(); // null in an empty block
    auto* doubles = points ? vtkDoubleArray::SafeDownCast(points->GetData()) : nullptr;
    if (this->Leaves[l].SameNumbering && blocks[l]->GetNumberOfPoints() == nodes && doubles &&
      doubles->GetNumberOfComponents() == 3) // plain doubles, as the merged points are
    {
      mergedPoints = blocks[l]->GetPoints();
      this->SharedPoints = true;
    }
  }
  if (!mergedPoints)
  {
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    AllocateTuples(coordinates, nodes);
    double* to = coordinates->GetPointer(0);
    for (std::size_t l = 0, i = 0, node = 0; l < blocks.size(); ++l)
    {
      for (std::size_t k = 0; k < pieces.Counts[l]; ++k, ++i)
      {
        if (static_cast<std::size_t>(first[i]) == i)
        {
          std::memcpy(to + 3 * node++, pieces.Points[l] + 3 * k, 3 * sizeof(double));
        }
      }
    }
    mergedPoints = vtkSmartPointer<vtkPoints>::New();
    mergedPoints->SetData(coordinates);
  }
  this->Merged->SetPoints(mergedPoints);

  // 4. The selected arrays: the first leaf that has one sets its number of components; leaves
  //    without it (or with another shape) contribute zeros.
  for (const std::string& name : arrays)
  {
    vtkSmartPointer<vtkDoubleArray> merged;
    for (std::size_t l = 0; l < blocks.size(); ++l)
    {
      vtkDataArray* source = blocks[l]->GetPointData()->GetArray(name.c_str());
      if (!source)
      {
        continue;
      }
      if (!merged)
      {
        merged = vtkSmartPointer<vtkDoubleArray>::New();
        merged->SetName(name.c_str());
        merged->SetNumberOfComponents(source->GetNumberOfComponents());
        AllocateTuples(merged, nodes);
        merged->FillValue(0.0);
      }
      if (source->GetNumberOfComponents() == merged->GetNumberOfComponents())
      {
        MergeNodeValues worker{ this->Leaves[l], merged->GetPointer(0), name == markerName };
        if (!vtkArrayDispatch::Dispatch::Execute(source, worker))
        {
          worker(source); // an array type outside the dispatch list
        }
      }
    }
    if (merged)
    {
      this->Merged->GetPointData()->AddArray(merged);
    }
  }

  // 5. The cells. A 3D mesh's patches (leaves of polygons only) go to a grid of their own on the
  //    same points, so that the volume's cells can be shared rather than copied.
  std::vector<std::uint8_t> polygonsOnly(blocks.size());
  std::vector<std::array<bool, 256>> types(blocks.size()); // one pass over each block's types
  int largest = 0;
  for (std::size_t l = 0; l < blocks.size(); ++l)
  {
    bool polygons = true;
    types[l] = CellTypesOf(blocks[l]);
    this->Leaves[l].CellDimension = CellDimensionOf(types[l], polygons);
    polygonsOnly[l] = polygons ? 1 : 0;
    largest = std::max(largest, this->Leaves[l].CellDimension);
  }
  std::vector<std::size_t> volume, patches;
  for (std::size_t l = 0; l < blocks.size(); ++l)
  {
    (largest == 3 && this->Leaves[l].CellDimension < 3 ? patches : volume).push_back(l);
  }
  if (!std::all_of(patches.begin(), patches.end(), [&](std::size_t l) { return polygonsOnly[l]; }))
  {
    // Lines or other lower-dimensional cells: every cell in the merged grid, as the single-grid
    // path sees such a mesh.
    volume.resize(blocks.size());
    std::iota(volume.begin(), volume.end(), std::size_t(0));
    patches.clear();
  }
  this->SetCells(blocks, types, volume, this->Merged);
  if (!patches.empty())
  {
    this->Patches = vtkSmartPointer<vtkUnstructuredGrid>::New();
    this->Patches->SetPoints(mergedPoints);
    for (std::size_t l : patches)
    {
      this->Leaves[l].InPatches = true;
    }
    this->SetCells(blocks, types, patches, this->Patches);
  }
}

void CompositeMesh::SetCells(const std::vector<vtkPointSet*>& blocks,
  const std::vector<std::array<bool, 256>>& types, const std::vector<std::size_t>& merged,
  vtkUnstructuredGrid* grid)
{
  if (merged.size() == 1 && grid == this->Merged)
  {
    // One grid leaf on the merged nodes in their order (a CFD reader's volume): its cells as
    // they are. 64-bit storage only (the face matching's fast path reads it); polyhedra with
    // their face arrays, checked first.
    Leaf& leaf = this->Leaves[merged[0]];
    auto* leafGrid = vtkUnstructuredGrid::SafeDownCast(blocks[merged[0]]);
    vtkCellArray* cells = leafGrid ? leafGrid->GetCells() : nullptr;
    const bool polyhedra = types[merged[0]][VTK_POLYHEDRON];
    if (leaf.SameNumbering && cells && cells->IsStorage64Bit() && leafGrid->GetCellTypesArray() &&
      leafGrid->GetNumberOfCells() > 0 &&
      (!polyhedra || (leafGrid->GetFaceLocations() && leafGrid->GetFaces())))
    {
      if (polyhedra)
      {
        CheckPolyhedronFaces(leafGrid);
        grid->SetCells(
          leafGrid->GetCellTypesArray(), cells, leafGrid->GetFaceLocations(), leafGrid->GetFaces());
      }
      else
      {
        // No polyhedra: the arrays as they are (VTK's two-argument form would look for a
        // polyhedron type again, one value at a time: 13 ms at 8.2M cells).
        grid->SetCells(leafGrid->GetCellTypesArray(), cells, nullptr, nullptr);
      }
      leaf.FirstCell = 0;
      leaf.Cells = leafGrid->GetNumberOfCells();
      this->SharedCells = true;
      return;
    }
  }
  vtkIdType totalCells = 0;
  vtkIdType totalIds = 0;
  for (std::size_t l : merged)
  {
    vtkIdType cells = 0;
    vtkIdType ids = 0;
    CountCells(blocks[l], cells, ids);
    totalCells += cells;
    totalIds += ids;
  }
  MergedCells cells(totalCells, totalIds);
  for (std::size_t l : merged)
  {
    Leaf& leaf = this->Leaves[l];
    leaf.FirstCell = cells.NumberOfCells;
    cells.Append(blocks[l], leaf, types[l]);
    leaf.Cells = cells.NumberOfCells - leaf.FirstCell;
  }
  cells.SetOn(grid);
}

void CompositeMesh::ScatterResult(vtkUnstructuredGrid* deformed,
  vtkUnstructuredGrid* deformedPatches, vtkCompositeDataSet* output) const
{
  namespace names = dgmf::names;
  output->Initialize();
  // Every array the filter adds to one grid's output: the blocks get what a grid would.
  this->Scatter(deformed, deformedPatches, { names::R, names::F },
    { names::SizeSkew, names::Inverted, names::InputInvalid, names::NonOrthogonality }, output);
  vtkNew<vtkFieldData> fieldData;
  fieldData->PassData(this->Input->GetFieldData());
  for (int k = 0; k < deformed->GetFieldData()->GetNumberOfArrays(); ++k)
  {
    fieldData->AddArray(deformed->GetFieldData()->GetAbstractArray(k));
  }
  output->SetFieldData(fieldData);
}

void CompositeMesh::Scatter(vtkUnstructuredGrid* deformed, vtkUnstructuredGrid* deformedPatches,
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
    const vtkIdType n = leaf.NumberOfPoints;
    // A leaf whose points are the merged grid's, in its order (the volume of a CFD reader's
    // output, as a rule), shares the deformed points and arrays; the others get copies.
    const bool allPoints = leaf.SameNumbering && n == deformed->GetNumberOfPoints();
    vtkUnstructuredGrid* cellsFrom = leaf.InPatches ? deformedPatches : deformed;
    const bool allCells =
      cellsFrom && leaf.FirstCell == 0 && leaf.Cells == cellsFrom->GetNumberOfCells();
    if (allPoints)
    {
      copy->SetPoints(deformed->GetPoints());
    }
    else
    {
      vtkNew<vtkPoints> points;
      points->SetData(Gathered(deformed->GetPoints()->GetData(), leaf));
      copy->SetPoints(points);
    }
    for (const std::string& name : pointArrays)
    {
      if (vtkDataArray* result = deformed->GetPointData()->GetArray(name.c_str()))
      {
        copy->GetPointData()->AddArray(allPoints ? result : Gathered(result, leaf).Get());
      }
    }
    for (const std::string& name : cellArrays)
    {
      if (vtkDataArray* result =
            cellsFrom ? cellsFrom->GetCellData()->GetArray(name.c_str()) : nullptr)
      {
        copy->GetCellData()->AddArray(
          allCells ? result : Range(result, leaf.FirstCell, leaf.Cells).Get());
      }
    }
    output->SetDataSet(iterator, copy);
  }
}

} // namespace dgmf_vtk
