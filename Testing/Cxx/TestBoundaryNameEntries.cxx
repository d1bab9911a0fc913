// Boundary entries of the named-block boxes (HexBoxBlocks.h): a file's family of blocks, entries
// that hold every node or no point, and a block changed in place.
#include "vtkDGMFDeformFilter.h"

#include "BoxDeformation.h"
#include "ErrorMessages.h"
#include "HexBoxBlocks.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using dgmf_test::PointsAfterTranslation;
using dgmf_test::VolumeOf;

TEST(BoundaryNames, AFamilyOfBlocksIsChosenByItsName)
{
  // A mesh file's family (a CGNS boundary condition's FamilyName, field data BoundaryFamily on
  // its block): "ysides" names ymin and ymax as one body, the result of "ymin|ymax", also as an
  // alternative. A block of the very name wins over a family of that name; unknown names list
  // the families.
  const int n = 4;
  const auto run = [n](const std::vector<std::string>& moving, const std::string& familyOfZmax,
                     std::string* error = nullptr)
  {
    vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(n, "");
    auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
    for (unsigned int b = 0; b < boundary->GetNumberOfBlocks(); ++b)
    {
      const std::string name = boundary->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
      const std::string family =
        name == "ymin" || name == "ymax" ? "ysides" : (name == "zmax" ? familyOfZmax : "");
      if (!family.empty())
      {
        vtkNew<vtkStringArray> array;
        array->SetName("BoundaryFamily");
        array->InsertNextValue(family);
        boundary->GetBlock(b)->GetFieldData()->AddArray(array);
      }
    }
    return PointsAfterTranslation(blocks, moving, error);
  };
  std::string error;
  const std::vector<double> family = run({ "ysides" }, "", &error);
  ASSERT_EQ(family.size(), 3u * (n + 1) * (n + 1) * (n + 1)) << error;
  EXPECT_EQ(family, run({ "ymin|ymax" }, "", &error));
  EXPECT_EQ(run({ "ysides|zmin" }, "", &error), run({ "ymin|ymax|zmin" }, "", &error));
  // zmax in a family named "ymin": "ymin" is still the block ymin.
  EXPECT_EQ(run({ "ymin" }, "ymin", &error), run({ "ymin" }, "", &error));
  EXPECT_TRUE(run({ "ysidez" }, "", &error).empty());
  EXPECT_NE(error.find("ymin (family ysides)"), std::string::npos) << error;
  EXPECT_NE(error.find("ymax (family ysides), zmin"), std::string::npos) << error;
}

TEST(BoundaryNames, MovingBoundariesHoldingEveryNodeAreRefused)
{
  // One cell between xmin and xmax: the two sides hold every node, as the empty patch
  // frontAndBack of a 2D mesh does; moving them turned the whole mesh rigidly until 2026-11-30.
  // One side alone is a deformation.
  for (const auto& [moving, refused] :
    { std::pair{ "xmin|xmax", true }, std::pair{ "xmin", false } })
  {
    vtkNew<vtkDGMFDeformFilter> filter;
    dgmf_test::ErrorMessages errors(filter);
    filter->SetInputData(dgmf_test::HexBoxBlocks(1, ""));
    filter->AddMovingBoundary(moving);
    filter->SetTranslation(0.0, 0.0, 0.1);
    filter->Update();
    EXPECT_EQ(VolumeOf(filter->GetOutputDataObject(0)) == nullptr, refused) << moving;
    EXPECT_EQ(errors.Contains("hold every node of the mesh"), refused) << moving;
  }
  // Two bodies that hold every node (a film between two moving walls) may be meant: said.
  vtkNew<vtkDGMFDeformFilter> twoBodies;
  dgmf_test::ErrorMessages warnings(twoBodies, vtkCommand::WarningEvent);
  twoBodies->SetInputData(dgmf_test::HexBoxBlocks(1, ""));
  twoBodies->AddMovingBoundary("xmin");
  twoBodies->AddMovingBoundary("xmax");
  twoBodies->Update();
  EXPECT_NE(VolumeOf(twoBodies->GetOutputDataObject(0)), nullptr);
  EXPECT_TRUE(warnings.Contains("hold every node of the mesh"));
}

TEST(BoundaryNames, ABlockChangedInPlaceIsReadAgain)
{
  // The volume block's points moved in place and the block marked Modified(), then a new motion:
  // the merge shares the block's points array, whose own MTime did not change; the graph of the
  // old points was reused until a review of 2026-11-30. The result is a fresh filter's.
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(4, "");
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("xmin");
  filter->SetTranslation(0.1, 0.0, 0.0);
  filter->Update();
  auto* volume = vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0));
  const vtkIdType inner = 1 + 5 * (2 + 5 * 2); // (1, 2, 2): an interior node
  double p[3];
  volume->GetPoint(inner, p);
  p[0] += 0.3;
  volume->GetPoints()->GetData()->SetTuple(inner, p); // no MTime change of the points
  volume->Modified();
  filter->SetTranslation(0.2, 0.0, 0.0);
  filter->Update();
  vtkNew<vtkDGMFDeformFilter> fresh;
  vtkNew<vtkMultiBlockDataSet> copy;
  copy->DeepCopy(blocks);
  fresh->SetInputData(copy);
  fresh->AddMovingBoundary("xmin");
  fresh->SetTranslation(0.2, 0.0, 0.0);
  fresh->Update();
  vtkUnstructuredGrid* reused = VolumeOf(filter->GetOutputDataObject(0));
  vtkUnstructuredGrid* anew = VolumeOf(fresh->GetOutputDataObject(0));
  ASSERT_TRUE(reused && anew);
  double largest = 0.0;
  for (vtkIdType i = 0; i < reused->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      largest = std::max(largest, std::abs(reused->GetPoint(i)[k] - anew->GetPoint(i)[k]));
    }
  }
  EXPECT_EQ(largest, 0.0);
}

TEST(BoundaryNames, AnEntryOfAnEmptyBlockIsSaid)
{
  // An OpenFOAM patch of no faces named as slip (accepted without a word until 2026-11-30): it
  // has no effect, and the warning says so; the result is that of the run without it.
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(3, "");
  auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  const unsigned int last = boundary->GetNumberOfBlocks();
  boundary->SetBlock(last, vtkNew<vtkPolyData>());
  boundary->GetMetaData(last)->Set(vtkCompositeDataSet::NAME(), "left");
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_test::ErrorMessages warnings(filter, vtkCommand::WarningEvent);
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("xmin");
  filter->AddSlipBoundary("left");
  filter->SetTranslation(0.1, 0.0, 0.0);
  filter->Update();
  ASSERT_NE(VolumeOf(filter->GetOutputDataObject(0)), nullptr);
  EXPECT_TRUE(warnings.Contains("The boundaries 'left' (slip) hold no point of the input"));
}

TEST(BoundaryNames, ANodeSetTheBodyDragsIsSaid)
{
  // Side ymin given as a node set (vertices: an Exodus file's boundaries as meshio writes them):
  // the moving side xmin drags its edge, said as for faces (no warning for node sets until
  // 2026-11-30); a node set wholly on the body (xmin's nodes) shears nothing and is not listed.
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = dgmf_test::HexBoxBlocks(3, "");
  auto* boundary = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(1));
  for (unsigned int b = 0; b < boundary->GetNumberOfBlocks(); ++b)
  {
    const std::string name = boundary->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
    auto* faces = vtkPolyData::SafeDownCast(boundary->GetBlock(b));
    if (name != "ymin" && name != "xmin")
    {
      continue;
    }
    vtkNew<vtkPolyData> nodes;
    nodes->SetPoints(faces->GetPoints());
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType i = 0; i < faces->GetNumberOfPoints(); ++i)
    {
      vertices->InsertNextCell(1, &i);
    }
    nodes->SetVerts(vertices);
    if (name == "ymin")
    {
      boundary->SetBlock(b, nodes);
    }
    else
    {
      const unsigned int last = boundary->GetNumberOfBlocks();
      boundary->SetBlock(last, nodes);
      boundary->GetMetaData(last)->Set(vtkCompositeDataSet::NAME(), "xminNodes");
    }
  }
  vtkNew<vtkDGMFDeformFilter> filter;
  dgmf_test::ErrorMessages warnings(filter, vtkCommand::WarningEvent);
  filter->SetInputData(blocks);
  filter->AddMovingBoundary("xmin");
  filter->SetTranslation(0.0, 0.0, 0.1);
  filter->Update();
  ASSERT_NE(VolumeOf(filter->GetOutputDataObject(0)), nullptr);
  EXPECT_TRUE(warnings.Contains("'ymin' (4, static for not being named)"));
  EXPECT_FALSE(warnings.Contains("xminNodes"));
}
