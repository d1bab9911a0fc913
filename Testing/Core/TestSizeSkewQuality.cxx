// Knupp's size-skew quality (Documentation/quality.md): ideal cells, size changes, units,
// hand-computed sheared cells, skew against shape, and the range of the score. Inversion,
// orientation, degenerate cells and the summary: TestSizeSkewInversion.cxx.
#include "QualityCells.h"

#include "dgmf/SizeSkewQuality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace dgmftest;
using dgmf::GetNumberOfCorners;

// ---- Basics -----------------------------------------------------------------------------------

TEST(SizeSkewQuality, NumberOfCornersFollowsVTK)
{
  EXPECT_EQ(GetNumberOfCorners(CellShape::Triangle), 3);
  EXPECT_EQ(GetNumberOfCorners(CellShape::Quad), 4);
  EXPECT_EQ(GetNumberOfCorners(CellShape::Tetra), 4);
  EXPECT_EQ(GetNumberOfCorners(CellShape::Hexahedron), 8);
  EXPECT_EQ(GetNumberOfCorners(CellShape::Wedge), 6);
  EXPECT_EQ(GetNumberOfCorners(CellShape::Pyramid), 5);
  for (const ShapeCase& c : AllShapes())
  {
    EXPECT_EQ(c.Ideal.size(), 3u * static_cast<unsigned>(GetNumberOfCorners(c.Shape))) << c.Name;
  }
}

TEST(SizeSkewQuality, IdealUndeformedCellScoresOne)
{
  for (const ShapeCase& c : AllShapes())
  {
    const CellQuality q = Quality(c.Shape, c.Ideal, c.Ideal);
    EXPECT_NEAR(q.SizeSkew, 1.0, kTol) << c.Name;
    EXPECT_LE(q.SizeSkew, 1.0) << c.Name;
    EXPECT_FALSE(q.Inverted) << c.Name;
  }
}

TEST(SizeSkewQuality, DoubledAreaOrVolumeScoresHalf)
{
  for (const ShapeCase& c : AllShapes())
  {
    // Area (2D) or volume (3D) doubled, shape unchanged.
    const double factor = std::pow(2.0, 1.0 / c.Dimension);
    const CellQuality grown = Quality(c.Shape, c.Ideal, Scaled(c.Ideal, factor));
    EXPECT_NEAR(grown.SizeSkew, 0.5, kTol) << c.Name;
    EXPECT_FALSE(grown.Inverted) << c.Name;
    // Halved scores the same: f_size = min(tau, 1/tau).
    const CellQuality shrunk = Quality(c.Shape, c.Ideal, Scaled(c.Ideal, 1.0 / factor));
    EXPECT_NEAR(shrunk.SizeSkew, 0.5, kTol) << c.Name;
  }
}

TEST(SizeSkewQuality, ScoreDoesNotDependOnUnits)
{
  for (const ShapeCase& c : AllShapes())
  {
    const Deformation d = ShearedCell(c.Shape);
    for (double unit : { 1e-6, 1e6 })
    {
      const CellQuality q = Quality(c.Shape, Scaled(d.Original, unit), Scaled(d.Deformed, unit));
      EXPECT_NEAR(q.SizeSkew, d.Expected, kTol) << c.Name << " unit " << unit;
    }
  }
}

// ---- Hand computations ------------------------------------------------------------------------

TEST(SizeSkewQuality, ShearedTriangleMatchesHandComputation)
{
  const Deformation d = ShearedTriangle();
  EXPECT_NEAR(d.Expected, 0.75, 1e-15); // the comment's closed form
  const CellQuality q = Quality(CellShape::Triangle, d.Original, d.Deformed);
  EXPECT_NEAR(q.SizeSkew, d.Expected, kTol);
  EXPECT_FALSE(q.Inverted);
}

TEST(SizeSkewQuality, ShearedQuadMatchesHandComputation)
{
  const Deformation d = ShearedQuad();
  const CellQuality q = Quality(CellShape::Quad, d.Original, d.Deformed);
  EXPECT_NEAR(q.SizeSkew, d.Expected, kTol);
  EXPECT_FALSE(q.Inverted);
}

TEST(SizeSkewQuality, ShearedTetraMatchesHandComputation)
{
  const Deformation d = ShearedTetra();
  const CellQuality q = Quality(CellShape::Tetra, d.Original, d.Deformed);
  EXPECT_NEAR(q.SizeSkew, d.Expected, kTol);
  EXPECT_FALSE(q.Inverted);
}

TEST(SizeSkewQuality, ShearedHexahedronMatchesHandComputation)
{
  const Deformation d = ShearedHexahedron();
  const CellQuality q = Quality(CellShape::Hexahedron, d.Original, d.Deformed);
  EXPECT_NEAR(q.SizeSkew, d.Expected, kTol);
  EXPECT_FALSE(q.Inverted);
}

TEST(SizeSkewQuality, ShearedWedgeMatchesHandComputation)
{
  const Deformation d = ShearedWedge();
  const CellQuality q = Quality(CellShape::Wedge, d.Original, d.Deformed);
  EXPECT_NEAR(q.SizeSkew, d.Expected, kTol);
  EXPECT_FALSE(q.Inverted);
}

TEST(SizeSkewQuality, ShearedPyramidMatchesHandComputation)
{
  const Deformation d = ShearedPyramid();
  const CellQuality q = Quality(CellShape::Pyramid, d.Original, d.Deformed);
  EXPECT_NEAR(q.SizeSkew, d.Expected, kTol);
  EXPECT_FALSE(q.Inverted);
}

TEST(SizeSkewQuality, ParallelogramAndParallelepipedSkewIsMeanOfInverseSines)
{
  // Shear x += z / 2 of the unit cube: volume kept, every corner has sine product
  // 1 / sqrt(1.25) -> f_skew = 8 / (8 * 1.25^(1/3)).
  Points hex = UnitCube();
  for (int i = 4; i < 8; ++i)
  {
    hex[3 * i] += 0.5;
  }
  EXPECT_NEAR(
    Quality(CellShape::Hexahedron, UnitCube(), hex).SizeSkew, 1.0 / std::cbrt(1.25), kTol);
  // Shear x += y / 2 of the unit square: area kept, f_skew = 4 / (4 * sqrt(1.25)).
  const Points quad = { 0, 0, 0, 1, 0, 0, 1.5, 1, 0, 0.5, 1, 0 };
  EXPECT_NEAR(Quality(CellShape::Quad, UnitSquare(), quad).SizeSkew, 1.0 / std::sqrt(1.25), kTol);
}

// ---- Documented choices -----------------------------------------------------------------------

TEST(SizeSkewQuality, SkewOfQuadsHexahedraAndWedgesIgnoresAspectRatio)
{
  // Knupp's skew only measures angles: a 10 x 1 rectangle, a 10 x 1 x 0.1 box and a flat prism
  // (boundary-layer cells) score 1 when undeformed.
  const Points rectangle = { 0, 0, 0, 10, 0, 0, 10, 1, 0, 0, 1, 0 };
  EXPECT_NEAR(Quality(CellShape::Quad, rectangle, rectangle).SizeSkew, 1.0, kTol);
  Points box = UnitCube();
  for (std::size_t i = 0; i < box.size(); i += 3)
  {
    box[i] *= 10.0;
    box[i + 2] *= 0.1;
  }
  EXPECT_NEAR(Quality(CellShape::Hexahedron, box, box).SizeSkew, 1.0, kTol);
  const Points flatPrism = IdealWedge(0.01);
  EXPECT_NEAR(Quality(CellShape::Wedge, flatPrism, flatPrism).SizeSkew, 1.0, kTol);
}

TEST(SizeSkewQuality, ShapeOfSimplicesAndPyramidsPenalisesAspectRatio)
{
  // Triangle (0,0), (4,0), (2,1): alpha = 4, edges^2 16, 5, 5, l11 + l22 - l12 = (16+5+5)/2 = 13,
  // f_shape = 4 sqrt(3) / 13.
  const Points flatTriangle = { 0, 0, 0, 4, 0, 0, 2, 1, 0 };
  EXPECT_NEAR(
    Quality(CellShape::Triangle, flatTriangle, flatTriangle).SizeSkew, 4.0 * kS3 / 13.0, kTol);
  // Pyramid with the apex at height 1/2 (a cube's sixth): every base corner has
  // a=(1,0,0), b=(0,1,0), c=(.5,.5,.5) up to symmetry: alpha 1/2, l33 = 0.75, l13 = l23 = 0.5,
  // 1/q = (1.5*2 + 2*0.75 + 0 - 2*1) / (3 (sqrt(2)/2)^(2/3)) = 2.5 / (3 * 0.5^(1/3)).
  Points pyramid = IdealPyramid();
  pyramid[14] = 0.5;
  EXPECT_NEAR(
    Quality(CellShape::Pyramid, pyramid, pyramid).SizeSkew, 3.0 * std::cbrt(0.5) / 2.5, kTol);
}

TEST(SizeSkewQuality, ValidCellsScoreBetweenZeroAndOne)
{
  // Random deformations of every ideal cell (jitter up to 30% of the edge): never above 1, never
  // NaN; the wedge and pyramid extensions are bounded by 1 like Knupp's metrics.
  std::mt19937 generator(12345);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (const ShapeCase& c : AllShapes())
  {
    for (int trial = 0; trial < 2000; ++trial)
    {
      Points deformed = c.Ideal;
      for (std::size_t i = 0; i < deformed.size(); ++i)
      {
        if (c.Dimension == 3 || i % 3 != 2)
        {
          deformed[i] += jitter(generator);
        }
      }
      // Undeformed (tests the shape part alone) and against the ideal original.
      for (const CellQuality q :
        { Quality(c.Shape, deformed, deformed), Quality(c.Shape, c.Ideal, deformed) })
      {
        ASSERT_FALSE(std::isnan(q.SizeSkew)) << c.Name;
        ASSERT_GE(q.SizeSkew, 0.0) << c.Name;
        ASSERT_LE(q.SizeSkew, 1.0) << c.Name;
        if (q.Inverted)
        {
          ASSERT_EQ(q.SizeSkew, 0.0) << c.Name;
        }
      }
    }
  }
}
