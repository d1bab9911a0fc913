/**
 * @file RigidMotionTestHelpers.h
 * @brief Independent 3x3 algebra and random rigid motions for the tests of the rigid-motion fit,
 * the axis-angle motions and DGMF with a fitted motion.
 */
#ifndef DGMFRigidMotionTestHelpers_h
#define DGMFRigidMotionTestHelpers_h

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace rigid_test
{
constexpr double Pi = 3.14159265358979323846;

using Vec = std::array<double, 3>;
using Mat = std::array<Vec, 3>;

inline Vec Unit(const Vec& v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / n, v[1] / n, v[2] / n };
}

inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Independent Rodrigues rotation matrix of `angle` radians about the unit axis k.
inline Mat Rodrigues(const Vec& k, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle), v = 1.0 - c;
  Mat R;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      R[i][j] = (i == j ? c : 0.0) + v * k[i] * k[j];
    }
  }
  R[0][1] -= s * k[2];
  R[0][2] += s * k[1];
  R[1][0] += s * k[2];
  R[1][2] -= s * k[0];
  R[2][0] -= s * k[1];
  R[2][1] += s * k[0];
  return R;
}

inline Mat Multiply(const Mat& A, const Mat& B)
{
  Mat C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        C[i][j] += A[i][k] * B[k][j];
  return C;
}

inline Vec Times(const Mat& R, const Vec& v)
{
  return { Dot(R[0], v), Dot(R[1], v), Dot(R[2], v) };
}

inline Mat ToMat(const double R[3][3])
{
  Mat M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      M[i][j] = R[i][j];
  return M;
}

inline double Determinant(const Mat& R)
{
  return R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) -
    R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
    R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
}

inline void ExpectMatrixNear(const Mat& A, const Mat& B, double tolerance, const char* what)
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(A[i][j], B[i][j], tolerance) << what << " (" << i << ", " << j << ")";
}

inline Vec RandomUnit(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  return Unit({ normal(random), normal(random), normal(random) });
}

/// Displacements D_i = c0 + R (x_i - c0) + t - x_i of a rigid motion.
inline std::vector<double> RigidDisplacements(
  const std::vector<double>& points, const Mat& R, const Vec& c0, const Vec& t)
{
  std::vector<double> D(points.size());
  for (std::size_t i = 0; i < points.size(); i += 3)
  {
    const Vec r = { points[i] - c0[0], points[i + 1] - c0[1], points[i + 2] - c0[2] };
    const Vec y = Times(R, r);
    for (int c = 0; c < 3; ++c)
    {
      D[i + c] = c0[c] + y[c] + t[c] - points[i + c];
    }
  }
  return D;
}

inline std::vector<double> RandomPoints(
  std::mt19937& random, int count, bool planar, double z = 0.0)
{
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::uniform_real_distribution<double> offset(-10.0, 10.0);
  const Vec shift = { offset(random), offset(random), offset(random) };
  std::vector<double> points;
  for (int i = 0; i < count; ++i)
  {
    points.push_back(shift[0] + coordinate(random));
    points.push_back(shift[1] + coordinate(random));
    points.push_back(planar ? z : shift[2] + coordinate(random));
  }
  return points;
}

/// Mean displacement, computed independently of the fit.
inline Vec MeanDisplacement(const std::vector<double>& D)
{
  Vec mean = { 0.0, 0.0, 0.0 };
  const double n = static_cast<double>(D.size() / 3);
  for (std::size_t i = 0; i < D.size(); i += 3)
    for (int c = 0; c < 3; ++c)
      mean[c] += D[i + c] / n;
  return mean;
}
} // namespace rigid_test

#endif
