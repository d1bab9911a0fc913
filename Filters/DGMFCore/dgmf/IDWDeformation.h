/**
 * @file IDWDeformation.h
 * @brief Inverse distance weighting of the boundary motion (Witteveen and Bijl 2009, with the
 * weights of Luke, Collins and Blades 2012).
 */
#ifndef dgmf_IDWDeformation_h
#define dgmf_IDWDeformation_h

#include "dgmf/BoundaryMotion.h"
#include "dgmf/ParallelFor.h"

#include <cstddef>

namespace dgmf
{

/// Parameters of the IDW method (Luke et al. 2012).
struct IDWParameters
{
  double ExponentA = 3.0; ///< a
  double ExponentB = 5.0; ///< b
  double Alpha = 5.0;     ///< alpha, weight of the short-range term
  /// Ldef, the reference length; 0: automatic (largest distance of a boundary node from the
  /// boundary nodes' centroid).
  double ReferenceLength = 0.0;
};

/**
 * s(x) = sum_i w_i s_i / sum_i w_i, w_i = A_i [ (Ldef/d_i)^a + (alpha Ldef/d_i)^b ], d_i = |x -
 * x_i|, summed exactly over all boundary nodes (cost O(N Nb)); deformed = x + s(x). A node within
 * 1e-150 Ldef of a boundary node (in practice: the same position) gets that node's displacement
 * exactly. Very small and very large distances are handled without overflow or underflow. In 2D
 * only x and y are used and z is not changed. Returns the Ldef used (1 if the automatic Ldef
 * would be 0). Throws std::invalid_argument for bad parameters or weights, or no boundary nodes.
 */
double DeformIDW(const BoundaryMotion& boundary, const IDWParameters& parameters,
  const double* points, std::size_t numberOfNodes, double* deformed,
  const ParallelFor& parallelFor);

} // namespace dgmf

#endif
