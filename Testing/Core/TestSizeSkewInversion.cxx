// Knupp's size-skew quality (Documentation/quality.md): inverted cells, rigid-motion invariance,
// the orientation of the original cell, degenerate and non-finite cells, and the summary.
#include "QualityCells.h"

#include "dgmf/SizeSkewQuality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace dgmftest;
using dgmf::QualitySummary;
using dgmf::SummarizeQuality;

// ---- Inversion --------------------------------------------------------------------------------

TEST(SizeSkewQuality, CornerMovedThroughOppositeFaceIsInvertedAndScoresZero)
{
  for (const ShapeCase& c : AllShapes())
  {
    Points deformed = c.Ideal;
    switch (c.Shape)
    {
      case CellShape::Triangle: // corner 2 through edge 0-1
        SetPoint(deformed, 2, 0.5, -0.3, 0);
        break;
      case CellShape::Quad: // corner 2 through the diagonal 1-3: reflex corner
        SetPoint(deformed, 2, 0.2, 0.2, 0);
        break;
      case CellShape::Tetra: // apex through the base
        deformed[11] = -0.5;
        break;
      case CellShape::Hexahedron: // corner 4 through the bottom face
        deformed[14] = -0.5;
        break;
      case CellShape::Wedge: // corner 3 through the bottom triangle
        deformed[11] = -0.5;
        break;
      case CellShape::Pyramid: // apex through the base
        deformed[14] = -0.5;
        break;
    }
    const CellQuality q = Quality(c.Shape, c.Ideal, deformed);
    EXPECT_EQ(q.SizeSkew, 0.0) << c.Name;
    EXPECT_TRUE(q.Inverted) << c.Name;
  }
}

TEST(SizeSkewQuality, CollapsedDeformedCellIsInverted)
{
  // alpha = 0 at a corner is invalid (alpha <= 0), e.g. a tet flattened into its base plane.
  Points flat = RegularTetra();
  flat[11] = 0.0;
  const CellQuality q = Quality(CellShape::Tetra, RegularTetra(), flat);
  EXPECT_EQ(q.SizeSkew, 0.0);
  EXPECT_TRUE(q.Inverted);
}

TEST(SizeSkewQuality, MirroredOrFlippedTriangleIsInverted)
{
  const Points original = EquilateralTriangle();
  // Mirror image in the plane x = 0: same size and shape, opposite orientation.
  const CellQuality mirrored = Quality(CellShape::Triangle, original, MirroredX(original));
  EXPECT_EQ(mirrored.SizeSkew, 0.0);
  EXPECT_TRUE(mirrored.Inverted);
  // Turned over in 3D (half a turn about the x axis): it now faces the other way.
  const double xAxis[3] = { 1, 0, 0 };
  const double noShift[3] = { 0, 0, 0 };
  const CellQuality turned =
    Quality(CellShape::Triangle, original, RotatedTranslated(original, xAxis, kPi, noShift));
  EXPECT_EQ(turned.SizeSkew, 0.0);
  EXPECT_TRUE(turned.Inverted);
}

TEST(SizeSkewQuality, MirroredOrBowTieQuadIsInverted)
{
  const Points original = UnitSquare();
  EXPECT_TRUE(Quality(CellShape::Quad, original, MirroredX(original)).Inverted);
  // Corners 2 and 3 swapped: a self-intersecting "bow tie".
  const CellQuality bowTie =
    Quality(CellShape::Quad, original, Reordered(original, { 0, 1, 3, 2 }));
  EXPECT_EQ(bowTie.SizeSkew, 0.0);
  EXPECT_TRUE(bowTie.Inverted);
}

// ---- Rigid motion and orientation -------------------------------------------------------------

TEST(SizeSkewQuality, RigidMotionOfDeformedCellDoesNotChangeScore)
{
  const double axis[3] = { 1, 2, 3 };
  const double shift[3] = { 10, -3, 7.5 };
  const double zAxis[3] = { 0, 0, 1 };
  for (const ShapeCase& c : AllShapes())
  {
    const Deformation d = ShearedCell(c.Shape);
    // A general rotation (it tilts a 2D cell by less than 90 degrees out of its plane).
    const CellQuality moved =
      Quality(c.Shape, d.Original, RotatedTranslated(d.Deformed, axis, 0.7, shift));
    EXPECT_NEAR(moved.SizeSkew, d.Expected, kTol) << c.Name;
    EXPECT_FALSE(moved.Inverted) << c.Name;
    // A large rotation about z (in the plane of the 2D cells).
    const CellQuality turned =
      Quality(c.Shape, d.Original, RotatedTranslated(d.Deformed, zAxis, 2.5, shift));
    EXPECT_NEAR(turned.SizeSkew, d.Expected, kTol) << c.Name;
    EXPECT_FALSE(turned.Inverted) << c.Name;
  }
}

TEST(SizeSkewQuality, CellsInATiltedPlaneOrPlaceBehaveLikeInTheXYPlane)
{
  // Original and deformed both moved rigidly: a triangle or quad in a tilted plane in 3D (and any
  // 3D cell anywhere) scores as in the reference position.
  const double axis[3] = { -2, 1, 0.5 };
  const double shift[3] = { 1, 2, 3 };
  for (const ShapeCase& c : AllShapes())
  {
    const Deformation d = ShearedCell(c.Shape);
    const Points original = RotatedTranslated(d.Original, axis, 1.1, shift);
    const Points deformed = RotatedTranslated(d.Deformed, axis, 1.1, shift);
    const CellQuality q = Quality(c.Shape, original, deformed);
    EXPECT_NEAR(q.SizeSkew, d.Expected, kTol) << c.Name;
    EXPECT_FALSE(q.Inverted) << c.Name;
    // Flipping it over relative to its own tilted plane is still an inversion.
    if (c.Dimension == 2)
    {
      EXPECT_TRUE(Quality(c.Shape, original, MirroredX(original)).Inverted) << c.Name;
    }
  }
}

TEST(SizeSkewQuality, ClockwiseOriginal2DCellIsNotInverted)
{
  // Clockwise = the same cells mirrored (negative signed area in the xy plane).
  for (CellShape shape : { CellShape::Triangle, CellShape::Quad })
  {
    const Deformation d = ShearedCell(shape);
    const Points original = MirroredX(d.Original);
    const CellQuality still = Quality(shape, original, original);
    EXPECT_NEAR(still.SizeSkew, 1.0, kTol);
    EXPECT_FALSE(still.Inverted);
    // The mirrored deformation scores as the counter-clockwise one.
    const CellQuality deformed = Quality(shape, original, MirroredX(d.Deformed));
    EXPECT_NEAR(deformed.SizeSkew, d.Expected, kTol);
    EXPECT_FALSE(deformed.Inverted);
    // Turning it counter-clockwise is an inversion for it.
    EXPECT_TRUE(Quality(shape, original, d.Original).Inverted);
  }
}

TEST(SizeSkewQuality, NegativelyOrientedOriginal3DCellIsJudgedAgainstItsOwnOrientation)
{
  // Mirror images of the VTK-ordered cells (inside-out in VTK's convention, as written by some
  // other tools): undeformed they score 1, deformed like their mirror they score the same,
  // and a true inversion is still detected.
  for (const ShapeCase& c : AllShapes())
  {
    if (c.Dimension != 3)
    {
      continue;
    }
    const Deformation d = ShearedCell(c.Shape);
    const Points mirroredIdeal = MirroredX(c.Ideal);
    const CellQuality still = Quality(c.Shape, mirroredIdeal, mirroredIdeal);
    EXPECT_NEAR(still.SizeSkew, 1.0, kTol) << c.Name;
    EXPECT_FALSE(still.Inverted) << c.Name;
    const Points original = MirroredX(d.Original);
    EXPECT_NEAR(Quality(c.Shape, original, MirroredX(d.Deformed)).SizeSkew, d.Expected, kTol)
      << c.Name;
    EXPECT_TRUE(Quality(c.Shape, original, d.Original).Inverted) << c.Name;
  }
}

TEST(SizeSkewQuality, WedgeInEitherTriangleOrderIsAccepted)
{
  // Bottom triangle counter-clockwise seen from the top (the opposite of VTK's documented order).
  const Points other = Reordered(IdealWedge(), { 0, 2, 1, 3, 5, 4 });
  const CellQuality still = Quality(CellShape::Wedge, other, other);
  EXPECT_NEAR(still.SizeSkew, 1.0, kTol);
  EXPECT_FALSE(still.Inverted);
  Points through = other;
  through[11] = -0.5; // corner 3 through the bottom triangle
  EXPECT_TRUE(Quality(CellShape::Wedge, other, through).Inverted);
}

// ---- Degenerate and invalid input -------------------------------------------------------------

TEST(SizeSkewQuality, DegenerateOriginalScoresZeroWithoutBeingInverted)
{
  for (const ShapeCase& c : AllShapes())
  {
    // All corners at one point, and the cell squashed flat (z = 0 for 3D cells, y = 0 for 2D).
    const Points point(c.Ideal.size(), 1.5);
    Points flat = c.Ideal;
    for (std::size_t i = (c.Dimension == 3 ? 2 : 1); i < flat.size(); i += 3)
    {
      flat[i] = 0.0;
    }
    for (const Points& original : { point, flat })
    {
      const CellQuality q = Quality(c.Shape, original, c.Ideal);
      EXPECT_EQ(q.SizeSkew, 0.0) << c.Name;
      EXPECT_FALSE(q.Inverted) << c.Name;
    }
  }
}

TEST(SizeSkewQuality, NonFiniteCoordinatesNeverGiveNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const ShapeCase& c : AllShapes())
  {
    Points broken = c.Ideal;
    broken[4] = nan;
    const CellQuality fromOriginal = Quality(c.Shape, broken, c.Ideal);
    EXPECT_EQ(fromOriginal.SizeSkew, 0.0) << c.Name; // treated as a degenerate original
    EXPECT_FALSE(fromOriginal.Inverted) << c.Name;
    const CellQuality fromDeformed = Quality(c.Shape, c.Ideal, broken);
    EXPECT_EQ(fromDeformed.SizeSkew, 0.0) << c.Name; // no valid Jacobian: counted as inverted
    EXPECT_TRUE(fromDeformed.Inverted) << c.Name;
  }
}

// ---- Summary ----------------------------------------------------------------------------------

TEST(SizeSkewQuality, SummaryIgnoresNaNAndCountsInvertedFlags)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double values[] = { 0.5, nan, 1.0, 0.0, nan, 0.25 };
  const std::uint8_t flags[] = { 0, 0, 0, 1, 0, 0 };
  const QualitySummary s = SummarizeQuality(values, flags, 6);
  EXPECT_EQ(s.Evaluated, 4u);
  EXPECT_EQ(s.NotComputed, 2u);
  EXPECT_EQ(s.Inverted, 1u);
  EXPECT_DOUBLE_EQ(s.Mean, (0.5 + 1.0 + 0.0 + 0.25) / 4.0);
  EXPECT_EQ(s.Minimum, 0.0);
}

TEST(SizeSkewQuality, SummaryWithoutFlagsOrCells)
{
  const double values[] = { 0.75, 0.5 };
  const QualitySummary s = SummarizeQuality(values, nullptr, 2);
  EXPECT_EQ(s.Evaluated, 2u);
  EXPECT_EQ(s.Inverted, 0u);
  EXPECT_DOUBLE_EQ(s.Mean, 0.625);
  EXPECT_EQ(s.Minimum, 0.5);

  const QualitySummary empty = SummarizeQuality(values, nullptr, 0);
  EXPECT_EQ(empty.Evaluated, 0u);
  EXPECT_EQ(empty.Mean, 0.0);
  EXPECT_EQ(empty.Minimum, 0.0);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double onlyNaN[] = { nan, nan };
  const QualitySummary none = SummarizeQuality(onlyNaN, nullptr, 2);
  EXPECT_EQ(none.Evaluated, 0u);
  EXPECT_EQ(none.NotComputed, 2u);
  EXPECT_EQ(none.Mean, 0.0);
  EXPECT_EQ(none.Minimum, 0.0);
}

TEST(SizeSkewQuality, SummaryIsReproducible)
{
  // Same input, same bits; and it matches a plain left-to-right sum.
  std::vector<double> values(100001);
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double& v : values)
  {
    v = uniform(generator);
  }
  double sum = 0.0;
  for (double v : values)
  {
    sum += v;
  }
  const QualitySummary a = SummarizeQuality(values.data(), nullptr, values.size());
  const QualitySummary b = SummarizeQuality(values.data(), nullptr, values.size());
  EXPECT_EQ(a.Mean, b.Mean);
  EXPECT_EQ(a.Mean, sum / static_cast<double>(values.size()));
}
