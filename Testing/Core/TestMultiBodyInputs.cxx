// The multi-body core's checks of its inputs: body ids against the node kinds and the motions,
// and the motions' own values (split from TestMultiBodyDeformation.cxx).
#include "TwoBodyNodes.h"

#include "dgmf/MultiBodyDeformation.h"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

using dgmf_test::Map;

TEST(MultiBodyDeformation, RejectsInconsistentBodyIds)
{
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare(32, 10, 300);
  const dgmf::DelaunayMapping mapping = Map(set);
  const std::vector<dgmf::BodyMotion> bodies(2);
  std::vector<double> out(3 * set.Size()), f(set.Size());
  const auto deform = [&](const std::vector<std::int32_t>& ids,
                        const std::vector<dgmf::BodyMotion>& motions, double r0s = 1.0)
  {
    dgmf::DeformMultiBody(mapping, ids.data(), motions, r0s, dgmf::DampingFunction::U1,
      dgmf::DeformationMode::DGMF2, set.Points.data(), out.data(), f.data(), dgmf::SerialFor);
  };
  EXPECT_NO_THROW(deform(set.BodyIds, bodies));
  EXPECT_EQ(dgmf::CheckBodyIds(mapping, set.BodyIds.data()), 2);
  std::size_t staticNode = 0, interiorNode = 0;
  while (set.Kinds[staticNode] != dgmf::NodeKind::StaticBoundary)
    ++staticNode;
  while (set.Kinds[interiorNode] != dgmf::NodeKind::Interior)
    ++interiorNode;
  std::vector<std::int32_t> ids = set.BodyIds;
  ids[0] = -1;
  EXPECT_THROW(deform(ids, bodies), std::invalid_argument) << "negative id";
  ids = set.BodyIds;
  ids[staticNode] = 1;
  EXPECT_THROW(deform(ids, bodies), std::invalid_argument) << "body id on a static node";
  ids = set.BodyIds;
  ids[interiorNode] = 2;
  EXPECT_THROW(deform(ids, bodies), std::invalid_argument) << "body id on an interior node";
  ids = set.BodyIds;
  ids[0] = 0;
  EXPECT_THROW(deform(ids, bodies), std::invalid_argument) << "moving node without a body";
  EXPECT_THROW(deform(set.BodyIds, std::vector<dgmf::BodyMotion>(1)), std::invalid_argument)
    << "fewer motions than bodies";
  EXPECT_THROW(deform(set.BodyIds, bodies, 0.5), std::invalid_argument) << "r0s < 1";
  std::vector<dgmf::BodyMotion> bad(2);
  bad[1].Motion.AnglesDegrees[2] = 10.0;
  bad[1].Motion.AxisAngleDegrees = 10.0;
  EXPECT_THROW(deform(set.BodyIds, bad), std::invalid_argument) << "Euler and axis angles";
  EXPECT_THROW(dgmf::ComputeBodyDampingFactor(mapping, set.BodyIds.data(), 0, 1.0,
                 dgmf::DampingFunction::U1, f.data(), dgmf::SerialFor),
    std::invalid_argument);
  EXPECT_THROW(dgmf::CheckBodyIds(mapping, nullptr), std::invalid_argument);
  // More motions than bodies: the extra ones do nothing.
  EXPECT_NO_THROW(deform(set.BodyIds, std::vector<dgmf::BodyMotion>(5)));
}

TEST(MultiBodyDeformation, DistinctPositionsFitTheSameBitsInAnyOrderAndWithCopies)
{
  // A distributed run's nodes: each process holds its piece's nodes first, the others' copies
  // after them, some positions twice. With distinctPositions the fit is the one of the distinct
  // positions in increasing order, bit for bit, whatever the order and the copies; without it,
  // copies weigh twice and the fit moves (the displacement has a shape part).
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare();
  std::vector<double> D(3 * set.Size(), 0.0);
  std::vector<std::int32_t> moving;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.BodyIds[i] == 1)
    {
      const double* x = set.Points.data() + 3 * i;
      D[3 * i] = -0.2 * x[1] + 0.05 * x[0] * x[0];
      D[3 * i + 1] = 0.2 * x[0];
      moving.push_back(static_cast<std::int32_t>(i));
    }
  }
  ASSERT_GT(moving.size(), 10u);
  // Body 1's nodes reversed, then the first third of them again (an arc of the circle): points,
  // displacements, ids.
  std::vector<std::size_t> order(moving.rbegin(), moving.rend());
  for (std::size_t k = 0; k < moving.size() / 3; ++k)
  {
    order.push_back(static_cast<std::size_t>(moving[k]));
  }
  std::vector<double> points, displacement;
  for (const std::size_t i : order)
  {
    points.insert(points.end(), set.Points.begin() + 3 * i, set.Points.begin() + 3 * i + 3);
    displacement.insert(displacement.end(), D.begin() + 3 * i, D.begin() + 3 * i + 3);
  }
  const std::vector<std::int32_t> ones(order.size(), 1);
  const std::vector<std::int32_t> body(set.BodyIds.begin(), set.BodyIds.end());
  std::vector<std::int32_t> onlyBody1(body.size(), 0);
  for (const std::int32_t i : moving)
  {
    onlyBody1[static_cast<std::size_t>(i)] = 1;
  }
  const auto fit = [](const std::vector<double>& p, const std::vector<double>& d,
                     const std::vector<std::int32_t>& ids, bool distinct)
  {
    return dgmf::ExtractBodyMotions(
      2, p.data(), d.data(), ids.size(), ids.data(), 1, nullptr, distinct)[0];
  };
  const dgmf::FittedMotion inOrder = fit(set.Points, D, onlyBody1, true);
  const dgmf::FittedMotion copies = fit(points, displacement, ones, true);
  EXPECT_EQ(copies.NumberOfPoints, moving.size());
  EXPECT_EQ(std::memcmp(inOrder.Center, copies.Center, sizeof copies.Center), 0);
  EXPECT_EQ(std::memcmp(inOrder.Translation, copies.Translation, sizeof copies.Translation), 0);
  EXPECT_EQ(inOrder.AngleDegrees, copies.AngleDegrees);
  // The same nodes in their order, without distinctPositions: the same fit up to rounding.
  const dgmf::FittedMotion plain = fit(set.Points, D, onlyBody1, false);
  EXPECT_NEAR(plain.AngleDegrees, inOrder.AngleDegrees, 1e-12);
  // The copies weighed twice: another fit.
  const dgmf::FittedMotion weighted = fit(points, displacement, ones, false);
  EXPECT_GT(std::abs(weighted.Center[0] - inOrder.Center[0]) +
      std::abs(weighted.Center[1] - inOrder.Center[1]),
    1e-6);
}
