// RBF interpolation of the boundary motion: exactness, polynomial reproduction, sparse and dense
// solves, greedy selection, size guard, threads.
#include "SyntheticNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/BoundaryMotion.h"
#include "dgmf/RBFDeformation.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{
using dgmf_test::TwoThreadFor;

dgmf::BoundaryMotion Gather(const dgmf_test::NodeSet& set, const dgmf::RigidMotion& motion)
{
  return dgmf::GatherBoundaryMotion(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), motion, nullptr);
}

/// The circle rotated by `degrees` about the origin, the square static.
dgmf::BoundaryMotion RotatedCircle(const dgmf_test::NodeSet& set, double degrees)
{
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = degrees;
  return Gather(set, motion);
}

double MaximumDisplacement(const dgmf::BoundaryMotion& boundary)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < boundary.Size(); ++i)
  {
    const double* d = boundary.Displacements.data() + 3 * i;
    largest = std::max(largest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  return largest;
}

/// Largest |s(x_i) - d_i| / max |d| over the boundary nodes, evaluated through the public API.
double RelativeBoundaryError(
  const dgmf::RBFInterpolation& rbf, const dgmf::BoundaryMotion& boundary)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < boundary.Size(); ++i)
  {
    double s[3];
    rbf.Evaluate(boundary.Positions.data() + 3 * i, s);
    double e2 = 0.0;
    for (int c = 0; c < boundary.Dimension; ++c)
    {
      const double e = s[c] - boundary.Displacements[3 * i + c];
      e2 += e * e;
    }
    largest = std::max(largest, std::sqrt(e2));
  }
  return largest / MaximumDisplacement(boundary);
}

double Wendland(double r)
{
  return r < 1.0 ? std::pow(1.0 - r, 4) * (4.0 * r + 1.0) : 0.0;
}

/**
 * Independent reference: the whole saddle-point system [Phi P; P^T 0] written out densely with an
 * unscaled polynomial [1 x y (z)], solved by partial-pivoting LU.
 */
struct DenseReference
{
  int Dimension;
  double Radius;
  std::vector<double> Centres;
  Eigen::MatrixXd Solution; // (k + dim + 1) x dim

  DenseReference(const dgmf::BoundaryMotion& boundary, double radius)
    : Dimension(boundary.Dimension)
    , Radius(radius)
    , Centres(boundary.Positions)
  {
    const auto k = static_cast<Eigen::Index>(boundary.Size());
    const int m = this->Dimension + 1;
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(k + m, k + m);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(k + m, this->Dimension);
    for (Eigen::Index i = 0; i < k; ++i)
    {
      for (Eigen::Index j = 0; j < k; ++j)
      {
        M(i, j) = Wendland(this->Distance(&this->Centres[3 * i], j) / radius);
      }
      M(i, k) = M(k, i) = 1.0;
      for (int c = 0; c < this->Dimension; ++c)
      {
        M(i, k + 1 + c) = M(k + 1 + c, i) = this->Centres[3 * i + c];
        rhs(i, c) = boundary.Displacements[3 * i + c];
      }
    }
    this->Solution = M.partialPivLu().solve(rhs);
  }

  double Distance(const double* x, Eigen::Index j) const
  {
    double d2 = 0.0;
    for (int c = 0; c < this->Dimension; ++c)
    {
      d2 += (x[c] - this->Centres[3 * j + c]) * (x[c] - this->Centres[3 * j + c]);
    }
    return std::sqrt(d2);
  }

  void Evaluate(const double* x, double s[3]) const
  {
    const auto k = static_cast<Eigen::Index>(this->Centres.size() / 3);
    for (int c = 0; c < 3; ++c)
    {
      s[c] = 0.0;
      if (c >= this->Dimension)
      {
        continue;
      }
      for (Eigen::Index j = 0; j < k; ++j)
      {
        s[c] += this->Solution(j, c) * Wendland(this->Distance(x, j) / this->Radius);
      }
      s[c] += this->Solution(k, c);
      for (int e = 0; e < this->Dimension; ++e)
      {
        s[c] += this->Solution(k + 1 + e, c) * x[e];
      }
    }
  }
};

std::vector<double> Deform(const dgmf::RBFInterpolation& rbf, const dgmf_test::NodeSet& set,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  std::vector<double> deformed(set.Points.size());
  dgmf::DeformRBF(rbf, set.Points.data(), set.Size(), deformed.data(), parallelFor);
  return deformed;
}
} // namespace

TEST(RBFDeformation, ReproducesBoundaryMotionWithGlobalSupport)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  const dgmf::BoundaryMotion boundary = RotatedCircle(set, 10.0);
  const dgmf::RBFInterpolation rbf(boundary, dgmf::RBFParameters());
  EXPECT_EQ(rbf.GetNumberOfCentres(), boundary.Size());
  EXPECT_NEAR(rbf.GetSupportRadius(), std::sqrt(200.0), 1e-12); // diagonal of [-5, 5]^2
  EXPECT_LE(rbf.GetBoundaryError(), 1e-10);
  EXPECT_LE(RelativeBoundaryError(rbf, boundary), 1e-10);

  // DeformRBF at the boundary nodes: deformed = x + d.
  const std::vector<double> deformed = Deform(rbf, set);
  const double scale = MaximumDisplacement(boundary);
  for (std::size_t b = 0; b < boundary.Size(); ++b)
  {
    const std::size_t i = static_cast<std::size_t>(boundary.Nodes[b]);
    for (int c = 0; c < 2; ++c)
    {
      EXPECT_NEAR(deformed[3 * i + c], set.Points[3 * i + c] + boundary.Displacements[3 * b + c],
        1e-10 * scale);
    }
  }
}

TEST(RBFDeformation, ReproducesBoundaryMotionWithCompactSupport)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(64, 40);
  const dgmf::BoundaryMotion boundary = RotatedCircle(set, 10.0);
  dgmf::RBFParameters parameters;
  parameters.SupportRadius = 0.8;
  const dgmf::RBFInterpolation rbf(boundary, parameters);
  EXPECT_EQ(rbf.GetSupportRadius(), 0.8);
  EXPECT_LE(rbf.GetBoundaryError(), 1e-10);
  EXPECT_LE(RelativeBoundaryError(rbf, boundary), 1e-10);
}

TEST(RBFDeformation, CompactSupportSparseSolveMatchesDenseSolve)
{
  // R = 0.8 with 64 + 160 boundary nodes: about 4% nonzeros, so the sparse path (kd-tree
  // assembly, sparse Cholesky, kd-tree evaluation) is used; compare with a dense LU of the
  // same system, at every node of the set (boundary and interior).
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(64, 40);
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 10.0;
  motion.Translation[0] = 0.2;
  const dgmf::BoundaryMotion boundary = Gather(set, motion);
  dgmf::RBFParameters parameters;
  parameters.SupportRadius = 0.8;
  const dgmf::RBFInterpolation rbf(boundary, parameters);
  const DenseReference reference(boundary, 0.8);
  const double scale = MaximumDisplacement(boundary);
  double largest = 0.0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    double s[3], r[3];
    rbf.Evaluate(set.Points.data() + 3 * i, s);
    reference.Evaluate(set.Points.data() + 3 * i, r);
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest, std::abs(s[c] - r[c]));
    }
  }
  EXPECT_LE(largest, 1e-9 * scale);

  // The same with the automatic (global) support: the dense Cholesky + Schur path.
  const dgmf::RBFInterpolation global(boundary, dgmf::RBFParameters());
  const DenseReference globalReference(boundary, global.GetSupportRadius());
  largest = 0.0;
  for (std::size_t i = 0; i < set.Size(); i += 7)
  {
    double s[3], r[3];
    global.Evaluate(set.Points.data() + 3 * i, s);
    globalReference.Evaluate(set.Points.data() + 3 * i, r);
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest, std::abs(s[c] - r[c]));
    }
  }
  EXPECT_LE(largest, 1e-9 * scale);
}

TEST(RBFDeformation, PureTranslationIsExactEverywhere)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::BoundaryMotion boundary = RotatedCircle(set, 0.0);
  const double t[3] = { 0.37, -1.21, 0.0 };
  for (std::size_t i = 0; i < boundary.Size(); ++i)
  {
    std::copy(t, t + 3, boundary.Displacements.begin() + 3 * i);
  }
  for (double radius : { 0.0, 0.8 })
  {
    dgmf::RBFParameters parameters;
    parameters.SupportRadius = radius;
    const dgmf::RBFInterpolation rbf(boundary, parameters);
    for (std::size_t i = 0; i < set.Size(); ++i)
    {
      double s[3];
      rbf.Evaluate(set.Points.data() + 3 * i, s);
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_NEAR(s[c], t[c], 1e-12 * 1.27) << "node " << i << " radius " << radius;
      }
    }
  }
}

TEST(RBFDeformation, AffineMotionIsReproducedByThePolynomial)
{
  // d = G x + t is in the polynomial space: the RBF coefficients vanish (up to round-off) and
  // the interpolant equals d at interior nodes too. The boundary-node positions (not only
  // their displacements) matter here, so this checks the linear polynomial itself.
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::BoundaryMotion boundary = RotatedCircle(set, 0.0);
  const double G[2][2] = { { 0.01, 0.02 }, { -0.03, 0.015 } };
  const auto affine = [&](const double* x, int c) { return G[c][0] * x[0] + G[c][1] * x[1] + 0.1; };
  for (std::size_t i = 0; i < boundary.Size(); ++i)
  {
    for (int c = 0; c < 2; ++c)
    {
      boundary.Displacements[3 * i + c] = affine(boundary.Positions.data() + 3 * i, c);
    }
  }
  const double scale = MaximumDisplacement(boundary);
  for (double radius : { 0.0, 0.8 })
  {
    dgmf::RBFParameters parameters;
    parameters.SupportRadius = radius;
    const dgmf::RBFInterpolation rbf(boundary, parameters);
    double largest = 0.0;
    for (std::size_t i = 0; i < set.Size(); ++i)
    {
      double s[3];
      rbf.Evaluate(set.Points.data() + 3 * i, s);
      for (int c = 0; c < 2; ++c)
      {
        largest = std::max(largest, std::abs(s[c] - affine(set.Points.data() + 3 * i, c)));
      }
    }
    EXPECT_LE(largest, 1e-12 * scale) << "radius " << radius;
  }
}

TEST(RBFDeformation, TwoDimensionalMeshStaysTwoDimensional)
{
  dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    set.Points[3 * i + 2] = 1.5 + 1e-3 * static_cast<double>(i % 7); // z is ignored in 2D
  }
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 10.0;
  motion.Translation[2] = 0.5; // a z translation in 2D must not leak into the result
  const dgmf::BoundaryMotion boundary = Gather(set, motion);
  for (double radius : { 0.0, 0.8 })
  {
    dgmf::RBFParameters parameters;
    parameters.SupportRadius = radius;
    const dgmf::RBFInterpolation rbf(boundary, parameters);
    const std::vector<double> deformed = Deform(rbf, set);
    for (std::size_t i = 0; i < set.Size(); ++i)
    {
      ASSERT_EQ(deformed[3 * i + 2], set.Points[3 * i + 2]);
      double s[3];
      rbf.Evaluate(set.Points.data() + 3 * i, s);
      ASSERT_EQ(s[2], 0.0);
    }
    EXPECT_LE(rbf.GetBoundaryError(), 1e-10);
  }
}

TEST(RBFDeformation, GreedySelectionMeetsTheTolerance)
{
  // Rotating circle, 400 + 400 boundary nodes. Measured (Release, -O2): about 15 ms with ~160
  // centres; the full dense fit of all 800 nodes takes ~40 ms.
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(400, 100);
  const dgmf::BoundaryMotion boundary = RotatedCircle(set, 10.0);
  for (double tolerance : { 1e-3, 1e-5 })
  {
    dgmf::RBFParameters parameters;
    parameters.Greedy = true;
    parameters.GreedyTolerance = tolerance;
    const dgmf::RBFInterpolation rbf(boundary, parameters);
    EXPECT_LE(rbf.GetBoundaryError(), tolerance);
    EXPECT_NEAR(RelativeBoundaryError(rbf, boundary), rbf.GetBoundaryError(), 1e-12);
    EXPECT_LT(rbf.GetNumberOfCentres(), boundary.Size());
    EXPECT_GE(rbf.GetNumberOfCentres(), 3u);
  }
}

TEST(RBFDeformation, GreedySelectionStopsAtTheMaximumNumberOfPoints)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(400, 100);
  const dgmf::BoundaryMotion boundary = RotatedCircle(set, 10.0);
  dgmf::RBFParameters parameters;
  parameters.Greedy = true;
  parameters.GreedyTolerance = 1e-12;
  parameters.GreedyMaximumPoints = 20;
  const dgmf::RBFInterpolation rbf(boundary, parameters);
  EXPECT_EQ(rbf.GetNumberOfCentres(), 20u);
  EXPECT_GT(rbf.GetBoundaryError(), 1e-12);
  EXPECT_NEAR(RelativeBoundaryError(rbf, boundary), rbf.GetBoundaryError(), 1e-12);
}

TEST(RBFDeformation, TooLargeDenseSystemThrowsBeforeAllocating)
{
  // 13,000 boundary nodes on a grid with a global support: 1.35 GB and O(n^3) for the dense
  // matrix. The constructor must refuse at once (measured: a few ms) with an actionable message.
  dgmf::BoundaryMotion boundary;
  boundary.Dimension = 2;
  for (int i = 0; i < 130; ++i)
  {
    for (int j = 0; j < 100; ++j)
    {
      boundary.Nodes.push_back(static_cast<std::int32_t>(boundary.Nodes.size()));
      boundary.Positions.insert(boundary.Positions.end(), { 0.1 * i, 0.1 * j, 0.0 });
      boundary.Displacements.insert(boundary.Displacements.end(), { 0.01 * i, 0.0, 0.0 });
    }
  }
  const auto start = std::chrono::steady_clock::now();
  try
  {
    const dgmf::RBFInterpolation rbf(boundary, dgmf::RBFParameters());
    FAIL() << "expected std::invalid_argument";
  }
  catch (const std::invalid_argument& error)
  {
    const std::string message = error.what();
    EXPECT_NE(message.find("13000"), std::string::npos) << message;
    EXPECT_NE(message.find("RBFGreedy"), std::string::npos) << message;
    EXPECT_NE(message.find("SupportRadius"), std::string::npos) << message;
  }
  // Not a timing assert on the machine's speed: a dense attempt would take minutes, not seconds.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}

TEST(RBFDeformation, RejectsTooFewOrDegenerateBoundaryNodes)
{
  dgmf::BoundaryMotion boundary;
  boundary.Dimension = 2;
  boundary.Nodes = { 0, 1 };
  boundary.Positions = { 0, 0, 0, 1, 0, 0 };
  boundary.Displacements = { 0, 0, 0, 0.1, 0, 0 };
  EXPECT_THROW(dgmf::RBFInterpolation(boundary, dgmf::RBFParameters()), std::invalid_argument);

  // Ten collinear nodes: the linear polynomial is not determined.
  boundary.Nodes.clear();
  boundary.Positions.clear();
  boundary.Displacements.clear();
  for (int i = 0; i < 10; ++i)
  {
    boundary.Nodes.push_back(i);
    boundary.Positions.insert(boundary.Positions.end(), { 1.0 * i, 2.0 * i, 0.0 });
    boundary.Displacements.insert(boundary.Displacements.end(), { 0.0, 0.1 * i, 0.0 });
  }
  EXPECT_THROW(dgmf::RBFInterpolation(boundary, dgmf::RBFParameters()), std::invalid_argument);

  // Coplanar nodes in 3D.
  boundary.Dimension = 3;
  boundary.Positions.clear();
  for (int i = 0; i < 10; ++i)
  {
    boundary.Positions.insert(boundary.Positions.end(), { 1.0 * (i % 3), 1.0 * (i / 3), 2.0 });
  }
  EXPECT_THROW(dgmf::RBFInterpolation(boundary, dgmf::RBFParameters()), std::invalid_argument);
}

TEST(RBFDeformation, DuplicatedBoundaryNodesAreMerged)
{
  // A boundary node listed twice (same position and displacement) would make Phi singular.
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::BoundaryMotion boundary = RotatedCircle(set, 10.0);
  for (std::size_t i = 0; i < 5; ++i)
  {
    boundary.Nodes.push_back(boundary.Nodes[i]);
    for (int c = 0; c < 3; ++c)
    {
      boundary.Positions.push_back(boundary.Positions[3 * i + c]);
      boundary.Displacements.push_back(boundary.Displacements[3 * i + c]);
    }
  }
  const dgmf::RBFInterpolation rbf(boundary, dgmf::RBFParameters());
  EXPECT_EQ(rbf.GetNumberOfCentres(), boundary.Size() - 5);
  EXPECT_LE(RelativeBoundaryError(rbf, boundary), 1e-10);
}

TEST(RBFDeformation, ReproducesBoundaryMotionIn3D)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(500);
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[0] = 5.0;
  motion.AnglesDegrees[1] = 10.0;
  motion.Translation[2] = 0.1;
  const dgmf::BoundaryMotion boundary = Gather(set, motion);
  for (double radius : { 0.0, 1.5 })
  {
    dgmf::RBFParameters parameters;
    parameters.SupportRadius = radius;
    const dgmf::RBFInterpolation rbf(boundary, parameters);
    EXPECT_LE(rbf.GetBoundaryError(), 1e-10) << "radius " << radius;
    EXPECT_LE(RelativeBoundaryError(rbf, boundary), 1e-10) << "radius " << radius;
  }
  dgmf::RBFParameters greedy;
  greedy.Greedy = true;
  const dgmf::RBFInterpolation rbf(boundary, greedy);
  EXPECT_LE(rbf.GetBoundaryError(), greedy.GreedyTolerance);
}

TEST(RBFDeformation, SerialAndTwoThreadsGiveIdenticalResults)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(64, 20, 5000);
  const dgmf::BoundaryMotion boundary = RotatedCircle(set, 30.0);
  for (double radius : { 0.0, 0.8 })
  {
    dgmf::RBFParameters parameters;
    parameters.SupportRadius = radius;
    const dgmf::RBFInterpolation rbf(boundary, parameters);
    const std::vector<double> serial = Deform(rbf, set);
    const std::vector<double> threaded = Deform(rbf, set, TwoThreadFor);
    ASSERT_EQ(serial.size(), threaded.size());
    EXPECT_EQ(std::memcmp(serial.data(), threaded.data(), serial.size() * sizeof(double)), 0);
  }
}
