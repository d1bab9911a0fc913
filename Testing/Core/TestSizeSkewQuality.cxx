// Knupp's size-skew quality (Documentation/quality.md): ideal cells, size changes, hand-computed
// sheared cells, inversion, rigid-motion invariance, orientation of the original cell, degenerate
// cells and the summary.
#include "dgmf/SizeSkewQuality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using dgmf::CellQuality;
using dgmf::CellShape;
using dgmf::ComputeSizeSkew;
using dgmf::GetNumberOfCorners;
using dgmf::QualitySummary;
using dgmf::SummarizeQuality;

namespace
{

using Points = std::vector<double>; // 3 coordinates per corner, VTK corner order

const double kS3 = std::sqrt(3.0);
const double kPi = std::acos(-1.0);
constexpr double kTol = 1e-12;

// ---- Ideal cells (edge length 1) --------------------------------------------------------------

Points EquilateralTriangle()
{
  return { 0, 0, 0, 1, 0, 0, 0.5, kS3 / 2, 0 };
}

Points UnitSquare()
{
  return { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
}

Points RegularTetra()
{
  // Apex above the centroid of the base, at height sqrt(2/3); (1-0)x(2-0) points toward it.
  return { 0, 0, 0, 1, 0, 0, 0.5, kS3 / 2, 0, 0.5, kS3 / 6, std::sqrt(2.0 / 3.0) };
}

Points UnitCube()
{
  return { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
}

/// Right prism over an equilateral triangle, height 1, in VTK's order: the normal (1-0)x(2-0) of
/// the bottom triangle points away from the top triangle.
Points IdealWedge(double height = 1.0)
{
  return { 0, 0, 0, 0.5, kS3 / 2, 0, 1, 0, 0, 0, 0, height, 0.5, kS3 / 2, height, 1, 0, height };
}

/// Unit square base, all eight edges of length 1 (apex height 1/sqrt(2)).
Points IdealPyramid()
{
  return { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1 / std::sqrt(2.0) };
}

struct ShapeCase
{
  CellShape Shape;
  const char* Name;
  Points Ideal;
  int Dimension;
};

std::vector<ShapeCase> AllShapes()
{
  return { { CellShape::Triangle, "triangle", EquilateralTriangle(), 2 },
    { CellShape::Quad, "quad", UnitSquare(), 2 }, { CellShape::Tetra, "tetra", RegularTetra(), 3 },
    { CellShape::Hexahedron, "hexahedron", UnitCube(), 3 },
    { CellShape::Wedge, "wedge", IdealWedge(), 3 },
    { CellShape::Pyramid, "pyramid", IdealPyramid(), 3 } };
}

// ---- Point transformations --------------------------------------------------------------------

Points Scaled(Points p, double factor)
{
  for (double& x : p)
  {
    x *= factor;
  }
  return p;
}

/// Rotation by `angle` about the unit vector along `axis` (Rodrigues), then translation.
Points RotatedTranslated(const Points& p, const double axis[3], double angle, const double t[3])
{
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const double u[3] = { axis[0] / n, axis[1] / n, axis[2] / n };
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const double r[3][3] = { { c + u[0] * u[0] * (1 - c), u[0] * u[1] * (1 - c) - u[2] * s,
                             u[0] * u[2] * (1 - c) + u[1] * s },
    { u[1] * u[0] * (1 - c) + u[2] * s, c + u[1] * u[1] * (1 - c),
      u[1] * u[2] * (1 - c) - u[0] * s },
    { u[2] * u[0] * (1 - c) - u[1] * s, u[2] * u[1] * (1 - c) + u[0] * s,
      c + u[2] * u[2] * (1 - c) } };
  Points out(p.size());
  for (std::size_t i = 0; i < p.size(); i += 3)
  {
    for (int row = 0; row < 3; ++row)
    {
      out[i + row] = r[row][0] * p[i] + r[row][1] * p[i + 1] + r[row][2] * p[i + 2] + t[row];
    }
  }
  return out;
}

Points MirroredX(Points p)
{
  for (std::size_t i = 0; i < p.size(); i += 3)
  {
    p[i] = -p[i];
  }
  return p;
}

/// Same cell with its corners listed in another order: out corner i = in corner order[i].
Points Reordered(const Points& p, const std::vector<int>& order)
{
  Points out;
  for (int i : order)
  {
    out.insert(out.end(), p.begin() + 3 * i, p.begin() + 3 * i + 3);
  }
  return out;
}

void SetPoint(Points& p, int i, double x, double y, double z)
{
  p[3 * i] = x;
  p[3 * i + 1] = y;
  p[3 * i + 2] = z;
}

CellQuality Quality(CellShape shape, const Points& original, const Points& deformed)
{
  return ComputeSizeSkew(shape, original.data(), deformed.data());
}

// ---- Sheared cells with hand-computed scores (used by several tests) ---------------------------
// Each returns the deformed cell; its original is the ideal cell of AllShapes() unless stated.

struct Deformation
{
  Points Original;
  Points Deformed;
  double Expected;
};

Deformation ShearedTriangle()
{
  // Equilateral (area sqrt(3)/4) -> (0,0), (1,0), (1,1) (area 1/2).
  // tau = (1/2) / (sqrt(3)/4) = 2/sqrt(3) > 1, so f_size = sqrt(3)/2.
  // Corner 0: a = (1,0), b = (1,1): alpha = 1, l11 = 1, l22 = 2, l12 = 1,
  // f_shape = sqrt(3) * 1 / (1 + 2 - 1) = sqrt(3)/2. Size-shape = 3/4.
  const double fSize = (kS3 / 4.0) / 0.5;
  const double fShape = kS3 * 1.0 / (1.0 + 2.0 - 1.0);
  return { EquilateralTriangle(), { 0, 0, 0, 1, 0, 0, 1, 1, 0 }, fSize * fShape };
}

Deformation ShearedQuad()
{
  // Unit square -> (0,0), (1,0), (1,2), (0,1): area (shoelace) 3/2, f_size = 2/3.
  // Corner k: a = p(k+1) - p(k), b = p(k-1) - p(k), term sqrt(l11 l22) / alpha:
  //   0: a=(1,0),   b=(0,1):   alpha=1, sqrt(1*1)=1      -> 1
  //   1: a=(0,2),   b=(-1,0):  alpha=2, sqrt(4*1)=2      -> 1
  //   2: a=(-1,-1), b=(0,-2):  alpha=2, sqrt(2*4)=2*sqrt2 -> sqrt(2)
  //   3: a=(0,-1),  b=(1,1):   alpha=1, sqrt(1*2)=sqrt2  -> sqrt(2)
  // f_skew = 4 / (2 + 2 sqrt(2)).
  const double fSize = 1.0 / 1.5;
  const double fSkew = 4.0 / (1.0 + 1.0 + std::sqrt(2.0) + std::sqrt(2.0));
  return { UnitSquare(), { 0, 0, 0, 1, 0, 0, 1, 2, 0, 0, 1, 0 }, fSize * fSkew };
}

Deformation ShearedTetra()
{
  // Corner tet (0,0,0), (1,0,0), (0,1,0), (0,0,1): alpha = 1.
  // Deformed: apex -> (0.5, 0, 2) (sheared and stretched): alpha = 2, tau = 2, f_size = 1/2.
  // a=(1,0,0), b=(0,1,0), c=(0.5,0,2): l11=1, l22=1, l33=4.25, l12=0, l13=0.5, l23=0.
  // f_shape = 3 (sqrt(2)*2)^(2/3) / (1.5*(1+1+4.25) - (0+0.5+0)) = 3*2 / 8.875.
  const double fSize = 0.5;
  const double fShape = 3.0 * 2.0 / (1.5 * (1.0 + 1.0 + 4.25) - 0.5);
  return { { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 }, { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0, 2 },
    fSize * fShape };
}

Deformation ShearedHexahedron()
{
  // Unit cube with corner 6 pulled from (1,1,1) up to (1,1,2).
  // Corner triples (VTK order) and their terms (sqrt(l11 l22 l33) / alpha)^(2/3):
  //   0,1,3,4: unchanged right angles                          -> 1 each
  //   2: (-x, -y, (0,0,2)):          alpha 2, sqrt(1*1*4) = 2    -> 1
  //   5: (-x, (0,1,1), -z):          alpha 1, sqrt(1*2*1)        -> 2^(1/3)
  //   7: ((1,0,1), -y, -z):          alpha 1, sqrt(2*1*1)        -> 2^(1/3)
  //   6: ((0,-1,-1), (-1,0,-1), (0,0,-2)): alpha 2, sqrt(2*2*4) = 4 -> 2^(2/3)
  // f_skew = 8 / (5 + 2 * 2^(1/3) + 2^(2/3)).
  // Size: sum of alphas 1+1+2+1+1+1+2+1 = 10 against 8: tau = 1.25, f_size = 0.8.
  Points deformed = UnitCube();
  SetPoint(deformed, 6, 1, 1, 2);
  const double fSkew = 8.0 / (5.0 + 2.0 * std::cbrt(2.0) + std::cbrt(4.0));
  return { UnitCube(), deformed, 0.8 * fSkew };
}

Deformation ShearedWedge()
{
  // Ideal wedge with corner 5 pulled from (1,0,1) up to (1,0,2).
  // Corner terms ((sqrt(3)/2) sqrt(l11 l22 l33) / alpha)^(2/3):
  //   0, 1: unchanged                                              -> 1
  //   2: (p1-p2, p0-p2, (0,0,2)): alpha sqrt(3), sqrt(1*1*4) = 2     -> 1
  //   3: (p4-p3, (1,0,1), -z): alpha sqrt(3)/2, sqrt(1*2*1)          -> 2^(1/3)
  //   4: ((1/2,-sqrt3/2,1), p3-p4, -z): alpha sqrt(3)/2, sqrt(2*1*1) -> 2^(1/3)
  //   5: ((-1,0,-1), (-1/2,sqrt3/2,-1), (0,0,-2)): alpha sqrt(3), sqrt(2*2*4) = 4 -> 2^(2/3)
  // f_skew = 6 / (3 + 2 * 2^(1/3) + 2^(2/3)).
  // Size: sum of alphas (sqrt3/2) (1+1+2+1+1+2) against 6 sqrt3/2: tau = 4/3, f_size = 3/4.
  Points deformed = IdealWedge();
  SetPoint(deformed, 5, 1, 0, 2);
  const double fSkew = 6.0 / (3.0 + 2.0 * std::cbrt(2.0) + std::cbrt(4.0));
  return { IdealWedge(), deformed, 0.75 * fSkew };
}

Deformation ShearedPyramid()
{
  // Ideal pyramid -> base corner 2 moved to (1.5,1,0), apex to (0.5,0.5,1).
  // Base corner k: a = p(k+1)-p(k), b = p(k-1)-p(k), c = apex - p(k),
  // 1/q_k = (1.5 (l11+l22) + 2 l33 + l12 - 2 (l13+l23)) / (3 (sqrt(2) alpha)^(2/3)):
  //   0: a=(1,0,0), b=(0,1,0), c=(.5,.5,1): alpha 1; 1.5*2 + 2*1.5 + 0 - 2*1 = 4
  //   1: a=(.5,1,0), b=(-1,0,0), c=(-.5,.5,1): alpha 1; 1.5*2.25 + 3 - 0.5 - 2*0.75 = 4.375
  //   2: a=(-1.5,0,0), b=(-.5,-1,0), c=(-1,-.5,1): alpha 1.5; 1.5*3.5 + 4.5 + .75 - 2*2.5 = 5.5
  //   3: a=(0,-1,0), b=(1.5,0,0), c=(.5,-.5,1): alpha 1.5; 1.5*3.25 + 3 + 0 - 2*1.25 = 5.375
  // f_shape = 4 / sum_k 1/q_k, with (sqrt(2)*1)^(2/3) = 2^(1/3), (sqrt(2)*1.5)^(2/3) = 4.5^(1/3).
  // Size: sum of alphas 5 against 4/sqrt(2): tau = 5/(2 sqrt(2)) > 1, f_size = 2 sqrt(2)/5.
  Points deformed = IdealPyramid();
  SetPoint(deformed, 2, 1.5, 1, 0);
  SetPoint(deformed, 4, 0.5, 0.5, 1);
  const double c1 = 3.0 * std::cbrt(2.0);
  const double c15 = 3.0 * std::cbrt(4.5);
  const double fShape = 4.0 / (4.0 / c1 + 4.375 / c1 + 5.5 / c15 + 5.375 / c15);
  const double fSize = 2.0 * std::sqrt(2.0) / 5.0;
  return { IdealPyramid(), deformed, fSize * fShape };
}

Deformation ShearedCell(CellShape shape)
{
  switch (shape)
  {
    case CellShape::Triangle:
      return ShearedTriangle();
    case CellShape::Quad:
      return ShearedQuad();
    case CellShape::Tetra:
      return ShearedTetra();
    case CellShape::Hexahedron:
      return ShearedHexahedron();
    case CellShape::Wedge:
      return ShearedWedge();
    case CellShape::Pyramid:
      return ShearedPyramid();
  }
  return {};
}

} // namespace

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
