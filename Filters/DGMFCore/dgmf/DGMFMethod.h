/**
 * @file DGMFMethod.h
 * @brief DGMF behind the DeformationMethod interface (use CreateMethod).
 */
#ifndef dgmf_DGMFMethod_h
#define dgmf_DGMFMethod_h

#include "dgmf/DeformationMethod.h"

#include <memory>

namespace dgmf
{

/**
 * DGMF with `parameters`: one body (DeformDGMF, r and f kept in the FieldStore between motions),
 * several bodies or extracted rigid motions (DeformMultiBody), or large motions in sub-steps with
 * the quality guard (DeformInSubSteps) when parameters.UsesSubSteps().
 */
std::unique_ptr<DeformationMethod> MakeDGMFMethod(const MethodParameters& parameters);

} // namespace dgmf

#endif
