/**
 * @file DGMFInputNodes.h
 * @brief The input mesh's nodes as the core reads them: the selected arrays found and checked for
 * shape, the points and displacement as doubles, the node kinds (from the marker, or from the
 * mesh's boundary) and the body ids (private to the DGMF::Filters module). The core checks the
 * values (dgmf::ValidateProblem).
 */
#ifndef DGMFInputNodes_h
#define DGMFInputNodes_h

#include "DGMFBoundaryDetection.h"
#include "DGMFBoundaryNames.h"
#include "DGMFContentKey.h"

#include "dgmf/DeformationProblem.h"
#include "dgmf/ExtrudedLayers.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/NodeKind.h"

#include "vtkType.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkDataArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// Indices of the filter's arrays in SetInputArrayToProcess.
enum InputArrayIndex
{
  DisplacementArrayIndex = 0,
  MarkerArrayIndex = 1,
  BodyIdArrayIndex = 2
};

/// The point arrays the user selected; "" for none (ParaView's "None" also means none).
struct SelectedArrays
{
  std::string Displacement;
  std::string Marker;
  std::string BodyIds;
};

/**
 * The names given to `algorithm` with SetInputArrayToProcess at the InputArrayIndex indices ("":
 * None). With `input`, a selection never made (C++ without SetInputArrayToProcess; ParaView
 * always makes one) is the point array `Displacement` (3 components) or `BoundaryMarker` (1) when
 * the input has it, as the plugin's defaults are.
 */
SelectedArrays GetSelectedArrays(vtkAlgorithm* algorithm, vtkDataObject* input = nullptr);

/// The nodes of the input mesh, with the copies the core needs (the other processes' boundary
/// nodes follow this piece's in a distributed run).
struct InputNodes
{
  std::size_t LocalNodes = 0;    ///< this piece's nodes, the first ones
  std::size_t NumberOfNodes = 0; ///< with the other processes' boundary nodes
  bool Distributed = false;      ///< the other processes' boundary nodes were appended
  int Dimension = 3;
  const double* Points = nullptr;
  std::vector<double> PointCopy; ///< the points as doubles, when they are not already
  const double* Displacement = nullptr;
  std::vector<double> DisplacementCopy; ///< the displacement as doubles, when it is not already
  std::vector<dgmf::NodeKind> Kinds;
  std::vector<std::int32_t> BodyIds; ///< per node, when a body-id array is selected
  std::int32_t NumberOfBodies = 0;   ///< the largest body id
  dgmf::SlipConstraint Slip;         ///< the slip boundaries' nodes and planes
  /// A distributed run's slip nodes of this piece per slip entry, and the entries' names: their
  /// planes are fitted to every piece's nodes once the pieces have met (AgreeOnSlipPlanes).
  std::vector<std::vector<std::int32_t>> SlipGroups;
  std::vector<std::string> SlipNames;
  /// Per slip plane (an index into Slip.Planes) the moving nodes on its blocks, and its name
  /// (serial runs with boundaries by name): MovingNodesOffSlipPlanes checks them after the motion.
  struct MovingOnPlane
  {
    std::int32_t Plane;
    std::vector<std::int32_t> Nodes;
    std::string Name;
  };
  std::vector<MovingOnPlane> MovingOnSlip;
  dgmf::ExtrudedLayers Layers;       ///< the two layers of a one-cell-thick mesh, if it is one
  std::vector<std::string> Warnings; ///< for the user
  /// A composite input's boundary patches on the mesh's points (GatherOptions::Patches), or null.
  vtkUnstructuredGrid* Patches = nullptr;

  /// The nodes as a core problem (one default rigid motion: the caller sets the motions).
  dgmf::DeformationProblem ToProblem() const;
};

/// How a one-cell-thick mesh (two planes of paired nodes, as OpenFOAM's 2D meshes) is deformed.
enum OneCellThickModes
{
  OneCellThickDetect = 0, ///< as the 2D mesh of one layer when the mesh is one (default)
  OneCellThickOff = 1,    ///< always as a 3D mesh
  OneCellThickOn = 2      ///< as a 2D layer; an error when the mesh is not one cell thick
};

/// What Gather uses besides the mesh.
struct GatherOptions
{
  SelectedArrays Arrays;
  int Dimension = 0;                ///< 2 or 3; 0: found from the mesh (2 without 3D cells)
  bool Distributed = false;         ///< one piece of a distributed mesh
  const NodeRoles* Roles = nullptr; ///< node roles from boundary names (then no marker is read)
  int OneCellThick = OneCellThickDetect;
  bool DistinctPoints = false; ///< no two points coincide (a merged composite input)
  /// A composite input's boundary patches, kept apart from the mesh on its points
  /// (CompositeMesh::GetPatches): their polygons are the mesh's 2D cells as well.
  vtkUnstructuredGrid* Patches = nullptr;
};

/**
 * A composite input's boundary patches between executions (CompositeMesh::GetPatches): the
 * ContentKey of their cells, or none. A new merge of the same blocks (a reader's new objects at
 * each time step) matches by content.
 */
class PatchesKey
{
public:
  /// True when `patches` (may be null) have the cells the key was set for (none for none).
  bool Matches(vtkUnstructuredGrid* patches);
  /// Remembers `patches` (may be null).
  void Set(vtkUnstructuredGrid* patches);

private:
  ContentKey Cells;
  bool None = true;
  bool Valid = false;
};

/**
 * Gathers the input nodes of one mesh, and keeps between executions what depends only on
 * unchanged inputs: the node kinds of an unchanged marker array, and the mesh's boundary facets.
 */
class InputGatherer
{
public:
  /**
   * Fills `nodes` from `mesh`. The kinds come from the node roles (boundary names), else the
   * boundary marker, else the mesh's boundary (the nodes of its boundary faces, but for the two
   * planes of a one-cell-thick mesh), moving where the displacement is not zero. Slip nodes (from
   * the roles, or marker value 3: one plane) get their planes. Throws std::invalid_argument, with
   * the message for the user, for an empty mesh, a 2D mesh off a plane z = constant, a selected
   * array that is missing or has the wrong number of components, no array and no name given,
   * array values the core does not allow, and slip boundaries that are not planar. In a
   * distributed run an empty piece is allowed, without a marker the pieces need ghost cells, and
   * one-cell-thick meshes are deformed as 3D meshes.
   */
  void Gather(vtkUnstructuredGrid* mesh, const GatherOptions& options, InputNodes& nodes);

  /// The boundary facets of `mesh` with the polygons of `patches` (may be null; cached while
  /// the cells of both are unchanged).
  const BoundaryFacets& GetBoundaryFacets(
    vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches, int dimension);

  /// Memory kept between executions, in bytes.
  std::size_t GetMemorySize() const;

  /**
   * The work the last Gather left for later, off the critical path: the hash of the cells that
   * keys the closing polygons kept for the next execution (0.06 s of one thread at 8.2M
   * hexahedra). Each job runs on one thread, beside the graph's insertion as a rule, and must run
   * before the next Gather (which drops those not taken). A job not run costs nothing but the
   * next execution with another object of the same cells: the polygons' check again.
   */
  std::vector<std::function<void()>> TakeDeferredJobs();

  /// Whether the last Gather looked for the mesh's boundary faces: without a marker, or for
  /// named boundaries whose patches do not close the mesh (RolesCoverTheBoundary).
  bool SearchedBoundary() const { return this->Searched; }

private:
  void GatherKinds(vtkUnstructuredGrid* mesh, const GatherOptions& options, vtkDataArray* marker,
    InputNodes& nodes);
  void GatherSlipPlanes(const GatherOptions& options, InputNodes& nodes);
  // 1 for the nodes on the mesh's boundary faces (for a one-cell-thick mesh, the faces across
  // its two planes).
  std::vector<std::uint8_t> FlagMeshBoundary(vtkUnstructuredGrid* mesh, const InputNodes& nodes);
  /// The slip nodes on faces of the boundary no block was read for (`unread` nodes) made static.
  void MakeSlipEdgesStatic(
    vtkUnstructuredGrid* mesh, const std::vector<std::uint8_t>& unread, InputNodes& nodes);
  // Whether the mesh's boundary nodes all have a role in `nodes.Kinds` already, known without
  // the boundary: the mesh's polygons (boundary patches) close it and their nodes have roles
  // (but for the two planes of a one-cell-thick mesh, whose nodes need none).
  bool RolesCoverTheBoundary(vtkUnstructuredGrid* mesh, const InputNodes& nodes);
  bool Searched = false; // SearchedBoundary()
  // The kinds of the last marker array (checked once).
  vtkDataArray* Marker = nullptr;
  vtkMTimeType MarkerMTime = 0;
  dgmf::UninitializedVector<dgmf::NodeKind> MarkerKinds; ///< converted on the threads
  // The boundary facets depend on the cells only (and on whether points may coincide).
  bool DistinctPoints = false;
  ContentKey Cells;
  PatchesKey FacetPatches; // the facets' patches
  std::unique_ptr<BoundaryFacets> Facets;
  // Whether the polygons close the mesh (PolygonsCloseTheMesh) depends on the cells only: then
  // the polygons' cell ids (the patches' numbered after the mesh's cells), else none.
  ContentKey ClosingCells;
  PatchesKey ClosingPatches; // the closing polygons' patches
  std::vector<vtkIdType> ClosingPolygons;
  std::vector<std::function<void()>> Deferred; // TakeDeferredJobs()
  // The layers of a one-cell-thick mesh depend on the points only (looking for them takes one
  // pass over the points; a repeated deformation need not pay it).
  ContentKey LayerPoints;
  dgmf::ExtrudedLayers Layers;
};

} // namespace dgmf_vtk

#endif
