/**
 * @file DGMFNonOrthogonality.h
 * @brief The face non-orthogonality of a deformed grid as OpenFOAM's checkMesh reports it: the
 * cell array NonOrthogonality and the field data MaximumNonOrthogonality and
 * InputMaximumNonOrthogonality (private to the DGMF::Filters module).
 */
#ifndef DGMFNonOrthogonality_h
#define DGMFNonOrthogonality_h

#include "DGMFContentKey.h"

#include "dgmf/NonOrthogonality.h"
#include "dgmf/ParallelFor.h"

#include <memory>

class vtkDataSetAttributes;
class vtkFieldData;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/**
 * What the non-orthogonality keeps between executions: the internal faces of the last mesh while
 * its cells are unchanged, and the orientation of its cells while its input points are unchanged
 * too (a new motion of the same mesh only measures the deformed points).
 */
class InternalFacesCache
{
public:
  /// The internal faces of `mesh`'s 3D cells (found again when its cells changed).
  const dgmf::InternalFaces& Get(vtkUnstructuredGrid* mesh, const dgmf::ParallelFor& parallelFor);
  /// The orientation of `mesh`'s cells with the points `original` (n points of `mesh`).
  const dgmf::InputOrientation& Orient(
    vtkUnstructuredGrid* mesh, const double* original, const dgmf::ParallelFor& parallelFor);

private:
  ContentKey Cells;
  std::unique_ptr<dgmf::InternalFaces> Faces;
  std::uint64_t OriginalHash = 0;
  std::unique_ptr<dgmf::InputOrientation> Orientation;
};

/**
 * Adds the non-orthogonality of `mesh`'s internal faces between `originalPoints` and
 * `deformedPoints` (3 doubles per point): the cell array NonOrthogonality (degrees, the largest
 * over the cell's internal faces) to `cellData`, and MaximumNonOrthogonality and
 * InputMaximumNonOrthogonality (degrees) to `fieldData`. 3D cells (tetrahedra, hexahedra, voxels,
 * wedges, pyramids, polyhedra) take part; other cells get 0. Returns the maximum.
 */
double AddNonOrthogonality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDataSetAttributes* cellData, vtkFieldData* fieldData,
  InternalFacesCache& cache, const dgmf::ParallelFor& parallelFor);

} // namespace dgmf_vtk

#endif
