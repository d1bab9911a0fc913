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
