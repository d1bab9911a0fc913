// Composite input deformed as one mesh, and the cache across inputs that are new objects with the
// same mesh (a temporal reader reads the mesh again at each time step).
#include "vtkDGMFDeformFilter.h"
#include "vtkSizeSkewQualityFilter.h"

#include "HexBoxBlocks.h"
#include "ShippedMesh.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

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
/// The side patches of HexBoxBlocks(n, "") (block 1), in their order.
std::vector<vtkPolyData*> SidesOf(vtkMultiBlockDataSet* blocks)
{
  std::vector<vtkPolyData*> sides;
  auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  for (unsigned int b = 0; boundary && b < boundary->GetNumberOfBlocks(); ++b)
  {
    sides.push_back(vtkPolyData::SafeDownCast(boundary->GetBlock(b)));
  }
  return sides;
}

/**
 * HexBoxBlocks(n, "") as one grid, as a gmsh or SU2 file gives it: the volume's points and
 * hexahedra, then the sides' quads on those points, in the blocks' order; with the volume's point
 * arrays.
 */
vtkSmartPointer<vtkUnstructuredGrid> AsOneGrid(vtkMultiBlockDataSet* blocks, int n)
{
  auto* volume = vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0));
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(volume);
  for (vtkPolyData* side : SidesOf(blocks))
  {
    for (vtkIdType c = 0; c < side->GetNumberOfCells(); ++c)
    {
      vtkNew<vtkIdList> own;
      side->GetCellPoints(c, own);
      vtkIdType quad[4];
      for (vtkIdType k = 0; k < 4; ++k)
      {
        const double* p = side->GetPoint(own->GetId(k)); // integer coordinates
        quad[k] = static_cast<vtkIdType>(p[0] + (n + 1) * (p[1] + (n + 1) * p[2]));
      }
      grid->InsertNextCell(VTK_QUAD, 4, quad);
    }
  }
  return grid;
}
} // namespace

TEST(Composite, AVolumeAndItsPatchesDeformAsOneGridWithItsPolygons)
{
  // A CFD reader's volume lends the merged mesh its cells, and its patches' polygons are kept
  // apart: the boundary found from them, the quality guard's cells, the quality and its summary
  // must be those of one grid holding both, bit for bit. Two ways to the boundary: the mesh's own
  // (a displacement array, sub-steps with the guard) and the patches' nodes (a named moving patch,
  // against the same marker).
  const int n = 6;
  for (const bool named : { false, true })
  {
    vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(n, "");
    auto* volume = vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0));
    vtkNew<vtkDoubleArray> displacement; // xmin pushed in, more at the top
    displacement->SetName("Displacement");
    displacement->SetNumberOfComponents(3);
    vtkNew<vtkDoubleArray> marker; // the named boundaries as a marker
    marker->SetName("BoundaryMarker");
    for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i)
    {
      const double* p = volume->GetPoint(i);
      const bool xmin = p[0] == 0.0;
      displacement->InsertNextTuple3(xmin ? 0.4 + 0.1 * p[2] : 0.0, 0.0, xmin ? 0.2 : 0.0);
      const bool boundary =
        xmin || p[0] == n || p[1] == 0.0 || p[1] == n || p[2] == 0.0 || p[2] == n;
      marker->InsertNextValue(xmin ? 2.0 : boundary ? 1.0 : 0.0);
    }
    volume->GetPointData()->AddArray(displacement);
    vtkSmartPointer<vtkUnstructuredGrid> one = AsOneGrid(blocks, n);
    one->GetPointData()->AddArray(marker);
    // The merged mesh holds the volume's cells themselves: they must come out untouched.
    const vtkMTimeType cellsTime = volume->GetCells()->GetMTime();
    const vtkMTimeType typesTime = volume->GetCellTypesArray()->GetMTime();
    const vtkMTimeType volumeTime = volume->GetMTime();

    std::vector<vtkSmartPointer<vtkDGMFDeformFilter>> filters;
    for (vtkDataObject* input :
      { static_cast<vtkDataObject*>(blocks.Get()), static_cast<vtkDataObject*>(one.Get()) })
    {
      auto filter = vtkSmartPointer<vtkDGMFDeformFilter>::New();
      filter->SetInputData(input);
      if (named)
      {
        filter->SetRotationAngles(0, 8, 0);
        filter->SetTranslation(0.3, 0, 0);
        if (input == one.Get())
        {
          filter->SetBoundaryMarkerArrayName("BoundaryMarker");
        }
        else
        {
          filter->AddMovingBoundary("xmin");
        }
      }
      else
      {
        filter->SetDisplacementArrayName("Displacement");
        filter->SetBoundaryMarkerArrayName("");
        filter->SetSubSteps(2);
        filter->SetRepairThreshold(0.2);
      }
      filter->ComputeNonOrthogonalityOn();
      filter->Update();
      filters.push_back(filter);
    }
    EXPECT_EQ(volume->GetCells()->GetMTime(), cellsTime);
    EXPECT_EQ(volume->GetCellTypesArray()->GetMTime(), typesTime);
    EXPECT_EQ(volume->GetMTime(), volumeTime);
    auto* out = vtkMultiBlockDataSet::SafeDownCast(filters[0]->GetOutputDataObject(0));
    auto* oneOut = vtkUnstructuredGrid::SafeDownCast(filters[1]->GetOutputDataObject(0));
    ASSERT_TRUE(out && oneOut) << "named " << named;
    auto* deformed = vtkUnstructuredGrid::SafeDownCast(out->GetBlock(0));
    ASSERT_TRUE(deformed);
    const vtkIdType points = volume->GetNumberOfPoints();
    ASSERT_EQ(deformed->GetNumberOfPoints(), points);
    ASSERT_EQ(oneOut->GetNumberOfPoints(), points);
    int moved = 0;
    for (vtkIdType i = 0; i < points; ++i)
    {
      ASSERT_EQ(std::memcmp(deformed->GetPoint(i), oneOut->GetPoint(i), 3 * sizeof(double)), 0)
        << "node " << i << ", named " << named;
      moved += std::memcmp(deformed->GetPoint(i), volume->GetPoint(i), 3 * sizeof(double)) != 0;
    }
    EXPECT_GT(moved, (n + 1) * (n + 1) + 20) << "interior nodes moved, not only xmin's";
    // The quality: the volume's hexahedra, then each side's quads, as in the one grid; every
    // quality array the one grid has.
    auto* sides = vtkMultiBlockDataSet::SafeDownCast(out->GetBlock(1));
    ASSERT_TRUE(sides);
    ASSERT_EQ(sides->GetNumberOfBlocks(), 6u);
    for (const char* name : { "SizeSkew", "Inverted", "InputInvalid" })
    {
      vtkDataArray* oneValues = oneOut->GetCellData()->GetArray(name);
      ASSERT_TRUE(oneValues) << name;
      std::vector<vtkDataArray*> blocks{ deformed->GetCellData()->GetArray(name) };
      for (unsigned int b = 0; b < 6; ++b)
      {
        auto* side = vtkPolyData::SafeDownCast(sides->GetBlock(b));
        ASSERT_TRUE(side);
        blocks.push_back(side->GetCellData()->GetArray(name));
      }
      vtkIdType cell = 0;
      double lowest = 1.0;
      for (vtkDataArray* values : blocks)
      {
        ASSERT_TRUE(values) << name;
        for (vtkIdType c = 0; c < values->GetNumberOfTuples(); ++c, ++cell)
        {
          ASSERT_EQ(values->GetTuple1(c), oneValues->GetTuple1(cell)) << name << ", cell " << cell;
          lowest = std::min(lowest, values->GetTuple1(c));
        }
      }
      EXPECT_EQ(cell, oneOut->GetNumberOfCells()) << name;
      if (std::string(name) == "SizeSkew")
      {
        EXPECT_LT(lowest, 0.999) << "the motion deformed cells";
      }
    }
    // The volume's face non-orthogonality (its hexahedra are the one grid's first cells).
    vtkDataArray* angles = deformed->GetCellData()->GetArray("NonOrthogonality");
    vtkDataArray* oneAngles = oneOut->GetCellData()->GetArray("NonOrthogonality");
    ASSERT_TRUE(angles && oneAngles);
    ASSERT_EQ(angles->GetNumberOfTuples(), deformed->GetNumberOfCells());
    for (vtkIdType c = 0; c < angles->GetNumberOfTuples(); ++c)
    {
      ASSERT_EQ(angles->GetTuple1(c), oneAngles->GetTuple1(c)) << "cell " << c;
    }
    vtkFieldData* summary = out->GetFieldData();
    vtkFieldData* oneSummary = oneOut->GetFieldData();
    for (const char* name :
      { "SizeSkewMean", "SizeSkewMinimum", "InvertedCellCount", "SizeSkewEvaluatedCells" })
    {
      ASSERT_TRUE(summary->GetArray(name) && oneSummary->GetArray(name)) << name;
      EXPECT_EQ(summary->GetArray(name)->GetTuple1(0), oneSummary->GetArray(name)->GetTuple1(0))
        << name;
    }
    EXPECT_EQ(summary->GetArray("SizeSkewEvaluatedCells")->GetTuple1(0), n * n * n)
      << "the volume's cells (the patches' are left out, as for one grid)";
  }
}

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

  // Empty blocks without a points object (what a clip or a threshold leaves of a patch) are
  // passed on empty; the rest deforms as before (they crashed the filter until 2026-11-30).
  blocks->SetNumberOfBlocks(4);
  blocks->SetBlock(2, vtkNew<vtkUnstructuredGrid>());
  blocks->SetBlock(3, vtkNew<vtkPolyData>());
  ASSERT_EQ(vtkPointSet::SafeDownCast(blocks->GetBlock(2))->GetPoints(), nullptr);
  filter->SetRotationAngles(0, 0, 60);
  filter->Update();
  out = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfBlocks(), 4u);
  CheckBlock(lower, vtkUnstructuredGrid::SafeDownCast(out->GetBlock(0)), reference);
  CheckBlock(upper, vtkUnstructuredGrid::SafeDownCast(out->GetBlock(1)), reference);
  for (unsigned int b : { 2u, 3u })
  {
    ASSERT_NE(out->GetBlock(b), nullptr);
    EXPECT_EQ(vtkPointSet::SafeDownCast(out->GetBlock(b))->GetNumberOfPoints(), 0);
  }
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
