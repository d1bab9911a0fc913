// The gathering of a grid's nodes: its arrays found and checked, the boundary marker converted
// into node kinds (on the threads, kept while the marker is unchanged).
#include "DGMFBoundaryNames.h"
#include "DGMFInputNodes.h"
#include "DGMFSMPTools.h"
#include "HexahedraOfGrid.h"
#include "TwoSquares.h"

#include "dgmf/NodeKind.h"

#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

TEST(InputNodes, AMarkerOfManyBlocksIsConvertedOnTheThreadsAndItsFirstBadValueNamed)
{
  // 200,000 points in the plane z = 0 (and a triangle: a 2D mesh), a marker of 1s and 2s: converted
  // in blocks of 65,536 on two threads.
  const vtkIdType n = 200000;
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->InsertNextPoint(double(i % 1000), double(i / 1000), 0.0);
    marker->InsertNextValue(i % 3 == 0 ? 2 : i % 3 == 1 ? 1 : 0);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType triangle[3] = { 0, 1, 1000 };
  grid->InsertNextCell(VTK_TRIANGLE, 3, triangle);
  grid->GetPointData()->AddArray(marker);
  dgmf_vtk::GatherOptions options;
  options.Arrays.Marker = "BoundaryMarker";
  const auto gather = [&]()
  {
    std::string error = "no error";
    dgmf_vtk::InputGatherer gatherer;
    dgmf_vtk::InputNodes nodes;
    dgmf_vtk::RunWithThreads(2,
      [&]()
      {
        try
        {
          gatherer.Gather(grid, options, nodes);
        }
        catch (const std::invalid_argument& e)
        {
          error = e.what();
        }
      });
    return std::make_pair(nodes.Kinds, error);
  };
  const auto good = gather();
  ASSERT_EQ(good.second, "no error");
  ASSERT_EQ(good.first.size(), static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const dgmf::NodeKind expected = i % 3 == 0 ? dgmf::NodeKind::MovingBoundary
      : i % 3 == 1                             ? dgmf::NodeKind::StaticBoundary
                                               : dgmf::NodeKind::Interior;
    ASSERT_EQ(good.first[static_cast<std::size_t>(i)], expected) << "point " << i;
  }
  // Bad values in the second and third blocks (and a later one in the second): the first is
  // named, whichever block a thread finishes first.
  marker->SetValue(150000, 9);
  marker->SetValue(70001, 5);
  marker->SetValue(131000, 4);
  marker->Modified();
  EXPECT_NE(
    gather().second.find("'BoundaryMarker' has the value 5 at point 70001"), std::string::npos);
}

TEST(InputNodes, ArraysAreFoundCheckedForShapeAndNamedInErrors)
{
  auto grid = TwoSquares();
  dgmf_vtk::InputGatherer gatherer;
  dgmf_vtk::InputNodes nodes;
  dgmf_vtk::GatherOptions options;
  options.Arrays.Marker = "BoundaryMarker";
  const dgmf_vtk::SelectedArrays arrays = options.Arrays;
  gatherer.Gather(grid, options, nodes);
  EXPECT_EQ(nodes.NumberOfNodes, 6u);
  EXPECT_EQ(nodes.Dimension, 2);
  EXPECT_EQ(nodes.Kinds[2], dgmf::NodeKind::MovingBoundary);
  EXPECT_EQ(nodes.Displacement, nullptr);
  const auto message = [&](const dgmf_vtk::SelectedArrays& selected)
  {
    try
    {
      dgmf_vtk::InputNodes ignored;
      dgmf_vtk::GatherOptions given;
      given.Arrays = selected;
      gatherer.Gather(grid, given, ignored);
    }
    catch (const std::invalid_argument& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(
    message(dgmf_vtk::SelectedArrays()).find("Select a boundary-marker array"), std::string::npos);
  dgmf_vtk::SelectedArrays wrong;
  wrong.Displacement = "BoundaryMarker";
  EXPECT_NE(
    message(wrong).find("'BoundaryMarker' has 1 components; it must have 3"), std::string::npos);
  wrong = arrays;
  wrong.BodyIds = "Nope";
  EXPECT_NE(
    message(wrong).find("The body-id array 'Nope' is not a point array"), std::string::npos);
  // An array of another length than the points (a hand-made grid): named, never read past.
  vtkNew<vtkIntArray> shorter;
  shorter->SetName("Short");
  shorter->SetNumberOfValues(5);
  shorter->FillValue(1);
  grid->GetPointData()->AddArray(shorter);
  wrong = arrays;
  wrong.Marker = "Short";
  EXPECT_NE(message(wrong).find("The boundary-marker array 'Short' has 5 tuples; the mesh has 6 "
                                "points"),
    std::string::npos);
  grid->GetPointData()->GetArray("BoundaryMarker")->SetTuple1(1, 7);
  grid->GetPointData()->GetArray("BoundaryMarker")->Modified();
  EXPECT_NE(
    message(arrays).find("The boundary-marker array 'BoundaryMarker' has the value 7 at point 1"),
    std::string::npos);
}

TEST(InputNodes, AMarkerIsNotReusedAfterAnotherOnesConversionFailedHalfWay)
{
  // Two markers, "A" and "B": B differs at point 0 and has a bad value at its last point, so its
  // conversion writes point 0 before it fails. A's kinds, kept from its first conversion, must not
  // be taken again afterwards.
  auto grid = TwoSquares();
  vtkNew<vtkIntArray> b;
  b->SetName("B");
  for (int value : { 2, 0, 2, 1, 0, 7 })
  {
    b->InsertNextValue(value);
  }
  grid->GetPointData()->AddArray(b);
  dgmf_vtk::InputGatherer gatherer;
  const auto kindsWith = [&](const char* marker)
  {
    dgmf_vtk::GatherOptions options;
    options.Arrays.Marker = marker;
    dgmf_vtk::InputNodes nodes;
    gatherer.Gather(grid, options, nodes);
    return nodes.Kinds;
  };
  const std::vector<dgmf::NodeKind> first = kindsWith("BoundaryMarker");
  EXPECT_EQ(first[0], dgmf::NodeKind::StaticBoundary);
  EXPECT_THROW(kindsWith("B"), std::invalid_argument);
  EXPECT_EQ(kindsWith("BoundaryMarker"), first);
}

namespace
{
/// A box of n^3 hexahedra and its sides' quads kept apart on its points (a composite input's
/// patches: CompositeMesh::GetPatches), with the roles of named boundaries on the sides read:
/// the side x = 0 moving, the others static; without the side x = n when `allSides` is false (a
/// patch the reader was not asked for).
struct BoxWithPatches
{
  static constexpr int N = 5;
  vtkSmartPointer<vtkUnstructuredGrid> Volume = dgmf_test::HexahedralBox(N);
  vtkNew<vtkUnstructuredGrid> Patches;
  dgmf_vtk::NodeRoles Roles;

  static vtkIdType Id(int i, int j, int k) { return i + (N + 1) * (j + (N + 1) * k); }

  explicit BoxWithPatches(bool allSides)
  {
    const int n = N;
    vtkPoints* points = this->Volume->GetPoints();
    this->Patches->SetPoints(points);
    this->Roles.Kinds.resize(static_cast<std::size_t>(points->GetNumberOfPoints()));
    std::fill(this->Roles.Kinds.begin(), this->Roles.Kinds.end(), dgmf::NodeKind::Interior);
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int side = 0; side < 2; ++side)
      {
        if (!allSides && axis == 0 && side == 1)
        {
          continue;
        }
        for (int b = 0; b < n; ++b)
        {
          for (int a = 0; a < n; ++a)
          {
            vtkIdType quad[4];
            const int corners[4][2] = { { a, b }, { a + 1, b }, { a + 1, b + 1 }, { a, b + 1 } };
            for (int k = 0; k < 4; ++k)
            {
              int ijk[3];
              ijk[axis] = side * n;
              ijk[(axis + 1) % 3] = corners[k][0];
              ijk[(axis + 2) % 3] = corners[k][1];
              quad[k] = Id(ijk[0], ijk[1], ijk[2]);
              this->Roles.Kinds[static_cast<std::size_t>(quad[k])] = axis == 0 && side == 0
                ? dgmf::NodeKind::MovingBoundary
                : dgmf::NodeKind::StaticBoundary;
            }
            this->Patches->InsertNextCell(VTK_QUAD, 4, quad);
          }
        }
      }
    }
    // The moving side's own nodes are moving, corners shared with a static side too.
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        this->Roles.Kinds[static_cast<std::size_t>(Id(0, j, k))] = dgmf::NodeKind::MovingBoundary;
  }

  /// The options of a composite input's merged mesh, with these roles and patches.
  dgmf_vtk::GatherOptions Options()
  {
    dgmf_vtk::GatherOptions options;
    options.Roles = &this->Roles;
    options.Patches = this->Patches;
    options.DistinctPoints = true;
    options.OneCellThick = dgmf_vtk::OneCellThickOff;
    return options;
  }
};
} // namespace

TEST(InputNodes, PatchesThatCloseTheVolumeApartSpareTheSearchForItsBoundary)
{
  // With every side, the quads close the volume and its boundary is not searched for; without
  // the side x = n, it is, and that side becomes static.
  const int n = BoxWithPatches::N;
  const auto id = &BoxWithPatches::Id;
  for (const bool allSides : { true, false })
  {
    BoxWithPatches box(allSides);
    dgmf_vtk::InputGatherer gatherer;
    dgmf_vtk::InputNodes nodes;
    gatherer.Gather(box.Volume, box.Options(), nodes);
    EXPECT_EQ(gatherer.SearchedBoundary(), !allSides);
    EXPECT_EQ(nodes.Patches, box.Patches.Get());
    // The side x = n: static either way (its patch's role, or the mesh's own boundary).
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        EXPECT_EQ(
          nodes.Kinds[static_cast<std::size_t>(id(n, j, k))], dgmf::NodeKind::StaticBoundary)
          << "node " << id(n, j, k) << ", all sides " << allSides;
    EXPECT_EQ(nodes.Kinds[static_cast<std::size_t>(id(2, 2, 2))], dgmf::NodeKind::Interior);
  }
}

TEST(InputNodes, TheClosingCheckIsKeptForTheSameCellsOnceItsDeferredHashHasRun)
{
  // The check that the patches close the volume is kept with a hash of the volume's cells, so
  // that a reader's new objects with the same cells skip it. The hash is left as a job for later
  // (beside the graph's insertion): until it has run, only the same object matches.
  BoxWithPatches box(true);
  dgmf_vtk::InputGatherer gatherer;
  const auto gather = [&](vtkUnstructuredGrid* volume)
  {
    dgmf_vtk::InputNodes nodes;
    gatherer.Gather(volume, box.Options(), nodes);
    EXPECT_FALSE(gatherer.SearchedBoundary());
    return gatherer.TakeDeferredJobs();
  };
  const auto copyOf = [&]()
  {
    auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New(); // a reader's next time step
    copy->DeepCopy(box.Volume);
    return copy;
  };
  EXPECT_EQ(gather(box.Volume).size(), 1u) << "checked: the key's hash left for later";
  EXPECT_TRUE(gatherer.TakeDeferredJobs().empty()) << "taken once";
  EXPECT_TRUE(gather(box.Volume).empty()) << "the same object: kept without a hash";
  auto first = copyOf();
  const auto notRun = gather(first);
  EXPECT_EQ(notRun.size(), 1u) << "a new object before the hash ran: checked again";
  for (const auto& job : notRun)
  {
    job();
  }
  EXPECT_TRUE(gather(copyOf()).empty()) << "a new object of the same cells, after the hash ran";
  auto changed = copyOf();
  const vtkIdType swapped[8] = { BoxWithPatches::Id(1, 0, 0), BoxWithPatches::Id(0, 0, 0),
    BoxWithPatches::Id(0, 1, 0), BoxWithPatches::Id(1, 1, 0), BoxWithPatches::Id(1, 0, 1),
    BoxWithPatches::Id(0, 0, 1), BoxWithPatches::Id(0, 1, 1), BoxWithPatches::Id(1, 1, 1) };
  changed->GetCells()->ReplaceCellAtId(0, 8, swapped); // a mirrored first cell: other cells
  EXPECT_EQ(gather(changed).size(), 1u) << "other cells: checked again";
}
