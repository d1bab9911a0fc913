#include "dgmf/SlipPlanes.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace dgmf
{

namespace
{
/**
 * The least-spread fit of the first D coordinates of `nodes` of `points` (3 per point): their
 * centroid and bounds, the direction of least spread (the covariance's smallest eigenvector),
 * and the farthest node from the hyperplane through the centroid normal to it. The planes'
 * (D = 3) and the 2D meshes' lines' (D = 2) common arithmetic.
 */
template <int D>
struct LeastSpreadFit
{
  using Vector = Eigen::Matrix<double, D, 1>;
  using Matrix = Eigen::Matrix<double, D, D>;

  const double* Points;
  const std::int32_t* Nodes;
  std::size_t Count;
  Vector Centroid = Vector::Zero();
  Vector Low = Vector::Constant(std::numeric_limits<double>::infinity());
  Vector High = -Vector::Constant(std::numeric_limits<double>::infinity());
  double Extent = 0.0;

  LeastSpreadFit(const double* points, const std::int32_t* nodes, std::size_t count)
    : Points(points)
    , Nodes(nodes)
    , Count(count)
  {
    for (std::size_t k = 0; k < count; ++k)
    {
      const Vector p = this->At(k);
      this->Centroid += p;
      this->Low = this->Low.cwiseMin(p);
      this->High = this->High.cwiseMax(p);
    }
    this->Centroid /= static_cast<double>(count);
    this->Extent = (this->High - this->Low).norm();
  }

  /// Node k's first D coordinates.
  Vector At(std::size_t k) const
  {
    return Eigen::Map<const Vector>(this->Points + 3 * static_cast<std::size_t>(this->Nodes[k]));
  }

  /// The eigen-decomposition of the nodes' covariance (eigenvalues ascending).
  Eigen::SelfAdjointEigenSolver<Matrix> Spread() const
  {
    Matrix covariance = Matrix::Zero();
    for (std::size_t k = 0; k < this->Count; ++k)
    {
      const Vector y = this->At(k) - this->Centroid;
      covariance += y * y.transpose();
    }
    return Eigen::SelfAdjointEigenSolver<Matrix>(covariance);
  }

  /// `plane` through the centroid normal to `normal` (its first D coordinates), the nodes at
  /// most `farthest` from it.
  SlipPlane Through(SlipPlane plane, const Vector& normal, double farthest) const
  {
    for (int c = 0; c < D; ++c)
    {
      plane.Point[c] = this->Centroid[c];
      plane.Normal[c] = normal[c];
    }
    plane.Deviation = farthest;
    return plane;
  }

  /// The largest distance of a node from the hyperplane through the centroid normal to `normal`.
  double Farthest(const Vector& normal) const
  {
    double farthest = 0.0;
    for (std::size_t k = 0; k < this->Count; ++k)
    {
      farthest = std::max(farthest, std::abs(normal.dot(this->At(k) - this->Centroid)));
    }
    return farthest;
  }
};

/// FitSlipPlane of a 2D mesh: the line of the nodes in the plane z = constant.
SlipPlane FitSlipLine(const double* points, const std::int32_t* nodes, std::size_t count,
  const std::string& name, double relativeTolerance)
{
  if (count < 2)
  {
    throw std::invalid_argument("The slip boundary '" + name + "' has " + std::to_string(count) +
      " node: a line needs at least 2.");
  }
  const LeastSpreadFit<2> fit(points, nodes, count);
  const double z = points[3 * static_cast<std::size_t>(nodes[count - 1]) + 2];
  if (!(fit.Extent > 0.0) || !std::isfinite(fit.Extent))
  {
    throw std::invalid_argument(
      "The slip boundary '" + name + "' does not span a line (its nodes are at one place).");
  }
  SlipPlane plane;
  plane.Point[2] = z;
  plane.Normal[2] = 0.0;
  for (int axis = 0; axis < 2; ++axis)
  {
    if (fit.Low[axis] == fit.High[axis])
    {
      plane.Axis = axis;
      for (int c = 0; c < 2; ++c)
      {
        plane.Point[c] = c == axis ? fit.Low[axis] : fit.Centroid[c];
        plane.Normal[c] = c == axis ? 1.0 : 0.0;
      }
      return plane;
    }
  }
  const Eigen::Vector2d normal = fit.Spread().eigenvectors().col(0).normalized(); // least spread
  const double farthest = fit.Farthest(normal);
  if (farthest > relativeTolerance * fit.Extent)
  {
    std::ostringstream message;
    message << "The slip boundary '" << name << "' is not straight: a node is " << farthest
            << " from the best line through its nodes (size " << fit.Extent
            << "). A slip boundary of a 2D mesh must be a straight line; split a bent one, or "
               "make it static.";
    throw std::invalid_argument(message.str());
  }
  return fit.Through(plane, normal, farthest);
}
} // namespace

SlipPlane FitSlipPlane(const double* points, const std::int32_t* nodes, std::size_t count,
  const std::string& name, double relativeTolerance, int dimension)
{
  if (dimension == 2)
  {
    return FitSlipLine(points, nodes, count, name, relativeTolerance);
  }
  if (count < 3)
  {
    throw std::invalid_argument("The slip boundary '" + name + "' has " + std::to_string(count) +
      " nodes: a plane needs at least 3.");
  }
  const LeastSpreadFit<3> fit(points, nodes, count);
  SlipPlane plane;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (fit.Low[axis] == fit.High[axis] && fit.Extent > 0.0)
    {
      plane.Axis = axis;
      for (int c = 0; c < 3; ++c)
      {
        plane.Normal[c] = c == axis ? 1.0 : 0.0;
        plane.Point[c] = c == axis ? fit.Low[axis] : fit.Centroid[c];
      }
      return plane;
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver = fit.Spread();
  const Eigen::Vector3d spread = solver.eigenvalues(); // ascending
  if (!(spread[1] > 1e-12 * spread[2]) || !(fit.Extent > 0.0) || !std::isfinite(fit.Extent))
  {
    throw std::invalid_argument(
      "The slip boundary '" + name + "' does not span a plane (its nodes lie on a line).");
  }
  const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
  const double farthest = fit.Farthest(normal);
  if (farthest > relativeTolerance * fit.Extent)
  {
    std::ostringstream message;
    message << "The slip boundary '" << name << "' is not planar: a node is " << farthest
            << " from the best plane through its nodes (size " << fit.Extent
            << "). A slip boundary must be a plane: split a curved one, name planes that differ as "
               "separate slip boundaries, or make it static.";
    throw std::invalid_argument(message.str());
  }
  return fit.Through(plane, normal, farthest);
}

bool SamePlane(const SlipPlane& a, const SlipPlane& b)
{
  const double* m = a.Normal;
  const double* n = b.Normal;
  const double cross[3] = { m[1] * n[2] - m[2] * n[1], m[2] * n[0] - m[0] * n[2],
    m[0] * n[1] - m[1] * n[0] };
  if (!(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]) <=
        SlipPlaneTolerance))
  {
    return false;
  }
  const double d[3] = { b.Point[0] - a.Point[0], b.Point[1] - a.Point[1], b.Point[2] - a.Point[2] };
  const double apart = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double across = std::abs(d[0] * m[0] + d[1] * m[1] + d[2] * m[2]);
  return across <= SlipPlaneTolerance * apart + a.Deviation + b.Deviation;
}

bool SlipConstraint::operator==(const SlipConstraint& other) const
{
  const auto samePlane = [](const SlipPlane& a, const SlipPlane& b)
  {
    return std::equal(a.Point, a.Point + 3, b.Point) &&
      std::equal(a.Normal, a.Normal + 3, b.Normal) && a.Axis == b.Axis &&
      a.Deviation == b.Deviation;
  };
  return this->Nodes == other.Nodes && this->NodePlanes == other.NodePlanes &&
    this->SecondPlanes == other.SecondPlanes &&
    std::equal(this->Planes.begin(), this->Planes.end(), other.Planes.begin(), other.Planes.end(),
      samePlane);
}

void SlipConstraint::Apply(const double* points, double* deformed) const
{
  for (std::size_t k = 0; k < this->Nodes.size(); ++k)
  {
    const auto i = static_cast<std::size_t>(this->Nodes[k]);
    const SlipPlane& plane = this->Planes[static_cast<std::size_t>(this->NodePlanes[k])];
    const double* x = points + 3 * i;
    double* y = deformed + 3 * i;
    const std::int32_t second = this->SecondPlaneOf(k);
    if (second >= 0)
    {
      // Along the line of the two planes: both axes kept exactly, or the displacement projected
      // onto the line's direction.
      const SlipPlane& other = this->Planes[static_cast<std::size_t>(second)];
      if (plane.Axis >= 0 && other.Axis >= 0 && plane.Axis != other.Axis)
      {
        y[plane.Axis] = x[plane.Axis];
        y[other.Axis] = x[other.Axis];
        continue;
      }
      const double* a = plane.Normal;
      const double* b = other.Normal;
      double d[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0] };
      const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (length > SlipPlaneTolerance) // else one plane (a plane split in two patches)
      {
        const double along =
          ((y[0] - x[0]) * d[0] + (y[1] - x[1]) * d[1] + (y[2] - x[2]) * d[2]) / (length * length);
        for (int c = 0; c < 3; ++c)
        {
          y[c] = x[c] + along * d[c];
        }
        continue;
      }
    }
    if (plane.Axis >= 0)
    {
      y[plane.Axis] = x[plane.Axis];
      continue;
    }
    const double* n = plane.Normal;
    const double along = (y[0] - x[0]) * n[0] + (y[1] - x[1]) * n[1] + (y[2] - x[2]) * n[2];
    for (int c = 0; c < 3; ++c)
    {
      y[c] -= along * n[c];
    }
  }
}

} // namespace dgmf
