/**
 * @file RBFFit.h
 * @brief The fitted RBF interpolation behind RBFInterpolation (private to the core): centres,
 * coefficients, the solve of the interpolation system, and the evaluation.
 */
#ifndef dgmf_RBFFit_h
#define dgmf_RBFFit_h

#include "dgmf/RBFDeformation.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cstddef>
#include <memory>
#include <vector>

namespace dgmf
{
namespace rbf
{
using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using PointMap = CGAL::Pointer_property_map<Point3>::const_type;
/// Kd-tree over centre indices; 2D centres are stored with z = 0, so one tree type serves both.
using TreeTraits =
  CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<Kernel>>;
using Tree = CGAL::Kd_tree<TreeTraits>;
using Sphere = CGAL::Fuzzy_sphere<TreeTraits>;

/// Largest dense system: 12,000 centres need 1.15 GB for the matrix and ~6e11 flops for LLT.
constexpr std::size_t MaximumDenseCentres = 12000;

/**
 * Eigenvalues (ascending) and eigenvectors of the covariance of the points `xyz` (3 per point,
 * the first `dimension` coordinates used) about their mean, restricted to `indices`.
 */
Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> Covariance(
  const double* xyz, const std::vector<std::size_t>& indices, int dimension);

/// True if the points span the whole space (not all collinear in 2D / coplanar in 3D).
bool SpansSpace(const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>& covariance);
} // namespace rbf

struct RBFInterpolation::Internals
{
  int Dimension = 3;
  double Radius = 0.0;
  double RadiusSquared = 0.0;
  double InverseRadius = 0.0;
  /// The polynomial is written in scaled coordinates (x - Origin) * InverseScale, of order 1.
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double InverseScale = 1.0;
  /// Midrange of the boundary displacements, subtracted before the fit and added back after:
  /// the interpolant is unchanged (it reproduces constants) but a translation becomes exact.
  double Reference[3] = { 0.0, 0.0, 0.0 };
  std::vector<rbf::Point3> Centres;
  std::vector<double> Coefficients; ///< a_j, 3 per centre
  /// The centres and a_j by coordinate, for the vectorised loop over all centres.
  std::vector<double> CentreXYZ[3];
  std::vector<double> CoefficientXYZ[3];
  double Polynomial[4][3] = {};      ///< row 0: constant; row 1 + c: coefficient of coordinate c
  std::unique_ptr<rbf::Tree> Search; ///< over Centres; used for evaluation when UseSearch
  bool UseSearch = false;
  double BoundaryError = 0.0;

  rbf::Point3 ToPoint(const double* x) const
  {
    return rbf::Point3(x[0], x[1], this->Dimension == 3 ? x[2] : 0.0);
  }

  /// s(x): reference displacement + RBF sum + polynomial (z = 0 in 2D).
  void Evaluate(const double x[3], double out[3]) const;
  /// Adds sum_j a_j phi(|p - x_j| / R) over all centres to `sum`, in tiles of Eigen arrays.
  template <int Dimension>
  void SumAllCentres(const rbf::Point3& p, double sum[3]) const;
  /// Fits the interpolation with centres `selection` to the shifted displacements.
  void Fit(const BoundaryMotion& boundary, const std::vector<std::size_t>& selection,
    const std::vector<double>& shifted);
  /// Largest |s(x_i) - d_i| over all boundary nodes; `errors` receives each one.
  double ComputeErrors(const BoundaryMotion& boundary, std::vector<double>& errors) const;
};

} // namespace dgmf

#endif
