/**
 * @file DGMFCompressorClasses.h
 * @brief VTK's data compressor classes by the name a .vtu file records (vtkLZ4DataCompressor,
 * vtkZLibDataCompressor, vtkLZMADataCompressor): the one place that maps the name to the class.
 */
#ifndef DGMFCompressorClasses_h
#define DGMFCompressorClasses_h

#include "vtkDataCompressor.h"
#include "vtkLZ4DataCompressor.h"
#include "vtkLZMADataCompressor.h"
#include "vtkSmartPointer.h"
#include "vtkZLibDataCompressor.h"

#include <string>

namespace dgmf_cli
{

/**
 * `make(static_cast<C*>(nullptr))` for VTK's compressor class C named `className` (the pointer
 * only carries the class), or null for another name.
 */
template <typename Make>
vtkSmartPointer<vtkDataCompressor> WithCompressorClass(const std::string& className, Make&& make)
{
  if (className == "vtkLZ4DataCompressor")
  {
    return make(static_cast<vtkLZ4DataCompressor*>(nullptr));
  }
  if (className == "vtkZLibDataCompressor")
  {
    return make(static_cast<vtkZLibDataCompressor*>(nullptr));
  }
  if (className == "vtkLZMADataCompressor")
  {
    return make(static_cast<vtkLZMADataCompressor*>(nullptr));
  }
  return nullptr;
}

} // namespace dgmf_cli

#endif
