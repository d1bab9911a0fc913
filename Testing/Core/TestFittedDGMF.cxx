// DGMF with a motion fitted to the moving boundary's displacements.
#include "SyntheticNodes.h"

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/RigidMotionFit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace
{
std::vector<double> DeformWith(
  const dgmf_test::NodeSet& set, const dgmf::RigidMotion& motion, const double* displacement)
{
  dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  std::vector<double> r(set.Size()), f(set.Size()), out(3 * set.Size());
  dgmf::ComputeBoundaryDistanceField(mapping, 1.0, r.data(), dgmf::SerialFor);
  dgmf::ComputeDampingFactor(
    mapping, dgmf::DampingFunction::U1, r.data(), f.data(), dgmf::SerialFor);
  dgmf::DeformDGMF(mapping, f.data(), motion, displacement, dgmf::DeformationMode::DGMF2,
    set.Points.data(), out.data(), dgmf::SerialFor);
  return out;
}

/// The moving nodes of a set, and their displacements under `motion` (0 elsewhere).
std::vector<double> MovingDisplacements(
  const dgmf_test::NodeSet& set, const dgmf::RigidMotion& motion, std::vector<std::int32_t>& moving)
{
  std::vector<double> D(3 * set.Size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.Kinds[i] == dgmf::NodeKind::MovingBoundary)
    {
      moving.push_back(static_cast<std::int32_t>(i));
      double out[3];
      motion.Apply(1.0, set.Points.data() + 3 * i, nullptr, out);
      for (int c = 0; c < 3; ++c)
      {
        D[3 * i + c] = out[c] - set.Points[3 * i + c];
      }
    }
  }
  return D;
}
} // namespace

TEST(FittedDGMF, RotatingCircleFromDisplacementsMatchesExplicitRotation)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  for (const double tx : { 0.0, 0.3 })
  {
    // The circle turned by exactly 90 degrees about its centre: (x, y) -> (-y, x), plus (tx,
    // -tx/2).
    std::vector<double> D(3 * set.Size(), 0.0);
    std::vector<std::int32_t> moving;
    for (std::size_t i = 0; i < set.Size(); ++i)
    {
      if (set.Kinds[i] == dgmf::NodeKind::MovingBoundary)
      {
        moving.push_back(static_cast<std::int32_t>(i));
        const double x = set.Points[3 * i], y = set.Points[3 * i + 1];
        D[3 * i] = -y - x + tx;
        D[3 * i + 1] = x - y - 0.5 * tx;
      }
    }
    const dgmf::FittedMotion fit =
      dgmf::FitRigidMotion(2, set.Points.data(), D.data(), moving.data(), moving.size());
    EXPECT_NEAR(fit.AngleDegrees, 90.0, 1e-12);
    EXPECT_EQ(fit.Axis[2], 1.0);
    EXPECT_LT(fit.ResidualRMS, 1e-14);
    std::vector<double> residual(3 * set.Size(), 0.0);
    dgmf::ComputeFitResidual(
      fit, set.Points.data(), D.data(), moving.data(), moving.size(), residual.data());

    dgmf::RigidMotion explicitMotion;
    explicitMotion.AnglesDegrees[2] = 90.0;
    explicitMotion.Translation[0] = tx;
    explicitMotion.Translation[1] = -0.5 * tx;
    const std::vector<double> expected = DeformWith(set, explicitMotion, nullptr);
    const std::vector<double> fitted = DeformWith(set, fit.ToRigidMotion(), residual.data());
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
      EXPECT_NEAR(fitted[i], expected[i], 1e-9 * std::max(1.0, std::abs(expected[i])))
        << "node " << i / 3;
    }
  }
}

TEST(FittedDGMF, RotatingSphereFromDisplacementsMatchesExplicitRotation)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox();
  dgmf::RigidMotion explicitMotion;
  explicitMotion.Axis[0] = 1.0;
  explicitMotion.Axis[1] = 2.0;
  explicitMotion.Axis[2] = -0.5;
  explicitMotion.AxisAngleDegrees = 120.0;
  explicitMotion.Translation[1] = 0.2;
  std::vector<std::int32_t> moving;
  const std::vector<double> D = MovingDisplacements(set, explicitMotion, moving);
  const dgmf::FittedMotion fit =
    dgmf::FitRigidMotion(3, set.Points.data(), D.data(), moving.data(), moving.size());
  EXPECT_NEAR(fit.AngleDegrees, 120.0, 1e-10);
  std::vector<double> residual(3 * set.Size(), 0.0);
  dgmf::ComputeFitResidual(
    fit, set.Points.data(), D.data(), moving.data(), moving.size(), residual.data());
  const std::vector<double> expected = DeformWith(set, explicitMotion, nullptr);
  const std::vector<double> fitted = DeformWith(set, fit.ToRigidMotion(), residual.data());
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    EXPECT_NEAR(fitted[i], expected[i], 1e-9 * std::max(1.0, std::abs(expected[i])));
  }
}
