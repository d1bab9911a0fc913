/**
 * @file DGMFOutputArrays.h
 * @brief The arrays and field data the filters add to their output, under the names of
 * dgmf/ResultNames.h: one place for vtkDGMFDeformFilter and vtkSizeSkewQualityFilter (private to
 * the DGMF::Filters module).
 */
#ifndef DGMFOutputArrays_h
#define DGMFOutputArrays_h

#include "dgmf/DeformationMethod.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/SizeSkewQuality.h"

#include <cstddef>

class vtkDataSetAttributes;
class vtkDoubleArray;
class vtkFieldData;
class vtkPoints;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{
class InternalFacesCache;
struct HexReferences;
struct QualityArrays;

/// Adds a one-tuple vtkIdTypeArray `name` with `value` to `fieldData` (replacing one of that name).
void AddFieldCount(vtkFieldData* fieldData, const char* name, std::size_t value);

/// Adds a one-tuple vtkDoubleArray `name` with `value` to `fieldData`.
void AddFieldValue(vtkFieldData* fieldData, const char* name, double value);

/// Adds a one-value vtkStringArray `name` with `value` to `fieldData`.
void AddFieldString(vtkFieldData* fieldData, const char* name, const char* value);

/// The value of the first tuple of the field-data array `name` (0 when it is missing or empty).
double GetFieldValue(vtkFieldData* fieldData, const char* name);

/// Adds every value of a method's report to `fieldData` (counts as vtkIdTypeArray, values as
/// vtkDoubleArray, one tuple per body for per-body values).
void AddReport(vtkFieldData* fieldData, const dgmf::DeformationReport& report);

/**
 * The deformed grid: `output` gets `input`'s cells and point, cell and field arrays, and
 * `deformedPoints` (double coordinates), cut to their first `localNodes` (a distributed run also
 * deformed the other pieces' boundary nodes).
 */
void SetDeformedGrid(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output,
  vtkPoints* deformedPoints, std::size_t localNodes);

/**
 * A method's results on `output`: the point arrays `r` and `f` when not null (their first
 * `localNodes` values: a distributed run also deformed the other pieces' boundary nodes), the
 * values of `report`, GraphReused (when the method used the graph) and the Method name.
 */
void AddMethodResults(vtkUnstructuredGrid* output, vtkDoubleArray* r, vtkDoubleArray* f,
  const dgmf::DeformationReport& report, bool usedGraph, bool graphReused, const char* methodName,
  std::size_t localNodes);

/**
 * The size-skew quality of `mesh`'s cells between `originalPoints` and `deformedPoints` (3 doubles
 * per point): the cell arrays SizeSkew, Inverted and InputInvalid into `cellData`, and the summary
 * (SizeSkewMean, SizeSkewMinimum, InvertedCellCount, InputInvalidCellCount,
 * SizeSkewEvaluatedCells) into `fieldData`.
 * Returns the summary. The hexahedra's reference sizes are read from, or left in, `references`
 * (ComputeCellQuality). With `kept`, the arrays are the last execution's when nobody else holds
 * them (QualityArrays).
 */
dgmf::QualitySummary AddCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDataSetAttributes* cellData, vtkFieldData* fieldData,
  const HexReferences& references, const dgmf::ParallelFor& parallelFor,
  QualityArrays* kept = nullptr);

/**
 * The quality outputs a filter's options ask for, on `output` (the deformed `mesh`): SizeSkew,
 * Inverted, InputInvalid and their summary when `sizeSkew` (AddCellQuality), and the face
 * non-orthogonality when `faces` is not null (AddNonOrthogonality, with those cached faces).
 * The hexahedra's reference sizes come from `references` (ComputeCellQuality).
 * Returns the summary (empty without `sizeSkew`).
 */
dgmf::QualitySummary AddOutputQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkUnstructuredGrid* output, bool sizeSkew,
  const HexReferences& references, InternalFacesCache* faces, const dgmf::ParallelFor& parallelFor,
  QualityArrays* kept = nullptr);

/// Writes `summary` into `fieldData` (SizeSkewMean, SizeSkewMinimum, InvertedCellCount,
/// SizeSkewEvaluatedCells), replacing the arrays of those names.
void SetQualitySummary(vtkFieldData* fieldData, const dgmf::QualitySummary& summary);

} // namespace dgmf_vtk

#endif
