#include "dgmf/RigidMotionFit.h"

#include "dgmf/DampedRigidMotion.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dgmf
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Sets the axis and angle of `fit` from a unit axis and an angle in radians in [0, pi].
void SetAxisAngle(const double axis[3], double angle, FittedMotion& fit)
{
  if (!(angle > 0.0))
  {
    fit.Axis[0] = 0.0;
    fit.Axis[1] = 0.0;
    fit.Axis[2] = 1.0;
    fit.AngleDegrees = 0.0;
    return;
  }
  std::copy(axis, axis + 3, fit.Axis);
  fit.AngleDegrees = std::min(angle, Pi) / Pi * 180.0; // exactly 180 for angle = pi
}

/// A unit vector perpendicular to the unit vector `u`.
Eigen::Vector3d Perpendicular(const Eigen::Vector3d& u)
{
  Eigen::Index smallest = 0;
  u.cwiseAbs().minCoeff(&smallest);
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  e[smallest] = 1.0;
  return u.cross(e).normalized();
}

/**
 * Axis and angle (radians, [0, pi]) of a rotation matrix. cos(angle) comes from the trace and
 * sin(angle) k from the skew-symmetric part. Below 90 degrees the axis is the direction of the
 * skew part; beyond, where sin(angle) vanishes towards 180 degrees, it is the dominant column of
 * the symmetric part R + R^T - (tr R - 1) I = 2 (1 - cos) k k^T, its sign taken from the skew part.
 */
void ToAxisAngle(const Eigen::Matrix3d& R, Eigen::Vector3d& axis, double& angle)
{
  const Eigen::Vector3d w(
    0.5 * (R(2, 1) - R(1, 2)), 0.5 * (R(0, 2) - R(2, 0)), 0.5 * (R(1, 0) - R(0, 1)));
  const double cosine = std::max(-1.0, std::min(1.0, 0.5 * (R.trace() - 1.0)));
  if (cosine >= 0.0)
  {
    const double sine = w.norm();
    if (sine == 0.0)
    {
      axis = Eigen::Vector3d(0.0, 0.0, 1.0);
      angle = 0.0;
      return;
    }
    axis = w / sine;
    angle = std::atan2(sine, cosine);
    return;
  }
  const Eigen::Matrix3d S = R + R.transpose() - (R.trace() - 1.0) * Eigen::Matrix3d::Identity();
  Eigen::Index column = 0;
  S.diagonal().maxCoeff(&column);
  axis = S.col(column).normalized();
  double sine = axis.dot(w);
  if (sine < 0.0)
  {
    axis = -axis;
    sine = -sine;
  }
  else if (sine == 0.0)
  {
    // Exactly 180 degrees: k and -k are the same rotation; make the largest component positive.
    Eigen::Index largest = 0;
    axis.cwiseAbs().maxCoeff(&largest);
    if (axis[largest] < 0.0)
    {
      axis = -axis;
    }
  }
  angle = std::atan2(sine, cosine);
}

std::size_t NodeOf(const std::int32_t* nodes, std::size_t i)
{
  return nodes ? static_cast<std::size_t>(nodes[i]) : i;
}

/**
 * d_i = (x_i + D_i) - M(x_i) with M the fitted motion as DGMF applies it at f = 1. Writes d_i
 * (if `residual` is not null) and returns the sum of |d_i|^2; `largest` receives max |d_i|.
 */
double ResidualPass(const FittedMotion& fit, const double* points, const double* displacements,
  const std::int32_t* nodes, std::size_t count, double* residual, double& largest)
{
  largest = 0.0;
  if (count == 0)
  {
    return 0.0;
  }
  const DampedRigidMotion damped(fit.ToRigidMotion());
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    if (nodes && nodes[i] < 0)
    {
      throw std::invalid_argument("negative node id in a rigid-motion residual");
    }
    const std::size_t node = NodeOf(nodes, i);
    const double* x = points + 3 * node;
    const double* D = displacements + 3 * node;
    double moved[3];
    damped.Apply(1.0, x, nullptr, moved);
    const double d[3] = { (x[0] + D[0]) - moved[0], (x[1] + D[1]) - moved[1],
      (x[2] + D[2]) - moved[2] };
    const double squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    sum += squared;
    largest = std::max(largest, std::sqrt(squared));
    if (residual)
    {
      std::copy(d, d + 3, residual + 3 * node);
    }
  }
  return sum;
}
} // namespace

void RotationToAxisAngle(const double R[3][3], double axis[3], double& angleDegrees)
{
  Eigen::Matrix3d matrix;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      matrix(i, j) = R[i][j];
    }
  }
  Eigen::Vector3d k;
  double angle = 0.0;
  ToAxisAngle(matrix, k, angle);
  for (int c = 0; c < 3; ++c)
  {
    axis[c] = k[c];
  }
  angleDegrees = angle * 180.0 / 3.14159265358979323846;
}

bool CentreOnRotationAxis(FittedMotion& fit, double maximumDistance)
{
  const double theta = fit.AngleDegrees * 3.14159265358979323846 / 180.0;
  if (!(theta > 0.0))
  {
    return false;
  }
  const double* a = fit.Axis;
  const double* t = fit.Translation;
  // Solve (I - R) q = t_perp with q perpendicular to the axis:
  // q = (t_perp + cot(theta / 2) a x t_perp) / 2.
  const double along = t[0] * a[0] + t[1] * a[1] + t[2] * a[2];
  const double perp[3] = { t[0] - along * a[0], t[1] - along * a[1], t[2] - along * a[2] };
  const double cross[3] = { a[1] * perp[2] - a[2] * perp[1], a[2] * perp[0] - a[0] * perp[2],
    a[0] * perp[1] - a[1] * perp[0] };
  const double cot = std::cos(0.5 * theta) / std::sin(0.5 * theta);
  double q[3];
  for (int c = 0; c < 3; ++c)
  {
    q[c] = 0.5 * (perp[c] + cot * cross[c]);
  }
  if (!(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) <= maximumDistance))
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    fit.Center[c] += q[c];
    fit.Translation[c] = along * a[c];
  }
  return true;
}

RigidMotion FittedMotion::ToRigidMotion() const
{
  RigidMotion motion;
  for (int c = 0; c < 3; ++c)
  {
    motion.Center[c] = this->Center[c];
    motion.Translation[c] = this->Translation[c];
    motion.Axis[c] = this->Axis[c];
  }
  motion.AxisAngleDegrees = this->AngleDegrees;
  return motion;
}

FittedMotion FitRigidMotion(int dimension, const double* points, const double* displacements,
  const std::int32_t* nodes, std::size_t count)
{
  if (dimension != 2 && dimension != 3)
  {
    throw std::invalid_argument("the dimension of a rigid-motion fit must be 2 or 3");
  }
  FittedMotion fit;
  fit.NumberOfPoints = count;
  if (count == 0)
  {
    return fit;
  }
  if (!points || !displacements)
  {
    throw std::invalid_argument("a rigid-motion fit needs points and displacements");
  }
  // Centroid of the original points and mean displacement.
  double sumX[3] = { 0.0, 0.0, 0.0 };
  double sumD[3] = { 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < count; ++i)
  {
    if (nodes && nodes[i] < 0)
    {
      throw std::invalid_argument("negative node id in a rigid-motion fit");
    }
    const std::size_t node = NodeOf(nodes, i);
    for (int c = 0; c < 3; ++c)
    {
      const double x = points[3 * node + c];
      const double d = displacements[3 * node + c];
      if (!std::isfinite(x) || !std::isfinite(d))
      {
        throw std::invalid_argument("non-finite coordinate or displacement in a rigid-motion fit");
      }
      sumX[c] += x;
      sumD[c] += d;
    }
  }
  const double n = static_cast<double>(count);
  for (int c = 0; c < 3; ++c)
  {
    fit.Center[c] = sumX[c] / n;
    fit.Translation[c] = sumD[c] / n;
  }
  if (dimension == 2)
  {
    fit.Center[2] = points[3 * NodeOf(nodes, 0) + 2];
    fit.Translation[2] = 0.0;
  }

  // Cross-covariance H = sum p q^T of the centred original (p) and displaced (q) points.
  const int used = dimension;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  double pp = 0.0, qq = 0.0, magnitude = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t node = NodeOf(nodes, i);
    Eigen::Vector3d p = Eigen::Vector3d::Zero(), q = Eigen::Vector3d::Zero();
    for (int c = 0; c < used; ++c)
    {
      const double x = points[3 * node + c];
      const double d = displacements[3 * node + c];
      p[c] = x - fit.Center[c];
      q[c] = p[c] + (d - fit.Translation[c]);
      magnitude = std::max({ magnitude, std::abs(x), std::abs(x + d) });
    }
    H += p * q.transpose();
    pp += p.squaredNorm();
    qq += q.squaredNorm();
  }
  // A singular value of H below `relative` means p and q are uncorrelated (for the second one,
  // relative to the first: the points lie on a line); below `noise`, it is at the level of the
  // round-off of the coordinates (points that coincide up to round-off).
  const double relative = RotationFitTolerance * std::sqrt(pp * qq);
  const double noise =
    RotationFitTolerance * magnitude * std::sqrt(n) * (std::sqrt(pp) + std::sqrt(qq));

  Eigen::Vector3d axis(0.0, 0.0, 1.0);
  double angle = 0.0;
  if (dimension == 2)
  {
    // 2D Procrustes: the angle maximising sum q . R p.
    const double dot = H(0, 0) + H(1, 1);
    const double cross = H(0, 1) - H(1, 0);
    if (std::hypot(dot, cross) > std::max(relative, noise))
    {
      fit.Status = RotationFit::Determined;
      const double theta = std::atan2(cross, dot);
      angle = std::abs(theta);
      axis[2] = theta < 0.0 && angle < Pi ? -1.0 : 1.0;
    }
  }
  else
  {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d& sigma = svd.singularValues();
    const Eigen::Matrix3d& U = svd.matrixU();
    const Eigen::Matrix3d& V = svd.matrixV();
    if (!(sigma[0] > std::max(relative, noise)))
    {
      // No correlation between p and q: nothing to fit (R = I).
    }
    else if (!(sigma[1] > std::max(RotationFitTolerance * sigma[0], noise)))
    {
      // H = sigma_1 u v^T: any R with R u = v is optimal. Take the smallest such rotation.
      fit.Status = RotationFit::Collinear;
      const Eigen::Vector3d u = U.col(0);
      const Eigen::Vector3d v = V.col(0);
      const Eigen::Vector3d normal = u.cross(v);
      const double sine = normal.norm();
      const double cosine = u.dot(v);
      if (sine > 0.0)
      {
        axis = normal / sine;
        angle = std::atan2(sine, cosine);
      }
      else if (cosine < 0.0)
      {
        axis = Perpendicular(u);
        angle = Pi;
      }
    }
    else
    {
      // Kabsch: R = V diag(1, 1, det(V U^T)) U^T, a proper rotation even when V U^T reflects.
      fit.Status = RotationFit::Determined;
      Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
      D(2, 2) = (V * U.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
      const Eigen::Matrix3d R = V * D * U.transpose();
      ToAxisAngle(R, axis, angle);
    }
  }
  const double unitAxis[3] = { axis[0], axis[1], axis[2] };
  SetAxisAngle(unitAxis, angle, fit);
  fit.ToRigidMotion().GetRotationMatrix(1.0, fit.Rotation);

  // Residual statistics.
  const double sum =
    ResidualPass(fit, points, displacements, nodes, count, nullptr, fit.MaximumResidual);
  fit.ResidualRMS = std::sqrt(sum / n);
  return fit;
}

double ComputeFitResidual(const FittedMotion& fit, const double* points,
  const double* displacements, const std::int32_t* nodes, std::size_t count, double* residual)
{
  double largest = 0.0;
  const double sum = ResidualPass(fit, points, displacements, nodes, count, residual, largest);
  return count == 0 ? 0.0 : std::sqrt(sum / static_cast<double>(count));
}

} // namespace dgmf
