// Cells shared by the size-skew tests (Documentation/quality.md): the ideal cell of each shape,
// rigid motions and mirrors of a cell, and one sheared cell per shape with its hand-computed score.
#ifndef dgmftest_QualityCells_h
#define dgmftest_QualityCells_h

#include "dgmf/SizeSkewQuality.h"

#include <cmath>
#include <vector>

namespace dgmftest
{
using dgmf::CellQuality;
using dgmf::CellShape;

using Points = std::vector<double>; // 3 coordinates per corner, VTK corner order

inline const double kS3 = std::sqrt(3.0);
inline const double kPi = std::acos(-1.0);
constexpr double kTol = 1e-12;

// ---- Ideal cells (edge length 1) --------------------------------------------------------------

inline Points EquilateralTriangle()
{
  return { 0, 0, 0, 1, 0, 0, 0.5, kS3 / 2, 0 };
}

inline Points UnitSquare()
{
  return { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
}

inline Points RegularTetra()
{
  // Apex above the centroid of the base, at height sqrt(2/3); (1-0)x(2-0) points toward it.
  return { 0, 0, 0, 1, 0, 0, 0.5, kS3 / 2, 0, 0.5, kS3 / 6, std::sqrt(2.0 / 3.0) };
}

inline Points UnitCube()
{
  return { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
}

/// Right prism over an equilateral triangle, height 1, in VTK's order: the normal (1-0)x(2-0) of
/// the bottom triangle points away from the top triangle.
inline Points IdealWedge(double height = 1.0)
{
  return { 0, 0, 0, 0.5, kS3 / 2, 0, 1, 0, 0, 0, 0, height, 0.5, kS3 / 2, height, 1, 0, height };
}

/// Unit square base, all eight edges of length 1 (apex height 1/sqrt(2)).
inline Points IdealPyramid()
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

inline std::vector<ShapeCase> AllShapes()
{
  return { { CellShape::Triangle, "triangle", EquilateralTriangle(), 2 },
    { CellShape::Quad, "quad", UnitSquare(), 2 }, { CellShape::Tetra, "tetra", RegularTetra(), 3 },
    { CellShape::Hexahedron, "hexahedron", UnitCube(), 3 },
    { CellShape::Wedge, "wedge", IdealWedge(), 3 },
    { CellShape::Pyramid, "pyramid", IdealPyramid(), 3 } };
}

// ---- Point transformations --------------------------------------------------------------------

inline Points Scaled(Points p, double factor)
{
  for (double& x : p)
  {
    x *= factor;
  }
  return p;
}

/// Rotation by `angle` about the unit vector along `axis` (Rodrigues), then translation.
inline Points RotatedTranslated(
  const Points& p, const double axis[3], double angle, const double t[3])
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

inline Points MirroredX(Points p)
{
  for (std::size_t i = 0; i < p.size(); i += 3)
  {
    p[i] = -p[i];
  }
  return p;
}

/// Same cell with its corners listed in another order: out corner i = in corner order[i].
inline Points Reordered(const Points& p, const std::vector<int>& order)
{
  Points out;
  for (int i : order)
  {
    out.insert(out.end(), p.begin() + 3 * i, p.begin() + 3 * i + 3);
  }
  return out;
}

inline void SetPoint(Points& p, int i, double x, double y, double z)
{
  p[3 * i] = x;
  p[3 * i + 1] = y;
  p[3 * i + 2] = z;
}

inline CellQuality Quality(CellShape shape, const Points& original, const Points& deformed)
{
  return dgmf::ComputeSizeSkew(shape, original.data(), deformed.data());
}

// ---- Sheared cells with hand-computed scores (used by several tests) ---------------------------
// Each returns the deformed cell; its original is the ideal cell of AllShapes() unless stated.

struct Deformation
{
  Points Original;
  Points Deformed;
  double Expected;
};

inline Deformation ShearedTriangle()
{
  // Equilateral (area sqrt(3)/4) -> (0,0), (1,0), (1,1) (area 1/2).
  // tau = (1/2) / (sqrt(3)/4) = 2/sqrt(3) > 1, so f_size = sqrt(3)/2.
  // Corner 0: a = (1,0), b = (1,1): alpha = 1, l11 = 1, l22 = 2, l12 = 1,
  // f_shape = sqrt(3) * 1 / (1 + 2 - 1) = sqrt(3)/2. Size-shape = 3/4.
  const double fSize = (kS3 / 4.0) / 0.5;
  const double fShape = kS3 * 1.0 / (1.0 + 2.0 - 1.0);
  return { EquilateralTriangle(), { 0, 0, 0, 1, 0, 0, 1, 1, 0 }, fSize * fShape };
}

inline Deformation ShearedQuad()
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

inline Deformation ShearedTetra()
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

inline Deformation ShearedHexahedron()
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

inline Deformation ShearedWedge()
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

inline Deformation ShearedPyramid()
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

inline Deformation ShearedCell(CellShape shape)
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

} // namespace dgmftest

#endif
