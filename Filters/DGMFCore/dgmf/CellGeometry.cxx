#include "dgmf/CellGeometry.h"

namespace dgmf
{
namespace
{
template <std::size_t C, std::size_t E>
constexpr ShapeTables MakeTables(
  const CornerEdges (&corners)[C], const int (&edges)[E][2], int dimension)
{
  return { corners, static_cast<int>(C), edges, static_cast<int>(E), dimension };
}
} // namespace

ShapeTables GetShapeTables(CellShape shape)
{
  switch (shape)
  {
    case CellShape::Triangle:
      return MakeTables(kTriangleCorners, kTriangleEdges, 2);
    case CellShape::Quad:
      return MakeTables(kQuadCorners, kQuadEdges, 2);
    case CellShape::Tetra:
      return MakeTables(kTetraCorners, kTetraEdges, 3);
    case CellShape::Hexahedron:
      return MakeTables(kHexCorners, kHexEdges, 3);
    case CellShape::Wedge:
      return MakeTables(kWedgeCorners, kWedgeEdges, 3);
    case CellShape::Pyramid:
      return MakeTables(kPyramidCorners, kPyramidEdges, 3);
  }
  return { nullptr, 0, nullptr, 0, 0 };
}

} // namespace dgmf
