// DGMF steps 3-6 on synthetic node sets: boundary exactness, r and f, continuity, threads.
#include "SyntheticNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampedRigidMotion.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Result
{
  std::vector<double> R, F, Points;
};

Result Deform(const dgmf_test::NodeSet& set, const dgmf::RigidMotion& motion,
  const double* displacement, dgmf::DeformationMode mode, double r0s,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), parallelFor);
  Result result;
  result.R.resize(set.Size());
  result.F.resize(set.Size());
  result.Points.resize(3 * set.Size());
  dgmf::ComputeBoundaryDistanceField(mapping, r0s, result.R.data(), parallelFor);
  dgmf::ComputeDampingFactor(
    mapping, dgmf::DampingFunction::U1, result.R.data(), result.F.data(), parallelFor);
  dgmf::DeformDGMF(mapping, result.F.data(), motion, displacement, mode, set.Points.data(),
    result.Points.data(), parallelFor);
  return result;
}

/// Independent computation of the prescribed position: rotation about z then the rest.
void Prescribed2D(const double* x, double angleDegrees, const double* c, const double* t,
  const double* d, double* out)
{
  const double a = angleDegrees * Pi / 180.0;
  const double dx = x[0] - c[0], dy = x[1] - c[1];
  out[0] = c[0] + std::cos(a) * dx - std::sin(a) * dy + t[0] + d[0];
  out[1] = c[1] + std::sin(a) * dx + std::cos(a) * dy + t[1] + d[1];
  out[2] = x[2] + t[2] + d[2];
}

using dgmf_test::TwoThreadFor;
} // namespace

TEST(DGMFDeformation, BoundaryNodesFollowThePrescribedMotion2D)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 90.0;
  motion.Center[0] = 0.1;
  motion.Center[1] = -0.2;
  motion.Translation[0] = 0.3;
  motion.Translation[1] = -0.1;
  std::vector<double> displacement(3 * set.Size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.Kinds[i] == dgmf::NodeKind::MovingBoundary)
    {
      displacement[3 * i] = 0.05 * set.Points[3 * i + 1]; // a shape deformation on the body
      displacement[3 * i + 1] = -0.02;
    }
  }
  const Result result = Deform(set, motion, displacement.data(), dgmf::DeformationMode::DGMF2, 1.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double* x = set.Points.data() + 3 * i;
    const double* y = result.Points.data() + 3 * i;
    if (set.Kinds[i] == dgmf::NodeKind::MovingBoundary)
    {
      double expected[3];
      Prescribed2D(
        x, 90.0, motion.Center, motion.Translation, displacement.data() + 3 * i, expected);
      const double scale = std::max(1.0, std::hypot(expected[0], expected[1]));
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(y[c], expected[c], 1e-12 * scale) << "moving node " << i;
      }
      EXPECT_EQ(result.R[i], 0.0);
      EXPECT_EQ(result.F[i], 1.0);
    }
    else if (set.Kinds[i] == dgmf::NodeKind::StaticBoundary)
    {
      EXPECT_EQ(std::memcmp(x, y, 3 * sizeof(double)), 0) << "static node " << i << " moved";
      EXPECT_EQ(result.R[i], 1.0);
      EXPECT_EQ(result.F[i], 0.0);
    }
    EXPECT_GE(result.F[i], 0.0);
    EXPECT_LE(result.F[i], 1.0);
    EXPECT_EQ(y[2], 0.0) << "a 2D node left its plane";
  }
}

TEST(DGMFDeformation, RIsInterpolatedBetweenZeroAndStaticR0)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::RigidMotion motion;
  const Result result = Deform(set, motion, nullptr, dgmf::DeformationMode::DGMF2, 2.5);
  double smallest = 1e300, largest = -1e300;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.Kinds[i] == dgmf::NodeKind::MovingBoundary)
    {
      EXPECT_EQ(result.R[i], 0.0);
    }
    else if (set.Kinds[i] == dgmf::NodeKind::StaticBoundary)
    {
      EXPECT_EQ(result.R[i], 2.5);
    }
    else
    {
      smallest = std::min(smallest, result.R[i]);
      largest = std::max(largest, result.R[i]);
    }
    // Without a motion nothing moves.
    EXPECT_EQ(std::memcmp(set.Points.data() + 3 * i, result.Points.data() + 3 * i, 24), 0);
  }
  EXPECT_GE(smallest, 0.0);
  EXPECT_LE(largest, 2.5);
  EXPECT_LT(smallest, 0.5); // nodes near the circle
  EXPECT_GT(largest, 2.0);  // nodes near the square
  EXPECT_THROW(
    Deform(set, motion, nullptr, dgmf::DeformationMode::DGMF2, 0.5), std::invalid_argument);
}

TEST(DGMFDeformation, NodeOnASharedFaceGetsTheSameDeformationFromBothElements)
{
  // Paper Fig. 2: a node on the edge shared by two Delaunay triangles, the edge having a moving
  // vertex. The weight of each triangle's opposite vertex is 0 there, so Eq. 7 gives the same d
  // from either triangle. (On an edge between two static vertices d may differ, but f = 0 there.)
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare(16, 8, 0);
  dgmf::DelaunayMapping mapping(
    2, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  const dgmf::DelaunayGraph& graph = mapping.GetGraph();
  std::vector<double> displacement(3 * set.Size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    displacement[3 * i] = set.Points[3 * i] * 0.3 + 0.1;
    displacement[3 * i + 1] = -set.Points[3 * i + 1] * 0.7;
  }
  const std::vector<double> vertexDeformation =
    dgmf::GatherVertexDeformation(mapping, displacement.data());
  int sharedEdgesTested = 0;
  const auto elements = static_cast<std::int32_t>(graph.GetNumberOfElements());
  for (std::int32_t a = 0; a < elements; ++a)
  {
    for (std::int32_t b = a + 1; b < elements; ++b)
    {
      const std::int32_t* va = graph.GetElement(a);
      const std::int32_t* vb = graph.GetElement(b);
      std::vector<std::int32_t> shared;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (va[i] == vb[j])
            shared.push_back(va[i]);
      if (shared.size() != 2)
        continue;
      // Only meaningful when an opposite vertex is moving (its weight must vanish on the edge) and
      // the edge has a moving vertex (else f = 0 on the edge).
      const bool edgeMoving = mapping.GetVertexKind(shared[0]) == dgmf::NodeKind::MovingBoundary ||
        mapping.GetVertexKind(shared[1]) == dgmf::NodeKind::MovingBoundary;
      bool oppositeMoving = false;
      for (int i = 0; i < 3; ++i)
      {
        for (const std::int32_t v : { va[i], vb[i] })
        {
          if (v != shared[0] && v != shared[1] &&
            mapping.GetVertexKind(v) == dgmf::NodeKind::MovingBoundary)
          {
            oppositeMoving = true;
          }
        }
      }
      if (!oppositeMoving || !edgeMoving)
        continue;
      // A point on the shared edge, at 3/8 of its length.
      const double* p0 = graph.GetVertexPosition(shared[0]);
      const double* p1 = graph.GetVertexPosition(shared[1]);
      const double p[3] = { p0[0] + 0.375 * (p1[0] - p0[0]), p0[1] + 0.375 * (p1[1] - p0[1]), 0.0 };
      double wa[4], wb[4];
      graph.ComputeWeights(a, p, wa);
      graph.ComputeWeights(b, p, wb);
      double da[3], db[3];
      dgmf::InterpolateMovingDeformation(mapping, vertexDeformation.data(), a, wa, da);
      dgmf::InterpolateMovingDeformation(mapping, vertexDeformation.data(), b, wb, db);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(da[c], db[c], 1e-12) << "elements " << a << " and " << b;
      }
      ++sharedEdgesTested;
    }
  }
  EXPECT_GT(sharedEdgesTested, 10);
}

TEST(DGMFDeformation, BoundaryNodesFollowThePrescribedMotion3D)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox();
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[0] = 20.0;
  motion.AnglesDegrees[1] = -35.0;
  motion.AnglesDegrees[2] = 50.0;
  motion.Translation[0] = 0.4;
  motion.Translation[2] = -0.3;
  const Result result = Deform(set, motion, nullptr, dgmf::DeformationMode::DGMF2, 1.0);
  // Independent rotation: Rz(c) Ry(b) Rx(a), right-handed.
  const double a = 20.0 * Pi / 180, b = -35.0 * Pi / 180, c = 50.0 * Pi / 180;
  const double Rx[3][3] = { { 1, 0, 0 }, { 0, std::cos(a), -std::sin(a) },
    { 0, std::sin(a), std::cos(a) } };
  const double Ry[3][3] = { { std::cos(b), 0, std::sin(b) }, { 0, 1, 0 },
    { -std::sin(b), 0, std::cos(b) } };
  const double Rz[3][3] = { { std::cos(c), -std::sin(c), 0 }, { std::sin(c), std::cos(c), 0 },
    { 0, 0, 1 } };
  double RyRx[3][3] = {}, R[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        RyRx[i][j] += Ry[i][k] * Rx[k][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        R[i][j] += Rz[i][k] * RyRx[k][j];
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double* x = set.Points.data() + 3 * i;
    const double* y = result.Points.data() + 3 * i;
    if (set.Kinds[i] == dgmf::NodeKind::MovingBoundary)
    {
      for (int r = 0; r < 3; ++r)
      {
        const double expected =
          R[r][0] * x[0] + R[r][1] * x[1] + R[r][2] * x[2] + motion.Translation[r];
        EXPECT_NEAR(y[r], expected, 1e-12) << "moving node " << i;
      }
    }
    else if (set.Kinds[i] == dgmf::NodeKind::StaticBoundary)
    {
      EXPECT_EQ(std::memcmp(x, y, 24), 0) << "static node " << i << " moved";
    }
    EXPECT_GE(result.F[i], 0.0);
    EXPECT_LE(result.F[i], 1.0);
  }
}

TEST(DGMFDeformation, InteriorNodesTurnByTheirDampedAngle)
{
  // Pure rotation about the circle's centre: a node at distance rho from the centre stays at rho
  // and turns by f * angle (paper Eqs. 3-4).
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 60.0;
  const Result result = Deform(set, motion, nullptr, dgmf::DeformationMode::DGMF2, 1.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double* x = set.Points.data() + 3 * i;
    const double* y = result.Points.data() + 3 * i;
    EXPECT_NEAR(std::hypot(x[0], x[1]), std::hypot(y[0], y[1]), 1e-12);
    const double turned = std::remainder(std::atan2(y[1], y[0]) - std::atan2(x[1], x[0]), 2 * Pi);
    EXPECT_NEAR(turned, result.F[i] * 60.0 * Pi / 180.0, 1e-12) << "node " << i;
  }
}

TEST(DGMFDeformation, DGMF1UsesEachNodesOwnDisplacement)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  std::vector<double> displacement(3 * set.Size());
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    displacement[3 * i] = 0.1 * std::sin(set.Points[3 * i + 1]);
    displacement[3 * i + 1] = 0.05;
    displacement[3 * i + 2] = 0.0;
  }
  dgmf::RigidMotion none;
  const Result result = Deform(set, none, displacement.data(), dgmf::DeformationMode::DGMF1, 1.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double f = set.Kinds[i] == dgmf::NodeKind::StaticBoundary ? 0.0 : result.F[i];
    for (int c = 0; c < 2; ++c)
    {
      EXPECT_NEAR(
        result.Points[3 * i + c], set.Points[3 * i + c] + f * displacement[3 * i + c], 1e-15);
    }
  }
}

TEST(DGMFDeformation, SameBitsWithOneAndTwoThreads)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(20000);
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[1] = 30.0;
  motion.Translation[2] = 0.2;
  const Result serial =
    Deform(set, motion, nullptr, dgmf::DeformationMode::DGMF2, 1.0, dgmf::SerialFor);
  const Result threaded =
    Deform(set, motion, nullptr, dgmf::DeformationMode::DGMF2, 1.0, TwoThreadFor);
  EXPECT_EQ(std::memcmp(
              serial.Points.data(), threaded.Points.data(), serial.Points.size() * sizeof(double)),
    0);
  EXPECT_EQ(std::memcmp(serial.F.data(), threaded.F.data(), serial.F.size() * sizeof(double)), 0);
}

TEST(DGMFDeformation, FourNodesAtOnceGiveTheSameBitsAsOneAtATime)
{
  // DeformDGMF moves interior nodes four at a time (ApplyFour); the result must be Apply's, bit
  // for bit, for Euler angles, an axis rotation, with and without a node's own displacement.
  dgmf::RigidMotion euler;
  euler.AnglesDegrees[0] = 17.0;
  euler.AnglesDegrees[1] = -230.0;
  euler.AnglesDegrees[2] = 600.0;
  euler.Translation[0] = 0.3;
  euler.Center[1] = -1.5;
  dgmf::RigidMotion axis;
  axis.Axis[0] = 1.0;
  axis.Axis[1] = 2.0;
  axis.Axis[2] = -0.5;
  axis.AxisAngleDegrees = 95.0;
  axis.Translation[2] = -2.0;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0), coordinate(-20.0, 20.0);
  for (const dgmf::RigidMotion& motion : { euler, axis })
  {
    const dgmf::DampedRigidMotion damped(motion);
    for (int t = 0; t < 2000; ++t)
    {
      // f in [0, 1], with the table's end points and exact entries among them.
      const double f[4] = { t % 50 == 0 ? 1.0 : unit(random), t % 7 == 0 ? 0.25 : unit(random),
        t % 11 == 0 ? 0.0 : unit(random), unit(random) };
      double x[4][3], d[4][3], single[4][3], four[4][3];
      for (int l = 0; l < 4; ++l)
        for (int c = 0; c < 3; ++c)
        {
          x[l][c] = coordinate(random);
          d[l][c] = coordinate(random) * 0.01;
        }
      // Lanes with and without their own displacement, mixed.
      const bool withD[4] = { t % 2 == 1, t % 3 == 1, t % 2 == 0, true };
      const double* xs[4];
      const double* ds[4];
      double* outs[4];
      for (int l = 0; l < 4; ++l)
      {
        damped.Apply(f[l], x[l], withD[l] ? d[l] : nullptr, single[l]);
        xs[l] = x[l];
        ds[l] = withD[l] ? d[l] : nullptr;
        outs[l] = four[l];
      }
      damped.ApplyFour(f, xs, ds, outs);
      ASSERT_EQ(std::memcmp(single, four, sizeof(single)), 0)
        << "f = " << f[0] << ", " << f[1] << ", " << f[2] << ", " << f[3];
    }
  }
}

TEST(DGMFDeformation, DampedRotationMatchesSinAndCosForSmallAndLargeAngles)
{
  // Small angles use a shorter Taylor series (DampedRigidMotion::ShortSeriesLimit): both series
  // must give the rotation by f * angle to round-off.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double degrees : { 0.5, 3.0, 28.0, 57.0, 60.0, 170.0, -300.0, 719.0 })
  {
    dgmf::RigidMotion motion;
    motion.AnglesDegrees[2] = degrees;
    const dgmf::DampedRigidMotion damped(motion);
    double worst = 0.0;
    for (int t = 0; t < 5000; ++t)
    {
      const double f = unit(random);
      const double x[3] = { 3.0, -4.0, 1.0 };
      double out[3];
      damped.Apply(f, x, nullptr, out);
      // Reference in long double: its own round-off is far below the tolerance.
      const long double a =
        static_cast<long double>(f) * degrees * 3.14159265358979323846264338327950288L / 180.0L;
      const long double ca = std::cos(a), sa = std::sin(a);
      const long double expected[3] = { ca * x[0] - sa * x[1], sa * x[0] + ca * x[1], x[2] };
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, static_cast<double>(std::abs(out[c] - expected[c])));
      }
    }
    EXPECT_LT(worst, 1e-14) << degrees << " degrees"; // |x| = 5.1: a few units in the last place
  }
}

TEST(DGMFDeformation, RAndFInOnePassAreTheBitsOfTheirOwnPasses)
{
  // A first deformation makes r and f in one pass (ComputeDampingField); a new damping function
  // or r0s makes them apart. Every function, two values of r0s, two threads.
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(5000);
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), TwoThreadFor);
  for (const double r0s : { 1.0, 2.5 })
  {
    for (int u = 1; u <= 7; ++u)
    {
      const auto damping = static_cast<dgmf::DampingFunction>(u);
      std::vector<double> r(set.Size()), f(set.Size()), rTogether(set.Size(), -1.0),
        fTogether(set.Size(), -1.0);
      dgmf::ComputeBoundaryDistanceField(mapping, r0s, r.data(), TwoThreadFor);
      dgmf::ComputeDampingFactor(mapping, damping, r.data(), f.data(), TwoThreadFor);
      dgmf::ComputeDampingField(
        mapping, r0s, damping, rTogether.data(), fTogether.data(), TwoThreadFor);
      EXPECT_EQ(std::memcmp(r.data(), rTogether.data(), r.size() * sizeof(double)), 0) << u;
      EXPECT_EQ(std::memcmp(f.data(), fTogether.data(), f.size() * sizeof(double)), 0) << u;
      // f is the scalar function's value at every interior node, and exactly 0 or 1 on the
      // boundary.
      for (std::size_t i = 0; i < set.Size(); ++i)
      {
        const double expected = set.Kinds[i] == dgmf::NodeKind::Interior
          ? dgmf::EvaluateDamping(damping, r[i])
          : set.Kinds[i] == dgmf::NodeKind::MovingBoundary ? 1.0
                                                           : 0.0;
        ASSERT_EQ(fTogether[i], expected) << "node " << i << ", u" << u;
      }
    }
  }
}

TEST(DGMFDeformation, TheSameMeshWithOtherRoundOffGivesTheSameDeformation)
{
  // A structured channel (a gmsh user's kind): a square obstacle (moving) through a box (its
  // top and bottom static too), every node on the grid, so the boundary nodes lie on planes and
  // spheres (a degenerate Delaunay graph: many equally valid ones). The same mesh with every
  // coordinate off by up to two ulps (as the same mesh written as ASCII and as binary): the same
  // deformation. Until 2026-11-30 the graph's perturbation followed the coordinates' bits:
  // another graph, f off by 0.43 and nodes by 0.15 (the user's channel).
  dgmf_test::NodeSet exact;
  exact.Dimension = 3;
  const int n = 16, layers = 6;
  for (int k = 0; k <= layers; ++k)
  {
    for (int i = 0; i <= n; ++i)
    {
      for (int j = 0; j <= n; ++j)
      {
        const bool outer = i == 0 || j == 0 || i == n || j == n || k == 0 || k == layers;
        const bool inside = i > 6 && i < 10 && j > 6 && j < 10;
        const bool obstacle = i >= 6 && i <= 10 && j >= 6 && j <= 10 && !inside;
        if (inside)
        {
          continue;
        }
        exact.Add(i / 8.0, j / 8.0, k / 6.0,
          obstacle && !(k == 0 || k == layers)
            ? dgmf::NodeKind::MovingBoundary
            : (outer || obstacle ? dgmf::NodeKind::StaticBoundary : dgmf::NodeKind::Interior));
      }
    }
  }
  dgmf_test::NodeSet nudged = exact;
  std::mt19937 random(11);
  for (double& c : nudged.Points)
  {
    const int ulps = static_cast<int>(random() % 5) - 2;
    for (int k = 0; k < std::abs(ulps); ++k)
    {
      c = std::nextafter(c, ulps > 0 ? 10.0 : -10.0);
    }
  }
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = 15.0;
  motion.Center[0] = motion.Center[1] = 1.0;
  const Result a = Deform(exact, motion, nullptr, dgmf::DeformationMode::DGMF2, 1.0);
  const Result b = Deform(nudged, motion, nullptr, dgmf::DeformationMode::DGMF2, 1.0);
  double points = 0.0, f = 0.0;
  for (std::size_t i = 0; i < exact.Size(); ++i)
  {
    f = std::max(f, std::abs(a.F[i] - b.F[i]));
    for (int c = 0; c < 3; ++c)
    {
      points = std::max(points, std::abs(a.Points[3 * i + c] - b.Points[3 * i + c]));
    }
  }
  EXPECT_LT(f, 1e-9);
  EXPECT_LT(points, 1e-9);
}
