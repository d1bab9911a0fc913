#include "dgmf/CellFaces.h"

namespace dgmf
{

const std::int64_t* GetShapeFaceStream(CellShape shape)
{
  static const std::int64_t triangle[] = { 1, 3, 0, 1, 2 };
  static const std::int64_t quad[] = { 1, 4, 0, 1, 2, 3 };
  static const std::int64_t wedge[] = { 5, 3, 0, 1, 2, 3, 3, 5, 4, 4, 0, 3, 4, 1, 4, 1, 4, 5, 2, 4,
    2, 5, 3, 0 };
  static const std::int64_t pyramid[] = { 5, 4, 0, 3, 2, 1, 3, 0, 1, 4, 3, 1, 2, 4, 3, 2, 3, 4, 3,
    3, 0, 4 };
  switch (shape)
  {
    case CellShape::Triangle:
      return triangle;
    case CellShape::Quad:
      return quad;
    case CellShape::Tetra:
      return TetraFaceStream;
    case CellShape::Hexahedron:
      return HexahedronFaceStream;
    case CellShape::Wedge:
      return wedge;
    case CellShape::Pyramid:
      return pyramid;
  }
  return triangle;
}

std::int64_t FaceStreamLength(const std::int64_t* faceStream)
{
  std::int64_t at = 1;
  for (std::int64_t f = 0; f < faceStream[0]; ++f)
  {
    at += 1 + faceStream[at];
  }
  return at;
}

const std::int64_t* FaceOfStream(
  const std::int64_t* faceStream, std::int32_t face, std::int64_t& count)
{
  std::int64_t at = 1;
  for (std::int32_t f = 0; f < face; ++f)
  {
    at += 1 + faceStream[at];
  }
  count = faceStream[at];
  return faceStream + at + 1;
}

} // namespace dgmf
