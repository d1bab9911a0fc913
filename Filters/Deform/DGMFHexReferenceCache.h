/**
 * @file DGMFHexReferenceCache.h
 * @brief The original half of the hexahedra's size-skew quality, kept between motions of the same
 * mesh (private to the DGMF::Filters module).
 */
#ifndef DGMFHexReferenceCache_h
#define DGMFHexReferenceCache_h

#include "DGMFContentKey.h"

#include <cstddef>
#include <memory>

class vtkDataArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// Where ComputeCellQuality finds, or leaves, the hexahedra's reference sizes.
struct HexReferences
{
  /// One value per cell, meaningful for the hexahedra (dgmf::ComputeHexReferenceSize); null:
  /// none kept, each quality computes them again.
  double* Sizes = nullptr;
  /// True: Sizes holds the values of this mesh and these original points. False: the quality
  /// writes them there (every hexahedron's) as it goes.
  bool Known = false;
};

/**
 * The reference sizes of a mesh's hexahedra (the signed sums of their original corner Jacobians),
 * kept while the mesh's cells and original points are the same objects, unmodified (their MTime),
 * so that a new motion computes only the deformed half of the metric. Other objects, even with
 * the same content, compute them again: that costs about what hashing the content would. 8 bytes
 * per cell, taken only when at least half the cells are hexahedra (a tetrahedral mesh has several
 * cells per node, and its cells' original half is cheap): otherwise nothing is kept.
 */
class HexReferenceCache
{
public:
  /**
   * The sizes for `mesh`, whose original points are the values of `originalPoints`: Known when
   * the cells and the points have the content of the last call. When not Known and not null, the
   * caller must fill every hexahedron's size before the next call.
   */
  HexReferences For(vtkUnstructuredGrid* mesh, vtkDataArray* originalPoints);
  /// Bytes kept.
  std::size_t GetMemorySize() const { return this->Sizes ? this->Count * sizeof(double) : 0; }

private:
  ContentKey Cells, Points;
  std::unique_ptr<double[]> Sizes; ///< one per cell (the non-hexahedra's not meaningful)
  std::size_t Count = 0;
};

} // namespace dgmf_vtk

#endif
