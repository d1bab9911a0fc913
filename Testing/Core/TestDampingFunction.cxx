// Damping functions u1..u7 against hand-computed values (paper Table 1, u3 with the Wendland "+3").
#include "dgmf/DampingFunction.h"

#include <gtest/gtest.h>

using dgmf::DampingFunction;
using dgmf::EvaluateDamping;

TEST(DampingFunction, HandComputedValuesAtHalf)
{
  // At r = 1/2, 1 - r = 1/2:
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U1, 0.5), 0.25 * 1.5);   // (1/2)^2 (3/2)
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U2, 0.5), 0.0625 * 3.0); // (1/2)^4 (3)
  EXPECT_DOUBLE_EQ(
    EvaluateDamping(DampingFunction::U3, 0.5), (8.75 + 9 + 3) / 192.0); // (1/64)(35/4+9+3)/3
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U4, 0.5), (4 + 6.25 + 4 + 1) / 256.0);
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U5, 0.5), 0.125 * 1.5);
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U6, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U7, 0.5), 0.5);
}

TEST(DampingFunction, HandComputedValuesAtQuarter)
{
  // r = 1/4, 1 - r = 3/4.
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U1, 0.25), 0.5625 * 1.25);
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U2, 0.25), 0.31640625 * 2.0);
  EXPECT_DOUBLE_EQ(EvaluateDamping(DampingFunction::U6, 0.25), 0.5625);
}

TEST(DampingFunction, OneOnTheMovingBoundaryZeroFromOneOn)
{
  for (int u = 1; u <= 7; ++u)
  {
    const auto function = static_cast<DampingFunction>(u);
    EXPECT_DOUBLE_EQ(EvaluateDamping(function, 0.0), 1.0) << "u" << u;
    EXPECT_DOUBLE_EQ(EvaluateDamping(function, 1.0), 0.0) << "u" << u;
    EXPECT_DOUBLE_EQ(EvaluateDamping(function, 1.5), 0.0) << "u" << u;
    EXPECT_DOUBLE_EQ(EvaluateDamping(function, -1e-17), 1.0) << "u" << u;
  }
}

TEST(DampingFunction, DecreasingBetweenZeroAndOne)
{
  for (int u = 1; u <= 7; ++u)
  {
    const auto function = static_cast<DampingFunction>(u);
    double previous = 1.0;
    for (int k = 1; k <= 100; ++k)
    {
      const double value = EvaluateDamping(function, k / 100.0);
      EXPECT_LE(value, previous) << "u" << u << " at r = " << k / 100.0;
      EXPECT_GE(value, 0.0);
      previous = value;
    }
  }
}

TEST(DampingFunction, ValidValues)
{
  EXPECT_FALSE(dgmf::IsValidDampingFunction(0));
  EXPECT_TRUE(dgmf::IsValidDampingFunction(1));
  EXPECT_TRUE(dgmf::IsValidDampingFunction(7));
  EXPECT_FALSE(dgmf::IsValidDampingFunction(8));
}
