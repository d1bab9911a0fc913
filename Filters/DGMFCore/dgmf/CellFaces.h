/**
 * @file CellFaces.h
 * @brief The faces of a cell as a face stream (VTK's polyhedron layout: the number of faces, then
 * for each face its number of corners and its corners), and the face streams of the standard
 * shapes in VTK's corner order. Used by the quality of cells judged through their faces
 * (DecomposedSizeSkew) and by the non-orthogonality of faces (NonOrthogonality).
 */
#ifndef dgmf_CellFaces_h
#define dgmf_CellFaces_h

#include "dgmf/SizeSkewQuality.h"

#include <cstdint>

namespace dgmf
{

/// The face streams of the tetrahedron and the hexahedron (GetShapeFaceStream's), for code that
/// needs them at compile time.
inline constexpr std::int64_t TetraFaceStream[] = { 4, 3, 0, 1, 3, 3, 1, 2, 3, 3, 2, 0, 3, 3, 0, 2,
  1 };
inline constexpr std::int64_t HexahedronFaceStream[] = { 6, 4, 0, 4, 7, 3, 4, 1, 2, 6, 5, 4, 0, 1,
  5, 4, 4, 3, 7, 6, 2, 4, 0, 3, 2, 1, 4, 4, 5, 6, 7 };

/**
 * The face stream of `shape`, with corners numbered 0 .. GetNumberOfCorners(shape) - 1 (VTK's
 * face order and corner order, e.g. vtkHexahedron's faces). A 2D shape is one face: the polygon.
 */
const std::int64_t* GetShapeFaceStream(CellShape shape);

/// The number of values of a face stream (1 + for each face, 1 + its corners).
std::int64_t FaceStreamLength(const std::int64_t* faceStream);

/// The points of face `face` of a face stream; `count` gets their number.
const std::int64_t* FaceOfStream(
  const std::int64_t* faceStream, std::int32_t face, std::int64_t& count);

} // namespace dgmf

#endif
