// Deforming the named-block boxes of HexBoxBlocks.h in the boundary-name tests: the volume of an
// output, and the points after named entries moved (TestBoundaryNamesOnBoxes.cxx,
// TestBoundaryNameEntries.cxx).
#ifndef dgmf_test_BoxDeformation_h
#define dgmf_test_BoxDeformation_h

#include "vtkDGMFDeformFilter.h"

#include "ErrorMessages.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <string>
#include <vector>

namespace dgmf_test
{
/// The volume block (block 0) of a filter's multiblock output, or null.
inline vtkUnstructuredGrid* VolumeOf(vtkDataObject* output)
{
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(output);
  return blocks ? vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0)) : nullptr;
}

/// The volume's points after the entries `moving` (one body each) of `blocks` translated by 0.3
/// along z; empty when the filter fails (its messages appended to `error`, if given).
inline std::vector<double> PointsAfterTranslation(
  vtkMultiBlockDataSet* blocks, const std::vector<std::string>& moving, std::string* error)
{
  vtkNew<vtkDGMFDeformFilter> filter;
  filter->SetInputData(blocks);
  for (const std::string& entry : moving)
  {
    filter->AddMovingBoundary(entry.c_str());
  }
  filter->SetTranslation(0.0, 0.0, 0.3);
  dgmf_test::ErrorMessages errors(filter);
  filter->Update();
  for (const std::string& message : errors.Messages)
  {
    if (error)
    {
      *error += message;
    }
  }
  vtkUnstructuredGrid* volume = VolumeOf(filter->GetOutputDataObject(0));
  std::vector<double> xyz;
  for (vtkIdType i = 0; volume && i < volume->GetNumberOfPoints(); ++i)
  {
    xyz.insert(xyz.end(), volume->GetPoint(i), volume->GetPoint(i) + 3);
  }
  return xyz;
}
} // namespace dgmf_test

#endif
