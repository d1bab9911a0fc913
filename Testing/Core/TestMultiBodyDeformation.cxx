// DGMF with several moving bodies: per-body damping fields, the summed motion, exactness on the
// bodies, the single-body case, threads, validity between two bodies, extracted motions.
#include "SyntheticNodes.h"
#include "TwoBodyNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayGraph.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/MultiBodyDeformation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

using dgmf_test::TwoThreadFor;

using dgmf_test::Map;

struct Result
{
  std::vector<double> Points, F;
};

Result DeformBodies(const dgmf::DelaunayMapping& mapping, const dgmf_test::BodyNodeSet& set,
  const std::vector<dgmf::BodyMotion>& bodies,
  dgmf::DeformationMode mode = dgmf::DeformationMode::DGMF2, double r0s = 1.0,
  dgmf::DampingFunction u = dgmf::DampingFunction::U1,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  Result result;
  result.Points.resize(3 * set.Size());
  result.F.resize(set.Size());
  dgmf::DeformMultiBody(mapping, set.BodyIds.data(), bodies, r0s, u, mode, set.Points.data(),
    result.Points.data(), result.F.data(), parallelFor);
  return result;
}

std::vector<double> BodyF(const dgmf::DelaunayMapping& mapping, const dgmf_test::BodyNodeSet& set,
  std::int32_t body, double r0s = 1.0, dgmf::DampingFunction u = dgmf::DampingFunction::U1,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  std::vector<double> f(set.Size());
  dgmf::ComputeBodyDampingFactor(mapping, set.BodyIds.data(), body, r0s, u, f.data(), parallelFor);
  return f;
}

/// A body set with every body node's own shape deformation (a small wobble).
std::vector<double> Wobble(const dgmf_test::BodyNodeSet& set)
{
  std::vector<double> d(3 * set.Size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.BodyIds[i] > 0)
    {
      d[3 * i] = 0.03 * std::sin(3.0 * set.Points[3 * i + 1]);
      d[3 * i + 1] = -0.02 * set.Points[3 * i];
      d[3 * i + 2] = set.Dimension == 3 ? 0.01 * set.Points[3 * i + 1] : 0.0;
    }
  }
  return d;
}

/// Rotation by a motion's Euler or axis angle, through RigidMotion (matrix path) with d added.
void Prescribed(const dgmf::RigidMotion& motion, const double* x, const double* d, double* out)
{
  motion.Apply(1.0, x, d, out);
}

std::vector<dgmf::BodyMotion> TwoMotions2D(const dgmf_test::BodyNodeSet& set, const double* shape)
{
  std::vector<dgmf::BodyMotion> bodies(2);
  bodies[0].Motion.AnglesDegrees[2] = 30.0;
  bodies[0].Motion.Center[0] = set.Centers[0][0];
  bodies[0].Motion.Translation[0] = 0.1;
  bodies[0].Motion.Translation[1] = 0.2;
  bodies[0].Displacement = shape;
  bodies[1].Motion.Axis[2] = -1.0;
  bodies[1].Motion.AxisAngleDegrees = 45.0;
  bodies[1].Motion.Center[0] = set.Centers[1][0];
  bodies[1].Motion.Translation[0] = -0.1;
  return bodies;
}

/// Signed area (2D) of the triangle of points a, b, c (3 coordinates each).
double SignedArea(const double* a, const double* b, const double* c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}
} // namespace

TEST(MultiBodyDeformation, EachBodyFollowsItsOwnMotion2D)
{
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare();
  const dgmf::DelaunayMapping mapping = Map(set);
  const std::vector<double> shape = Wobble(set);
  const std::vector<dgmf::BodyMotion> bodies = TwoMotions2D(set, shape.data());
  const Result result = DeformBodies(mapping, set, bodies);
  const std::vector<double> f1 = BodyF(mapping, set, 1), f2 = BodyF(mapping, set, 2);
  int both = 0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double* x = set.Points.data() + 3 * i;
    const double* y = result.Points.data() + 3 * i;
    const std::int32_t body = set.BodyIds[i];
    if (body > 0)
    {
      const dgmf::BodyMotion& motion = bodies[static_cast<std::size_t>(body - 1)];
      double expected[3];
      Prescribed(
        motion.Motion, x, motion.Displacement ? motion.Displacement + 3 * i : nullptr, expected);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(y[c], expected[c], 1e-12) << "node " << i << " of body " << body;
      }
      EXPECT_EQ(f1[i], body == 1 ? 1.0 : 0.0);
      EXPECT_EQ(f2[i], body == 2 ? 1.0 : 0.0);
      EXPECT_EQ(result.F[i], 1.0);
    }
    else if (set.Kinds[i] == dgmf::NodeKind::StaticBoundary)
    {
      EXPECT_EQ(std::memcmp(x, y, 24), 0) << "static node " << i << " moved";
      EXPECT_EQ(f1[i], 0.0);
      EXPECT_EQ(f2[i], 0.0);
      EXPECT_EQ(result.F[i], 0.0);
    }
    else
    {
      EXPECT_GE(f1[i], 0.0);
      EXPECT_LE(f1[i], 1.0);
      EXPECT_GE(f2[i], 0.0);
      EXPECT_LE(f2[i], 1.0);
      EXPECT_NEAR(result.F[i], std::min(1.0, f1[i] + f2[i]), 1e-15);
      both += f1[i] > 0.0 && f2[i] > 0.0;
    }
    EXPECT_EQ(y[2], 0.0) << "a 2D node left its plane";
  }
  EXPECT_GT(both, 5); // some nodes feel both bodies
}

TEST(MultiBodyDeformation, EachBodyFollowsItsOwnMotion3D)
{
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoSpheresInBox();
  const dgmf::DelaunayMapping mapping = Map(set);
  const std::vector<double> shape = Wobble(set);
  std::vector<dgmf::BodyMotion> bodies(2);
  bodies[0].Motion.Axis[0] = 1.0;
  bodies[0].Motion.Axis[1] = 1.0;
  bodies[0].Motion.AxisAngleDegrees = 150.0;
  bodies[0].Motion.Center[0] = -2.5;
  bodies[0].Motion.Translation[2] = 0.3;
  bodies[1].Motion.AnglesDegrees[0] = 20.0;
  bodies[1].Motion.AnglesDegrees[1] = -40.0;
  bodies[1].Motion.Center[0] = 2.5;
  bodies[1].Displacement = shape.data();
  const Result result = DeformBodies(mapping, set, bodies);
  const std::vector<double> f1 = BodyF(mapping, set, 1), f2 = BodyF(mapping, set, 2);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double* x = set.Points.data() + 3 * i;
    const double* y = result.Points.data() + 3 * i;
    const std::int32_t body = set.BodyIds[i];
    if (body > 0)
    {
      const dgmf::BodyMotion& motion = bodies[static_cast<std::size_t>(body - 1)];
      double expected[3];
      Prescribed(
        motion.Motion, x, motion.Displacement ? motion.Displacement + 3 * i : nullptr, expected);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(y[c], expected[c], 1e-12) << "node " << i << " of body " << body;
      }
      EXPECT_EQ(f1[i], body == 1 ? 1.0 : 0.0);
      EXPECT_EQ(f2[i], body == 2 ? 1.0 : 0.0);
    }
    else if (set.Kinds[i] == dgmf::NodeKind::StaticBoundary)
    {
      EXPECT_EQ(std::memcmp(x, y, 24), 0) << "static node " << i << " moved";
      EXPECT_EQ(f1[i], 0.0);
      EXPECT_EQ(f2[i], 0.0);
    }
    EXPECT_LE(result.F[i], 1.0);
    EXPECT_GE(result.F[i], 0.0);
  }
}

TEST(MultiBodyDeformation, NodesMoveByTheSumOfTheBodiesDisplacements)
{
  // x' = x + sum_k [M_k(f_k; x) - x], checked with the matrix path of RigidMotion.
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare(48, 20, 3000, 1.2, 0.8);
  const dgmf::DelaunayMapping mapping = Map(set);
  const std::vector<dgmf::BodyMotion> bodies = TwoMotions2D(set, nullptr);
  const Result result = DeformBodies(mapping, set, bodies);
  const std::vector<double> f1 = BodyF(mapping, set, 1), f2 = BodyF(mapping, set, 2);
  int both = 0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.Kinds[i] != dgmf::NodeKind::Interior)
    {
      continue;
    }
    const double* x = set.Points.data() + 3 * i;
    double m1[3], m2[3];
    bodies[0].Motion.Apply(f1[i], x, nullptr, m1);
    bodies[1].Motion.Apply(f2[i], x, nullptr, m2);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(result.Points[3 * i + c], x[c] + (m1[c] - x[c]) + (m2[c] - x[c]), 1e-13);
    }
    both += f1[i] > 0.0 && f2[i] > 0.0;
  }
  EXPECT_GT(both, 50); // the bodies are close: many nodes feel both
}

TEST(MultiBodyDeformation, OneBodyGivesTheSingleBodyResult)
{
  const dgmf_test::NodeSet single = dgmf_test::CircleInSquare();
  dgmf_test::BodyNodeSet set;
  static_cast<dgmf_test::NodeSet&>(set) = single;
  for (const dgmf::NodeKind kind : single.Kinds)
  {
    set.BodyIds.push_back(kind == dgmf::NodeKind::MovingBoundary ? 1 : 0);
  }
  const dgmf::DelaunayMapping mapping = Map(set);
  const std::vector<double> shape = Wobble(set);
  for (const bool offCentre : { false, true })
  {
    for (const dgmf::DeformationMode mode :
      { dgmf::DeformationMode::DGMF2, dgmf::DeformationMode::DGMF1 })
    {
      for (const double r0s : { 1.0, 2.0 })
      {
        std::vector<dgmf::BodyMotion> bodies(1);
        bodies[0].Motion.AnglesDegrees[2] = 75.0;
        bodies[0].Motion.Translation[0] = 0.2;
        bodies[0].Motion.Translation[1] = -0.3;
        bodies[0].Motion.Center[0] = offCentre ? 0.3 : 0.0;
        bodies[0].Motion.Center[1] = offCentre ? -0.1 : 0.0;
        bodies[0].Displacement = shape.data();
        const Result multi = DeformBodies(mapping, set, bodies, mode, r0s);

        std::vector<double> r(set.Size()), f(set.Size()), expected(3 * set.Size());
        dgmf::ComputeBoundaryDistanceField(mapping, r0s, r.data(), dgmf::SerialFor);
        dgmf::ComputeDampingFactor(
          mapping, dgmf::DampingFunction::U1, r.data(), f.data(), dgmf::SerialFor);
        dgmf::DeformDGMF(mapping, f.data(), bodies[0].Motion, shape.data(), mode, set.Points.data(),
          expected.data(), dgmf::SerialFor);
        const std::vector<double> f1 = BodyF(mapping, set, 1, r0s);
        std::size_t different = 0;
        for (std::size_t i = 0; i < set.Size(); ++i)
        {
          for (int c = 0; c < 3; ++c)
          {
            const double e = expected[3 * i + c];
            EXPECT_NEAR(multi.Points[3 * i + c], e, 1e-15 * std::max(1.0, std::abs(e)));
            different += multi.Points[3 * i + c] != e;
          }
          EXPECT_NEAR(multi.F[i], f[i], 1e-15);
          EXPECT_NEAR(f1[i], f[i], 1e-15);
          if (f[i] > 1e-20)
          {
            EXPECT_EQ(f1[i], f[i]) << "node " << i; // same arithmetic wherever f matters
          }
        }
        if (!offCentre)
        {
          EXPECT_EQ(different, 0u) << "not bit for bit";
        }
      }
    }
  }
}

TEST(MultiBodyDeformation, SameBitsWithOneAndTwoThreads)
{
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare(48, 20, 20000);
  const dgmf::DelaunayMapping mapping = Map(set, TwoThreadFor);
  const std::vector<double> shape = Wobble(set);
  const std::vector<dgmf::BodyMotion> bodies = TwoMotions2D(set, shape.data());
  const Result serial = DeformBodies(mapping, set, bodies, dgmf::DeformationMode::DGMF2, 1.0,
    dgmf::DampingFunction::U1, dgmf::SerialFor);
  const Result threaded = DeformBodies(mapping, set, bodies, dgmf::DeformationMode::DGMF2, 1.0,
    dgmf::DampingFunction::U1, TwoThreadFor);
  EXPECT_EQ(std::memcmp(
              serial.Points.data(), threaded.Points.data(), serial.Points.size() * sizeof(double)),
    0);
  EXPECT_EQ(std::memcmp(serial.F.data(), threaded.F.data(), serial.F.size() * sizeof(double)), 0);
  const std::vector<double> fSerial =
    BodyF(mapping, set, 2, 1.0, dgmf::DampingFunction::U1, dgmf::SerialFor);
  const std::vector<double> fThreaded =
    BodyF(mapping, set, 2, 1.0, dgmf::DampingFunction::U1, TwoThreadFor);
  EXPECT_EQ(std::memcmp(fSerial.data(), fThreaded.data(), fSerial.size() * sizeof(double)), 0);
}

TEST(MultiBodyDeformation, DampingFactorsSumToAtMostOne)
{
  // With every damping function of the paper, sum_k f_k <= 1: the sum never overshoots.
  for (const bool threeD : { false, true })
  {
    const dgmf_test::BodyNodeSet set =
      threeD ? dgmf_test::TwoSpheresInBox() : dgmf_test::TwoCirclesInSquare(48, 20, 3000, 1.2, 0.8);
    const dgmf::DelaunayMapping mapping = Map(set);
    for (int u = 1; u <= 7; ++u)
    {
      for (const double r0s : { 1.0, 1.5 })
      {
        const auto function = static_cast<dgmf::DampingFunction>(u);
        const std::vector<double> f1 = BodyF(mapping, set, 1, r0s, function);
        const std::vector<double> f2 = BodyF(mapping, set, 2, r0s, function);
        double largest = 0.0;
        for (std::size_t i = 0; i < set.Size(); ++i)
        {
          largest = std::max(largest, f1[i] + f2[i]);
        }
        EXPECT_LE(largest, 1.0 + 1e-15) << "u" << u << " r0s " << r0s;
      }
    }
  }
}

namespace
{
struct MeshCheck
{
  std::size_t Triangles = 0, Inverted = 0;
  double WorstBodyAreaRatio = 1.0; ///< min over triangles touching a body of min(A'/A, A/A')
};

/// Inverted triangles of the Delaunay triangulation of all nodes (without those inside a body).
MeshCheck CheckMesh(const dgmf::DelaunayGraph& mesh, const dgmf_test::BodyNodeSet& set,
  const std::vector<double>& deformed)
{
  MeshCheck check;
  const std::vector<std::int32_t>& node = mesh.GetPointOfVertex();
  for (std::int32_t e = 0; e < static_cast<std::int32_t>(mesh.GetNumberOfElements()); ++e)
  {
    const std::int32_t* v = mesh.GetElement(e);
    const auto a = static_cast<std::size_t>(node[static_cast<std::size_t>(v[0])]);
    const auto b = static_cast<std::size_t>(node[static_cast<std::size_t>(v[1])]);
    const auto c = static_cast<std::size_t>(node[static_cast<std::size_t>(v[2])]);
    const std::int32_t ba = set.BodyIds[a], bb = set.BodyIds[b], bc = set.BodyIds[c];
    if (ba > 0 && ba == bb && bb == bc)
    {
      continue; // inside a circle
    }
    const double before = SignedArea(&set.Points[3 * a], &set.Points[3 * b], &set.Points[3 * c]);
    if (before <= 1e-9)
    {
      continue;
    }
    ++check.Triangles;
    const double after = SignedArea(&deformed[3 * a], &deformed[3 * b], &deformed[3 * c]);
    check.Inverted += after <= 0.0;
    if (ba > 0 || bb > 0 || bc > 0)
    {
      check.WorstBodyAreaRatio =
        std::min(check.WorstBodyAreaRatio, std::min(after / before, before / after));
    }
  }
  return check;
}
} // namespace

TEST(MultiBodyDeformation, OppositeRotationsLeaveAValidMesh)
{
  // Two circles of radius 0.8 centred 5 apart turning 45 degrees in opposite directions. The
  // "mesh" is the Delaunay triangulation of all nodes without the triangles inside the circles.
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare(48, 20, 10000);
  const dgmf::DelaunayMapping mapping = Map(set);
  const dgmf::DelaunayGraph mesh(2, set.Points.data(), set.Size());
  ASSERT_EQ(mesh.GetNumberOfVertices(), set.Size());
  for (const double sense : { 1.0, -1.0 })
  {
    std::vector<dgmf::BodyMotion> bodies(2), alone(2);
    for (std::size_t k = 0; k < 2; ++k)
    {
      bodies[k].Motion.AnglesDegrees[2] = k == 0 ? 45.0 * sense : -45.0 * sense;
      bodies[k].Motion.Center[0] = set.Centers[k][0];
    }
    const MeshCheck both = CheckMesh(mesh, set, DeformBodies(mapping, set, bodies).Points);
    EXPECT_GT(both.Triangles, 19000u);
    EXPECT_EQ(both.Inverted, 0u) << "inverted triangles, sense " << sense;
    // The cells touching a body turn with it: their area hardly changes, and not less than when
    // each body turns alone.
    EXPECT_GT(both.WorstBodyAreaRatio, 0.8);
    for (std::size_t k = 0; k < 2; ++k)
    {
      alone = bodies;
      alone[1 - k].Motion = dgmf::RigidMotion();
      const MeshCheck single = CheckMesh(mesh, set, DeformBodies(mapping, set, alone).Points);
      EXPECT_EQ(single.Inverted, 0u);
      EXPECT_GT(both.WorstBodyAreaRatio, single.WorstBodyAreaRatio - 0.05);
    }
  }
}

TEST(MultiBodyDeformation, ExtractedMotionsReproduceExplicitOnes)
{
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare();
  const dgmf::DelaunayMapping mapping = Map(set);
  std::vector<dgmf::BodyMotion> explicitBodies(2);
  explicitBodies[0].Motion.AnglesDegrees[2] = 60.0;
  explicitBodies[0].Motion.Center[0] = set.Centers[0][0];
  explicitBodies[0].Motion.Translation[1] = 0.25;
  explicitBodies[1].Motion.AnglesDegrees[2] = -170.0;
  explicitBodies[1].Motion.Center[0] = set.Centers[1][0];
  std::vector<double> D(3 * set.Size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.BodyIds[i] > 0)
    {
      double out[3];
      explicitBodies[static_cast<std::size_t>(set.BodyIds[i] - 1)].Motion.Apply(
        1.0, set.Points.data() + 3 * i, nullptr, out);
      for (int c = 0; c < 3; ++c)
      {
        D[3 * i + c] = out[c] - set.Points[3 * i + c];
      }
    }
  }
  std::vector<double> residual(3 * set.Size(), 99.0);
  const std::vector<dgmf::FittedMotion> fits = dgmf::ExtractBodyMotions(
    2, set.Points.data(), D.data(), set.Size(), set.BodyIds.data(), 2, residual.data());
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_NEAR(fits[0].AngleDegrees, 60.0, 1e-10);
  EXPECT_EQ(fits[0].Axis[2], 1.0);
  EXPECT_NEAR(fits[0].Center[0], -2.5, 1e-14);
  EXPECT_NEAR(fits[0].Translation[1], 0.25, 1e-14);
  EXPECT_NEAR(fits[1].AngleDegrees, 170.0, 1e-10);
  EXPECT_EQ(fits[1].Axis[2], -1.0);
  for (std::size_t i = 0; i < residual.size(); ++i)
  {
    EXPECT_NEAR(residual[i], 0.0, 1e-14);
  }
  std::vector<dgmf::BodyMotion> fitted(2);
  for (std::size_t k = 0; k < 2; ++k)
  {
    fitted[k].Motion = fits[k].ToRigidMotion();
    fitted[k].Displacement = residual.data();
  }
  const Result expected = DeformBodies(mapping, set, explicitBodies);
  const Result result = DeformBodies(mapping, set, fitted);
  for (std::size_t i = 0; i < expected.Points.size(); ++i)
  {
    EXPECT_NEAR(
      result.Points[i], expected.Points[i], 1e-9 * std::max(1.0, std::abs(expected.Points[i])));
  }

  // With a shape deformation on body 2, the body nodes still land exactly where prescribed.
  const std::vector<double> shape = Wobble(set);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.BodyIds[i] == 2)
    {
      for (int c = 0; c < 3; ++c)
      {
        D[3 * i + c] += shape[3 * i + c];
      }
    }
  }
  const std::vector<dgmf::FittedMotion> deformedFits = dgmf::ExtractBodyMotions(
    2, set.Points.data(), D.data(), set.Size(), set.BodyIds.data(), 2, residual.data());
  EXPECT_GT(deformedFits[1].ResidualRMS, 1e-3);
  for (std::size_t k = 0; k < 2; ++k)
  {
    fitted[k].Motion = deformedFits[k].ToRigidMotion();
  }
  const Result deformed = DeformBodies(mapping, set, fitted);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.BodyIds[i] > 0)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(deformed.Points[3 * i + c], set.Points[3 * i + c] + D[3 * i + c], 1e-12);
      }
    }
  }
  // A third body without nodes is an identity fit.
  const std::vector<dgmf::FittedMotion> three = dgmf::ExtractBodyMotions(
    2, set.Points.data(), D.data(), set.Size(), set.BodyIds.data(), 3, nullptr);
  EXPECT_EQ(three[2].NumberOfPoints, 0u);
  EXPECT_EQ(three[2].Status, dgmf::RotationFit::Undetermined);
  EXPECT_THROW(dgmf::ExtractBodyMotions(
                 2, set.Points.data(), D.data(), set.Size(), set.BodyIds.data(), 1, nullptr),
    std::invalid_argument);
}
