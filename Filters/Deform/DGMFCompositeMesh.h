/**
 * @file DGMFCompositeMesh.h
 * @brief Composite input (multiblock, partitioned dataset collection) as one mesh: the blocks are
 * merged at their shared nodes, deformed together, and scattered back (private to the
 * DGMF::Filters module).
 */
#ifndef DGMFCompositeMesh_h
#define DGMFCompositeMesh_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkCompositeDataSet;
class vtkPointSet;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/**
 * The blocks of a composite dataset as one unstructured grid. Every leaf with explicit points
 * (unstructured grids, polydata such as boundary patches, structured grids) contributes its cells;
 * nodes at exactly the same coordinates, in the same or different blocks, become one node.
 * A 3D mesh's boundary patches (leaves of polygons only: the OpenFOAM, CGNS and Exodus readers'
 * patches, zones' boundaries and side sets) keep their cells in a grid of their own on the same
 * points (GetPatches()), so that the volume's cells need no copy when one leaf has them all on
 * the merged nodes in order (a CFD reader's internal mesh): the merged grid then shares them.
 * The merged grid carries the point arrays `displacementName` and `markerName` when they are not
 * empty (first non-zero value found for each merged node, except the boundary marker, which
 * keeps the largest: a node that moves in any block moves); a block without the array
 * contributes zeros.
 */
class CompositeMesh
{
public:
  CompositeMesh(
    vtkCompositeDataSet* input, const std::string& displacementName, const std::string& markerName);

  /// The merged grid (empty when no leaf has points): every leaf's cells but the patches'.
  vtkUnstructuredGrid* GetMergedMesh() const { return this->Merged; }

  /**
   * The boundary patches' polygons, on the merged grid's points (the same vtkPoints), or null
   * when the cells are all in the merged grid (no 3D cells, no patches, or a lower-dimensional
   * leaf with cells other than polygons, such as lines).
   */
  vtkUnstructuredGrid* GetPatches() const { return this->Patches; }

  /// Whether the merged grid's cells are an input leaf's (shared, not copied).
  bool SharesInputCells() const { return this->SharedCells; }

  /// Whether the merged grid's points are an input leaf's (a leaf with all of them, in order).
  bool SharesInputPoints() const { return this->SharedPoints; }

  /// Number of leaves that were skipped (no explicit points, e.g. image data).
  int GetNumberOfSkippedBlocks() const { return this->Skipped; }

  /**
   * The deformation's result as the composite output: Scatter() with the filters' point arrays
   * (r, f) and cell arrays (SizeSkew, Inverted, InputInvalid, NonOrthogonality: those present),
   * and the input's field data with the result's.
   */
  void ScatterResult(vtkUnstructuredGrid* deformed, vtkUnstructuredGrid* deformedPatches,
    vtkCompositeDataSet* output) const;

  /**
   * Builds the output: `output` gets the structure of the input; every merged leaf becomes a copy
   * of the input leaf (all its arrays) with the deformed points and the merged result's point
   * arrays `pointArrays` and cell arrays `cellArrays` (a patch's from `deformedPatches`, the
   * deformed GetPatches(); may be null without patches); the other leaves are passed as they
   * are. A leaf with all the merged points in the merged order (all its grid's cells) shares the
   * deformed points and point arrays (cell arrays) instead of copying them.
   */
  void Scatter(vtkUnstructuredGrid* deformed, vtkUnstructuredGrid* deformedPatches,
    const std::vector<std::string>& pointArrays, const std::vector<std::string>& cellArrays,
    vtkCompositeDataSet* output) const;

  /// A leaf of the input merged into the grid.
  struct Leaf
  {
    unsigned int FlatIndex; ///< the leaf's flat index in the input
    std::string Name;       ///< its block name (vtkCompositeDataSet::NAME), or ""
    /// Merged node of each of the leaf's points; empty when SameNumbering (point i is node i:
    /// a CFD volume, as a rule, whose identity map would take 8 bytes a node). Read it through
    /// Node().
    std::vector<vtkIdType> NodeOf;
    vtkIdType NumberOfPoints;   ///< the leaf's points
    vtkIdType FirstCell, Cells; ///< the leaf's cells in its grid (merged grid or patches)
    int CellDimension;          ///< largest dimension of its cells (0 without cells)
    bool SameNumbering;         ///< point i is merged node i, for every point
    bool InPatches = false;     ///< its cells are in GetPatches(), not in the merged grid

    /// The merged node of the leaf's point `i`.
    vtkIdType Node(vtkIdType i) const
    {
      return this->SameNumbering ? i : this->NodeOf[static_cast<std::size_t>(i)];
    }
  };

  /// The merged leaves, in the input's order.
  const std::vector<Leaf>& GetLeaves() const { return this->Leaves; }

  /// The input.
  vtkCompositeDataSet* GetInput() const { return this->Input; }

private:
  /// The cells of the leaves `merged` (their indices in Leaves; `types`: each block's cell
  /// types) into `grid`: for the merged grid, shared when one grid leaf has them all on the
  /// merged nodes in order; else copied.
  void SetCells(const std::vector<vtkPointSet*>& blocks,
    const std::vector<std::array<bool, 256>>& types, const std::vector<std::size_t>& merged,
    vtkUnstructuredGrid* grid);

  vtkCompositeDataSet* Input;
  vtkSmartPointer<vtkUnstructuredGrid> Merged;
  vtkSmartPointer<vtkUnstructuredGrid> Patches; // null: every cell in Merged
  std::vector<Leaf> Leaves;
  int Skipped = 0;
  bool SharedPoints = false;
  bool SharedCells = false;
};

} // namespace dgmf_vtk

#endif
