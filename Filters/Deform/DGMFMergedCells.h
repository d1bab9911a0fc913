/**
 * @file DGMFMergedCells.h
 * @brief The merged grid's cells of a composite input: every block's cells, their points
 * renumbered, in VTK arrays sized once (private to the DGMF::Filters module).
 */
#ifndef DGMFMergedCells_h
#define DGMFMergedCells_h

#include "DGMFCompositeMesh.h"

#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkType.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <vector>

class vtkPointSet;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// The number of cells of `block` and of point ids in their connectivity.
void CountCells(vtkPointSet* block, vtkIdType& cells, vtkIdType& ids);

/**
 * Checks that the faces of every polyhedron of `grid` (VTK's face locations and faces arrays, both
 * present) lie within its faces array: std::runtime_error naming the first cell whose faces run
 * past its end (a broken writer's arrays are read in place, never past them).
 */
void CheckPolyhedronFaces(vtkUnstructuredGrid* grid);

/**
 * The merged grid's cells, written into VTK arrays sized once for all the blocks (no copy when
 * they are handed to the grid); a grid is copied array by array, on the vtkSMPTools threads (its
 * polyhedra's faces polyhedron by polyhedron).
 */
class MergedCells
{
public:
  /// Room for `cells` cells of `ids` point ids in all (CountCells over the blocks).
  MergedCells(vtkIdType cells, vtkIdType ids);

  /// Appends the cells of `block` (whose cell types are `types`: CellTypesOf), their points
  /// renumbered to the merged nodes of `leaf` (CompositeMesh::Leaf::Node).
  void Append(
    vtkPointSet* block, const CompositeMesh::Leaf& leaf, const std::array<bool, 256>& types);

  /// Gives `grid` the cells.
  void SetOn(vtkUnstructuredGrid* grid);

  vtkIdType NumberOfCells = 0;
  vtkIdType NumberOfIds = 0;

private:
  /// A grid: its types, offsets and connectivity array by array, and its polyhedra's faces
  /// (VTK's face locations and faces arrays) polyhedron by polyhedron.
  void AppendGrid(vtkUnstructuredGrid* grid, const CompositeMesh::Leaf& leaf,
    const std::array<bool, 256>& present);
  /// The faces of the grid's polyhedra, renumbered; std::runtime_error when a polyhedron's faces
  /// run past the faces array (CheckPolyhedronFaces).
  void AppendPolyhedronFaces(vtkUnstructuredGrid* grid, const CompositeMesh::Leaf& leaf);
  void AppendCellByCell(vtkPointSet* block, const CompositeMesh::Leaf& leaf);

  vtkNew<vtkUnsignedCharArray> Types;
  vtkNew<vtkIdTypeArray> Offsets;
  vtkNew<vtkIdTypeArray> Connectivity;
  std::vector<vtkIdType> FaceLocations; // polyhedra: -1, or where the cell's faces start
  std::vector<vtkIdType> Faces;         // polyhedra: nfaces, then (count, ids...) per face
};

} // namespace dgmf_vtk

#endif
