// Boundaries chosen by name on a hexahedral box whose six sides are named blocks
// (dgmf_test::HexBoxBlocks, as a CFD reader gives them): the patches against the mesh's own
// boundary, and a node on two slip planes.
#include "vtkDGMFDeformFilter.h"

#include "BoxDeformation.h"
#include "ErrorMessages.h"
#include "HexBoxBlocks.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace
{
using dgmf_test::PointsAfterTranslation;
using dgmf_test::VolumeOf;

/// The volume's points (x, y, z of each) after `input`'s side xmin moved by `translation` and
/// turned by `angleX` degrees about x, the blocks `slip` sliding; empty when the filter fails.
std::vector<double> PointsAfterXminMoves(vtkMultiBlockDataSet* input,
  const std::vector<std::string>& slip, double translation, double angleX)
{
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(input);
  filter->AddMovingBoundary("xmin");
  for (const std::string& name : slip)
  {
    filter->AddSlipBoundary(name.c_str());
  }
  filter->SetTranslation(translation, 0.0, 0.0);
  filter->SetRotationAngles(angleX, 0.0, 0.0);
  filter->Update();
  std::vector<double> xyz;
  if (vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0)))
  {
    for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i)
    {
      const double* p = volume->GetPoint(i);
      xyz.insert(xyz.end(), p, p + 3);
    }
  }
  return xyz;
}
} // namespace

TEST(BoundaryNames, PatchesThatCloseTheVolumeGiveTheResultOfTheMeshsOwnBoundary)
{
  // With every side read, the patches are the volume's boundary and it is not searched for (the
  // faces' parity says so); with "xmax" not read, it is, and "xmax" stays as an unnamed
  // boundary. Both must give the same mesh, bit for bit, and "xmax" must not move.
  const int n = 6;
  std::vector<std::vector<double>> results;
  for (const std::string omit : { "", "xmax" })
  {
    vtkNew<vtkDGMFDeformFilter> filter;
    filter->SetInputData(dgmf_test::HexBoxBlocks(n, omit));
    filter->AddMovingBoundary("xmin");
    filter->SetTranslation(-0.3, 0.2, 0.1);
    filter->SetRotationAngles(0, 5, 0);
    filter->Update();
    vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0));
    ASSERT_NE(volume, nullptr) << "omitted: '" << omit << "'";
    ASSERT_EQ(volume->GetNumberOfPoints(), (n + 1) * (n + 1) * (n + 1));
    std::vector<double> xyz(static_cast<std::size_t>(3 * volume->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i)
    {
      volume->GetPoint(i, xyz.data() + 3 * i);
      const vtkIdType side = n + 1;
      if (i % side == n) // on "xmax": where it was
      {
        const double at[3] = { double(n), double(i / side % side), double(i / side / side) };
        ASSERT_EQ(std::memcmp(xyz.data() + 3 * i, at, sizeof at), 0)
          << "node " << i << " omitted: '" << omit << "'";
      }
    }
    results.push_back(xyz);
  }
  // An interior node moved (the test would not tell otherwise).
  const vtkIdType inside = 2 + (n + 1) * (3 + (n + 1) * 3);
  EXPECT_NE(results[0][3 * inside], 2.0);
  EXPECT_EQ(results[0], results[1]);
}

TEST(BoundaryNames, ANodeOnTwoSlipPlanesSlidesAlongTheirLine)
{
  // A piston: the box's side xmin pushed by 0.5 along x, ymin and zmin slip planes (a quarter
  // model), the other sides static. The nodes on the edge where ymin and zmin meet slide along x,
  // their y and z kept bit for bit (they were held static until 2026-11-30, which inverted cells
  // next to the body on such edges); the nodes on one plane keep its coordinate.
  const int n = 6;
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(dgmf_test::HexBoxBlocks(n, ""));
  filter->AddMovingBoundary("xmin");
  filter->AddSlipBoundary("ymin");
  filter->AddSlipBoundary("zmin");
  filter->SetTranslation(0.5, 0.0, 0.0);
  filter->Update();
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  vtkUnstructuredGrid* volume = VolumeOf(blocks);
  ASSERT_NE(volume, nullptr);
  EXPECT_EQ(blocks->GetFieldData()->GetArray("InvertedCellCount")->GetTuple1(0), 0.0);
  const vtkIdType side = n + 1;
  double slid = 1.0;
  for (int x = 1; x < n; ++x)
  {
    const double* p = volume->GetPoint(x); // y = 0, z = 0
    ASSERT_EQ(p[1], 0.0) << "edge node x = " << x;
    ASSERT_EQ(p[2], 0.0) << "edge node x = " << x;
    slid = std::min(slid, p[0] - x);
    ASSERT_EQ(volume->GetPoint(x + side * side * 3)[1], 0.0); // on ymin only (z = 3)
    ASSERT_EQ(volume->GetPoint(x + side * 3)[2], 0.0);        // on zmin only (y = 3)
  }
  EXPECT_GT(slid, 0.01) << "the edge's nodes follow the piston";
}

TEST(BoundaryNames, AnEntryOfSeveralBlocksIsOneBody)
{
  // "y*" and "ymin|ymax" name both y sides as one body (a patch group, a wing of several
  // patches): the same bits, every node of both sides moved by the translation, and another
  // result than the two sides as two bodies (each its own damping field). An alternative that
  // names no block is an error.
  const int n = 6;
  const auto run = [n](const std::vector<std::string>& moving, std::string* error = nullptr)
  { return PointsAfterTranslation(dgmf_test::HexBoxBlocks(n, ""), moving, error); };
  const std::vector<double> glob = run({ "y*" });
  const std::vector<double> alternatives = run({ "ymin | ymax" });
  // Two bodies differ from one where a graph element touches both (the damping is not linear):
  // adjacent sides, whose common edge such elements surround (opposite sides of the cube may
  // have no node in an element touching both, and then give the same points either way).
  const std::vector<double> adjacentOne = run({ "ymin|zmin" });
  const std::vector<double> twoBodies = run({ "ymin", "zmin" });
  const std::size_t side = n + 1;
  ASSERT_EQ(glob.size(), 3 * side * side * side);
  EXPECT_EQ(glob, alternatives);
  EXPECT_NE(adjacentOne, twoBodies);
  for (std::size_t i = 0; i < side * side * side; ++i)
  {
    const std::size_t y = i / side % side;
    if (y == 0 || y == static_cast<std::size_t>(n))
    {
      ASSERT_EQ(glob[3 * i + 2], static_cast<double>(i / side / side) + 0.3) << "node " << i;
    }
  }
  std::string error;
  EXPECT_TRUE(run({ "ymin|ymxa" }, &error).empty());
  EXPECT_NE(error.find("No block of the input matches 'ymxa'"), std::string::npos) << error;
}

TEST(BoundaryNames, MovingNodesOnStaticBoundariesAreSaid)
{
  // The box's side xmin moving: its edges lie on the four sides around it, static (named so, or
  // for not being named); their faces there shear (a wedge or cyclic patch, a ground plane under
  // a wheel: the solver's check fails). Said since 2026-11-30, with the nodes each shares; not
  // when they slip.
  const int n = 6;
  const std::string edge = std::to_string(n + 1);
  for (const std::vector<std::string>& slip :
    { std::vector<std::string>{}, { "ymin" }, { "ymin", "ymax", "zmin", "zmax" } })
  {
    vtkNew<vtkDGMFDeformFilter> filter;
    dgmf_test::ErrorMessages warnings(filter, vtkCommand::WarningEvent);
    filter->SetInputData(dgmf_test::HexBoxBlocks(n, ""));
    filter->AddMovingBoundary("xmin");
    if (slip.empty())
    {
      filter->AddStaticBoundary("zmax");
    }
    for (const std::string& name : slip)
    {
      filter->AddSlipBoundary(name.c_str());
    }
    filter->SetTranslation(0.0, 0.0, 0.0);
    filter->SetRotationAngles(2.0, 0.0, 0.0);
    filter->Update();
    ASSERT_NE(VolumeOf(filter->GetOutputDataObject(0)), nullptr) << slip.size();
    EXPECT_EQ(warnings.Contains("Nodes of the moving boundaries also lie on static boundaries"),
      slip.size() < 4)
      << slip.size();
    EXPECT_EQ(warnings.Contains("'ymin' (" + edge + ", static for not being named)"), slip.empty())
      << slip.size();
    EXPECT_EQ(warnings.Contains("'zmax' (" + edge + ")"), slip.empty()) << slip.size();
    EXPECT_EQ(
      warnings.Contains("'zmax' (" + edge + ", static for not being named)"), slip.size() == 1)
      << slip.size();
  }
}

TEST(BoundaryNames, AMotionTakingMovingNodesOffASlipPlaneIsSaid)
{
  // The box's side xmin moving, ymin a slip plane: the nodes on their common edge are moving
  // (moving wins over slip). Along the plane (x) they stay in it: nothing said; across it (y)
  // they leave it, and the plane is no longer flat (a half model pitched across its symmetry
  // plane: checkMesh failed "not planar" with no word until 2026-11-30).
  const int n = 6;
  for (const double across : { 0.0, 0.2 })
  {
    vtkNew<vtkDGMFDeformFilter> filter;
    dgmf_test::ErrorMessages warnings(filter, vtkCommand::WarningEvent);
    filter->SetInputData(dgmf_test::HexBoxBlocks(n, ""));
    filter->AddMovingBoundary("xmin");
    filter->AddSlipBoundary("ymin");
    filter->SetTranslation(0.3, across, 0.0);
    filter->Update();
    ASSERT_NE(VolumeOf(filter->GetOutputDataObject(0)), nullptr) << across;
    EXPECT_EQ(warnings.Contains("The motion takes " + std::to_string(n + 1) +
                " nodes of the moving boundaries that lie on the slip boundary 'ymin' off its "
                "plane, by up to 0.2"),
      across > 0.0)
      << across;
    EXPECT_EQ(warnings.Contains("off its plane"), across > 0.0) << across;
    // The advice is one that helps: a static plane's nodes on the body still move (moving wins),
    // and the plane would bend all the same (the advice said "make the boundary static" until
    // 2026-11-30, which only added the moving-on-static warning).
    EXPECT_EQ(warnings.Contains("Keep the body's motion in the plane"), across > 0.0) << across;
  }
}

TEST(BoundaryNames, ASlipEntryOfSeveralPlanesIsAPlaneEach)
{
  // One slip entry naming several blocks that are not one plane ("ymin|ymax": parallel sides;
  // "ymin|zmin": two sides meeting along an edge, as a wedge's planes on its axis; an OpenFOAM
  // patch group such as "wedge" or "symmetryPlane" is such an entry) is a plane per block: the
  // bits of the blocks named one by one (until 2026-11-30 "The slip boundary ... is not planar").
  const int n = 6;
  const auto deform = [n](const std::vector<std::string>& slip)
  { return PointsAfterXminMoves(dgmf_test::HexBoxBlocks(n, ""), slip, 0.3, 3.0); };
  for (const auto& [together, apart] :
    { std::pair<std::string, std::vector<std::string>>{ "ymin|ymax", { "ymin", "ymax" } },
      std::pair<std::string, std::vector<std::string>>{ "ymin|zmin", { "ymin", "zmin" } } })
  {
    const std::vector<double> one = deform({ together }), each = deform(apart);
    ASSERT_EQ(one.size(), std::size_t(3 * (n + 1) * (n + 1) * (n + 1))) << together;
    EXPECT_EQ(one, each) << together;
  }
}

TEST(BoundaryNames, APlaneCutIntoPatchesNamedApartIsOnePlane)
{
  // ymin cut into two patches along x = n/2 ("ymin1", "ymin2"), zmin slipping too: named apart,
  // in one entry, or uncut, the same bits. Until 2026-11-30 the nodes where the two halves meet
  // were taken to be on two planes, and the one on zmin as well on three: made static, it held
  // the line x = n/2 on ymin still (a quarter model translated by 0.65 had 355 inverted cells).
  const int n = 6;
  const auto split = [n]()
  {
    vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(n, "");
    auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
    vtkNew<vtkMultiBlockDataSet> cut;
    unsigned int index = 0;
    for (unsigned int b = 0; b < boundary->GetNumberOfBlocks(); ++b)
    {
      const std::string name = boundary->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
      auto* faces = vtkPolyData::SafeDownCast(boundary->GetBlock(b));
      if (name != "ymin")
      {
        cut->SetBlock(index, faces);
        cut->GetMetaData(index++)->Set(vtkCompositeDataSet::NAME(), name.c_str());
        continue;
      }
      for (int half = 0; half < 2; ++half)
      {
        // The side's quads are rows of n along z, one row per x (ymin): cut at x = n/2.
        vtkNew<vtkCellArray> quads;
        for (vtkIdType c = 0; c < faces->GetNumberOfCells(); ++c)
        {
          if ((c / n < n / 2) == (half == 0))
          {
            vtkNew<vtkIdList> ids;
            faces->GetCellPoints(c, ids);
            quads->InsertNextCell(ids);
          }
        }
        vtkNew<vtkPolyData> piece;
        piece->SetPoints(faces->GetPoints());
        piece->SetPolys(quads);
        cut->SetBlock(index, piece);
        cut->GetMetaData(index++)->Set(vtkCompositeDataSet::NAME(), half ? "ymin2" : "ymin1");
      }
    }
    blocks->SetBlock(1, cut);
    return blocks;
  };
  const auto deform = [](vtkMultiBlockDataSet* input, const std::vector<std::string>& slip)
  { return PointsAfterXminMoves(input, slip, 0.4, 0.0); };
  const std::vector<double> whole = deform(dgmf_test::HexBoxBlocks(n, ""), { "ymin", "zmin" });
  ASSERT_EQ(whole.size(), std::size_t(3 * (n + 1) * (n + 1) * (n + 1)));
  EXPECT_EQ(deform(split(), { "ymin1", "ymin2", "zmin" }), whole);
  EXPECT_EQ(deform(split(), { "ymin1|ymin2", "zmin" }), whole);
  // The cut line moved (the test would not tell otherwise): node (n/2, 0, 1).
  const std::size_t node = n / 2 + (n + 1) * (0 + (n + 1) * 1);
  EXPECT_GT(whole[3 * node], double(n / 2));
}

TEST(BoundaryNames, ABlockOfTheNameGivenWinsOverContainersAndRegionPrefixes)
{
  // A mesh file's group named "boundary" sits in the reader's container "boundary": naming it
  // moved every patch, the whole mesh turned rigidly; a group "patch/wing" beside a group "wing"
  // was taken for "wing" (the OpenFOAM region prefix dropped). Both until 2026-11-30.
  const int n = 4;
  auto blocks = dgmf_test::HexBoxBlocks(n, "");
  auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  ASSERT_NE(boundary, nullptr);
  const auto rename = [&](const char* from, const char* to)
  {
    for (unsigned int b = 0; b < boundary->GetNumberOfBlocks(); ++b)
    {
      if (std::strcmp(boundary->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()), from) == 0)
      {
        boundary->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), to);
      }
    }
  };
  rename("xmin", "boundary");
  rename("ymin", "patch/wing");
  rename("ymax", "wing");
  for (const char* name : { "boundary", "patch/wing" })
  {
    vtkNew<vtkDGMFDeformFilter> filter;
    filter->SetInputData(blocks);
    filter->AddMovingBoundary(name);
    filter->SetTranslation(0.0, 0.0, 0.1); // along the named side, across none
    filter->Update();
    vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0));
    ASSERT_NE(volume, nullptr) << name;
    vtkUnstructuredGrid* input = VolumeOf(blocks);
    // Only the named side's nodes move by the whole translation: x = 0 for "boundary" (xmin),
    // y = 0 for "patch/wing" (ymin); the nodes of the opposite side (at n) stay.
    const int axis = std::strcmp(name, "boundary") == 0 ? 0 : 1;
    vtkIdType moved = 0, oppositeMoved = 0;
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double before[3], after[3];
      input->GetPoint(i, before);
      volume->GetPoint(i, after);
      const bool movedAll = std::abs(after[2] - before[2] - 0.1) < 1e-12;
      moved += before[axis] == 0.0 && movedAll ? 1 : 0;
      oppositeMoved += before[axis] == n && after[2] != before[2] ? 1 : 0;
    }
    EXPECT_EQ(moved, (n + 1) * (n + 1)) << name;
    EXPECT_EQ(oppositeMoved, 0) << name;
  }
  // The group's block not loaded (a piece of a distributed mesh without it): its name is still
  // the group's, not the container's: nothing to move here, not every patch.
  for (unsigned int b = 0; b < boundary->GetNumberOfBlocks(); ++b)
  {
    if (std::strcmp(boundary->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()), "boundary") == 0)
    {
      boundary->SetBlock(b, nullptr);
    }
  }
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_test::ErrorMessages errors(filter);
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("boundary");
  filter->SetTranslation(0.0, 0.0, 0.1);
  filter->Update();
  EXPECT_EQ(VolumeOf(filter->GetOutputDataObject(0)), nullptr);
  EXPECT_TRUE(errors.Contains("No block of the input is named 'boundary'"));
  // No block named so at all: the reader's container is not a boundary either (only a selector,
  // "/Root/boundary/...", reaches into the tree).
  vtkNew<vtkDGMFDeformFilter> plain;
  dgmf_test::ErrorMessages plainErrors(plain);
  plain->SetInputData(dgmf_test::HexBoxBlocks(n, ""));
  plain->AddMovingBoundary("boundary");
  plain->Update();
  EXPECT_EQ(VolumeOf(plain->GetOutputDataObject(0)), nullptr);
  EXPECT_TRUE(plainErrors.Contains("No block of the input is named 'boundary'"));
}

TEST(BoundaryNames, ASlipPlaneMeetingAnUnreadBoundaryHasItsEdgesStatic)
{
  // The box read with its moving side xmin and its slip side ymin only (the others unread: static
  // as the mesh's own boundary). The slip side's edges on the unread sides are static, as when
  // those sides are read as static patches (static over slip): until 2026-11-30 they stayed slip,
  // the slip side lay outside the graph (a half model read without its far field: 168 inverted
  // cells, checkMesh failed). The same points as with every side read.
  // Also a slip entry of two blocks, not one plane (a plane each, their common edge a line):
  // its nodes made static must not come back as slip nodes ("slip node 6 is not a slip boundary
  // node" after the first version of this change).
  const int n = 6;
  for (const std::string slip : { "ymin", "ymin|zmin" })
  {
    const auto deform = [&](bool everySide)
    {
      auto blocks = dgmf_test::HexBoxBlocks(n, "");
      auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
      for (unsigned int b = 0; !everySide && b < boundary->GetNumberOfBlocks(); ++b)
      {
        const std::string name = boundary->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
        if (name != "xmin" && name != "ymin" && name != "zmin")
        {
          boundary->SetBlock(b, nullptr);
        }
      }
      vtkNew<vtkDGMFDeformFilter> filter;
      filter->SetInputData(blocks);
      filter->AddMovingBoundary("xmin");
      if (slip == "ymin")
      {
        filter->AddStaticBoundary("zmin");
      }
      filter->AddSlipBoundary(slip.c_str());
      filter->SetTranslation(0.0, 0.0, 0.3); // along the slip side
      filter->Update();
      vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0));
      EXPECT_NE(volume, nullptr) << everySide;
      std::vector<double> points;
      for (vtkIdType i = 0; volume && i < volume->GetNumberOfPoints(); ++i)
      {
        double p[3];
        volume->GetPoint(i, p);
        points.insert(points.end(), p, p + 3);
      }
      vtkDataArray* count =
        filter->GetOutputDataObject(0)->GetFieldData()->GetArray("OutsideNodeCount");
      const double outside = count ? count->GetTuple1(0) : -1.0;
      return std::make_pair(points, outside);
    };
    const auto [read, readOutside] = deform(true);
    const auto [unread, unreadOutside] = deform(false);
    EXPECT_EQ(readOutside, 0.0) << slip;
    EXPECT_EQ(unreadOutside, 0.0) << slip;
    ASSERT_EQ(unread.size(), read.size()) << slip;
    double largest = 0.0;
    for (std::size_t k = 0; k < read.size(); ++k)
    {
      largest = std::max(largest, std::abs(unread[k] - read[k]));
    }
    EXPECT_LT(largest, 1e-12) << slip;
  }
}

TEST(BoundaryNames, TheVolumeBlockIsRefusedAlsoWhenPatchesHoldPointsOfTheirOwn)
{
  // A piece of a redistributed mesh: a patch block holds a point its volume piece does not, so
  // the volume block is not all of the merged nodes. Until 2026-11-30 the volume block named as
  // moving was then taken (pvbatch on 2 processes turned the whole mesh); it is the volume by
  // its cells.
  auto blocks = dgmf_test::HexBoxBlocks(3, "");
  auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  auto* side = vtkPolyData::SafeDownCast(boundary->GetBlock(0));
  ASSERT_NE(side, nullptr);
  side->GetPoints()->InsertNextPoint(10.0, 10.0, 10.0); // in no cell of the volume piece
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_test::ErrorMessages errors(filter);
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("internalMesh");
  filter->SetTranslation(0.1, 0.0, 0.0);
  filter->Update();
  EXPECT_EQ(VolumeOf(filter->GetOutputDataObject(0)), nullptr);
  EXPECT_TRUE(errors.Contains("'internalMesh' is the whole mesh (its volume block)"));
}
