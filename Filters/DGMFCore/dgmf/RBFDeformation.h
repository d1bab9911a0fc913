/**
 * @file RBFDeformation.h
 * @brief Global radial-basis-function interpolation of the boundary motion (de Boer, van der
 * Schoot, Bijl 2007), with optional greedy centre selection (Rendall and Allen 2009).
 */
#ifndef dgmf_RBFDeformation_h
#define dgmf_RBFDeformation_h

#include "dgmf/BoundaryMotion.h"
#include "dgmf/ParallelFor.h"

#include <cstddef>
#include <memory>

namespace dgmf
{

/// Parameters of the RBF method.
struct RBFParameters
{
  /// Support radius R of the Wendland C2 basis phi(r/R) = (1-r/R)^4 (4r/R+1); 0: automatic
  /// (the diagonal of the boundary nodes' bounding box, so every centre influences every node).
  double SupportRadius = 0.0;
  /// Greedy centre selection: add centres until the interpolation error at every boundary node
  /// is below GreedyTolerance times the largest boundary displacement.
  bool Greedy = false;
  double GreedyTolerance = 1e-3;          ///< relative error tolerance of the greedy selection
  std::size_t GreedyMaximumPoints = 2000; ///< upper bound on the number of centres
};

/**
 * @class RBFInterpolation
 * @brief s(x) = sum_j a_j phi(|x - x_j| / R) + p(x), p linear, with sum a_j = 0 and
 * sum a_j x_j = 0, fitted to the boundary displacements (each component separately, one
 * factorisation). In 2D only x and y are used and the z displacement is 0.
 *
 * Solved with Eigen by the Schur complement of the (positive definite) RBF block: a sparse
 * Cholesky (SimplicialLLT) when fewer than 10% of the entries are nonzero (neighbours from a CGAL
 * kd-tree, which also serves the evaluation), a dense in-place LLT otherwise. Boundary nodes at
 * exactly the same position are merged (the first one is the centre). A dense system of more than
 * 12,000 centres is refused before anything is allocated (std::invalid_argument).
 * Evaluate() is const and may be called from several threads at once.
 */
class RBFInterpolation
{
public:
  /**
   * Fits the interpolation. Throws std::invalid_argument for bad parameters, fewer than
   * dimension + 1 distinct boundary nodes, boundary nodes that are all collinear (2D) or coplanar
   * (3D), or a system too large to solve (the message names RBFGreedy and SupportRadius);
   * std::runtime_error when the factorisation fails (nearly coincident nodes).
   */
  RBFInterpolation(const BoundaryMotion& boundary, const RBFParameters& parameters);
  ~RBFInterpolation();
  RBFInterpolation(const RBFInterpolation&) = delete;
  RBFInterpolation& operator=(const RBFInterpolation&) = delete;

  /// The interpolated displacement at x.
  void Evaluate(const double x[3], double displacement[3]) const;
  /// Number of centres used (all boundary nodes, or the greedy selection).
  std::size_t GetNumberOfCentres() const;
  /// Largest interpolation error |s(x_i) - d_i| over all boundary nodes, relative to the largest
  /// |d_i| (absolute if every d_i is 0).
  double GetBoundaryError() const;
  /// The support radius used.
  double GetSupportRadius() const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

/**
 * Moves every node by the RBF interpolation of the boundary motion: deformed = x + s(x)
 * (3 coordinates per node). Boundary nodes get the interpolated value too (exact up to round-off
 * unless the selection is greedy).
 */
void DeformRBF(const RBFInterpolation& rbf, const double* points, std::size_t numberOfNodes,
  double* deformed, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
