/**
 * @file DGRBFDeformation.h
 * @brief Delaunay graph with local radial basis functions (Wang, Qin, Zhao 2015): in each graph
 * element, a small RBF interpolation of its vertices' displacements.
 */
#ifndef dgmf_DGRBFDeformation_h
#define dgmf_DGRBFDeformation_h

#include "dgmf/BoundaryMotion.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"

namespace dgmf
{

/**
 * DGRBF: per graph element, the Wendland C2 interpolation phi(r/R) = (1-r/R)^4 (4r/R+1) of the
 * displacements of its 3 (2D) or 4 (3D) vertices, evaluated at the nodes of the element:
 *   s(x) = sum_k a_k phi(|x - x_k|/R) / sum_k b_k phi(|x - x_k|/R),  Phi a = D,  Phi b = 1,
 * a fixed-size Eigen solve per element. The denominator (rescaled RBF) makes a pure translation
 * exact; at the vertices both forms give the prescribed displacement. No polynomial term (with a
 * linear one, the 3- or 4-point interpolation would be DGM's barycentric one).
 *
 * R: `supportRadius` (mesh units), but never less than the element's longest edge, so every point
 * of the element is inside the support of every vertex; 0 means twice the longest edge.
 * Like the method it reproduces, the result can be discontinuous across graph faces.
 */
void DeformDGRBF(const DelaunayMapping& mapping, const BoundaryMotion& boundary,
  double supportRadius, const double* points, double* deformed, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
