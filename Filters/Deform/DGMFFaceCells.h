/**
 * @file DGMFFaceCells.h
 * @brief The faces of a vtkUnstructuredGrid's 3D cells as the core's face matching reads them
 * (private to the DGMF::Filters module).
 */
#ifndef DGMFFaceCells_h
#define DGMFFaceCells_h

#include "dgmf/FaceMatching.h"

#include "vtkType.h"

#include <array>
#include <cstdint>
#include <vector>

class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/**
 * The faces of a grid's 3D cells in VTK's face order: tetrahedra, hexahedra, voxels, wedges,
 * pyramids (their corners) and polyhedra (their face streams); other cells have no faces here.
 * With `canonical` (one id per point), every point id is replaced by canonical[id] (coincident
 * points taken as one).
 */
class VTKFaceCells : public dgmf::FaceCells
{
public:
  explicit VTKFaceCells(
    vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>* canonical = nullptr);

  std::size_t GetNumberOfCells() const override;
  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override;
  const std::int64_t* GetCornerFaces(
    std::size_t cell, std::vector<std::int64_t>& corners) const override;
  /// Runs of cells of one standard shape in 64-bit storage, with exactly its corners, in VTK's
  /// corner order and without canonical ids (hexahedra, tetrahedra, wedges, pyramids, prisms).
  const std::int64_t* GetCornerRun(std::size_t cell, std::size_t maxCells, const void*& ids,
    std::size_t& count, int& cornersPerCell) const override;

  /**
   * Whether every 3D cell type of `types` (CellTypesPresent) has its faces here, i.e. no 3D cell
   * other than the linear shapes and polyhedra (quadratic and Lagrange cells have mid-edge nodes
   * on their faces).
   */
  static bool CoversAll3DCells(const std::array<bool, 256>& types);

private:
  vtkUnstructuredGrid* Mesh;
  const unsigned char* Types; ///< the cells' types (no virtual call per cell)
  const std::vector<vtkIdType>* Canonical;
  /// The cells' offsets and connectivity when VTK stores them in 64 bits (no dispatch per cell).
  const vtkTypeInt64* Offsets64 = nullptr;
  const vtkTypeInt64* Connectivity64 = nullptr;
  /// Per cell type: a standard 3D shape (its corner order and face stream), or none.
  struct ShapeOfType
  {
    const int* Order = nullptr;
    const std::int64_t* Faces = nullptr; ///< null: not a standard 3D shape
    int Corners = 0;
    bool InOrder = false; ///< the corners are VTK's points in their order (not pixel, voxel)
  };
  std::array<ShapeOfType, 256> Shapes;
};

} // namespace dgmf_vtk

#endif
