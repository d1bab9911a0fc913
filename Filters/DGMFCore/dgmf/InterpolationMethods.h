/**
 * @file InterpolationMethods.h
 * @brief The paper's comparison methods behind the DeformationMethod interface (use CreateMethod).
 */
#ifndef dgmf_InterpolationMethods_h
#define dgmf_InterpolationMethods_h

#include "dgmf/DeformationMethod.h"

#include <memory>

namespace dgmf
{

/**
 * DGM, DGRBF, RBF or IDW with `parameters`: each interpolates the total motion of the boundary
 * nodes (GatherTotalBoundaryMotion) into the mesh. Throws std::invalid_argument for Method::DGMF.
 */
std::unique_ptr<DeformationMethod> MakeInterpolationMethod(
  Method method, const MethodParameters& parameters);

} // namespace dgmf

#endif
