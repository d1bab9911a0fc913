#include "dgmf/RBFDeformation.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
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
/// Memory bound of the sparse assembly (triplets + compressed lower triangle), in bytes.
constexpr double MaximumSparseBytes = 1.5e9;
/// The RBF matrix is treated as sparse below this fraction of nonzeros.
constexpr double SparseDensity = 0.1;
/// Number of centres whose neighbours are counted to estimate the fraction of nonzeros.
constexpr std::size_t DensitySamples = 256;
/// Nodes per block of DeformRBF (fixed, so results do not depend on the ParallelFor).
constexpr std::size_t BlockSize = 1024;
/// Centres per tile of the vectorised evaluation over all centres.
constexpr Eigen::Index Tile = 256;
using TileArray = Eigen::Array<double, Eigen::Dynamic, 1, 0, Tile, 1>;

/// Wendland C2 function of r = distance / R, for 0 <= r < 1.
inline double Wendland(double r)
{
  const double q = 1.0 - r;
  const double q2 = q * q;
  return q2 * q2 * (4.0 * r + 1.0);
}

inline double SquaredDistance(const Point3& a, const Point3& b)
{
  const double dx = a.x() - b.x();
  const double dy = a.y() - b.y();
  const double dz = a.z() - b.z();
  return dx * dx + dy * dy + dz * dz;
}

std::string Gigabytes(double bytes)
{
  std::ostringstream text;
  text.precision(3);
  text << bytes / 1e9 << " GB";
  return text.str();
}

/**
 * Solves the saddle-point system [Phi P; P^T 0] [A; B] = [D; 0] by the Schur complement of the
 * symmetric positive definite block Phi: Y = Phi^-1 P, S = P^T Y (small, SPD when P has full
 * column rank), B = S^-1 P^T Phi^-1 D, A = Phi^-1 D - Y B. Up to two steps of iterative refinement
 * on the whole system follow. `solve(X)` returns Phi^-1 X, `multiply(X)` returns Phi X.
 */
template <typename SolveFunction, typename MultiplyFunction>
void SolveSaddlePoint(const SolveFunction& solve, const MultiplyFunction& multiply,
  const Eigen::MatrixXd& P, const Eigen::MatrixXd& D, Eigen::MatrixXd& A, Eigen::MatrixXd& B)
{
  const Eigen::MatrixXd Y = solve(P);
  const Eigen::MatrixXd S = P.transpose() * Y;
  const Eigen::LLT<Eigen::MatrixXd> schur(S);
  if (schur.info() != Eigen::Success || !(schur.rcond() > 1e-15))
  {
    throw std::runtime_error("RBF: the linear polynomial part of the interpolation is singular "
                             "(the centres are nearly collinear in 2D or coplanar in 3D)");
  }
  const auto correction = [&](const Eigen::MatrixXd& r1, const Eigen::MatrixXd& r2,
                            Eigen::MatrixXd& dA, Eigen::MatrixXd& dB)
  {
    const Eigen::MatrixXd Z = solve(r1);
    dB = schur.solve(P.transpose() * Z - r2);
    dA = Z - Y * dB;
  };
  correction(D, Eigen::MatrixXd::Zero(P.cols(), D.cols()), A, B);
  const double scale = D.cwiseAbs().maxCoeff();
  for (int step = 0; step < 2 && scale > 0.0; ++step)
  {
    const Eigen::MatrixXd r1 = D - multiply(A) - P * B;
    if (!(r1.cwiseAbs().maxCoeff() > 1e-15 * scale))
    {
      break;
    }
    const Eigen::MatrixXd r2 = -(P.transpose() * A);
    Eigen::MatrixXd dA, dB;
    correction(r1, r2, dA, dB);
    A += dA;
    B += dB;
  }
  if (!A.allFinite() || !B.allFinite())
  {
    throw std::runtime_error("RBF: the interpolation system could not be solved (non-finite "
                             "coefficients; nearly coincident boundary nodes?)");
  }
}

/// Thrown when Phi is not positive definite in floating point.
[[noreturn]] void ThrowNotPositiveDefinite()
{
  throw std::runtime_error("RBF: the RBF matrix is not positive definite in floating point "
                           "(nearly coincident boundary nodes, or a support radius far larger "
                           "than the node spacing); try a smaller SupportRadius or RBFGreedy");
}

/**
 * Eigenvalues (ascending) and eigenvectors of the covariance of the points `xyz` (3 per point,
 * the first `dimension` coordinates used) about their mean, restricted to `indices`.
 */
Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> Covariance(
  const double* xyz, const std::vector<std::size_t>& indices, int dimension)
{
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(dimension);
  for (std::size_t i : indices)
  {
    for (int c = 0; c < dimension; ++c)
    {
      mean[c] += xyz[3 * i + c];
    }
  }
  mean /= static_cast<double>(indices.size());
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(dimension, dimension);
  for (std::size_t i : indices)
  {
    Eigen::VectorXd y(dimension);
    for (int c = 0; c < dimension; ++c)
    {
      y[c] = xyz[3 * i + c] - mean[c];
    }
    covariance += y * y.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(covariance);
}

/// True if the points span the whole space (not all collinear in 2D / coplanar in 3D).
bool SpansSpace(const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>& covariance)
{
  const Eigen::VectorXd& lambda = covariance.eigenvalues();
  return lambda[0] > 1e-20 * lambda[lambda.size() - 1];
}
} // namespace

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
  std::vector<Point3> Centres;
  std::vector<double> Coefficients; ///< a_j, 3 per centre
  /// The centres and a_j by coordinate, for the vectorised loop over all centres.
  std::vector<double> CentreXYZ[3];
  std::vector<double> CoefficientXYZ[3];
  double Polynomial[4][3] = {}; ///< row 0: constant; row 1 + c: coefficient of coordinate c
  std::unique_ptr<Tree> Search; ///< over Centres; used for evaluation when UseSearch
  bool UseSearch = false;
  double BoundaryError = 0.0;

  Point3 ToPoint(const double* x) const
  {
    return Point3(x[0], x[1], this->Dimension == 3 ? x[2] : 0.0);
  }

  /// s(x): reference displacement + RBF sum + polynomial (z = 0 in 2D).
  void Evaluate(const double x[3], double out[3]) const;
  /// Adds sum_j a_j phi(|p - x_j| / R) over all centres to `sum`, in tiles of Eigen arrays.
  template <int Dimension>
  void SumAllCentres(const Point3& p, double sum[3]) const;
  /// Fits the interpolation with centres `selection` to the shifted displacements.
  void Fit(const BoundaryMotion& boundary, const std::vector<std::size_t>& selection,
    const std::vector<double>& shifted);
  /// Largest |s(x_i) - d_i| over all boundary nodes; `errors` receives each one.
  double ComputeErrors(const BoundaryMotion& boundary, std::vector<double>& errors) const;
};

template <int Dimension>
void RBFInterpolation::Internals::SumAllCentres(const Point3& p, double sum[3]) const
{
  using ConstMap = Eigen::Map<const Eigen::ArrayXd>;
  const auto count = static_cast<Eigen::Index>(this->Centres.size());
  for (Eigen::Index start = 0; start < count; start += Tile)
  {
    const Eigen::Index length = std::min(Tile, count - start);
    TileArray d2 = (ConstMap(this->CentreXYZ[0].data() + start, length) - p.x()).square() +
      (ConstMap(this->CentreXYZ[1].data() + start, length) - p.y()).square();
    if (Dimension == 3)
    {
      d2 += (ConstMap(this->CentreXYZ[2].data() + start, length) - p.z()).square();
    }
    // phi = q^4 (4 r + 1) with q = max(1 - r, 0): zero outside the support, no branch.
    const TileArray r = d2.sqrt() * this->InverseRadius;
    const TileArray q2 = (1.0 - r).max(0.0).square();
    const TileArray phi = q2 * q2 * (4.0 * r + 1.0);
    for (int c = 0; c < Dimension; ++c)
    {
      sum[c] += (phi * ConstMap(this->CoefficientXYZ[c].data() + start, length)).sum();
    }
  }
}

void RBFInterpolation::Internals::Evaluate(const double x[3], double out[3]) const
{
  const Point3 p = this->ToPoint(x);
  double sum[3] = { 0.0, 0.0, 0.0 };
  const double* a = this->Coefficients.data();
  const auto add = [&](std::size_t j)
  {
    const double d2 = SquaredDistance(p, this->Centres[j]);
    if (d2 < this->RadiusSquared)
    {
      const double phi = Wendland(std::sqrt(d2) * this->InverseRadius);
      sum[0] += phi * a[3 * j];
      sum[1] += phi * a[3 * j + 1];
      sum[2] += phi * a[3 * j + 2];
    }
  };
  if (this->UseSearch)
  {
    const Sphere query(p, this->Radius, 0.0, this->Search->traits());
    this->Search->search(boost::make_function_output_iterator(std::ref(add)), query);
  }
  else if (this->Dimension == 3)
  {
    this->SumAllCentres<3>(p, sum);
  }
  else
  {
    this->SumAllCentres<2>(p, sum);
  }
  const double y[3] = { (p.x() - this->Origin[0]) * this->InverseScale,
    (p.y() - this->Origin[1]) * this->InverseScale,
    (p.z() - this->Origin[2]) * this->InverseScale };
  for (int c = 0; c < 3; ++c)
  {
    double value = this->Polynomial[0][c];
    for (int k = 0; k < this->Dimension; ++k)
    {
      value += this->Polynomial[1 + k][c] * y[k];
    }
    out[c] = c < this->Dimension ? this->Reference[c] + (sum[c] + value) : 0.0;
  }
}

void RBFInterpolation::Internals::Fit(const BoundaryMotion& boundary,
  const std::vector<std::size_t>& selection, const std::vector<double>& shifted)
{
  const std::size_t k = selection.size();
  const int dim = this->Dimension;
  const int m = dim + 1;
  this->Search.reset();
  this->UseSearch = false;
  this->Centres.clear();
  this->Centres.reserve(k);
  double lower[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double upper[3] = { -lower[0], -lower[1], -lower[2] };
  for (std::size_t i : selection)
  {
    this->Centres.push_back(this->ToPoint(boundary.Positions.data() + 3 * i));
    for (int c = 0; c < 3; ++c)
    {
      lower[c] = std::min(lower[c], this->Centres.back()[c]);
      upper[c] = std::max(upper[c], this->Centres.back()[c]);
    }
  }
  double diagonal2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    diagonal2 += (upper[c] - lower[c]) * (upper[c] - lower[c]);
  }

  // Fraction of nonzeros: 1 when every pair of centres is within R, else sampled with a kd-tree.
  double fraction = 1.0;
  if (this->RadiusSquared < diagonal2)
  {
    this->Search = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
      boost::counting_iterator<std::size_t>(k), Tree::Splitter(),
      TreeTraits(PointMap(this->Centres.data())));
    this->Search->build();
    const std::size_t samples = std::min(k, DensitySamples);
    double count = 0.0;
    for (std::size_t s = 0; s < samples; ++s)
    {
      const Sphere query(this->Centres[s * k / samples], this->Radius, 0.0, this->Search->traits());
      const auto counter = [&count](std::size_t) { count += 1.0; };
      this->Search->search(boost::make_function_output_iterator(std::ref(counter)), query);
    }
    fraction = count / (static_cast<double>(samples) * static_cast<double>(k));
  }
  const bool sparse = fraction < SparseDensity;
  if (!sparse && k > MaximumDenseCentres)
  {
    const double kk = static_cast<double>(k);
    throw std::invalid_argument("RBF: " + std::to_string(k) + " centres give a dense system (" +
      std::to_string(static_cast<int>(100.0 * fraction + 0.5)) + "% nonzeros) that would need " +
      Gigabytes(8.0 * kk * kk) + " and O(n^3) time; the limit is " +
      std::to_string(MaximumDenseCentres) +
      " centres. Enable greedy centre selection "
      "(RBFGreedy, with RBFGreedyMaximumPoints <= " +
      std::to_string(MaximumDenseCentres) +
      ") or choose a smaller SupportRadius so that the system becomes sparse.");
  }

  Eigen::MatrixXd P(static_cast<Eigen::Index>(k), m);
  Eigen::MatrixXd D(static_cast<Eigen::Index>(k), dim);
  for (std::size_t r = 0; r < k; ++r)
  {
    const auto row = static_cast<Eigen::Index>(r);
    P(row, 0) = 1.0;
    for (int c = 0; c < dim; ++c)
    {
      P(row, 1 + c) = (this->Centres[r][c] - this->Origin[c]) * this->InverseScale;
      D(row, c) = shifted[3 * selection[r] + c];
    }
  }
  Eigen::MatrixXd A, B;
  if (sparse)
  {
    const double kk = static_cast<double>(k);
    const double entries = 0.5 * fraction * kk * kk + 0.5 * kk;
    if (entries * 28.0 > MaximumSparseBytes)
    {
      throw std::invalid_argument("RBF: the sparse system of " + std::to_string(k) +
        " centres would need about " + Gigabytes(entries * 28.0) +
        " before fill-in; choose a smaller SupportRadius or enable greedy selection (RBFGreedy)");
    }
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<std::size_t>(entries * 1.1) + k);
    for (std::size_t i = 0; i < k; ++i)
    {
      const Point3& xi = this->Centres[i];
      const Sphere query(xi, this->Radius, 0.0, this->Search->traits());
      const auto addEntry = [&](std::size_t j)
      {
        if (j < i)
        {
          return;
        }
        const double d2 = SquaredDistance(xi, this->Centres[j]);
        if (j == i || d2 < this->RadiusSquared)
        {
          triplets.emplace_back(static_cast<int>(j), static_cast<int>(i),
            Wendland(std::sqrt(d2) * this->InverseRadius));
        }
      };
      this->Search->search(boost::make_function_output_iterator(std::ref(addEntry)), query);
    }
    Eigen::SparseMatrix<double> phi(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
    phi.setFromTriplets(triplets.begin(), triplets.end());
    std::vector<Eigen::Triplet<double>>().swap(triplets);
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt(phi);
    if (llt.info() != Eigen::Success)
    {
      ThrowNotPositiveDefinite();
    }
    SolveSaddlePoint([&](const Eigen::MatrixXd& x) -> Eigen::MatrixXd { return llt.solve(x); },
      [&](const Eigen::MatrixXd& x) -> Eigen::MatrixXd
      { return phi.selfadjointView<Eigen::Lower>() * x; },
      P, D, A, B);
    this->UseSearch = true;
  }
  else
  {
    this->Search.reset();
    // Both triangles are filled; the in-place LLT overwrites the lower one (and the diagonal,
    // which is phi(0) = 1), so the strictly upper triangle still holds Phi for the refinement.
    Eigen::MatrixXd phi(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
    for (std::size_t j = 0; j < k; ++j)
    {
      const auto col = static_cast<Eigen::Index>(j);
      phi(col, col) = 1.0;
      for (std::size_t i = j + 1; i < k; ++i)
      {
        const double d2 = SquaredDistance(this->Centres[i], this->Centres[j]);
        const double value =
          d2 < this->RadiusSquared ? Wendland(std::sqrt(d2) * this->InverseRadius) : 0.0;
        phi(static_cast<Eigen::Index>(i), col) = value;
        phi(col, static_cast<Eigen::Index>(i)) = value;
      }
    }
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(phi);
    if (llt.info() != Eigen::Success)
    {
      ThrowNotPositiveDefinite();
    }
    SolveSaddlePoint([&](const Eigen::MatrixXd& x) -> Eigen::MatrixXd { return llt.solve(x); },
      [&](const Eigen::MatrixXd& x) -> Eigen::MatrixXd
      {
        Eigen::MatrixXd y = x;
        y.noalias() += phi.triangularView<Eigen::StrictlyUpper>() * x;
        y.noalias() += phi.triangularView<Eigen::StrictlyUpper>().transpose() * x;
        return y;
      },
      P, D, A, B);
  }

  this->Coefficients.assign(3 * k, 0.0);
  for (int c = 0; c < 3; ++c)
  {
    this->CentreXYZ[c].resize(k);
    this->CoefficientXYZ[c].assign(k, 0.0);
  }
  for (std::size_t r = 0; r < k; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->CentreXYZ[c][r] = this->Centres[r][c];
    }
    for (int c = 0; c < dim; ++c)
    {
      this->Coefficients[3 * r + c] = A(static_cast<Eigen::Index>(r), c);
      this->CoefficientXYZ[c][r] = this->Coefficients[3 * r + c];
    }
  }
  for (int row = 0; row < 4; ++row)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Polynomial[row][c] = row < m && c < dim ? B(row, c) : 0.0;
    }
  }
}

double RBFInterpolation::Internals::ComputeErrors(
  const BoundaryMotion& boundary, std::vector<double>& errors) const
{
  const std::size_t n = boundary.Size();
  errors.resize(n);
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    double s[3];
    this->Evaluate(boundary.Positions.data() + 3 * i, s);
    double e2 = 0.0;
    for (int c = 0; c < this->Dimension; ++c)
    {
      const double e = s[c] - boundary.Displacements[3 * i + c];
      e2 += e * e;
    }
    errors[i] = std::sqrt(e2);
    largest = std::max(largest, errors[i]);
  }
  return largest;
}

namespace
{
/// Boundary nodes in index order, without exact duplicates of an earlier node's position.
std::vector<std::size_t> UniqueNodes(const BoundaryMotion& boundary)
{
  const std::size_t n = boundary.Size();
  const int dim = boundary.Dimension;
  const double* x = boundary.Positions.data();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto less = [&](std::size_t a, std::size_t b)
  {
    for (int c = 0; c < dim; ++c)
    {
      if (x[3 * a + c] != x[3 * b + c])
      {
        return x[3 * a + c] < x[3 * b + c];
      }
    }
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<char> duplicate(n, 0);
  for (std::size_t r = 1; r < n; ++r)
  {
    bool same = true;
    for (int c = 0; c < dim; ++c)
    {
      same = same && x[3 * order[r] + c] == x[3 * order[r - 1] + c];
    }
    duplicate[order[r]] = same ? 1 : 0; // the earlier index sorts first and is kept
  }
  std::vector<std::size_t> unique;
  unique.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!duplicate[i])
    {
      unique.push_back(i);
    }
  }
  return unique;
}

/**
 * Initial greedy set: the node with the largest displacement, then farthest-point sampling up to
 * 2 (dimension + 1) nodes, then (rarely needed) the nodes farthest from the set's affine hull
 * until the set spans the space, so that the linear polynomial is determined.
 */
std::vector<std::size_t> InitialCentres(
  const BoundaryMotion& boundary, const std::vector<std::size_t>& unique, std::size_t count)
{
  const int dim = boundary.Dimension;
  const double* x = boundary.Positions.data();
  const double* d = boundary.Displacements.data();
  std::size_t first = 0;
  double largest = -1.0;
  for (std::size_t u = 0; u < unique.size(); ++u)
  {
    const std::size_t i = unique[u];
    double d2 = 0.0;
    for (int c = 0; c < dim; ++c)
    {
      d2 += d[3 * i + c] * d[3 * i + c];
    }
    if (d2 > largest)
    {
      largest = d2;
      first = u;
    }
  }
  std::vector<std::size_t> selection{ unique[first] };
  std::vector<double> distance(unique.size(), std::numeric_limits<double>::max());
  const auto update = [&](std::size_t centre)
  {
    for (std::size_t u = 0; u < unique.size(); ++u)
    {
      double d2 = 0.0;
      for (int c = 0; c < dim; ++c)
      {
        const double e = x[3 * unique[u] + c] - x[3 * centre + c];
        d2 += e * e;
      }
      distance[u] = std::min(distance[u], d2);
    }
  };
  update(unique[first]);
  while (selection.size() < count)
  {
    const std::size_t u = static_cast<std::size_t>(
      std::max_element(distance.begin(), distance.end()) - distance.begin());
    if (!(distance[u] > 0.0))
    {
      break;
    }
    selection.push_back(unique[u]);
    update(unique[u]);
  }
  for (int attempt = 0; attempt < dim; ++attempt)
  {
    const auto covariance = Covariance(x, selection, dim);
    if (SpansSpace(covariance))
    {
      break;
    }
    // Distance from the affine hull: the component along the eigenvectors of (near) zero variance.
    const Eigen::VectorXd& lambda = covariance.eigenvalues();
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(dim);
    for (std::size_t i : selection)
    {
      for (int c = 0; c < dim; ++c)
      {
        mean[c] += x[3 * i + c] / static_cast<double>(selection.size());
      }
    }
    std::size_t farthest = unique[0];
    double farthestDistance = -1.0;
    for (std::size_t i : unique)
    {
      Eigen::VectorXd y(dim);
      for (int c = 0; c < dim; ++c)
      {
        y[c] = x[3 * i + c] - mean[c];
      }
      double off = 0.0;
      for (int e = 0; e < dim; ++e)
      {
        if (!(lambda[e] > 1e-20 * lambda[dim - 1]))
        {
          const double t = covariance.eigenvectors().col(e).dot(y);
          off += t * t;
        }
      }
      if (off > farthestDistance)
      {
        farthestDistance = off;
        farthest = i;
      }
    }
    selection.push_back(farthest);
  }
  return selection;
}
} // namespace

RBFInterpolation::RBFInterpolation(const BoundaryMotion& boundary, const RBFParameters& parameters)
  : Impl(std::make_unique<Internals>())
{
  Internals& impl = *this->Impl;
  const int dim = boundary.Dimension;
  if (dim != 2 && dim != 3)
  {
    throw std::invalid_argument("RBF: the dimension must be 2 or 3");
  }
  const std::size_t n = boundary.Size();
  if (boundary.Positions.size() != 3 * n || boundary.Displacements.size() != 3 * n)
  {
    throw std::invalid_argument("RBF: boundary positions and displacements need 3 values per node");
  }
  if (!std::isfinite(parameters.SupportRadius) || parameters.SupportRadius < 0.0)
  {
    throw std::invalid_argument("RBF: SupportRadius must be finite and >= 0 (0: automatic)");
  }
  if (parameters.Greedy && !(parameters.GreedyTolerance >= 0.0))
  {
    throw std::invalid_argument("RBF: RBFGreedyTolerance must be >= 0");
  }
  if (parameters.Greedy && parameters.GreedyMaximumPoints < static_cast<std::size_t>(dim + 1))
  {
    throw std::invalid_argument(
      "RBF: RBFGreedyMaximumPoints must be at least " + std::to_string(dim + 1));
  }
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    if (!std::isfinite(boundary.Positions[i]) || !std::isfinite(boundary.Displacements[i]))
    {
      throw std::invalid_argument("RBF: boundary node " + std::to_string(i / 3) +
        " has a non-finite position or displacement");
    }
  }
  impl.Dimension = dim;

  const std::vector<std::size_t> unique = UniqueNodes(boundary);
  if (unique.size() < static_cast<std::size_t>(dim + 1))
  {
    throw std::invalid_argument("RBF: at least " + std::to_string(dim + 1) +
      " distinct boundary nodes are needed to determine the linear polynomial, got " +
      std::to_string(unique.size()));
  }
  const double* x = boundary.Positions.data();
  if (!SpansSpace(Covariance(x, unique, dim)))
  {
    throw std::invalid_argument(dim == 2
        ? "RBF: all boundary nodes are collinear: the linear polynomial is not determined"
        : "RBF: all boundary nodes are coplanar: the linear polynomial is not determined");
  }

  // Polynomial frame, bounding box, automatic radius, reference displacement.
  double lower[3], upper[3], dLower[3], dUpper[3];
  for (int c = 0; c < 3; ++c)
  {
    lower[c] = dLower[c] = std::numeric_limits<double>::max();
    upper[c] = dUpper[c] = -std::numeric_limits<double>::max();
  }
  for (std::size_t i : unique)
  {
    for (int c = 0; c < dim; ++c)
    {
      impl.Origin[c] += x[3 * i + c] / static_cast<double>(unique.size());
      lower[c] = std::min(lower[c], x[3 * i + c]);
      upper[c] = std::max(upper[c], x[3 * i + c]);
    }
  }
  double maximumDisplacement = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    double d2 = 0.0;
    for (int c = 0; c < dim; ++c)
    {
      const double di = boundary.Displacements[3 * i + c];
      dLower[c] = std::min(dLower[c], di);
      dUpper[c] = std::max(dUpper[c], di);
      d2 += di * di;
    }
    maximumDisplacement = std::max(maximumDisplacement, std::sqrt(d2));
  }
  double diagonal2 = 0.0;
  double scale2 = 0.0;
  for (int c = 0; c < dim; ++c)
  {
    diagonal2 += (upper[c] - lower[c]) * (upper[c] - lower[c]);
    impl.Reference[c] = 0.5 * dLower[c] + 0.5 * dUpper[c];
  }
  for (std::size_t i : unique)
  {
    double r2 = 0.0;
    for (int c = 0; c < dim; ++c)
    {
      r2 += (x[3 * i + c] - impl.Origin[c]) * (x[3 * i + c] - impl.Origin[c]);
    }
    scale2 = std::max(scale2, r2);
  }
  impl.InverseScale = 1.0 / std::sqrt(scale2);
  impl.Radius = parameters.SupportRadius > 0.0 ? parameters.SupportRadius : std::sqrt(diagonal2);
  impl.RadiusSquared = impl.Radius * impl.Radius;
  impl.InverseRadius = 1.0 / impl.Radius;

  std::vector<double> shifted(boundary.Displacements);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      shifted[3 * i + c] = c < dim ? shifted[3 * i + c] - impl.Reference[c] : 0.0;
    }
  }

  std::vector<double> errors;
  if (!parameters.Greedy)
  {
    impl.Fit(boundary, unique, shifted);
    const double error = impl.ComputeErrors(boundary, errors);
    impl.BoundaryError = maximumDisplacement > 0.0 ? error / maximumDisplacement : error;
    return;
  }

  const std::size_t cap = std::min(parameters.GreedyMaximumPoints, unique.size());
  if (impl.RadiusSquared >= diagonal2 && cap > MaximumDenseCentres)
  {
    throw std::invalid_argument("RBF: greedy selection with a global support could reach " +
      std::to_string(cap) + " centres, above the dense limit of " +
      std::to_string(MaximumDenseCentres) +
      "; lower RBFGreedyMaximumPoints or choose a smaller "
      "SupportRadius");
  }
  std::vector<std::size_t> selection =
    InitialCentres(boundary, unique, std::min<std::size_t>(2 * (dim + 1), cap));
  std::vector<char> selected(n, 0);
  for (std::size_t i : selection)
  {
    selected[i] = 1;
  }
  const double tolerance = parameters.GreedyTolerance * maximumDisplacement;
  std::vector<std::size_t> candidates;
  double error = 0.0;
  for (;;)
  {
    impl.Fit(boundary, selection, shifted);
    error = impl.ComputeErrors(boundary, errors);
    if (error <= tolerance || selection.size() >= cap)
    {
      break;
    }
    // Add the worst nodes in a batch that grows with the set (1/8 of it): O(log) refits.
    candidates.clear();
    for (std::size_t i : unique)
    {
      if (!selected[i] && errors[i] > tolerance)
      {
        candidates.push_back(i);
      }
    }
    if (candidates.empty())
    {
      break; // the remaining error is at duplicates with a different displacement
    }
    const std::size_t batch = std::min({ std::max<std::size_t>(1, selection.size() / 8),
      cap - selection.size(), candidates.size() });
    std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(batch),
      candidates.end(),
      [&](std::size_t a, std::size_t b)
      { return errors[a] > errors[b] || (errors[a] == errors[b] && a < b); });
    for (std::size_t r = 0; r < batch; ++r)
    {
      selection.push_back(candidates[r]);
      selected[candidates[r]] = 1;
    }
  }
  impl.BoundaryError = maximumDisplacement > 0.0 ? error / maximumDisplacement : error;
}

RBFInterpolation::~RBFInterpolation() = default;

void RBFInterpolation::Evaluate(const double x[3], double displacement[3]) const
{
  this->Impl->Evaluate(x, displacement);
}

std::size_t RBFInterpolation::GetNumberOfCentres() const
{
  return this->Impl->Centres.size();
}

double RBFInterpolation::GetBoundaryError() const
{
  return this->Impl->BoundaryError;
}

double RBFInterpolation::GetSupportRadius() const
{
  return this->Impl->Radius;
}

void DeformRBF(const RBFInterpolation& rbf, const double* points, std::size_t numberOfNodes,
  double* deformed, const ParallelFor& parallelFor)
{
  const std::size_t blocks = (numberOfNodes + BlockSize - 1) / BlockSize;
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      const std::size_t begin = block * BlockSize;
      const std::size_t end = std::min(begin + BlockSize, numberOfNodes);
      for (std::size_t i = begin; i < end; ++i)
      {
        const double x[3] = { points[3 * i], points[3 * i + 1], points[3 * i + 2] };
        double d[3];
        rbf.Evaluate(x, d);
        for (int c = 0; c < 3; ++c)
        {
          deformed[3 * i + c] = x[c] + d[c];
        }
      }
    });
}

} // namespace dgmf
