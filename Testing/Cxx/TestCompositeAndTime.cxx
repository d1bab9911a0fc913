// Composite input deformed as one mesh, and the cache across inputs that are new objects with the
// same mesh (a temporal reader reads the mesh again at each time step).
#include "vtkDGMFDeformFilter.h"
#include "vtkSizeSkewQualityFilter.h"

#include "ShippedMesh.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>

namespace
{
/// The cells of `mesh` for which `keep(cell centre x)` holds, as a block with its own numbering
/// (nodes on the cut appear in both blocks) and the point arrays of `mesh`.
vtkSmartPointer<vtkUnstructuredGrid> Part(vtkUnstructuredGrid* mesh, bool upper)
{
  auto part = vtkSmartPointer<vtkUnstructuredGrid>::New();
  std::map<vtkIdType, vtkIdType> local;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  part->GetPointData()->CopyAllocate(mesh->GetPointData());
  vtkNew<vtkIdList> ids;
  part->Allocate(mesh->GetNumberOfCells());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    double centre = 0;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      centre += mesh->GetPoint(ids->GetId(k))[0] / ids->GetNumberOfIds();
    if ((centre > 0.3) != upper)
      continue;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      auto found = local.emplace(ids->GetId(k), points->GetNumberOfPoints());
      if (found.second)
      {
        points->InsertNextPoint(mesh->GetPoint(ids->GetId(k)));
        part->GetPointData()->CopyData(mesh->GetPointData(), ids->GetId(k), found.first->second);
      }
      ids->SetId(k, found.first->second);
    }
    part->InsertNextCell(mesh->GetCellType(c), ids);
  }
  part->SetPoints(points);
  return part;
}

using Position = std::tuple<double, double, double>;

/// Deformed position of every original position, from a single-mesh run.
std::map<Position, Position> Reference(vtkUnstructuredGrid* mesh)
{
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(mesh);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetRotationAngles(0, 0, 60);
  filter->Update();
  std::map<Position, Position> moved;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double* x = mesh->GetPoint(i);
    const double* y = filter->GetOutput()->GetPoint(i);
    moved[Position(x[0], x[1], x[2])] = Position(y[0], y[1], y[2]);
  }
  return moved;
}

void CheckBlock(vtkUnstructuredGrid* before, vtkUnstructuredGrid* after,
  const std::map<Position, Position>& reference)
{
  ASSERT_NE(after, nullptr);
  ASSERT_EQ(after->GetNumberOfPoints(), before->GetNumberOfPoints());
  ASSERT_EQ(after->GetNumberOfCells(), before->GetNumberOfCells());
  for (vtkIdType i = 0; i < before->GetNumberOfPoints(); ++i)
  {
    const double* x = before->GetPoint(i);
    const Position expected = reference.at(Position(x[0], x[1], x[2]));
    const double* y = after->GetPoint(i);
    EXPECT_NEAR(y[0], std::get<0>(expected), 1e-12);
    EXPECT_NEAR(y[1], std::get<1>(expected), 1e-12);
  }
  EXPECT_NE(after->GetPointData()->GetArray("BoundaryMarker"), nullptr);
  EXPECT_NE(after->GetPointData()->GetArray("f"), nullptr);
  ASSERT_NE(after->GetCellData()->GetArray("SizeSkew"), nullptr);
  EXPECT_EQ(
    after->GetCellData()->GetArray("SizeSkew")->GetNumberOfTuples(), before->GetNumberOfCells());
}
} // namespace

TEST(Composite, MultiBlockIsDeformedAsOneMeshAndKeepsItsStructure)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  const auto reference = Reference(mesh);
  auto lower = Part(mesh, false);
  auto upper = Part(mesh, true);
  ASSERT_GT(lower->GetNumberOfCells(), 100);
  ASSERT_GT(upper->GetNumberOfCells(), 100);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, lower);
  blocks->SetBlock(1, upper);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(blocks);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetRotationAngles(0, 0, 60);
  filter->Update();
  auto* out = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfBlocks(), 2u);
  // The cut between the blocks is not a boundary: each block moves as the whole mesh does.
  CheckBlock(lower, vtkUnstructuredGrid::SafeDownCast(out->GetBlock(0)), reference);
  CheckBlock(upper, vtkUnstructuredGrid::SafeDownCast(out->GetBlock(1)), reference);
  ASSERT_NE(out->GetFieldData()->GetArray("InvertedCellCount"), nullptr);
  EXPECT_EQ(out->GetFieldData()->GetArray("InvertedCellCount")->GetTuple1(0), 0.0);

  // A new execution on the same blocks reuses the graph (the merged mesh is rebuilt each time,
  // with the same content).
  filter->SetRotationAngles(0, 0, 30);
  filter->Update();
  EXPECT_TRUE(filter->GetLastExecutionReusedGraph());
}

TEST(Composite, PartitionedDataSetCollection)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  const auto reference = Reference(mesh);
  auto lower = Part(mesh, false);
  auto upper = Part(mesh, true);
  vtkNew<vtkPartitionedDataSetCollection> collection;
  collection->SetNumberOfPartitionedDataSets(1);
  vtkNew<vtkPartitionedDataSet> partitions;
  partitions->SetNumberOfPartitions(2);
  partitions->SetPartition(0, lower);
  partitions->SetPartition(1, upper);
  collection->SetPartitionedDataSet(0, partitions);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(collection);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetRotationAngles(0, 0, 60);
  filter->Update();
  auto* out = vtkPartitionedDataSetCollection::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfPartitionedDataSets(), 1u);
  ASSERT_EQ(out->GetNumberOfPartitions(0), 2u);
  CheckBlock(lower, vtkUnstructuredGrid::SafeDownCast(out->GetPartition(0, 0)), reference);
  CheckBlock(upper, vtkUnstructuredGrid::SafeDownCast(out->GetPartition(0, 1)), reference);
}

TEST(TimeSeries, ANewInputObjectWithTheSameMeshReusesTheGraph)
{
  // A temporal reader hands over a new grid at each time step: same points, new displacement.
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetDisplacementArrayName("Displacement");
  for (int step = 0; step < 3; ++step)
  {
    vtkNew<vtkUnstructuredGrid> atStep;
    atStep->DeepCopy(mesh);
    vtkDataArray* d = atStep->GetPointData()->GetArray("Displacement");
    for (vtkIdType i = 0; i < atStep->GetNumberOfPoints(); ++i)
      d->SetComponent(i, 1, 0.05 * step * atStep->GetPoint(i)[0]);
    filter->SetInputData(atStep);
    filter->SetRotationAngles(0, 0, 20.0 * step);
    filter->Update();
    EXPECT_EQ(filter->GetLastExecutionReusedGraph(), step > 0) << "step " << step;
    vtkNew<vtkDGMFDeformFilter> fresh;
    fresh->SetInputData(atStep);
    fresh->SetBoundaryMarkerArrayName("BoundaryMarker");
    fresh->SetDisplacementArrayName("Displacement");
    fresh->SetRotationAngles(0, 0, 20.0 * step);
    fresh->Update();
    for (vtkIdType i = 0; i < atStep->GetNumberOfPoints(); ++i)
    {
      ASSERT_EQ(filter->GetOutput()->GetPoint(i)[0], fresh->GetOutput()->GetPoint(i)[0]);
      ASSERT_EQ(filter->GetOutput()->GetPoint(i)[1], fresh->GetOutput()->GetPoint(i)[1]);
    }
  }
}

TEST(Composite, QualityFilterMeasuresTheBlocksDGMFDeformReturns)
{
  auto mesh = dgmf_test::ReadShippedMesh("rotating_circle.vtu", 822);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, Part(mesh, false));
  blocks->SetBlock(1, Part(mesh, true));
  vtkNew<vtkDGMFDeformFilter> deform;
  deform->SetInputData(blocks);
  deform->SetBoundaryMarkerArrayName("BoundaryMarker");
  deform->SetRotationAngles(0, 0, 75);
  deform->Update();
  auto* deformed = vtkMultiBlockDataSet::SafeDownCast(deform->GetOutputDataObject(0));
  ASSERT_NE(deformed, nullptr);
  // The deformed blocks against the input blocks: the same values, block by block, and the same
  // summary as the deformation's own.
  vtkNew<vtkSizeSkewQualityFilter> quality;
  quality->SetInputData(deformed);
  quality->SetReferenceData(blocks);
  quality->Update();
  auto* measured = vtkMultiBlockDataSet::SafeDownCast(quality->GetOutputDataObject(0));
  ASSERT_NE(measured, nullptr);
  ASSERT_EQ(measured->GetNumberOfBlocks(), 2u);
  for (unsigned int b = 0; b < 2; ++b)
  {
    vtkDataArray* ours =
      vtkUnstructuredGrid::SafeDownCast(measured->GetBlock(b))->GetCellData()->GetArray("SizeSkew");
    vtkDataArray* deforms =
      vtkUnstructuredGrid::SafeDownCast(deformed->GetBlock(b))->GetCellData()->GetArray("SizeSkew");
    ASSERT_TRUE(ours && deforms);
    ASSERT_EQ(ours->GetNumberOfTuples(), deforms->GetNumberOfTuples());
    for (vtkIdType c = 0; c < ours->GetNumberOfTuples(); ++c)
    {
      ASSERT_EQ(ours->GetTuple1(c), deforms->GetTuple1(c)) << "block " << b << " cell " << c;
    }
  }
  const auto summary = [](vtkMultiBlockDataSet* data, const char* name)
  { return data->GetFieldData()->GetArray(name)->GetTuple1(0); };
  // The mean is summed block by block here, over the merged mesh there: equal up to round-off.
  EXPECT_NEAR(summary(measured, "SizeSkewMean"), summary(deformed, "SizeSkewMean"), 1e-14);
  EXPECT_EQ(summary(measured, "SizeSkewMinimum"), summary(deformed, "SizeSkewMinimum"));
  EXPECT_EQ(summary(measured, "InvertedCellCount"), summary(deformed, "InvertedCellCount"));
  // A reference of another kind: a clear error.
  vtkNew<vtkSizeSkewQualityFilter> mismatch;
  mismatch->SetInputData(deformed);
  mismatch->SetReferenceData(mesh);
  mismatch->Update();
  EXPECT_EQ(
    vtkMultiBlockDataSet::SafeDownCast(mismatch->GetOutputDataObject(0))->GetNumberOfBlocks(), 0u);
}
