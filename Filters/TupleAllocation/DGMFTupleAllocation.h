/**
 * @file DGMFTupleAllocation.h
 * @brief Memory for a VTK array's tuples, made of whole huge pages when large, whose failure
 * throws std::bad_alloc instead of VTK's abort. Header only (an INTERFACE library,
 * DGMFTupleAllocation), so that the filters' module, the mesh-file module and dgmf-deform share it
 * without linking one another.
 *
 * When an allocation fails, VTK 9.2's arrays print "Unable to allocate" and, as Debian builds them
 * (without NDEBUG), call abort(): ParaView itself would go down. Arrays allocated here get their
 * memory from dgmf::AllocateOnHugePages (the malloc family) and hand it to VTK, which frees it.
 */
#ifndef DGMFTupleAllocation_h
#define DGMFTupleAllocation_h

#include "dgmf/HugePages.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkType.h"

#include <cstddef>
#include <new>

namespace dgmf_vtk
{
/**
 * Gives `array` `tuples` tuples of its number of components (values not initialised). Arrays
 * with VTK's standard memory layout get memory from the malloc family (freed by VTK), made of
 * whole huge pages when large (dgmf::AllocateOnHugePages); std::bad_alloc when it cannot be had.
 * Other arrays are VTK's own (SetNumberOfTuples).
 */
inline void AllocateTuples(vtkDataArray* array, vtkIdType tuples)
{
  const auto values =
    static_cast<std::size_t>(tuples) * static_cast<std::size_t>(array->GetNumberOfComponents());
  if (values == 0 || !array->HasStandardMemoryLayout())
  {
    array->SetNumberOfTuples(tuples);
    return;
  }
  void* memory =
    dgmf::AllocateOnHugePages(values * static_cast<std::size_t>(array->GetDataTypeSize()));
  if (!memory)
  {
    throw std::bad_alloc();
  }
  array->SetVoidArray(
    memory, static_cast<vtkIdType>(values), 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
}
} // namespace dgmf_vtk

#endif
