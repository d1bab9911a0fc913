/**
 * @file DGMFCoreDeformation.h
 * @brief Step 3 of vtkDGMFDeformFilter: the deformation of the gathered nodes through the core's
 * method interface, with what the method needs (graph, cells, boundary weights) and the caches
 * kept between executions (private to the DGMF::Filters module).
 */
#ifndef DGMFCoreDeformation_h
#define DGMFCoreDeformation_h

#include "DGMFBoundaryNames.h"
#include "DGMFCompositeMeshCache.h"
#include "DGMFHexReferenceCache.h"
#include "DGMFInputNodes.h"
#include "DGMFMappingCache.h"
#include "DGMFNonOrthogonality.h"
#include "DGMFOutputBuffers.h"

#include "dgmf/DeformationMethod.h"
#include "dgmf/ParallelFor.h"

#include "vtkSmartPointer.h"

#include <functional>

class vtkDoubleArray;
class vtkPoints;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{
class CompositeMesh;

/// What the filter keeps between executions.
struct DeformationCaches
{
  InputGatherer Inputs;                    ///< marker kinds, boundary facets
  MappingCache Mapping;                    ///< the graph and the node locations
  FieldArrays Fields;                      ///< r and f, kept between motions
  vtkSmartPointer<vtkPoints> OutputPoints; ///< the last output's points, reused
  InternalFacesCache Faces;                ///< for the non-orthogonality
  HexReferenceCache HexReferences;         ///< the hexahedra's original half of the quality
  QualityArrays Quality;                   ///< the quality's arrays, reused
  QualityArrays PatchQuality;              ///< those of a composite input's patches
  CompositeMeshCache Composite;            ///< a composite input's merged grid
  /// The node roles of the named boundaries, while the merge and the selection are unchanged.
  struct
  {
    std::uint64_t Generation = 0;
    BoundarySelection Selection;
    bool FindLayers = false;
    bool Valid = false;
    NodeRoles Roles;
  } Roles;
};

/**
 * Step 2 of vtkDGMFDeformFilter: checks that the deformation fits in memory, gives the nodes the
 * roles of the boundaries named in `boundaries` (if any; `composite` is then the input's blocks
 * and `input` their merged grid, with the planes of a one-cell-thick mesh looked for when
 * `findLayers` is on; kept in `caches` while the merge and the selection are unchanged) and
 * gathers `nodes` with `options` (whose Roles then point into `caches`).
 * Returns the error, empty on success; nothing is thrown.
 */
std::string GatherInputNodes(vtkUnstructuredGrid* input, const CompositeMesh* composite,
  const BoundarySelection& boundaries, bool findLayers, GatherOptions& options,
  DeformationCaches& caches, InputNodes& nodes);

/// The outcome of DeformThroughCore.
struct CoreDeformation
{
  dgmf::DeformationReport Report;
  dgmf::MethodNeeds Needs;
  bool GraphReused = false;
  double GraphSeconds = 0.0;            ///< graphs built (0 when the cached one was used)
  double LocationSeconds = 0.0;         ///< their node location
  double DeformationSeconds = 0.0;      ///< the method's deformation
  vtkSmartPointer<vtkDoubleArray> R, F; ///< r and f for the output (one value per node), if written
};

/**
 * Deforms `problem` (the gathered `nodes` with their motions) with `method`, writing 3 coordinates
 * per node into `deformed`. The method's graph is the cached one while the nodes' points and kinds
 * are unchanged; a one-cell-thick mesh (nodes.Layers) is deformed as the 2D mesh of its first
 * layer, whose in-plane motion both layers take. `progress` is told 0.5 once the graph is built
 * and the nodes located, then how far sub-steps and the quality guard are; its callback may stop
 * the run (dgmf::Aborted). Throws std::invalid_argument for what the method needs
 * but a distributed run cannot give (cells), and as the core does.
 */
CoreDeformation DeformThroughCore(const dgmf::DeformationMethod& method,
  const dgmf::DeformationProblem& problem, const InputNodes& nodes, vtkUnstructuredGrid* mesh,
  bool distributed, DeformationCaches& caches, vtkDoubleArray* deformed,
  const dgmf::ParallelFor& parallelFor, const dgmf::Progress& progress);

} // namespace dgmf_vtk

#endif
