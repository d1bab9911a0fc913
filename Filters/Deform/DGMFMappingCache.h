/**
 * @file DGMFMappingCache.h
 * @brief The Delaunay mapping kept between executions while the mesh's points, node kinds and
 * dimension are unchanged (private to the DGMF::Filters module).
 */
#ifndef DGMFMappingCache_h
#define DGMFMappingCache_h

#include "DGMFContentKey.h"

#include "dgmf/DeformationProblem.h"
#include "dgmf/DelaunayMapping.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDoubleArray;

namespace dgmf_vtk
{

/// The graph of the boundary nodes and the location of every node, for the last mesh.
class MappingCache
{
public:
  /**
   * True when the cached mapping is that of `problem`'s points, kinds, slip boundaries and
   * dimension (the identity and MTime of `pointsArray`, or else a hash of the points, tell).
   */
  bool Matches(const dgmf::DeformationProblem& problem, vtkDataArray* pointsArray);

  /**
   * Builds the mapping of `problem`'s nodes, located with `hintStride`; the `alongside` jobs run
   * beside the graph's insertion (dgmf::DelaunayGraph::SideJobs), with the hash of the points for
   * the cache's key. Throws as dgmf::DelaunayMapping.
   */
  const dgmf::DelaunayMapping& Build(const dgmf::DeformationProblem& problem,
    vtkDataArray* pointsArray, std::size_t hintStride,
    const dgmf::DelaunayGraph::SideJobs& alongside, const dgmf::ParallelFor& parallelFor);

  /**
   * The mapping of `problem`: Matches() or Build(), with the hint stride `hintStride()` (asked
   * only for a build: it samples the cells). Before a build, `beforeBuild` runs (on this
   * thread) and returns arrays whose memory is then zeroed, in parts, beside the graph's
   * insertion (first touches of output arrays, off the critical path), and so do the
   * `alongside` jobs (run here, in order, when the mapping is reused). `reused` tells which;
   * `warnings` gets what the new graph found (static nodes on moving ones, nodes outside the
   * graph).
   */
  const dgmf::DelaunayMapping& Update(const dgmf::DeformationProblem& problem,
    vtkDataArray* pointsArray, const std::function<std::size_t()>& hintStride,
    const std::function<std::vector<vtkDoubleArray*>()>& beforeBuild,
    const dgmf::DelaunayGraph::SideJobs& alongside, const dgmf::ParallelFor& parallelFor,
    bool& reused, std::vector<std::string>& warnings);

  /// The current mapping, or null.
  const dgmf::DelaunayMapping* Get() const { return this->Mapping.get(); }

  /// Memory used by the mapping, in bytes.
  std::size_t GetMemorySize() const;

private:
  ContentKey Points;
  int Dimension = 0;
  dgmf::SlipConstraint Slip; ///< the slip boundaries the mapping located its slip nodes with
  std::unique_ptr<dgmf::DelaunayMapping> Mapping;
};

} // namespace dgmf_vtk

#endif
