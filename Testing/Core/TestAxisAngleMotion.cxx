// Rigid motions given by an axis and an angle (DampedRigidMotion against Rodrigues).
#include "RigidMotionTestHelpers.h"

#include "dgmf/DampedRigidMotion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace rigid_test;

TEST(AxisAngleMotion, DampedMotionMatchesRodrigues)
{
  std::mt19937 random(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (const double angle : { 37.0, 90.0, 180.0, -120.0, 359.0, 720.0, -720.0, 1e-3 })
  {
    for (int trial = 0; trial < 5; ++trial)
    {
      dgmf::RigidMotion motion;
      const Vec direction = RandomUnit(random);
      const double length = 0.1 + 3.0 * unit(random); // the axis need not be unit length
      for (int c = 0; c < 3; ++c)
      {
        motion.Axis[c] = length * direction[c];
        motion.Center[c] = coordinate(random);
        motion.Translation[c] = coordinate(random);
      }
      motion.AxisAngleDegrees = angle;
      const dgmf::DampedRigidMotion damped(motion);
      std::vector<double> fractions = { 0.0, 1.0, 1e-9, 0.5, 1.0 - 1e-12 };
      for (int k = 0; k < 300; ++k)
      {
        fractions.push_back(unit(random));
      }
      for (const double f : fractions)
      {
        const Vec x = { coordinate(random), coordinate(random), coordinate(random) };
        const Vec d = { coordinate(random), coordinate(random), coordinate(random) };
        const Mat R = Rodrigues(direction, f * angle * Pi / 180.0);
        const Vec r = { x[0] - motion.Center[0], x[1] - motion.Center[1], x[2] - motion.Center[2] };
        const Vec y = Times(R, r);
        double out[3], outMatrix[3];
        damped.Apply(f, x.data(), d.data(), out);
        motion.Apply(f, x.data(), d.data(), outMatrix);
        for (int c = 0; c < 3; ++c)
        {
          const double expected = motion.Center[c] + y[c] + f * motion.Translation[c] + f * d[c];
          EXPECT_NEAR(out[c], expected, 1e-14) << "angle " << angle << " f " << f;
          EXPECT_NEAR(outMatrix[c], expected, 1e-14) << "angle " << angle << " f " << f;
        }
      }
    }
  }
}

TEST(AxisAngleMotion, CoordinateAxesMatchEulerAngles)
{
  std::mt19937 random(22);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (int axis = 0; axis < 3; ++axis)
  {
    for (const double angle : { 90.0, -45.0, 180.0, 300.0 })
    {
      for (const double sense : { 1.0, -1.0 })
      {
        dgmf::RigidMotion byAxis, byEuler;
        byAxis.Axis[0] = byAxis.Axis[1] = byAxis.Axis[2] = 0.0;
        byAxis.Axis[axis] = sense;
        byAxis.AxisAngleDegrees = angle;
        byEuler.AnglesDegrees[axis] = sense * angle;
        for (int c = 0; c < 3; ++c)
        {
          byAxis.Center[c] = byEuler.Center[c] = 0.3 * c - 0.2;
          byAxis.Translation[c] = byEuler.Translation[c] = 0.1 * c + 0.05;
        }
        double Ra[3][3], Re[3][3];
        byAxis.GetRotationMatrix(0.7, Ra);
        byEuler.GetRotationMatrix(0.7, Re);
        ExpectMatrixNear(ToMat(Ra), ToMat(Re), 1e-15, "matrix");
        const dgmf::DampedRigidMotion a(byAxis), e(byEuler);
        for (int k = 0; k < 200; ++k)
        {
          const double f = k == 0 ? 1.0 : unit(random);
          const Vec x = { coordinate(random), coordinate(random), coordinate(random) };
          double outA[3], outE[3];
          a.Apply(f, x.data(), nullptr, outA);
          e.Apply(f, x.data(), nullptr, outE);
          for (int c = 0; c < 3; ++c)
          {
            EXPECT_NEAR(outA[c], outE[c], 1e-14) << "axis " << axis << " angle " << angle;
          }
        }
      }
    }
  }
}

TEST(AxisAngleMotion, PredicatesAndMatrix)
{
  dgmf::RigidMotion motion;
  EXPECT_TRUE(motion.IsIdentity());
  EXPECT_FALSE(motion.HasRotation());
  motion.AxisAngleDegrees = 30.0;
  EXPECT_TRUE(motion.HasAxisRotation());
  EXPECT_FALSE(motion.HasEulerAngles());
  EXPECT_TRUE(motion.HasRotation());
  EXPECT_FALSE(motion.IsIdentity());
  motion.Axis[0] = 1.0;
  motion.Axis[1] = -2.0;
  motion.Axis[2] = 0.5;
  double R[3][3];
  motion.GetRotationMatrix(1.0, R);
  const Mat M = ToMat(R);
  Mat MtM{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        MtM[i][j] += M[k][i] * M[k][j];
  ExpectMatrixNear(MtM, Rodrigues({ 1, 0, 0 }, 0.0), 1e-15, "orthogonal");
  EXPECT_NEAR(Determinant(M), 1.0, 1e-15);
  // The axis is fixed by the rotation.
  const Vec k = Unit({ 1.0, -2.0, 0.5 });
  const Vec fixed = Times(M, k);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(fixed[c], k[c], 1e-15);
  }
  // With Euler angles the axis is ignored: the same bits whatever it holds.
  dgmf::RigidMotion euler, eulerWithAxis;
  euler.AnglesDegrees[0] = 20.0;
  euler.AnglesDegrees[2] = -70.0;
  eulerWithAxis = euler;
  eulerWithAxis.Axis[0] = 3.0;
  const dgmf::DampedRigidMotion a(euler), b(eulerWithAxis);
  const double x[3] = { 0.3, -1.2, 2.2 };
  double outA[3], outB[3];
  a.Apply(0.37, x, nullptr, outA);
  b.Apply(0.37, x, nullptr, outB);
  EXPECT_EQ(std::memcmp(outA, outB, sizeof(outA)), 0);
}

TEST(AxisAngleMotion, RejectsIllDefinedRotations)
{
  dgmf::RigidMotion both;
  both.AnglesDegrees[2] = 10.0;
  both.AxisAngleDegrees = 10.0;
  double R[3][3], out[3];
  const double x[3] = { 1, 2, 3 };
  EXPECT_THROW(dgmf::DampedRigidMotion{ both }, std::invalid_argument);
  EXPECT_THROW(both.GetRotationMatrix(1.0, R), std::invalid_argument);
  EXPECT_THROW(both.Apply(1.0, x, nullptr, out), std::invalid_argument);
  dgmf::RigidMotion zeroAxis;
  zeroAxis.Axis[2] = 0.0;
  zeroAxis.AxisAngleDegrees = 10.0;
  EXPECT_THROW(dgmf::DampedRigidMotion{ zeroAxis }, std::invalid_argument);
  dgmf::RigidMotion nanAxis;
  nanAxis.Axis[0] = std::numeric_limits<double>::quiet_NaN();
  nanAxis.AxisAngleDegrees = 10.0;
  EXPECT_THROW(dgmf::DampedRigidMotion{ nanAxis }, std::invalid_argument);
  dgmf::RigidMotion large;
  large.AxisAngleDegrees = 721.0;
  EXPECT_THROW(dgmf::DampedRigidMotion{ large }, std::invalid_argument);
  large.AxisAngleDegrees = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(dgmf::DampedRigidMotion{ large }, std::invalid_argument);
  // A zero axis with no axis angle is fine: the axis is not used.
  dgmf::RigidMotion unused;
  unused.Axis[2] = 0.0;
  unused.AnglesDegrees[1] = 5.0;
  EXPECT_NO_THROW(dgmf::DampedRigidMotion{ unused });
}
