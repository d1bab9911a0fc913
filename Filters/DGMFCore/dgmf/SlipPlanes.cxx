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
/// FitSlipPlane of a 2D mesh: the line of the nodes in the plane z = constant.
SlipPlane FitSlipLine(const double* points, const std::int32_t* nodes, std::size_t count,
  const std::string& name, double relativeTolerance)
{
  if (count < 2)
  {
    throw std::invalid_argument("The slip boundary '" + name + "' has " + std::to_string(count) +
      " node: a line needs at least 2.");
  }
  SlipPlane plane;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  double z = 0.0;
  for (std::size_t k = 0; k < count; ++k)
  {
    const double* x = points + 3 * static_cast<std::size_t>(nodes[k]);
    const Eigen::Vector2d p(x[0], x[1]);
    centroid += p;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
    z = x[2];
  }
  centroid /= static_cast<double>(count);
  const double extent = (high - low).norm();
  if (!(extent > 0.0) || !std::isfinite(extent))
  {
    throw std::invalid_argument(
      "The slip boundary '" + name + "' does not span a line (its nodes are at one place).");
  }
  for (int axis = 0; axis < 2; ++axis)
  {
    if (low[axis] == high[axis])
    {
      plane.Axis = axis;
      plane.Point[0] = axis == 0 ? low[0] : centroid[0];
      plane.Point[1] = axis == 1 ? low[1] : centroid[1];
      plane.Point[2] = z;
      plane.Normal[0] = axis == 0 ? 1.0 : 0.0;
      plane.Normal[1] = axis == 1 ? 1.0 : 0.0;
      plane.Normal[2] = 0.0;
      return plane;
    }
  }
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (std::size_t k = 0; k < count; ++k)
  {
    const double* x = points + 3 * static_cast<std::size_t>(nodes[k]);
    const Eigen::Vector2d y = Eigen::Vector2d(x[0], x[1]) - centroid;
    covariance += y * y.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance);
  const Eigen::Vector2d normal = solver.eigenvectors().col(0).normalized(); // least spread
  double farthest = 0.0;
  for (std::size_t k = 0; k < count; ++k)
  {
    const double* x = points + 3 * static_cast<std::size_t>(nodes[k]);
    farthest = std::max(farthest, std::abs(normal.dot(Eigen::Vector2d(x[0], x[1]) - centroid)));
  }
  if (farthest > relativeTolerance * extent)
  {
    std::ostringstream message;
    message << "The slip boundary '" << name << "' is not straight: a node is " << farthest
            << " from the best line through its nodes (size " << extent
            << "). A slip boundary of a 2D mesh must be a straight line; split a bent one, or "
               "make it static.";
    throw std::invalid_argument(message.str());
  }
  plane.Point[0] = centroid[0];
  plane.Point[1] = centroid[1];
  plane.Point[2] = z;
  plane.Normal[0] = normal[0];
  plane.Normal[1] = normal[1];
  plane.Normal[2] = 0.0;
  return plane;
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
  SlipPlane plane;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (std::size_t k = 0; k < count; ++k)
  {
    const Eigen::Vector3d p(points + 3 * static_cast<std::size_t>(nodes[k]));
    centroid += p;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  centroid /= static_cast<double>(count);
  const double extent = (high - low).norm();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (low[axis] == high[axis] && extent > 0.0)
    {
      plane.Axis = axis;
      for (int c = 0; c < 3; ++c)
      {
        plane.Normal[c] = c == axis ? 1.0 : 0.0;
        plane.Point[c] = c == axis ? low[axis] : centroid[c];
      }
      return plane;
    }
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < count; ++k)
  {
    const Eigen::Vector3d y =
      Eigen::Vector3d(points + 3 * static_cast<std::size_t>(nodes[k])) - centroid;
    covariance += y * y.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d spread = solver.eigenvalues(); // ascending
  if (!(spread[1] > 1e-12 * spread[2]) || !(extent > 0.0) || !std::isfinite(extent))
  {
    throw std::invalid_argument(
      "The slip boundary '" + name + "' does not span a plane (its nodes lie on a line).");
  }
  const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
  double farthest = 0.0;
  for (std::size_t k = 0; k < count; ++k)
  {
    const Eigen::Vector3d p(points + 3 * static_cast<std::size_t>(nodes[k]));
    farthest = std::max(farthest, std::abs(normal.dot(p - centroid)));
  }
  if (farthest > relativeTolerance * extent)
  {
    std::ostringstream message;
    message << "The slip boundary '" << name << "' is not planar: a node is " << farthest
            << " from the best plane through its nodes (size " << extent
            << "). A slip boundary must be a plane; split a curved one, or make it static.";
    throw std::invalid_argument(message.str());
  }
  for (int c = 0; c < 3; ++c)
  {
    plane.Point[c] = centroid[c];
    plane.Normal[c] = normal[c];
  }
  return plane;
}

void SlipConstraint::Apply(const double* points, double* deformed) const
{
  for (std::size_t k = 0; k < this->Nodes.size(); ++k)
  {
    const auto i = static_cast<std::size_t>(this->Nodes[k]);
    const SlipPlane& plane = this->Planes[static_cast<std::size_t>(this->NodePlanes[k])];
    const double* x = points + 3 * i;
    double* y = deformed + 3 * i;
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
