/**
 * @file DGMFCompositeMeshCache.h
 * @brief The merged grid of a composite input kept between executions while the input's blocks
 * are unchanged (private to the DGMF::Filters module).
 */
#ifndef DGMFCompositeMeshCache_h
#define DGMFCompositeMeshCache_h

#include "DGMFCompositeMesh.h"

#include "vtkType.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkCompositeDataSet;

namespace dgmf_vtk
{

/**
 * Merging a composite input hashes every point and copies every cell; a new motion of the same
 * input (ParaView's animation, a pvpython loop) need not pay it again. The merge is kept while the
 * input object, its leaves (object, MTime, flat index, name) and the selected array names are the
 * same: a leaf's MTime covers its points, cells and arrays, so a leaf changed in place is seen.
 * The kept merged grid is the same object from one execution to the next, so the caches keyed on
 * it (boundary facets, node kinds, the graph) match it by identity, without hashing.
 */
class CompositeMeshCache
{
public:
  /**
   * The merged mesh of `input` with the point arrays `displacementName` and `markerName`: the kept
   * one when nothing changed, else a new merge.
   */
  const CompositeMesh& Get(
    vtkCompositeDataSet* input, const std::string& displacementName, const std::string& markerName);

  /// True when the last Get() returned the kept merge.
  bool WasReused() const { return this->Reused; }

  /// True when the last Get() found a leaf of the kept input changed in place (the same object,
  /// a new MTime): the new merge may share that leaf's arrays, whose own MTimes need not have
  /// changed (DistrustedObjects).
  bool FoundLeafChangedInPlace() const { return this->LeafChangedInPlace; }

  /// Counts the merges made: what is derived from a merge is valid while this is unchanged.
  std::uint64_t GetGeneration() const { return this->Generation; }

  /// Memory held by the merged grid, in bytes.
  std::size_t GetMemorySize() const;

private:
  /// What identifies a leaf's content.
  struct LeafKey
  {
    unsigned int FlatIndex;
    const void* Object;
    vtkMTimeType MTime;
    std::string Name;
    bool operator==(const LeafKey& other) const
    {
      return this->FlatIndex == other.FlatIndex && this->Object == other.Object &&
        this->MTime == other.MTime && this->Name == other.Name;
    }
  };
  static std::vector<LeafKey> KeyOf(vtkCompositeDataSet* input);

  const void* Input = nullptr;
  std::vector<LeafKey> Leaves;
  std::string Displacement, Marker;
  std::unique_ptr<CompositeMesh> Mesh;
  bool Reused = false;
  bool LeafChangedInPlace = false;
  std::uint64_t Generation = 0;
};

} // namespace dgmf_vtk

#endif
