/**
 * @file FieldValue.h
 * @brief The filter tests' reading of the output's field data.
 */
#ifndef dgmf_test_FieldValue_h
#define dgmf_test_FieldValue_h

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <limits>

namespace dgmf_test
{

/// Component `component` of the first tuple of the field-data array `name` of `mesh`; NaN, and a
/// test failure, when there is no such array.
inline double Field(vtkUnstructuredGrid* mesh, const char* name, int component = 0)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  EXPECT_NE(array, nullptr) << name;
  return array ? array->GetComponent(0, component) : std::numeric_limits<double>::quiet_NaN();
}

} // namespace dgmf_test

#endif
