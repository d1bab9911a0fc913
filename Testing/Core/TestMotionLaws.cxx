// Motion in time: harmonic and ramp laws, and trajectories from a table (issue 19).
#include "dgmf/MotionLaw.h"
#include "dgmf/RigidMotion.h"
#include "dgmf/Trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
std::string MessageOf(const std::vector<dgmf::TrajectoryRow>& rows)
{
  try
  {
    dgmf::Trajectory trajectory(rows);
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "";
}

dgmf::TrajectoryRow Row(double t, int body, double tx, double angleZ, std::size_t row)
{
  dgmf::TrajectoryRow r;
  r.Time = t;
  r.Body = body;
  r.Translation[0] = tx;
  const double angles[3] = { 0.0, 0.0, angleZ };
  dgmf::EulerAnglesToQuaternion(angles, r.Quaternion);
  r.Row = row;
  return r;
}
} // namespace

TEST(MotionLaw, HarmonicIsPeriodicBitForBitAndRampIsLinear)
{
  dgmf::MotionLaw pitch;
  pitch.Kind = dgmf::MotionLawKind::Harmonic;
  const double parameters[4] = { 2.0, 20.0, 1.5, 30.0 }; // mean, amplitude, frequency, phase
  std::memcpy(pitch.Parameters, parameters, sizeof parameters);
  // The phase is rounded to 2^-40 of a period: within 3e-12 times the amplitude.
  EXPECT_NEAR(pitch.Evaluate(0.0), 2.0 + 20.0 * 0.5, 20.0 * 3e-12); // sin(30 degrees)
  EXPECT_NEAR(pitch.Evaluate(1.0 / 9.0), 2.0 + 20.0, 20.0 * 3e-12); // 1.5 t + 1/12 = 1/4: the top
  // Times one period (2/3) apart, as a frame loop computes them (k dt), give the same bits.
  const double period = 1.0 / 1.5;
  for (int k = 0; k < 50; ++k)
  {
    const double t = k * (period / 50.0);
    const double later = (k + 50) * (period / 50.0);
    const double twoLater = (k + 100) * (period / 50.0);
    ASSERT_EQ(pitch.Evaluate(t), pitch.Evaluate(later)) << "frame " << k;
    ASSERT_EQ(pitch.Evaluate(t), pitch.Evaluate(twoLater)) << "frame " << k;
    ASSERT_NEAR(
      pitch.Evaluate(t), 2.0 + 20.0 * std::sin(2 * M_PI * (1.5 * t + 30.0 / 360.0)), 20.0 * 3e-12);
  }

  dgmf::MotionLaw ramp;
  ramp.Kind = dgmf::MotionLawKind::Ramp;
  const double rampParameters[4] = { 0.0, 40.0, 0.5, 1.5 }; // 0 to 40 between t = 0.5 and 1.5
  std::memcpy(ramp.Parameters, rampParameters, sizeof rampParameters);
  EXPECT_EQ(ramp.Evaluate(0.0), 0.0);
  EXPECT_EQ(ramp.Evaluate(1.0), 20.0);
  EXPECT_EQ(ramp.Evaluate(9.0), 40.0);

  ramp.Parameters[3] = 0.5; // ends when it starts
  EXPECT_THROW(ramp.Evaluate(1.0), std::invalid_argument);
  // The harmonic law's defaults (0 10 1 0) taken as a ramp, as the GUI gives them when Ramp is
  // chosen: the message says what the four parameters are (until 2026-11-30 only "the ramp's
  // end time (0.000000) must be after its start time (1.000000)").
  dgmf::MotionLaw defaults{ dgmf::MotionLawKind::Ramp, { 0.0, 10.0, 1.0, 0.0 } };
  try
  {
    defaults.Check("the rotation law");
    ADD_FAILURE() << "a ramp ending before it starts was taken";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_EQ(std::string(e.what()),
      "the rotation law: a ramp's four parameters are its start value, end value, start time and "
      "end time, and its end time (0) must be after its start time (1)");
  }
  pitch.Parameters[2] = -1.0;
  EXPECT_THROW(pitch.Check("the rotation law"), std::invalid_argument);
  // The largest |v| over all times, for refusing a rotation beyond two turns up front.
  dgmf::MotionLaw swing{ dgmf::MotionLawKind::Harmonic, { -300.0, -500.0, 1.0, 0.0 } };
  EXPECT_EQ(swing.LargestMagnitude(), 800.0);
  dgmf::MotionLaw farRamp{ dgmf::MotionLawKind::Ramp, { 100.0, -730.0, 0.0, 1.0 } };
  EXPECT_EQ(farRamp.LargestMagnitude(), 730.0);
  EXPECT_EQ(dgmf::MotionLaw().LargestMagnitude(), 0.0);
  // A frequency of 0 holds one value: mean + amplitude sin(phase), 800 sin(30 degrees) here.
  dgmf::MotionLaw still{ dgmf::MotionLawKind::Harmonic, { 0.0, 800.0, 0.0, 30.0 } };
  EXPECT_NEAR(still.LargestMagnitude(), 400.0, 800.0 * 3e-12); // (the phase's rounding)
  pitch.Parameters[2] = NAN;
  EXPECT_THROW(pitch.Check(), std::invalid_argument);
}

TEST(Trajectory, InterpolatesTranslationLinearlyAndRotationAlongTheShortestArc)
{
  // Body 1 turns from 0 to 90 degrees about z and moves 2 along x between t = 0 and 1; body 2 is
  // given at other times.
  const dgmf::Trajectory trajectory({ Row(0.0, 1, 0.0, 0.0, 1), Row(1.0, 1, 2.0, 90.0, 2),
    Row(0.5, 2, 1.0, -30.0, 3), Row(2.0, 2, 1.0, -30.0, 4) });
  EXPECT_EQ(trajectory.GetTimes(), (std::vector<double>{ 0.0, 0.5, 1.0, 2.0 }));
  EXPECT_EQ(trajectory.GetLargestBody(), 2);
  const double center[3] = { 1.0, 0.0, 0.0 };
  const dgmf::RigidMotion half = trajectory.At(1, 0.5, center);
  EXPECT_NEAR(half.Translation[0], 1.0, 1e-15);
  EXPECT_NEAR(half.AxisAngleDegrees, 45.0, 1e-12);
  EXPECT_NEAR(half.Axis[2], 1.0, 1e-15);
  EXPECT_EQ(half.Center[0], 1.0);
  // The point (2, 0, 0) turns by 45 degrees about (1, 0, 0), then moves by 1 along x.
  double moved[3];
  const double p[3] = { 2.0, 0.0, 0.0 };
  half.Apply(1.0, p, nullptr, moved);
  EXPECT_NEAR(moved[0], 2.0 + std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(moved[1], std::sqrt(0.5), 1e-12);
  // Before the first and after the last row: held.
  EXPECT_EQ(trajectory.At(1, -1.0, center).AxisAngleDegrees, 0.0);
  EXPECT_NEAR(trajectory.At(1, 5.0, center).AxisAngleDegrees, 90.0, 1e-12);
  EXPECT_NEAR(trajectory.At(2, 0.0, center).AxisAngleDegrees, 30.0, 1e-12);
  EXPECT_NEAR(trajectory.At(2, 0.0, center).Axis[2], -1.0, 1e-15);

  // From 170 to -170 degrees: the short way (through 180), not back through 0.
  const dgmf::Trajectory across({ Row(0.0, 1, 0.0, 170.0, 1), Row(1.0, 1, 0.0, -170.0, 2) });
  EXPECT_NEAR(std::abs(across.At(1, 0.5, center).AxisAngleDegrees), 180.0, 1e-9);
  EXPECT_THROW(across.At(3, 0.5, center), std::invalid_argument);
}

TEST(Trajectory, AnAngleAboutOneAxisGoesOnPast180Degrees)
{
  // A body turning about z by 90 degrees per unit of time, to 450 degrees: DGMF damps the angle,
  // so it must not wrap from 180 to -180 (the mesh jumped by 6 in a domain of 10 between two
  // frames 0.02 apart, until 2026-11-30). As quaternions: the steps' angles add up.
  std::vector<dgmf::TrajectoryRow> quaternions, angles;
  for (int k = 0; k <= 5; ++k)
  {
    quaternions.push_back(Row(k, 1, 0.0, 90.0 * k, static_cast<std::size_t>(k + 1)));
    dgmf::TrajectoryRow row = quaternions.back();
    row.AngleAxis = k == 0 ? dgmf::TrajectoryRow::NoAxis : 2; // RZ alone, as given
    row.AngleDegrees = 90.0 * k;
    angles.push_back(row);
  }
  const double center[3] = { 0.0, 0.0, 0.0 };
  for (const auto* rows : { &quaternions, &angles })
  {
    const dgmf::Trajectory trajectory(*rows);
    double previous = 0.0;
    for (double t = 0.0; t <= 5.0; t += 0.01)
    {
      const dgmf::RigidMotion motion = trajectory.At(1, t, center);
      const double degrees = motion.AxisAngleDegrees * (motion.Axis[2] < 0.0 ? -1.0 : 1.0);
      EXPECT_NEAR(degrees, 90.0 * t, 1e-9) << "t = " << t;
      EXPECT_LT(std::abs(degrees - previous), 1.0) << "t = " << t; // no jump
      previous = degrees;
    }
  }
  // A spin about an oblique axis in 1-degree rows written with 7 digits (as solvers write
  // tables): the steps' axes differ by rounding, the angle still goes on past 180 degrees, and
  // the body is where each row puts it.
  const double spin[3] = { 0.6, 0.0, 0.8 };
  std::vector<dgmf::TrajectoryRow> rounded;
  for (int k = 0; k <= 400; ++k)
  {
    dgmf::TrajectoryRow row = Row(0.01 * k, 1, 0.0, 0.0, static_cast<std::size_t>(k + 1));
    const double half = 0.5 * k * 3.14159265358979323846 / 180.0;
    const double q[4] = { std::cos(half), std::sin(half) * spin[0], 0.0, std::sin(half) * spin[2] };
    for (int c = 0; c < 4; ++c)
    {
      row.Quaternion[c] = std::round(q[c] * 1e7) / 1e7;
    }
    rounded.push_back(row);
  }
  const dgmf::Trajectory spinning(rounded);
  double before = 0.0;
  for (int k = 0; k <= 400; ++k)
  {
    const dgmf::RigidMotion motion = spinning.At(1, 0.01 * k, center);
    const double turned = motion.AxisAngleDegrees *
      (motion.Axis[0] * spin[0] + motion.Axis[2] * spin[2] < 0.0 ? -1.0 : 1.0);
    EXPECT_NEAR(turned, k, 1e-3) << "row " << k;
    EXPECT_LT(std::abs(turned - before), 1.5) << "row " << k;
    before = turned;
    // The point (1, 1, 0) where the row's own quaternion puts it.
    const double p[3] = { 1.0, 1.0, 0.0 };
    double moved[3];
    motion.Apply(1.0, p, nullptr, moved);
    const double* q = rounded[static_cast<std::size_t>(k)].Quaternion;
    const double u[3] = { q[1], q[2], q[3] };
    const double uxp[3] = { u[1] * p[2] - u[2] * p[1], u[2] * p[0] - u[0] * p[2],
      u[0] * p[1] - u[1] * p[0] };
    const double uxuxp[3] = { u[1] * uxp[2] - u[2] * uxp[1], u[2] * uxp[0] - u[0] * uxp[2],
      u[0] * uxp[1] - u[1] * uxp[0] };
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(moved[c], p[c] + 2.0 * q[0] * uxp[c] + 2.0 * uxuxp[c], 1e-6) << "row " << k;
    }
  }

  // One row of RZ = 270: 270 degrees as given (as --angle 270), not -90.
  dgmf::TrajectoryRow once = angles[3];
  const dgmf::Trajectory single({ once });
  EXPECT_EQ(single.At(1, 0.0, center).AxisAngleDegrees, 270.0);
  EXPECT_EQ(single.At(1, 0.0, center).Axis[2], 1.0);
  // Steps about different axes: the orientation's own angle, at most 180 degrees.
  dgmf::TrajectoryRow tilted = Row(1.0, 1, 0.0, 0.0, 2);
  const double half = 0.5 * 100.0 * 3.14159265358979323846 / 180.0;
  tilted.Quaternion[0] = std::cos(half);
  tilted.Quaternion[1] = std::sin(half);
  tilted.Quaternion[3] = 0.0;
  const dgmf::Trajectory bent({ Row(0.0, 1, 0.0, 120.0, 1), tilted });
  EXPECT_LE(std::abs(bent.At(1, 0.5, center).AxisAngleDegrees), 180.0);
  EXPECT_NEAR(bent.At(1, 1.0, center).AxisAngleDegrees, 100.0, 1e-9);
}

TEST(Trajectory, BadRowsAreNamed)
{
  EXPECT_NE(MessageOf({ Row(0.0, 1, 0, 0, 1), Row(1.0, 1, 0, 0, 2), Row(0.5, 1, 0, 0, 3) })
              .find("trajectory row 3"),
    std::string::npos);
  // Equal times of different bodies are fine; of the same body, not.
  EXPECT_EQ(MessageOf({ Row(0.0, 1, 0, 0, 1), Row(0.0, 2, 0, 0, 2) }), "");
  EXPECT_NE(
    MessageOf({ Row(0.0, 1, 0, 0, 1), Row(0.0, 1, 0, 0, 2) }).find("row 2"), std::string::npos);
  dgmf::TrajectoryRow scaled = Row(0.0, 1, 0, 0, 7);
  scaled.Quaternion[0] = 1.01;
  const std::string message = MessageOf({ scaled });
  EXPECT_NE(message.find("row 7"), std::string::npos) << message;
  EXPECT_NE(message.find("length"), std::string::npos) << message;
  dgmf::TrajectoryRow body0 = Row(0.0, 0, 0, 0, 4);
  EXPECT_NE(MessageOf({ body0 }).find("row 4"), std::string::npos);
  dgmf::TrajectoryRow nan = Row(NAN, 1, 0, 0, 5);
  EXPECT_NE(MessageOf({ nan }).find("row 5"), std::string::npos);
  EXPECT_NE(MessageOf({}).find("no rows"), std::string::npos);
}
