/**
 * @file DGMFMeshConversion.h
 * @brief VTK meshes as the core reads them: points as doubles, cell types as shapes, cells as a
 * dgmf::CellMesh, the mesh's dimension and hint stride (private to the DGMF::Filters module).
 */
#ifndef DGMFMeshConversion_h
#define DGMFMeshConversion_h

#include "dgmf/CellMesh.h"
#include "dgmf/SizeSkewQuality.h"

#include "vtkSmartPointer.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

class vtkPoints;
class vtkPointSet;
class vtkDataArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// The points as a contiguous array of 3 doubles per point: their own memory when they already
/// are (no copy), otherwise a copy in `copy`.
const double* PointsAsDouble(vtkPoints* points, std::vector<double>& copy);

/**
 * The size-skew shape of a VTK cell type, and the order in which to read its point ids for that
 * shape (pixels and voxels are quads and hexahedra with their corners reordered). False for the
 * types the metric does not cover (polygons, polyhedra, quadratic cells, ...).
 */
bool CellShapeOf(int vtkCellType, dgmf::CellShape& shape, const int*& order);

/// `points` with its cells as an unstructured grid: itself when it is one, else a new grid that
/// shares its points (e.g. the polydata of a boundary patch).
vtkSmartPointer<vtkUnstructuredGrid> AsUnstructuredGrid(vtkPointSet* points);

/**
 * Which VTK cell types `mesh` has (one flag per type value), from one pass over its types array on
 * the threads (vtkUnstructuredGrid::GetDistinctCellTypesArray takes a std::set insertion per
 * cell: 0.5 s for 8 million cells).
 */
std::array<bool, 256> CellTypesPresent(vtkUnstructuredGrid* mesh);

/// The 2D cell types a boundary takes as they are, as polygons: triangles, quads, pixels, polygons.
bool IsPolygonType(int vtkCellType);

/// Which VTK cell types `block` has (CellTypesPresent for a grid; VTK's cell types otherwise).
std::array<bool, 256> CellTypesOf(vtkPointSet* block);

/**
 * The largest dimension of the cell types `types` (CellTypesOf; 0 without cells), and whether
 * they are all polygons (IsPolygonType; true without cells).
 */
int CellDimensionOf(const std::array<bool, 256>& types, bool& polygonsOnly);

/// The cells of `mesh` and of `patches` (may be null) together: a composite input's cells, the
/// patches' (CompositeMesh::GetPatches) numbered after the mesh's.
vtkIdType CellsWithPatches(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches);

/// The ids of the cells whose type is `wanted`, in increasing order (one pass on the threads).
std::vector<vtkIdType> CellsOfTypes(vtkUnstructuredGrid* mesh, const std::array<bool, 256>& wanted);

/**
 * The grid's cells in the corner order of the size-skew metric (the quality guard's input), then
 * those of `patches` (a composite input's boundary patches on the same points) when not null.
 */
dgmf::CellMesh ToCellMesh(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches = nullptr);

/**
 * The cells of `mesh` of its largest cell dimension that the quality guard does not see (no
 * CellShapeOf: polyhedra, polygons) and whose `sizeSkew` is below `threshold` (NaN is not).
 */
vtkIdType CountBadCellsOutsideTheGuard(
  vtkUnstructuredGrid* mesh, vtkDataArray* sizeSkew, double threshold);

/**
 * Adds CountBadCellsOutsideTheGuard of the deformed `output` (its SizeSkew) to its
 * UnrepairedCellCount field, so that the summary does not say "left unrepaired 0" with bad
 * polyhedra left; returns the warning that says how many, or "" for none (nothing changed
 * without the two arrays).
 */
std::string CountUnguardedCellsAsUnrepaired(vtkUnstructuredGrid* output, double threshold);

/// The cells of `mesh` of its largest cell dimension (its volume cells, without the boundary
/// faces or edges a merged composite input may hold).
vtkIdType CountCellsOfLargestDimension(vtkUnstructuredGrid* mesh);

/// How far apart the z of a 2D mesh's points may be, relative to its extent in x and y: the
/// round-off of a transform into a plane z = constant, or of single-precision points.
constexpr double PlanarZTolerance = 1e-6;

/// 2 when the mesh is planar (no 3D cell, all z equal up to PlanarZTolerance), 3 otherwise; -1 for
/// 2D cells off a z plane.
int DetectDimension(vtkUnstructuredGrid* mesh, const double* xyz, std::size_t n);

/// The mesh's hint stride for the node location (dgmf::FindHintStride), from up to 4,096 cells
/// spread over the mesh's cells and then those of `patches` (a composite input's patches on the
/// same points, when not null: the sample of one grid holding both).
std::size_t HintStrideOf(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches = nullptr);

} // namespace dgmf_vtk

#endif
