/**
 * @file DGMFCellQuality.h
 * @brief Per-cell SizeSkew of a deformed grid against its original points
 * (private to the DGMF::Filters module).
 */
#ifndef DGMFCellQuality_h
#define DGMFCellQuality_h

#include "DGMFHexReferenceCache.h"

#include "dgmf/ParallelFor.h"
#include "dgmf/SizeSkewQuality.h"

#include <vector>

class vtkDoubleArray;
class vtkPoints;
class vtkUnsignedCharArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/**
 * Fills `sizeSkew` (one value per cell, NaN for cell types the metric does not cover),
 * `inverted` (1 for a cell the deformation inverted) and `inputInvalid` (1 for a cell already
 * non-convex, inverted or degenerate in the input) and returns the summary, which leaves out the
 * ghost cells (vtkGhostType DUPLICATECELL: another process counts them). `mesh` gives the
 * connectivity; `originalPoints` and `deformedPoints` hold 3 doubles per point. Triangles, quads,
 * pixels, tetrahedra, hexahedra, voxels, wedges and pyramids get the corner metric; polyhedra,
 * polygons and cells invalid in the input are judged through their faces
 * (dgmf::ComputeDecomposedSizeSkew). Hexahedra are evaluated four at a time, from the reference
 * sizes in `references` when they are known there (the original points are then read only for a
 * cell invalid in the input), and otherwise from the original points, leaving their reference
 * sizes in `references.Sizes` when it is not null.
 */
dgmf::QualitySummary ComputeCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDoubleArray* sizeSkew, vtkUnsignedCharArray* inverted,
  vtkUnsignedCharArray* inputInvalid, const HexReferences& references,
  const dgmf::ParallelFor& parallelFor);

} // namespace dgmf_vtk

#endif
