// The RBF interpolation system (de Boer et al. 2007): assembly (dense, or sparse with a CGAL
// kd-tree), the Schur-complement solve with Eigen, and the evaluation.
#include "dgmf/RBFFit.h"

#include "dgmf/Wendland.h"

#include <Eigen/Cholesky>
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
namespace rbf
{
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
} // namespace rbf

namespace
{
using namespace rbf;

/// Memory bound of the sparse assembly (triplets + compressed lower triangle), in bytes.
constexpr double MaximumSparseBytes = 1.5e9;
/// The RBF matrix is treated as sparse below this fraction of nonzeros.
constexpr double SparseDensity = 0.1;
/// Number of centres whose neighbours are counted to estimate the fraction of nonzeros.
constexpr std::size_t DensitySamples = 256;
/// Centres per tile of the vectorised evaluation over all centres.
constexpr Eigen::Index Tile = 256;
using TileArray = Eigen::Array<double, Eigen::Dynamic, 1, 0, Tile, 1>;

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

} // namespace

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
      const double phi = WendlandC2(std::sqrt(d2) * this->InverseRadius);
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
            WendlandC2(std::sqrt(d2) * this->InverseRadius));
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
          d2 < this->RadiusSquared ? WendlandC2(std::sqrt(d2) * this->InverseRadius) : 0.0;
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

} // namespace dgmf
