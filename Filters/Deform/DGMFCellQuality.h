/**
 * @file DGMFCellQuality.h
 * @brief Per-cell SizeSkew of a deformed grid against its original points
 * (private to the DGMF::Filters module).
 */
#ifndef DGMFCellQuality_h
#define DGMFCellQuality_h

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
 * (dgmf::ComputeDecomposedSizeSkew).
 */
dgmf::QualitySummary ComputeCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDoubleArray* sizeSkew, vtkUnsignedCharArray* inverted,
  vtkUnsignedCharArray* inputInvalid, const dgmf::ParallelFor& parallelFor);

} // namespace dgmf_vtk

#endif
