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
  double GreedyTolerance = 1e-3;      ///< relative error tolerance of the greedy selection
  std::size_t GreedyMaximumPoints = 2000; ///< upper bound on the number of centres
};

/**
 * @class RBFInterpolation
 * @brief s(x) = sum_j a_j phi(|x - x_j| / R) + p(x), p linear, with sum a_j = 0 and
 * sum a_j x_j = 0, fitted to the boundary displacements (each component separately, one
 * factorisation). Solved with Eigen: a sparse factorisation when the support is compact, dense
 * otherwise.
 */
class RBFInterpolation
{
public:
  /// Fits the interpolation; throws std::invalid_argument / std::runtime_error when it cannot.
  RBFInterpolation(const BoundaryMotion& boundary, const RBFParameters& parameters);
  ~RBFInterpolation();
  RBFInterpolation(const RBFInterpolation&) = delete;
  RBFInterpolation& operator=(const RBFInterpolation&) = delete;

  /// The interpolated displacement at x.
  void Evaluate(const double x[3], double displacement[3]) const;
  /// Number of centres used (all boundary nodes, or the greedy selection).
  std::size_t GetNumberOfCentres() const;
  /// Largest interpolation error at the boundary nodes, relative to the largest displacement.
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
