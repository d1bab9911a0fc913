// Rigid-motion extraction (Kabsch fit, residual).
#include "RigidMotionTestHelpers.h"

#include "dgmf/DampedRigidMotion.h"
#include "dgmf/RigidMotionFit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace rigid_test;

TEST(RigidMotionFit, RecoversRandomRigidMotions3D)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angles(0.01, 180.0);
  std::uniform_real_distribution<double> shift(-2.0, 2.0);
  std::uniform_int_distribution<int> counts(3, 60);
  for (int trial = 0; trial < 300; ++trial)
  {
    const std::vector<double> points = RandomPoints(random, counts(random), false);
    const Vec axis = RandomUnit(random);
    const double angle = angles(random);
    const Vec c0 = { shift(random), shift(random), shift(random) };
    const Vec t = { shift(random), shift(random), shift(random) };
    const Mat R = Rodrigues(axis, angle * Pi / 180.0);
    const std::vector<double> D = RigidDisplacements(points, R, c0, t);
    const dgmf::FittedMotion fit =
      dgmf::FitRigidMotion(3, points.data(), D.data(), nullptr, points.size() / 3);
    ASSERT_EQ(fit.Status, dgmf::RotationFit::Determined) << "trial " << trial;
    EXPECT_NEAR(fit.AngleDegrees, angle, 1e-10) << "trial " << trial;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(fit.Axis[c], axis[c], 1e-10) << "trial " << trial;
    }
    const Vec mean = MeanDisplacement(D);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(fit.Translation[c], mean[c], 1e-10) << "trial " << trial;
    }
    ExpectMatrixNear(ToMat(fit.Rotation), R, 1e-12, "rotation");
    EXPECT_LT(fit.ResidualRMS, 1e-12);
    EXPECT_LT(fit.MaximumResidual, 1e-12);
    EXPECT_EQ(fit.NumberOfPoints, points.size() / 3);
  }
}

TEST(RigidMotionFit, RecoversRotationsNearAndAt180Degrees)
{
  std::mt19937 random(12);
  std::vector<Vec> axes = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  for (int k = 0; k < 20; ++k)
  {
    axes.push_back(RandomUnit(random));
  }
  for (const double angle : { 179.0, 179.9, 179.999999, 180.0 })
  {
    for (const Vec& axis : axes)
    {
      const std::vector<double> points = RandomPoints(random, 25, false);
      const Mat R = Rodrigues(axis, angle / 180.0 * Pi);
      const std::vector<double> D = RigidDisplacements(points, R, { 0.5, -1.0, 2.0 }, { 1, 2, 3 });
      const dgmf::FittedMotion fit =
        dgmf::FitRigidMotion(3, points.data(), D.data(), nullptr, points.size() / 3);
      EXPECT_EQ(fit.Status, dgmf::RotationFit::Determined);
      EXPECT_NEAR(fit.AngleDegrees, angle, 1e-10) << "angle " << angle;
      EXPECT_LE(fit.AngleDegrees, 180.0);
      const Vec fitted = { fit.Axis[0], fit.Axis[1], fit.Axis[2] };
      if (angle < 180.0)
      {
        EXPECT_NEAR(Dot(fitted, axis), 1.0, 1e-10) << "angle " << angle; // same sense
      }
      else
      {
        EXPECT_NEAR(std::abs(Dot(fitted, axis)), 1.0, 1e-10); // k and -k: the same rotation
      }
      ExpectMatrixNear(ToMat(fit.Rotation), R, 1e-12, "rotation");
      EXPECT_LT(fit.MaximumResidual, 1e-12);
    }
  }
}

TEST(RigidMotionFit, PureTranslationHasNoRotation)
{
  std::mt19937 random(13);
  const std::vector<double> points = RandomPoints(random, 40, false);
  const Mat I = Rodrigues({ 0, 0, 1 }, 0.0);
  const std::vector<double> D = RigidDisplacements(points, I, { 0, 0, 0 }, { 0.3, -0.7, 1.1 });
  const dgmf::FittedMotion fit = dgmf::FitRigidMotion(3, points.data(), D.data(), nullptr, 40);
  EXPECT_LT(fit.AngleDegrees, 1e-10);
  EXPECT_NEAR(fit.Translation[0], 0.3, 1e-14);
  EXPECT_NEAR(fit.Translation[1], -0.7, 1e-14);
  EXPECT_NEAR(fit.Translation[2], 1.1, 1e-14);
  // Nothing at all: exactly the identity.
  const std::vector<double> zero(points.size(), 0.0);
  const dgmf::FittedMotion still = dgmf::FitRigidMotion(3, points.data(), zero.data(), nullptr, 40);
  EXPECT_LT(still.AngleDegrees, 1e-12);
  EXPECT_EQ(still.Translation[0], 0.0);
  EXPECT_LT(still.MaximumResidual, 1e-14);
}

TEST(RigidMotionFit, RecoversRotations2D)
{
  std::mt19937 random(14);
  std::uniform_real_distribution<double> angles(-180.0, 180.0);
  std::uniform_real_distribution<double> shift(-2.0, 2.0);
  std::vector<double> tested;
  for (int trial = 0; trial < 200; ++trial)
  {
    tested.push_back(angles(random));
  }
  tested.insert(tested.end(), { 180.0, -180.0, 179.9, -179.9, 90.0, -90.0 });
  for (const double angle : tested)
  {
    const double z = 0.7;
    const std::vector<double> points =
      RandomPoints(random, 2 + static_cast<int>(random() % 30), true, z);
    const Mat R = Rodrigues({ 0, 0, 1 }, angle / 180.0 * Pi);
    std::vector<double> D = RigidDisplacements(
      points, R, { shift(random), shift(random), z }, { shift(random), shift(random), 0.0 });
    for (std::size_t i = 2; i < D.size(); i += 3)
    {
      D[i] = 0.0; // a 2D displacement has no z
    }
    const dgmf::FittedMotion fit =
      dgmf::FitRigidMotion(2, points.data(), D.data(), nullptr, points.size() / 3);
    ASSERT_EQ(fit.Status, dgmf::RotationFit::Determined);
    EXPECT_EQ(fit.Axis[0], 0.0);
    EXPECT_EQ(fit.Axis[1], 0.0);
    EXPECT_NEAR(fit.AngleDegrees, std::abs(angle), 1e-10) << "angle " << angle;
    if (std::abs(angle) < 180.0)
    {
      EXPECT_EQ(fit.Axis[2], angle < 0.0 ? -1.0 : 1.0) << "angle " << angle;
    }
    EXPECT_EQ(fit.Center[2], z);
    EXPECT_EQ(fit.Translation[2], 0.0);
    EXPECT_LT(fit.MaximumResidual, 1e-12);
    // The fitted motion keeps the plane bit for bit.
    const dgmf::DampedRigidMotion damped(fit.ToRigidMotion());
    for (std::size_t i = 0; i < points.size(); i += 3)
    {
      for (const double f : { 0.0, 0.3, 1.0 })
      {
        double out[3];
        damped.Apply(f, points.data() + i, nullptr, out);
        EXPECT_EQ(out[2], z);
      }
    }
  }
  // Exactly 180 degrees of a symmetric set: the sums of cross products vanish exactly.
  const std::vector<double> square = { 1, 1, 0, -1, 1, 0, -1, -1, 0, 1, -1, 0 };
  const std::vector<double> flip = { -2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0 };
  const dgmf::FittedMotion half = dgmf::FitRigidMotion(2, square.data(), flip.data(), nullptr, 4);
  EXPECT_EQ(half.AngleDegrees, 180.0);
  EXPECT_EQ(half.Axis[2], 1.0);
  EXPECT_LT(half.MaximumResidual, 1e-15);
}

TEST(RigidMotionFit, SymmetricDeformationHasNoRotation)
{
  // 3D: a point set symmetric under x -> -x, y -> -y, z -> -z about its centre, and a displacement
  // odd in each coordinate separately (a stretch with cubic terms): H = sum p q^T is diagonal and
  // positive, so R = I by symmetry, and the translation is 0.
  const Vec centre = { 1.0, -2.0, 0.5 };
  std::vector<double> points, D;
  for (int i = -2; i <= 2; ++i)
  {
    for (int j = -2; j <= 2; ++j)
    {
      for (int k = -2; k <= 2; ++k)
      {
        const double p[3] = { 0.7 * i, 0.4 * j, 0.3 * k };
        for (int c = 0; c < 3; ++c)
        {
          points.push_back(centre[c] + p[c]);
        }
        D.push_back(0.3 * p[0] + 0.1 * p[0] * p[0] * p[0]);
        D.push_back(-0.2 * p[1]);
        D.push_back(0.05 * p[2] * p[2] * p[2]);
      }
    }
  }
  const dgmf::FittedMotion fit =
    dgmf::FitRigidMotion(3, points.data(), D.data(), nullptr, points.size() / 3);
  EXPECT_LT(fit.AngleDegrees, 1e-12);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(fit.Translation[c], 0.0, 1e-15);
    EXPECT_NEAR(fit.Center[c], centre[c], 1e-14);
  }
  // The residual is the whole deformation.
  std::vector<double> residual(D.size());
  dgmf::ComputeFitResidual(
    fit, points.data(), D.data(), nullptr, points.size() / 3, residual.data());
  for (std::size_t i = 0; i < D.size(); ++i)
  {
    EXPECT_NEAR(residual[i], D[i], 1e-13);
  }

  // 2D: a bump symmetric about x = 0 on a circle (the twisted bar's kind of deformation).
  std::vector<double> circle, bump;
  for (int k = 0; k < 64; ++k)
  {
    const double a = 2 * Pi * k / 64;
    circle.insert(circle.end(), { std::cos(a), std::sin(a), 0.0 });
    bump.insert(bump.end(), { 0.0, 0.4 * std::exp(-4.0 * std::cos(a) * std::cos(a)), 0.0 });
  }
  const dgmf::FittedMotion fit2 = dgmf::FitRigidMotion(2, circle.data(), bump.data(), nullptr, 64);
  EXPECT_EQ(fit2.Status, dgmf::RotationFit::Determined);
  EXPECT_LT(fit2.AngleDegrees, 1e-12);
  EXPECT_NEAR(fit2.Translation[0], 0.0, 1e-15);
  EXPECT_NEAR(fit2.Translation[1], MeanDisplacement(bump)[1], 1e-15);
}

TEST(RigidMotionFit, RigidMotionOfADeformedBody)
{
  // x' = c0 + R0 (x + d(x) - c0) + t0. The fit is equivariant: it finds R = R0 R_d, with R_d the
  // deformation's own best rotation, and the residual is R0 times the deformation's own residual.
  std::mt19937 random(15);
  std::uniform_real_distribution<double> shift(-2.0, 2.0);
  for (int trial = 0; trial < 50; ++trial)
  {
    const std::vector<double> points = RandomPoints(random, 40, false);
    std::vector<double> d(points.size());
    for (std::size_t i = 0; i < points.size(); i += 3)
    {
      d[i] = 0.05 * std::sin(points[i + 1]);
      d[i + 1] = 0.03 * std::cos(2.0 * points[i + 2]) * points[i];
      d[i + 2] = 0.02 * points[i] * points[i + 1];
    }
    const Vec axis = RandomUnit(random);
    const double angle = 10.0 + 160.0 * trial / 49.0;
    const Mat R0 = Rodrigues(axis, angle * Pi / 180.0);
    const Vec c0 = { shift(random), shift(random), shift(random) };
    const Vec t0 = { shift(random), shift(random), shift(random) };
    std::vector<double> deformed(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      deformed[i] = points[i] + d[i];
    }
    std::vector<double> D = RigidDisplacements(deformed, R0, c0, t0);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      D[i] += deformed[i] - points[i]; // total displacement from the original points
    }
    const std::size_t n = points.size() / 3;
    const dgmf::FittedMotion own = dgmf::FitRigidMotion(3, points.data(), d.data(), nullptr, n);
    const dgmf::FittedMotion fit = dgmf::FitRigidMotion(3, points.data(), D.data(), nullptr, n);
    ASSERT_EQ(fit.Status, dgmf::RotationFit::Determined);
    ExpectMatrixNear(ToMat(fit.Rotation), Multiply(R0, ToMat(own.Rotation)), 1e-12, "R0 Rd");
    // The rigid part is approximately R0: the angles differ by at most the deformation's own.
    EXPECT_GT(own.AngleDegrees, 0.0);
    EXPECT_LE(std::abs(fit.AngleDegrees - angle), own.AngleDegrees + 1e-9);
    EXPECT_NEAR(fit.ResidualRMS, own.ResidualRMS, 1e-12);
    std::vector<double> residualOwn(points.size()), residual(points.size());
    dgmf::ComputeFitResidual(own, points.data(), d.data(), nullptr, n, residualOwn.data());
    dgmf::ComputeFitResidual(fit, points.data(), D.data(), nullptr, n, residual.data());
    for (std::size_t i = 0; i < points.size(); i += 3)
    {
      const Vec rotated = Times(R0, { residualOwn[i], residualOwn[i + 1], residualOwn[i + 2] });
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(residual[i + c], rotated[c], 1e-12);
      }
    }
    // The fitted motion plus the residual puts every point where it was prescribed.
    const dgmf::DampedRigidMotion damped(fit.ToRigidMotion());
    for (std::size_t i = 0; i < points.size(); i += 3)
    {
      double out[3];
      damped.Apply(1.0, points.data() + i, residual.data() + i, out);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(out[c], points[i + c] + D[i + c], 1e-13);
      }
    }
  }
}

TEST(RigidMotionFit, DegenerateSets)
{
  // No point: the identity.
  const dgmf::FittedMotion none = dgmf::FitRigidMotion(3, nullptr, nullptr, nullptr, 0);
  EXPECT_EQ(none.Status, dgmf::RotationFit::Undetermined);
  EXPECT_EQ(none.AngleDegrees, 0.0);
  EXPECT_EQ(none.ResidualRMS, 0.0);
  EXPECT_FALSE(none.ToRigidMotion().HasRotation());

  // One point, 2D and 3D: the rotation is not determined; the motion is its displacement.
  const double one[3] = { 1.0, 2.0, 3.0 };
  const double moveOne[3] = { 0.5, -0.25, 0.0 };
  for (const int dimension : { 2, 3 })
  {
    const dgmf::FittedMotion fit = dgmf::FitRigidMotion(dimension, one, moveOne, nullptr, 1);
    EXPECT_EQ(fit.Status, dgmf::RotationFit::Undetermined);
    EXPECT_EQ(fit.AngleDegrees, 0.0);
    EXPECT_EQ(fit.Translation[0], 0.5);
    EXPECT_EQ(fit.Translation[1], -0.25);
    EXPECT_EQ(fit.MaximumResidual, 0.0);
  }

  // Coincident points (3D), and points that collapse onto one point: undetermined.
  const std::vector<double> same = { 1, 1, 1, 1, 1, 1, 1, 1, 1 };
  const std::vector<double> moveSame = { 0.1, 0, 0, 0.1, 0, 0, 0.1, 0, 0 };
  EXPECT_EQ(dgmf::FitRigidMotion(3, same.data(), moveSame.data(), nullptr, 3).Status,
    dgmf::RotationFit::Undetermined);
  // ... also when their centroid is not exact (0.1 + 0.1 + 0.1 != 0.3): p is round-off only.
  const std::vector<double> tenths = { 0.1, 0.7, 1e3, 0.1, 0.7, 1e3, 0.1, 0.7, 1e3 };
  const std::vector<double> turnTenths = { 0.1, 0.2, 0.3, 0.1, 0.2, 0.3, 0.1, 0.2, 0.3 };
  const dgmf::FittedMotion coincident =
    dgmf::FitRigidMotion(3, tenths.data(), turnTenths.data(), nullptr, 3);
  EXPECT_EQ(coincident.Status, dgmf::RotationFit::Undetermined);
  EXPECT_EQ(coincident.AngleDegrees, 0.0);
  EXPECT_EQ(dgmf::FitRigidMotion(2, tenths.data(), turnTenths.data(), nullptr, 3).Status,
    dgmf::RotationFit::Undetermined);
  std::mt19937 random(16);
  const std::vector<double> cloud = RandomPoints(random, 10, false);
  std::vector<double> collapse(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
  {
    collapse[i] = 4.0 - cloud[i]; // every point to (4, 4, 4)
  }
  const dgmf::FittedMotion collapsed =
    dgmf::FitRigidMotion(3, cloud.data(), collapse.data(), nullptr, 10);
  EXPECT_EQ(collapsed.Status, dgmf::RotationFit::Undetermined);
  EXPECT_EQ(collapsed.AngleDegrees, 0.0);

  // 2D: two distinct points determine the rotation.
  const std::vector<double> pair2 = { 0, 0, 0, 2, 0, 0 };
  const Mat R30 = Rodrigues({ 0, 0, 1 }, Pi / 6);
  const std::vector<double> movePair2 = RigidDisplacements(pair2, R30, { 0, 0, 0 }, { 1, 1, 0 });
  const dgmf::FittedMotion fit2 =
    dgmf::FitRigidMotion(2, pair2.data(), movePair2.data(), nullptr, 2);
  EXPECT_EQ(fit2.Status, dgmf::RotationFit::Determined);
  EXPECT_NEAR(fit2.AngleDegrees, 30.0, 1e-12);
  EXPECT_EQ(fit2.Axis[2], 1.0);

  // 3D, collinear points turned about an axis perpendicular to their line: Collinear, and the
  // smallest rotation is the true one.
  const std::vector<double> line = { 0, 0, 0, 1, 1, 0, 2, 2, 0, 3.5, 3.5, 0 };
  const Vec perpendicular = Unit({ 1, -1, 2 });
  const Mat R40 = Rodrigues(perpendicular, 40.0 * Pi / 180);
  const std::vector<double> moveLine = RigidDisplacements(line, R40, { 1, 0, 0 }, { 0, 0, 1 });
  const dgmf::FittedMotion fitLine =
    dgmf::FitRigidMotion(3, line.data(), moveLine.data(), nullptr, 4);
  EXPECT_EQ(fitLine.Status, dgmf::RotationFit::Collinear);
  EXPECT_NEAR(fitLine.AngleDegrees, 40.0, 1e-10);
  EXPECT_NEAR(
    Dot({ fitLine.Axis[0], fitLine.Axis[1], fitLine.Axis[2] }, perpendicular), 1.0, 1e-10);
  EXPECT_LT(fitLine.MaximumResidual, 1e-12);
  // Two points in 3D are collinear too.
  EXPECT_EQ(dgmf::FitRigidMotion(3, line.data(), moveLine.data(), nullptr, 2).Status,
    dgmf::RotationFit::Collinear);

  // ... turned about a general axis: the fit is the smallest rotation taking the line to its new
  // direction; the points still land exactly (a line maps onto a line), the angle is smaller.
  const Mat R70 = Rodrigues(Unit({ 1, 2, 3 }), 70.0 * Pi / 180);
  const std::vector<double> moveGeneral = RigidDisplacements(line, R70, { 0, 0, 0 }, { 0, 0, 0 });
  const dgmf::FittedMotion general =
    dgmf::FitRigidMotion(3, line.data(), moveGeneral.data(), nullptr, 4);
  EXPECT_EQ(general.Status, dgmf::RotationFit::Collinear);
  EXPECT_LT(general.AngleDegrees, 70.0);
  EXPECT_LT(general.MaximumResidual, 1e-12);
  const Vec direction = Unit({ 1, 1, 0 });
  EXPECT_NEAR(Dot({ general.Axis[0], general.Axis[1], general.Axis[2] }, direction), 0.0, 1e-12);

  // ... turned about the line itself: nothing moves, nothing is fitted.
  const Mat about = Rodrigues(direction, 1.0);
  const std::vector<double> moveAbout = RigidDisplacements(line, about, { 0, 0, 0 }, { 0, 0, 0 });
  const dgmf::FittedMotion twist =
    dgmf::FitRigidMotion(3, line.data(), moveAbout.data(), nullptr, 4);
  EXPECT_LT(twist.AngleDegrees, 1e-10);
  EXPECT_LT(twist.MaximumResidual, 1e-12);

  // ... reversed (180 degrees): the axis is perpendicular to the line.
  const Mat flip = Rodrigues(Unit({ 0, 0, 1 }), Pi);
  const std::vector<double> moveFlip = RigidDisplacements(line, flip, { 0, 0, 0 }, { 0, 0, 0 });
  const dgmf::FittedMotion flipped =
    dgmf::FitRigidMotion(3, line.data(), moveFlip.data(), nullptr, 4);
  EXPECT_EQ(flipped.Status, dgmf::RotationFit::Collinear);
  EXPECT_NEAR(flipped.AngleDegrees, 180.0, 1e-10);
  EXPECT_NEAR(Dot({ flipped.Axis[0], flipped.Axis[1], flipped.Axis[2] }, direction), 0.0, 1e-12);
  EXPECT_LT(flipped.MaximumResidual, 1e-12);

  // 3D, three non-collinear points: determined.
  const std::vector<double> triangle = { 0, 0, 0, 1, 0, 0, 0, 2, 0 };
  const Vec axis = Unit({ -1, 3, 1 });
  const Mat R120 = Rodrigues(axis, 120.0 * Pi / 180);
  const std::vector<double> moveTriangle =
    RigidDisplacements(triangle, R120, { 0, 0, 0 }, { 1, 0, 0 });
  const dgmf::FittedMotion fit3 =
    dgmf::FitRigidMotion(3, triangle.data(), moveTriangle.data(), nullptr, 3);
  EXPECT_EQ(fit3.Status, dgmf::RotationFit::Determined);
  EXPECT_NEAR(fit3.AngleDegrees, 120.0, 1e-10);
  EXPECT_NEAR(Dot({ fit3.Axis[0], fit3.Axis[1], fit3.Axis[2] }, axis), 1.0, 1e-10);

  // A mirror image is not a rotation: the fit stays a proper rotation (det R = +1).
  std::vector<double> mirror(cloud.size());
  double meanZ = 0.0;
  for (std::size_t i = 2; i < cloud.size(); i += 3)
  {
    meanZ += cloud[i] / 10.0;
  }
  for (std::size_t i = 0; i < cloud.size(); ++i)
  {
    mirror[i] = i % 3 == 2 ? 2.0 * (meanZ - cloud[i]) : 0.0; // z -> 2 meanZ - z
  }
  const dgmf::FittedMotion mirrored =
    dgmf::FitRigidMotion(3, cloud.data(), mirror.data(), nullptr, 10);
  EXPECT_NEAR(Determinant(ToMat(mirrored.Rotation)), 1.0, 1e-14);
}

TEST(RigidMotionFit, NodeSubsetsAndResidualPlacement)
{
  std::mt19937 random(17);
  const std::vector<double> points = RandomPoints(random, 30, false);
  const Mat R = Rodrigues(RandomUnit(random), 1.0);
  std::vector<double> D = RigidDisplacements(points, R, { 0, 0, 0 }, { 1, 0, 0 });
  // Nodes 5..19 of the set form the body; the others carry garbage that must not be read.
  std::vector<std::int32_t> nodes;
  for (std::int32_t i = 5; i < 20; ++i)
  {
    nodes.push_back(i);
  }
  for (std::size_t i = 0; i < 15; ++i)
  {
    D[i] = std::numeric_limits<double>::quiet_NaN();
  }
  const dgmf::FittedMotion fit = dgmf::FitRigidMotion(3, points.data(), D.data(), nodes.data(), 15);
  EXPECT_NEAR(fit.AngleDegrees, 180.0 / Pi, 1e-10);
  std::vector<double> residual(points.size(), 7.0);
  const double rms =
    dgmf::ComputeFitResidual(fit, points.data(), D.data(), nodes.data(), 15, residual.data());
  EXPECT_EQ(rms, fit.ResidualRMS);
  for (std::size_t i = 0; i < 30; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (i >= 5 && i < 20)
      {
        EXPECT_NEAR(residual[3 * i + c], 0.0, 1e-13);
      }
      else
      {
        EXPECT_EQ(residual[3 * i + c], 7.0) << "a node outside the body was written";
      }
    }
  }
  // In place: the displacement array becomes the residual.
  dgmf::ComputeFitResidual(fit, points.data(), D.data(), nodes.data(), 15, D.data());
  for (std::size_t i = 15; i < 60; ++i)
  {
    EXPECT_NEAR(D[i], 0.0, 1e-13);
  }
}

TEST(RigidMotionFit, RejectsBadInput)
{
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  std::vector<double> D(9, 0.0);
  EXPECT_THROW(dgmf::FitRigidMotion(1, points.data(), D.data(), nullptr, 3), std::invalid_argument);
  EXPECT_THROW(dgmf::FitRigidMotion(4, points.data(), D.data(), nullptr, 3), std::invalid_argument);
  const std::int32_t negative[2] = { 0, -1 };
  EXPECT_THROW(
    dgmf::FitRigidMotion(3, points.data(), D.data(), negative, 2), std::invalid_argument);
  D[4] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(dgmf::FitRigidMotion(3, points.data(), D.data(), nullptr, 3), std::invalid_argument);
}

TEST(RigidMotionFit, CentreOnTheRotationAxisRecoversTheRotationCentre)
{
  // 2D: a rotation of 30 degrees about (1, 2), given as displacements of points around (0, 0).
  std::vector<double> points, displacements;
  const double a = 30.0 * 3.14159265358979323846 / 180.0;
  for (int k = 0; k < 12; ++k)
  {
    const double x = std::cos(0.5 * k) * (1.0 + 0.1 * k), y = std::sin(0.5 * k);
    points.insert(points.end(), { x, y, 0.0 });
    const double dx = x - 1.0, dy = y - 2.0;
    displacements.insert(displacements.end(),
      { 1.0 + std::cos(a) * dx - std::sin(a) * dy - x,
        2.0 + std::sin(a) * dx + std::cos(a) * dy - y, 0.0 });
  }
  dgmf::FittedMotion fit =
    dgmf::FitRigidMotion(2, points.data(), displacements.data(), nullptr, 12);
  ASSERT_TRUE(dgmf::CentreOnRotationAxis(fit, 100.0));
  EXPECT_NEAR(fit.Center[0], 1.0, 1e-12);
  EXPECT_NEAR(fit.Center[1], 2.0, 1e-12);
  EXPECT_NEAR(fit.Translation[0], 0.0, 1e-12);
  EXPECT_NEAR(fit.Translation[1], 0.0, 1e-12);
  EXPECT_NEAR(fit.AngleDegrees, 30.0, 1e-10);

  // 3D: a screw motion, 70 degrees about the axis (0, 1, 1)/sqrt(2) through p = (2, -1, 0.5),
  // and 0.3 along the axis.
  const double s = 1.0 / std::sqrt(2.0);
  const double axis[3] = { 0.0, s, s }, p[3] = { 2.0, -1.0, 0.5 };
  dgmf::RigidMotion screw;
  for (int c = 0; c < 3; ++c)
  {
    screw.Axis[c] = axis[c];
    screw.Center[c] = p[c];
    screw.Translation[c] = 0.3 * axis[c];
  }
  screw.AxisAngleDegrees = 70.0;
  std::vector<double> cloud, moved;
  for (int k = 0; k < 20; ++k)
  {
    const double x[3] = { std::cos(k * 1.3), std::sin(k * 0.7), 0.1 * k };
    double y[3];
    screw.Apply(1.0, x, nullptr, y);
    cloud.insert(cloud.end(), x, x + 3);
    moved.insert(moved.end(), { y[0] - x[0], y[1] - x[1], y[2] - x[2] });
  }
  dgmf::FittedMotion fit3 = dgmf::FitRigidMotion(3, cloud.data(), moved.data(), nullptr, 20);
  ASSERT_TRUE(dgmf::CentreOnRotationAxis(fit3, 100.0));
  // The centre is on the axis line through p, and the translation is along the axis.
  const double r[3] = { fit3.Center[0] - p[0], fit3.Center[1] - p[1], fit3.Center[2] - p[2] };
  const double along = r[0] * axis[0] + r[1] * axis[1] + r[2] * axis[2];
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(r[c] - along * axis[c], 0.0, 1e-10);
    EXPECT_NEAR(fit3.Translation[c], 0.3 * axis[c], 1e-10);
  }
  // A near translation keeps the centroid.
  dgmf::FittedMotion tiny = fit3;
  tiny.AngleDegrees = 1e-9;
  const double before[3] = { tiny.Center[0], tiny.Center[1], tiny.Center[2] };
  tiny.Translation[0] += 1.0;
  EXPECT_FALSE(dgmf::CentreOnRotationAxis(tiny, 100.0));
  EXPECT_EQ(tiny.Center[0], before[0]);
}
