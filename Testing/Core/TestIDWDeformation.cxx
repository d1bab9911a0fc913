// IDW interpolation of the boundary motion: exactness, hand computations, overflow, threads.
#include "SyntheticNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/BoundaryMotion.h"
#include "dgmf/IDWDeformation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
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

std::vector<double> Deform(const dgmf::BoundaryMotion& boundary, const dgmf_test::NodeSet& set,
  const dgmf::IDWParameters& parameters = dgmf::IDWParameters(),
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  std::vector<double> deformed(set.Points.size());
  dgmf::DeformIDW(
    boundary, parameters, set.Points.data(), set.Size(), deformed.data(), parallelFor);
  return deformed;
}

/// Two boundary nodes at (-1, 0) and (1, 0) (Ldef = 1) with different displacements.
dgmf::BoundaryMotion TwoNodes()
{
  dgmf::BoundaryMotion boundary;
  boundary.Dimension = 2;
  boundary.Nodes = { 0, 1 };
  boundary.Positions = { -1.0, 0.0, 0.0, 1.0, 0.0, 0.0 };
  boundary.Displacements = { 0.1, 0.2, 0.0, 0.3, -0.4, 0.0 };
  return boundary;
}

/// Displacement at x by a straightforward evaluation of the formula (no scaling, no tiles).
void HandIDW(const dgmf::BoundaryMotion& boundary, double a, double b, double alpha, double L,
  const double x[3], double s[2])
{
  double sw = 0.0, sum[2] = { 0.0, 0.0 };
  for (std::size_t i = 0; i < boundary.Size(); ++i)
  {
    const double* xi = boundary.Positions.data() + 3 * i;
    const double d = std::hypot(x[0] - xi[0], x[1] - xi[1]);
    const double A = boundary.Weights.empty() ? 1.0 : boundary.Weights[i];
    const double w = A * (std::pow(L / d, a) + std::pow(alpha * L / d, b));
    sw += w;
    sum[0] += w * boundary.Displacements[3 * i];
    sum[1] += w * boundary.Displacements[3 * i + 1];
  }
  s[0] = sum[0] / sw;
  s[1] = sum[1] / sw;
}

/// One query point through DeformIDW; returns the displacement.
std::vector<double> At(const dgmf::BoundaryMotion& boundary, const double x[3],
  const dgmf::IDWParameters& parameters = dgmf::IDWParameters(), double* L = nullptr)
{
  double deformed[3];
  const double used = dgmf::DeformIDW(boundary, parameters, x, 1, deformed, dgmf::SerialFor);
  if (L)
  {
    *L = used;
  }
  return { deformed[0] - x[0], deformed[1] - x[1], deformed[2] - x[2] };
}
} // namespace

TEST(IDWDeformation, BoundaryNodesFollowTheirDisplacementExactly)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 10.0;
  motion.Translation[0] = 0.05;
  const dgmf::BoundaryMotion boundary = Gather(set, motion);
  const std::vector<double> deformed = Deform(boundary, set);
  const double scale = MaximumDisplacement(boundary);
  for (std::size_t b = 0; b < boundary.Size(); ++b)
  {
    const std::size_t i = static_cast<std::size_t>(boundary.Nodes[b]);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(deformed[3 * i + c], set.Points[3 * i + c] + boundary.Displacements[3 * b + c],
        1e-14 * scale);
    }
  }
}

TEST(IDWDeformation, BoundaryNodesFollowTheirDisplacementExactlyIn3D)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(500);
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[0] = 5.0;
  motion.AnglesDegrees[1] = 10.0;
  motion.Translation[2] = 0.1;
  const dgmf::BoundaryMotion boundary = Gather(set, motion);
  const std::vector<double> deformed = Deform(boundary, set);
  const double scale = MaximumDisplacement(boundary);
  for (std::size_t b = 0; b < boundary.Size(); ++b)
  {
    const std::size_t i = static_cast<std::size_t>(boundary.Nodes[b]);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(deformed[3 * i + c], set.Points[3 * i + c] + boundary.Displacements[3 * b + c],
        1e-14 * scale);
    }
  }
}

TEST(IDWDeformation, PureTranslationIsExactEverywhere)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(500);
  dgmf::BoundaryMotion boundary = Gather(set, dgmf::RigidMotion());
  const double t[3] = { 0.37, -1.21, 0.05 };
  for (std::size_t i = 0; i < boundary.Size(); ++i)
  {
    std::copy(t, t + 3, boundary.Displacements.begin() + 3 * i);
  }
  const double scale = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const std::vector<double> s = At(boundary, set.Points.data() + 3 * i);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_NEAR(s[c], t[c], 1e-14 * scale) << "node " << i;
    }
  }
}

TEST(IDWDeformation, AutomaticReferenceLengthIsTheLargestDistanceFromTheCentroid)
{
  // Nodes (0, 0), (4, 0), (0, 3): centroid (4/3, 1); distances 5/3, sqrt(73)/3, sqrt(52)/3.
  dgmf::BoundaryMotion boundary;
  boundary.Dimension = 2;
  boundary.Nodes = { 0, 1, 2 };
  boundary.Positions = { 0, 0, 0, 4, 0, 0, 0, 3, 0 };
  boundary.Displacements = { 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0 };
  const double x[3] = { 1.0, 1.0, 0.0 };
  double L = 0.0;
  const std::vector<double> s = At(boundary, x, dgmf::IDWParameters(), &L);
  EXPECT_NEAR(L, std::sqrt(73.0) / 3.0, 1e-15 * L);
  double expected[2];
  HandIDW(boundary, 3.0, 5.0, 5.0, std::sqrt(73.0) / 3.0, x, expected);
  EXPECT_NEAR(s[0], expected[0], 1e-15);
  EXPECT_NEAR(s[1], expected[1], 1e-15);

  // An explicit Ldef is used and returned as given.
  dgmf::IDWParameters parameters;
  parameters.ReferenceLength = 2.5;
  const std::vector<double> t = At(boundary, x, parameters, &L);
  EXPECT_EQ(L, 2.5);
  HandIDW(boundary, 3.0, 5.0, 5.0, 2.5, x, expected);
  EXPECT_NEAR(t[0], expected[0], 1e-15);
  EXPECT_NEAR(t[1], expected[1], 1e-15);
}

TEST(IDWDeformation, EquidistantNodeGetsTheAverage)
{
  const dgmf::BoundaryMotion boundary = TwoNodes();
  const double x[3] = { 0.0, 0.7, 0.0 };
  const std::vector<double> s = At(boundary, x);
  EXPECT_NEAR(s[0], 0.2, 1e-15);
  EXPECT_NEAR(s[1], -0.1, 1e-15);
  EXPECT_EQ(s[2], 0.0);
}

TEST(IDWDeformation, AreaWeightsPullTowardTheirNode)
{
  dgmf::BoundaryMotion boundary = TwoNodes();
  const double x[3] = { 0.3, 0.4, 0.0 };
  // Hand computation: d1 = sqrt(1.85), d2 = sqrt(0.65), Ldef = 1, w = A (d^-3 + 5^5 d^-5).
  const double d1 = std::sqrt(1.85), d2 = std::sqrt(0.65);
  const auto w = [](double d) { return std::pow(1.0 / d, 3) + std::pow(5.0 / d, 5); };
  const std::vector<double> equal = At(boundary, x);
  const double e0 = (w(d1) * 0.1 + w(d2) * 0.3) / (w(d1) + w(d2));
  EXPECT_NEAR(equal[0], e0, 1e-15);

  boundary.Weights = { 2.0, 1.0 };
  const std::vector<double> weighted = At(boundary, x);
  const double s0 = (2 * w(d1) * 0.1 + w(d2) * 0.3) / (2 * w(d1) + w(d2));
  const double s1 = (2 * w(d1) * 0.2 - w(d2) * 0.4) / (2 * w(d1) + w(d2));
  EXPECT_NEAR(weighted[0], s0, 1e-15);
  EXPECT_NEAR(weighted[1], s1, 1e-15);
  // Closer to node 1's displacement (0.1, 0.2) than with equal weights.
  EXPECT_LT(
    std::hypot(weighted[0] - 0.1, weighted[1] - 0.2), std::hypot(equal[0] - 0.1, equal[1] - 0.2));

  // Scaling all A_i together changes nothing.
  boundary.Weights = { 2e-3, 1e-3 };
  const std::vector<double> scaled = At(boundary, x);
  EXPECT_NEAR(scaled[0], s0, 1e-15);
  EXPECT_NEAR(scaled[1], s1, 1e-15);
}

TEST(IDWDeformation, OtherExponentsAndAlpha)
{
  const dgmf::BoundaryMotion boundary = TwoNodes();
  const double x[3] = { 0.3, 0.4, 0.0 };
  dgmf::IDWParameters parameters;
  parameters.ExponentA = 2.0;
  parameters.ExponentB = 4.5;
  parameters.Alpha = 2.0;
  parameters.ReferenceLength = 3.0;
  double L = 0.0;
  const std::vector<double> s = At(boundary, x, parameters, &L);
  EXPECT_EQ(L, 3.0);
  double expected[2];
  HandIDW(boundary, 2.0, 4.5, 2.0, 3.0, x, expected);
  EXPECT_NEAR(s[0], expected[0], 1e-15);
  EXPECT_NEAR(s[1], expected[1], 1e-15);
}

TEST(IDWDeformation, TinyDistancesNeitherOverflowNorLoseTheNearestNode)
{
  // Node 0 at the origin, so that very small distances are representable.
  dgmf::BoundaryMotion boundary;
  boundary.Dimension = 3;
  boundary.Nodes = { 0, 1, 2, 3 };
  boundary.Positions = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  boundary.Displacements = { 0.1, 0.2, 0.3, 0, 0, 0, 0, 0, 0, -1, 0, 0 };
  for (double distance : { 0.0, 1e-310, 1e-200, 1e-100, 1e-60, 1e-30 })
  {
    const double x[3] = { distance, 0.0, 0.0 };
    const std::vector<double> s = At(boundary, x);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_TRUE(std::isfinite(s[c])) << distance;
      EXPECT_NEAR(s[c], boundary.Displacements[c], 1e-14) << "distance " << distance;
    }
  }
  // A far node: weights ~1e-300 must not underflow to 0/0.
  const double far[3] = { 1e100, 0.0, 0.0 };
  const std::vector<double> s = At(boundary, far);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_TRUE(std::isfinite(s[c]));
  }
}

TEST(IDWDeformation, RejectsInvalidInput)
{
  dgmf::BoundaryMotion boundary = TwoNodes();
  const double x[3] = { 0.0, 0.5, 0.0 };
  double out[3];
  boundary.Weights = { 1.0 };
  EXPECT_THROW(dgmf::DeformIDW(boundary, {}, x, 1, out, dgmf::SerialFor), std::invalid_argument);
  boundary.Weights = { 0.0, 0.0 };
  EXPECT_THROW(dgmf::DeformIDW(boundary, {}, x, 1, out, dgmf::SerialFor), std::invalid_argument);
  boundary.Weights = { -1.0, 1.0 };
  EXPECT_THROW(dgmf::DeformIDW(boundary, {}, x, 1, out, dgmf::SerialFor), std::invalid_argument);
  boundary.Weights.clear();
  dgmf::IDWParameters parameters;
  parameters.Alpha = -1.0;
  EXPECT_THROW(
    dgmf::DeformIDW(boundary, parameters, x, 1, out, dgmf::SerialFor), std::invalid_argument);
  EXPECT_THROW(
    dgmf::DeformIDW(dgmf::BoundaryMotion(), {}, x, 1, out, dgmf::SerialFor), std::invalid_argument);
}

TEST(IDWDeformation, SerialAndTwoThreadsGiveIdenticalResults)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(64, 20, 5000);
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 30.0;
  const dgmf::BoundaryMotion boundary = Gather(set, motion);
  for (double a : { 3.0, 2.5 })
  {
    dgmf::IDWParameters parameters;
    parameters.ExponentA = a;
    const std::vector<double> serial = Deform(boundary, set, parameters);
    const std::vector<double> threaded = Deform(boundary, set, parameters, TwoThreadFor);
    ASSERT_EQ(serial.size(), threaded.size());
    EXPECT_EQ(std::memcmp(serial.data(), threaded.data(), serial.size() * sizeof(double)), 0);
  }
}
