/**
 * @file DGMFDistributed.h
 * @brief The collective steps of a distributed run (pvbatch or pvserver under MPI): every process
 * holds a piece of the mesh, and every process builds the same Delaunay graph of all the boundary
 * nodes (private to the DGMF::Filters module).
 */
#ifndef DGMFDistributed_h
#define DGMFDistributed_h

#include "dgmf/SizeSkewQuality.h"

#include <cstddef>

#include <cstdint>
#include <string>
#include <vector>

class vtkFieldData;
class vtkInformation;
class vtkMultiProcessController;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{
struct BoundarySelection;
struct InputNodes;
struct NodeRoles;

/// True when `controller` runs more than one process.
bool IsDistributed(vtkMultiProcessController* controller);

/// The dimension of the whole distributed mesh: 3 if any piece has a 3D cell; 2 if the pieces
/// have only lower-dimensional cells and all their points have one z, up to PlanarZTolerance of
/// the x-y extent (-1 when the z differ more); 0 for no cell at all. `z` receives the smallest z.
/// Collective.
int AgreeOnDimension(vtkMultiProcessController* controller, vtkUnstructuredGrid* piece, double& z);

/// True on every process when `ok` is true on every process. Collective.
bool AllProcessesAgree(vtkMultiProcessController* controller, bool ok);

/**
 * Asks upstream for at least one layer of ghost cells in `inputInformation` (an input's pipeline
 * information), so that the faces between the pieces of a distributed mesh are not taken for its
 * boundary (e.g. from a Ghost Cells Generator).
 */
void RequestOneGhostLevel(vtkInformation* inputInformation);

/**
 * Every process's `send`, in process order (this process's included); `offsets` receives where
 * each process's values start, and their end (processes + 1 entries). Collective.
 */
std::vector<double> AllGatherDoubles(vtkMultiProcessController* controller,
  const std::vector<double>& send, std::vector<std::size_t>& offsets);

/// One boundary node as it travels between processes.
struct RemoteBoundaryNode
{
  double Position[3];
  double Displacement[3];
  std::int32_t Kind;   ///< dgmf::NodeKind
  std::int32_t BodyId; ///< 0 when there is no body-id array
};

/**
 * Sends this process's boundary nodes to every process and returns those of the other processes
 * (in process order). Collective.
 */
std::vector<RemoteBoundaryNode> ExchangeBoundaryNodes(
  vtkMultiProcessController* controller, const std::vector<RemoteBoundaryNode>& local);

/**
 * Boundaries chosen by name on a distributed mesh: "" when every entry of `selection` names a
 * block of some piece (a reader gives the blocks to one process, a redistribution drops the
 * blocks a piece has no cell of), else the error, the same on every process. `roles` is this
 * piece's (AssignRoles with `piece`), null when it has none (an empty piece). Collective.
 */
std::string AgreeOnNamedBoundaries(vtkMultiProcessController* controller,
  const BoundarySelection& selection, const NodeRoles* roles);

/**
 * A one-cell-thick mesh (OpenFOAM's 2D cases) in a distributed run, which deforms it as 3D: the
 * error when every non-empty piece lies on the same two planes (dgmf::FindExtrudedLayers) and no
 * node of any piece is a slip or an interior node (the roles agreed by
 * AppendRemoteBoundaryNodes): the two planes are then static and the mesh would come out frozen.
 * Else "". The same on every process. Collective.
 */
std::string CheckOneCellThickPieces(vtkMultiProcessController* controller, const InputNodes& nodes);

/// What JoinPieces checks and agrees on besides the nodes.
struct JoinOptions
{
  const BoundarySelection* Selection = nullptr; ///< the boundaries chosen by name
  const NodeRoles* Roles = nullptr;             ///< this piece's roles from them, or null
  bool CheckLayers = false;      ///< CheckOneCellThickPieces (OneCellThickMode Detect)
  bool NonOrthogonality = false; ///< warn when the piece has no ghost cells
};

/**
 * The collective steps of a distributed run once every process has gathered its nodes: the
 * names agreed (AgreeOnNamedBoundaries), a one-cell-thick mesh checked, the other pieces'
 * boundary nodes appended (AppendRemoteBoundaryNodes) and the slip planes fitted to all pieces
 * (AgreeOnSlipPlanes). Returns "" or the error, the same on every process; adds to
 * `nodes.Warnings` the non-orthogonality's faces between pieces left out when `piece` has no
 * ghost cells. Collective.
 */
std::string JoinPieces(vtkMultiProcessController* controller, const JoinOptions& options,
  vtkUnstructuredGrid* piece, InputNodes& nodes);

/**
 * Appends the other processes' boundary nodes to `nodes` (this piece's nodes stay first: the
 * graph is then the same on every process), and gives this piece's nodes that look interior but
 * are another piece's boundary nodes (ghost nodes whose boundary face is on a ghost cell) the kind
 * their owner found. Collective.
 */
void AppendRemoteBoundaryNodes(vtkMultiProcessController* controller, InputNodes& nodes);

/**
 * The field data of a distributed result made global: the quality summary (SizeSkewMean,
 * SizeSkewMinimum, InvertedCellCount, InputInvalidCellCount, SizeSkewEvaluatedCells),
 * OutsideNodeCount and, with `nonOrthogonality`, the largest MaximumNonOrthogonality and
 * InputMaximumNonOrthogonality (of the faces inside the pieces) over all processes. `ok` false on
 * any process makes it false on all. Collective.
 */
void ReduceFieldData(
  vtkMultiProcessController* controller, bool& ok, vtkFieldData* fieldData, bool nonOrthogonality);

/**
 * The quality summary over all processes (each process's summary leaves out its ghost cells),
 * and the sum of the outside-node counts; `ok` false on any process makes it false on all.
 * Collective.
 */
void ReduceSummary(vtkMultiProcessController* controller, bool& ok, dgmf::QualitySummary& summary,
  std::size_t& outsideNodes);

} // namespace dgmf_vtk

#endif
