/**
 * @file ShippedMesh.h
 * @brief Reads a mesh shipped in Data/ for the filter tests, and checks its size.
 */
#ifndef dgmf_test_ShippedMesh_h
#define dgmf_test_ShippedMesh_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <gtest/gtest.h>

#include <string>

namespace dgmf_test
{

/**
 * Data/`name` as a copy the test may modify. Its number of points (and of cells, unless `cells`
 * is negative) is checked: Debian 12's expat can make reads come back empty.
 */
inline vtkSmartPointer<vtkUnstructuredGrid> ReadShippedMesh(
  const std::string& name, vtkIdType points, vtkIdType cells = -1)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((std::string(DGMF_DATA_DIR) + "/" + name).c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), points) << name;
  if (cells >= 0)
  {
    EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), cells) << name;
  }
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->DeepCopy(reader->GetOutput());
  return copy;
}

} // namespace dgmf_test

#endif
