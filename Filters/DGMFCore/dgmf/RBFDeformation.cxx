#include "dgmf/RBFDeformation.h"

#include "dgmf/RBFFit.h"

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
using namespace rbf;

/// Nodes per block of DeformRBF (fixed, so results do not depend on the ParallelFor).
constexpr std::size_t BlockSize = 1024;

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
  ForEachIndex(parallelFor, numberOfNodes, BlockSize,
    [&](std::size_t i)
    {
      const double x[3] = { points[3 * i], points[3 * i + 1], points[3 * i + 2] };
      double d[3];
      rbf.Evaluate(x, d);
      for (int c = 0; c < 3; ++c)
      {
        deformed[3 * i + c] = x[c] + d[c];
      }
    });
}

} // namespace dgmf
