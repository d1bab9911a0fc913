/**
 * @file DecomposedSizeSkew.h
 * @brief The size-skew quality of a cell judged through its faces: polyhedra (OpenFOAM's,
 * snappyHexMesh's), and cells whose corner metric cannot judge them because they are already
 * non-convex or inverted in the input mesh (Documentation/quality.md).
 */
#ifndef dgmf_DecomposedSizeSkew_h
#define dgmf_DecomposedSizeSkew_h

#include "dgmf/SizeSkewQuality.h"

#include <cstdint>

namespace dgmf
{

/**
 * The size-skew of a cell through its face-centre decomposition, relative to the input cell.
 *
 * The cell is cut into tetrahedra (centre of the cell, centre of a face, two consecutive corners
 * of the face; centres are vertex averages), or a polygon (a face stream of one face) into
 * triangles about its centre. Each piece scores f_size * f_shape(deformed) / f_shape(original),
 * at most 1, with Knupp's tetrahedron (triangle) metric: 1 when the deformation did not change
 * it, whatever its shape. The cell scores the minimum over its pieces, and is inverted when a
 * piece is inverted relative to the same piece of the input (a piece keeps the orientation it
 * has in the input, so a non-convex input cell is judged by what the deformation does to it).
 * Pieces of zero size in the input are left out; a cell with no other piece scores 0.
 *
 * @param corners the number of corners of the cell
 * @param original 3 coordinates per corner before the deformation
 * @param deformed 3 coordinates per corner after the deformation
 * @param faceStream the cell's faces, with corners numbered 0 .. corners - 1 (CellFaces.h)
 */
CellQuality ComputeDecomposedSizeSkew(
  int corners, const double* original, const double* deformed, const std::int64_t* faceStream);

/**
 * The size-skew the metric and the quality guard give a cell of a standard shape: Knupp's corner
 * metric (ComputeSizeSkew), or for a cell invalid in the input its face decomposition
 * (ComputeDecomposedSizeSkew), with InputInvalid set. The corner metric finds the invalid input
 * cells itself, at no extra cost.
 */
CellQuality ComputeCellSizeSkew(CellShape shape, const double* original, const double* deformed);

/// The quality of a cell `corner` found invalid in the input: its face decomposition.
CellQuality JudgeInvalidInputCell(CellShape shape, const double* original, const double* deformed);

} // namespace dgmf

#endif
