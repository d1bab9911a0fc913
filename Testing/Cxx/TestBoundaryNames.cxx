// Boundaries chosen by name on composite input, slip boundaries and one-cell-thick meshes through
// the filter, on the rotating circle split into named blocks as a CFD reader gives them: a volume
// block and one block of boundary faces per patch.
#include "vtkDGMFDeformFilter.h"

#include "ErrorMessages.h"
#include "FieldValue.h"
#include "HexahedraOfGrid.h"
#include "ShippedMesh.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace
{
constexpr vtkIdType CirclePoints = 822;

/// The boundary edges of a triangle mesh, as (a, b) pairs of point ids.
std::vector<std::array<vtkIdType, 2>> BoundaryEdges(vtkUnstructuredGrid* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> count;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % ids->GetNumberOfIds());
      ++count[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::vector<std::array<vtkIdType, 2>> edges;
  for (const auto& edge : count)
  {
    if (edge.second == 1)
    {
      edges.push_back({ edge.first.first, edge.first.second });
    }
  }
  return edges;
}

/// The name of a patch for an edge of the circle mesh: "circle", or the side of the square.
std::string PatchOf(const double* a, const double* b)
{
  if (std::hypot(a[0], a[1]) < 2.0)
  {
    return "circle";
  }
  if (a[1] == -5.0 && b[1] == -5.0)
    return "bottom";
  if (a[1] == 5.0 && b[1] == 5.0)
    return "top";
  if (a[0] == -5.0 && b[0] == -5.0)
    return "left";
  return "right";
}

void Name(vtkMultiBlockDataSet* blocks, unsigned int index, const std::string& name)
{
  blocks->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name.c_str());
}

/**
 * The circle mesh as a CFD reader gives it: block "internalMesh" (the triangles, without the
 * marker) and one polydata block per patch, its points its own (as the OpenFOAM reader's).
 * `layer` > 0: the mesh extruded by `layer` along z into one layer of wedges, the patches quads,
 * with the "front" and "back" triangles as two more patches (`frontAndBack`: as one patch, as
 * OpenFOAM cases have them).
 */
vtkSmartPointer<vtkMultiBlockDataSet> NamedBlocks(
  vtkUnstructuredGrid* circle, double layer = 0.0, bool frontAndBack = false)
{
  const vtkIdType n = circle->GetNumberOfPoints();
  auto volume = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int l = 0; l < (layer > 0.0 ? 2 : 1); ++l)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double* p = circle->GetPoint(i);
      points->InsertNextPoint(p[0], p[1], l * layer);
    }
  }
  volume->SetPoints(points);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < circle->GetNumberOfCells(); ++c)
  {
    circle->GetCellPoints(c, ids);
    if (layer > 0.0)
    {
      const vtkIdType wedge[6] = { ids->GetId(0), ids->GetId(1), ids->GetId(2), ids->GetId(0) + n,
        ids->GetId(1) + n, ids->GetId(2) + n };
      volume->InsertNextCell(VTK_WEDGE, 6, wedge);
    }
    else
    {
      volume->InsertNextCell(VTK_TRIANGLE, ids);
    }
  }
  std::map<std::string, std::vector<std::vector<vtkIdType>>> patches;
  for (const auto& edge : BoundaryEdges(circle))
  {
    const std::string name = PatchOf(circle->GetPoint(edge[0]), circle->GetPoint(edge[1]));
    if (layer > 0.0)
    {
      patches[name].push_back({ edge[0], edge[1], edge[1] + n, edge[0] + n });
    }
    else
    {
      patches[name].push_back({ edge[0], edge[1] });
    }
  }
  if (layer > 0.0)
  {
    for (vtkIdType c = 0; c < circle->GetNumberOfCells(); ++c)
    {
      circle->GetCellPoints(c, ids);
      patches[frontAndBack ? "frontAndBack" : "front"].push_back(
        { ids->GetId(0), ids->GetId(1), ids->GetId(2) });
      patches[frontAndBack ? "frontAndBack" : "back"].push_back(
        { ids->GetId(0) + n, ids->GetId(1) + n, ids->GetId(2) + n });
    }
  }
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetBlock(0, volume);
  Name(blocks, 0, "internalMesh");
  vtkNew<vtkMultiBlockDataSet> boundary;
  unsigned int index = 0;
  for (const auto& patch : patches)
  {
    vtkNew<vtkPolyData> faces;
    vtkNew<vtkPoints> own;
    own->SetDataTypeToDouble();
    std::map<vtkIdType, vtkIdType> local;
    vtkNew<vtkCellArray> cells;
    for (const std::vector<vtkIdType>& face : patch.second)
    {
      std::vector<vtkIdType> renumbered;
      for (vtkIdType id : face)
      {
        const auto found = local.emplace(id, own->GetNumberOfPoints());
        if (found.second)
        {
          own->InsertNextPoint(points->GetPoint(id));
        }
        renumbered.push_back(found.first->second);
      }
      cells->InsertNextCell(static_cast<vtkIdType>(renumbered.size()), renumbered.data());
    }
    faces->SetPoints(own);
    if (patch.second.front().size() == 2)
    {
      faces->SetLines(cells);
    }
    else
    {
      faces->SetPolys(cells);
    }
    boundary->SetBlock(index, faces);
    Name(boundary, index++, patch.first);
  }
  blocks->SetBlock(1, boundary);
  Name(blocks, 1, "boundary");
  return blocks;
}

vtkUnstructuredGrid* VolumeOf(vtkDataObject* output)
{
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(output);
  return blocks ? vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0)) : nullptr;
}

/// The circle rotated by 60 degrees with its boundary-marker array: what names must reproduce.
vtkSmartPointer<vtkUnstructuredGrid> MarkedReference(vtkUnstructuredGrid* circle)
{
  vtkNew<vtkDGMFDeformFilter> marked;
  marked->SetInputData(circle);
  marked->SetBoundaryMarkerArrayName("BoundaryMarker");
  marked->SetRotationAngles(0, 0, 60);
  marked->Update();
  return marked->GetOutput();
}

using Errors = dgmf_test::ErrorMessages;
} // namespace

TEST(BoundaryNames, NamedPatchesGiveTheMarkersResultBitForBit)
{
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  const vtkSmartPointer<vtkUnstructuredGrid> reference = MarkedReference(circle);

  auto blocks = NamedBlocks(circle);
  vtkNew<vtkDGMFDeformFilter> named;
  named->SetInputData(blocks);
  named->AddMovingBoundary("circle"); // the square's four patches are static by default
  named->SetRotationAngles(0, 0, 60);
  named->Update();
  vtkUnstructuredGrid* volume = VolumeOf(named->GetOutputDataObject(0));
  ASSERT_NE(volume, nullptr);
  ASSERT_EQ(volume->GetNumberOfPoints(), CirclePoints);
  for (vtkIdType i = 0; i < CirclePoints; ++i)
  {
    ASSERT_EQ(std::memcmp(volume->GetPoint(i), reference->GetPoint(i), 3 * sizeof(double)), 0)
      << "node " << i;
  }
  // A selector path, as ParaView's block tree gives it, selects the same patch.
  vtkNew<vtkDGMFDeformFilter> byPath;
  byPath->SetInputData(blocks);
  byPath->AddMovingBoundary("/Root/boundary/circle");
  byPath->SetRotationAngles(0, 0, 60);
  byPath->Update();
  ASSERT_NE(VolumeOf(byPath->GetOutputDataObject(0)), nullptr);
  EXPECT_EQ(std::memcmp(VolumeOf(byPath->GetOutputDataObject(0))->GetPoint(5), volume->GetPoint(5),
              3 * sizeof(double)),
    0);

  // The same blocks as a partitioned data set collection (ParaView's IOSS reader), one named
  // partitioned data set per block: ParaView's block tree offers "/Root/circle" (refused until
  // 2026-11-30), and the plain name works too.
  vtkNew<vtkPartitionedDataSetCollection> collection;
  auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  for (unsigned int b = 0; b <= boundary->GetNumberOfBlocks(); ++b)
  {
    vtkNew<vtkPartitionedDataSet> partitioned;
    partitioned->SetPartition(0, b == 0 ? blocks->GetBlock(0) : boundary->GetBlock(b - 1));
    collection->SetPartitionedDataSet(b, partitioned);
    collection->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(),
      b == 0 ? "internalMesh" : boundary->GetMetaData(b - 1)->Get(vtkCompositeDataSet::NAME()));
  }
  for (const char* entry : { "/Root/circle", "circle" })
  {
    vtkNew<vtkDGMFDeformFilter> partitions;
    partitions->SetInputData(collection);
    partitions->AddMovingBoundary(entry);
    partitions->SetRotationAngles(0, 0, 60);
    partitions->Update();
    auto* out = vtkPartitionedDataSetCollection::SafeDownCast(partitions->GetOutputDataObject(0));
    ASSERT_NE(out, nullptr) << entry;
    ASSERT_EQ(out->GetNumberOfPartitionedDataSets(), collection->GetNumberOfPartitionedDataSets());
    auto* grid = vtkUnstructuredGrid::SafeDownCast(out->GetPartition(0, 0));
    ASSERT_NE(grid, nullptr) << entry;
    for (vtkIdType i = 0; i < CirclePoints; ++i)
    {
      ASSERT_EQ(std::memcmp(grid->GetPoint(i), reference->GetPoint(i), 3 * sizeof(double)), 0)
        << entry << ", node " << i;
    }
  }
}

TEST(BoundaryNames, AnUnknownNameListsTheBlocksAndANameNeedsBlocks)
{
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  vtkNew<vtkDGMFDeformFilter> filter;
  Errors errors(filter);
  filter->SetInputData(NamedBlocks(circle));
  filter->AddMovingBoundary("wing");
  filter->Update();
  EXPECT_EQ(
    vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0))->GetNumberOfBlocks(), 0u);
  EXPECT_TRUE(errors.Contains("No block of the input is named 'wing'"));
  EXPECT_TRUE(errors.Contains("internalMesh, bottom, circle, left, right, top"));

  // The volume block is not a boundary (moving, it turned the whole mesh; static, it froze it),
  // and a boundary named twice is ambiguous: both were accepted until 2026-11-30.
  for (const auto& [moving, other, expected] :
    { std::tuple{ "internalMesh", "", "'internalMesh' is the whole mesh (its volume block)" },
      std::tuple{ "circle", "internalMesh", "'internalMesh' is the whole mesh" },
      std::tuple{
        "circle", "circle", "The boundary 'circle' is named twice (as moving and as static)" },
      // ... so is a block named by two entries through a wildcard or alternatives (until
      // 2026-11-30 the moving one won without a word: "wing_*" moving and "wing_tip" static
      // moved the tip).
      std::tuple{ "circle", "c*e",
        "The block 'circle' is named by two entries ('circle' as moving and 'c*e' as static)" },
      std::tuple{ "left|circle", "circle|right",
        "The block 'circle' is named by two entries ('left|circle' as moving and 'circle|right' "
        "as static)" } })
  {
    vtkNew<vtkDGMFDeformFilter> named;
    Errors namedErrors(named);
    named->SetInputData(NamedBlocks(circle));
    named->AddMovingBoundary(moving);
    if (*other)
    {
      named->AddStaticBoundary(other);
    }
    named->SetRotationAngles(0, 0, 10);
    named->Update();
    EXPECT_EQ(
      vtkMultiBlockDataSet::SafeDownCast(named->GetOutputDataObject(0))->GetNumberOfBlocks(), 0u);
    EXPECT_TRUE(namedErrors.Contains(expected)) << expected;
  }

  vtkNew<vtkDGMFDeformFilter> grid;
  Errors gridErrors(grid);
  grid->SetInputData(circle);
  grid->AddMovingBoundary("circle");
  grid->Update();
  EXPECT_EQ(grid->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(gridErrors.Contains("Boundaries chosen by name need a composite input"));
}

TEST(BoundaryNames, SlipNodesStayOnTheirLineAndCornersStay)
{
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  auto blocks = NamedBlocks(circle);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("circle");
  filter->AddSlipBoundary("bottom");
  filter->SetTranslation(1.0, 0.0, 0.0);
  filter->Update();
  vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0));
  ASSERT_NE(volume, nullptr);
  int onLine = 0;
  for (vtkIdType i = 0; i < CirclePoints; ++i)
  {
    const double* before = circle->GetPoint(i);
    const double* after = volume->GetPoint(i);
    if (before[1] != -5.0)
    {
      continue;
    }
    ++onLine;
    ASSERT_EQ(after[1], -5.0) << "node " << i; // on the line, bit for bit
    if (std::abs(before[0]) == 5.0)
    {
      EXPECT_EQ(after[0], before[0]) << "corner " << i; // shared with a static side: static
    }
  }
  EXPECT_GT(onLine, 10);
  // (Far from the body, as here, a slip node's graph element is the hull edge between two static
  // corners, so it does not move; core.SlipPlanes.* has a body on the plane and the nodes slide.)
  auto* output = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  EXPECT_EQ(output->GetFieldData()->GetArray("InvertedCellCount")->GetTuple1(0), 0.0);
}

TEST(BoundaryNames, AOneCellThickMeshMovesAsItsLayerBothLayersAlike)
{
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  vtkNew<vtkDGMFDeformFilter> flat;
  flat->SetInputData(circle);
  flat->SetBoundaryMarkerArrayName("BoundaryMarker");
  flat->SetRotationAngles(0, 0, 45);
  flat->Update();

  // The planes as two patches, or as one (frontAndBack: until 2026-11-30 it was taken for a
  // static boundary, which froze the interior and inverted cells).
  for (const auto& [mode, frontAndBack] :
    { std::pair{ vtkDGMFDeformFilter::DETECT, false }, std::pair{ vtkDGMFDeformFilter::ON, false },
      std::pair{ vtkDGMFDeformFilter::DETECT, true }, std::pair{ vtkDGMFDeformFilter::ON, true } })
  {
    vtkNew<vtkDGMFDeformFilter> layered;
    layered->SetInputData(NamedBlocks(circle, 0.1, frontAndBack));
    layered->AddMovingBoundary("circle"); // front and back are not boundaries: not static
    layered->SetRotationAngles(0, 0, 45);
    layered->SetOneCellThickMode(mode);
    layered->Update();
    vtkUnstructuredGrid* volume = VolumeOf(layered->GetOutputDataObject(0));
    ASSERT_NE(volume, nullptr);
    ASSERT_EQ(volume->GetNumberOfPoints(), 2 * CirclePoints);
    for (vtkIdType i = 0; i < CirclePoints; ++i)
    {
      double front[3], back[3], expected[3];
      volume->GetPoint(i, front);
      volume->GetPoint(i + CirclePoints, back);
      flat->GetOutput()->GetPoint(i, expected);
      ASSERT_EQ(std::memcmp(front, expected, 2 * sizeof(double)), 0) << "node " << i;
      ASSERT_EQ(std::memcmp(back, expected, 2 * sizeof(double)), 0) << "node " << i;
      ASSERT_EQ(front[2], 0.0);
      ASSERT_EQ(back[2], 0.1);
    }
    EXPECT_EQ(vtkMultiBlockDataSet::SafeDownCast(layered->GetOutputDataObject(0))
                ->GetFieldData()
                ->GetArray("InvertedCellCount")
                ->GetTuple1(0),
      0.0);
  }
  // As a 3D mesh (OFF), every front and back node is a boundary node: the layers do not follow.
  auto blocks = NamedBlocks(circle, 0.1);
  vtkNew<vtkDGMFDeformFilter> solid;
  solid->SetInputData(blocks);
  solid->AddMovingBoundary("circle");
  solid->SetRotationAngles(0, 0, 45);
  solid->SetOneCellThickMode(vtkDGMFDeformFilter::OFF);
  solid->Update();
  auto* stiff = vtkMultiBlockDataSet::SafeDownCast(solid->GetOutputDataObject(0));
  ASSERT_NE(VolumeOf(stiff), nullptr);
  EXPECT_GT(stiff->GetFieldData()->GetArray("InvertedCellCount")->GetTuple1(0), 0.0);
}

TEST(BoundaryNames, ANewSelectionOfTheSameInputTakesEffect)
{
  // The merge and the node roles are kept between executions of the same input: another moving
  // boundary must still be seen.
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  auto blocks = NamedBlocks(circle);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("circle");
  filter->SetTranslation(0.5, 0.0, 0.0);
  filter->Update();
  vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0));
  ASSERT_NE(volume, nullptr);
  const auto moved = [&](vtkIdType i) { return volume->GetPoint(i)[0] != circle->GetPoint(i)[0]; };
  vtkIdType onCircle = -1, onLeft = -1;
  for (vtkIdType i = 0; i < CirclePoints; ++i)
  {
    const double* p = circle->GetPoint(i);
    onCircle = std::hypot(p[0], p[1]) < 2.0 && onCircle < 0 ? i : onCircle;
    onLeft = p[0] == -5.0 && std::abs(p[1]) < 4.0 && onLeft < 0 ? i : onLeft;
  }
  ASSERT_GE(onCircle, 0);
  ASSERT_GE(onLeft, 0);
  EXPECT_TRUE(moved(onCircle));
  EXPECT_FALSE(moved(onLeft));

  filter->RemoveAllMovingBoundaries();
  filter->AddMovingBoundary("left");
  filter->Update();
  volume = VolumeOf(filter->GetOutputDataObject(0));
  ASSERT_NE(volume, nullptr);
  EXPECT_FALSE(moved(onCircle)) << "the circle is a static patch now";
  EXPECT_TRUE(moved(onLeft));
}

TEST(BoundaryNames, TheOneCellThickLayersAreFoundAgainWhenThePointsChange)
{
  // The layers of a marked one-cell-thick grid are kept between executions while its points are
  // unchanged; a point moved in place (the same vtkPoints, Modified) must be seen.
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  vtkNew<vtkUnstructuredGrid> slab;
  slab->DeepCopy(VolumeOf(NamedBlocks(circle, 0.1)));
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  vtkDataArray* circleMarker = circle->GetPointData()->GetArray("BoundaryMarker");
  ASSERT_NE(circleMarker, nullptr);
  for (int layer = 0; layer < 2; ++layer)
  {
    for (vtkIdType i = 0; i < CirclePoints; ++i)
    {
      marker->InsertNextValue(static_cast<int>(circleMarker->GetTuple1(i)));
    }
  }
  slab->GetPointData()->AddArray(marker);
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(slab);
  filter->SetBoundaryMarkerArrayName("BoundaryMarker");
  filter->SetRotationAngles(0, 0, 45);
  filter->SetOneCellThickMode(vtkDGMFDeformFilter::ON);
  Errors errors(filter);
  filter->Update();
  ASSERT_TRUE(errors.Messages.empty());
  ASSERT_EQ(filter->GetOutput()->GetNumberOfPoints(), 2 * CirclePoints);

  double p[3];
  slab->GetPoints()->GetPoint(CirclePoints, p); // the back partner of node 0
  slab->GetPoints()->SetPoint(CirclePoints, p[0] + 1e-3, p[1], p[2]);
  slab->GetPoints()->Modified();
  filter->Update();
  EXPECT_TRUE(errors.Contains("not one cell thick")) << "the old layers were reused";
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);

  slab->GetPoints()->SetPoint(CirclePoints, p);
  slab->GetPoints()->Modified();
  errors.Messages.clear();
  filter->Update();
  EXPECT_TRUE(errors.Messages.empty());
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 2 * CirclePoints);
}

TEST(BoundaryNames, TheMeshsOwnBoundaryIsStaticWhenOnlyTheMovingPatchWasRead)
{
  // A reader asked for the internal mesh and the moving patch only (ParaView's OpenFOAM reader
  // with one patch ticked): the square's sides are no block, but they are the mesh's boundary and
  // must stay. The result is the marker's, bit for bit.
  auto circle = dgmf_test::ReadShippedMesh("rotating_circle.vtu", CirclePoints);
  const vtkSmartPointer<vtkUnstructuredGrid> reference = MarkedReference(circle);

  auto all = NamedBlocks(circle);
  auto* patches = vtkMultiBlockDataSet::SafeDownCast(all->GetBlock(1));
  ASSERT_NE(patches, nullptr);
  vtkNew<vtkMultiBlockDataSet> onlyCircle;
  for (unsigned int k = 0; k < patches->GetNumberOfBlocks(); ++k)
  {
    if (std::string(patches->GetMetaData(k)->Get(vtkCompositeDataSet::NAME())) == "circle")
    {
      onlyCircle->SetBlock(0, patches->GetBlock(k));
      Name(onlyCircle, 0, "circle");
    }
  }
  ASSERT_EQ(onlyCircle->GetNumberOfBlocks(), 1u);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, all->GetBlock(0));
  Name(blocks, 0, "internalMesh");
  blocks->SetBlock(1, onlyCircle);
  Name(blocks, 1, "boundary");

  vtkNew<vtkDGMFDeformFilter> named;
  named->SetInputData(blocks);
  named->AddMovingBoundary("circle");
  named->SetRotationAngles(0, 0, 60);
  named->Update();
  vtkUnstructuredGrid* volume = VolumeOf(named->GetOutputDataObject(0));
  ASSERT_NE(volume, nullptr);
  for (vtkIdType i = 0; i < CirclePoints; ++i)
  {
    ASSERT_EQ(std::memcmp(volume->GetPoint(i), reference->GetPoint(i), 3 * sizeof(double)), 0)
      << "node " << i;
  }
}
