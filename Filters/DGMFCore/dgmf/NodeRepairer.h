/**
 * @file NodeRepairer.h
 * @brief The quality guard's node moves (private to the core: LocalRepair.h is the interface):
 * the free nodes, the cells around them, and the untangling and smoothing steps of one node.
 */
#ifndef dgmf_NodeRepairer_h
#define dgmf_NodeRepairer_h

#include "dgmf/CellGeometry.h"
#include "dgmf/CellMesh.h"
#include "dgmf/LocalRepair.h"
#include "dgmf/Progress.h"
#include "dgmf/RepairTetraForm.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace dgmf
{
namespace repair
{

/// Untangling target beta: this fraction of the original cell's mean corner Jacobian.
constexpr double kUntangleFraction = 0.1;
/// Smallest rise of a node's minimum SizeSkew that counts as an improvement.
constexpr double kMinimumGain = 1e-12;
/// Smallest relative decrease of a node's untangling objective that counts as an improvement.
constexpr double kMinimumRelativeDecrease = 1e-12;
/// Weight exp(-sharpness (q - q_min)) of a cell in the smoothing ascent direction.
constexpr double kSoftMinimumSharpness = 40.0;
/// Finite-difference step of the SizeSkew gradient, relative to the node's mean edge length.
constexpr double kGradientStep = 1e-6;
/// Most untangling steps of one node in one pass.
constexpr int kUntangleStepsPerPass = 4;
/**
 * Nodes whose cells all score at least this times the threshold are not smoothed: they move only
 * once a neighbour's move has brought one of their cells below it (to make room).
 */
constexpr double kComfortFactor = 1.5;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Step lengths, in units of the node's mean edge length.
constexpr double kUntangleSteps[] = { 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625, 0.03125 };
constexpr double kLaplacianFractions[] = { 1.0, 0.5, 0.25, 0.125 };
constexpr double kAscentSteps[] = { 0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625 };
constexpr double kPatternSteps[] = { 0.125, 0.03125 };

/// A cell incident to a free node, with what the node steps need about its original shape.
struct ActiveCell
{
  // What every visit of a node reads about its cells comes first (one cache line).
  CellShape Shape = CellShape::Triangle;
  bool Degenerate = false; ///< degenerate original cell: always 0, ignored
  bool Inverted = false;   ///< currently inverted
  int NumberOfNodes = 0;
  const std::int64_t* Nodes = nullptr; ///< into the mesh connectivity
  double Quality = 0.0;                ///< current SizeSkew
  double Orientation = 1.0;            ///< 3D: sign of the original cell's size
  double OriginalAlpha = 0.0; ///< 3D: the sum of the original corner Jacobians, oriented (> 0)
  double Beta = 0.0;          ///< untangling target of every corner Jacobian
  int FreeNodeCount = 0;      ///< free nodes among its corners
  std::size_t Cell = 0;
  ShapeTables Tables{ nullptr, 0, nullptr, 0, 0 };
  Vec3 Normal0{ 0.0, 0.0, 0.0 };             ///< 2D: unit normal of the original cell
  double Original[3 * kMaximumCorners] = {}; ///< original corner coordinates
};

/// A node the repair may move.
struct FreeNode
{
  std::int64_t Id = 0;
  std::size_t CellBegin = 0; ///< its cells are Incident[CellBegin, CellEnd)
  std::size_t CellEnd = 0;
  /// The other ends of its edges, once per cell edge (an edge of k cells k times, in the order of
  /// its cells and their edges): EdgeEnds[EdgeBegin, EdgeEnd). Filled by NodeRepairer::Run.
  std::size_t EdgeBegin = 0;
  std::size_t EdgeEnd = 0;
  int Dimension = 3; ///< 2: moves in Basis[0], Basis[1]; 3: in all directions
  Vec3 Basis[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  Vec3 Normal{ 0.0, 0.0, 0.0 }; ///< 2D: unit normal of the plane of its cells
  bool Enabled = true;
};

/// Cell `cell`'s corners in `points`, written to out (3 per corner).
inline void GatherCorners(const CellMesh& mesh, std::size_t cell, const double* points, double* out)
{
  const std::int64_t begin = mesh.Offsets[cell];
  const std::int64_t count = mesh.Offsets[cell + 1] - begin;
  for (std::int64_t k = 0; k < count; ++k)
  {
    const std::int64_t node = mesh.Connectivity[static_cast<std::size_t>(begin + k)];
    out[3 * k] = points[3 * node];
    out[3 * k + 1] = points[3 * node + 1];
    out[3 * k + 2] = points[3 * node + 2];
  }
}

inline bool IsCovered(const CellMesh& mesh, std::size_t cell)
{
  return mesh.Covered.empty() || mesh.Covered[cell] != 0;
}

/// Newell normal (twice the vector area) of a triangle or quad given by its corners.
Vec3 PolygonNormal(CellShape shape, const double* corners);

/**
 * Runs the node steps over the free region (RepairCells builds the region: Cells, Incident and
 * Nodes). The untangling and smoothing steps are in RepairMoves.cxx, the rest in NodeRepairer.cxx.
 */
class NodeRepairer
{
public:
  NodeRepairer(const CellMesh& mesh, const double* originalPoints, double* points,
    const std::vector<std::int64_t>& freeIndex);

  std::vector<ActiveCell> Cells;
  std::vector<std::size_t> Incident; ///< active-cell indices, grouped by free node
  std::vector<FreeNode> Nodes;
  std::vector<std::int64_t> EdgeEnds; ///< see FreeNode::EdgeBegin
  /// Per entry of Incident: the node's corner in that cell if it is a non-degenerate tetrahedron
  /// with the node once (judged through a TetraForm), else -1. Filled by Run.
  std::vector<std::int8_t> TetraCorner;
  /// What a visit reads to build a TetraForm, per entry of Incident with a TetraCorner (filled
  /// with it; the others are not read): the cell's other corners in their order, and the
  /// original orientation and Jacobian. A node's entries lie together, where the cells' records
  /// and connectivity are scattered.
  struct TetraIncidence
  {
    std::int64_t Others[3];
    double Orientation;
    double OriginalAlpha;
  };
  std::vector<TetraIncidence> TetraIncidences;
  /// Per free node: it has cells, and every one has a TetraCorner (a non-degenerate tetrahedron
  /// with the node once), so its cells' other corners are exactly its edge ends.
  std::vector<std::uint8_t> OnlyTetrahedra;
  /// Fills the original-shape data and the current quality of an active cell.
  void InitializeCell(ActiveCell& cell, std::size_t c, double quality, bool inverted) const;
  /**
   * Runs at most `maximumPasses` passes; returns the number run. With `giveUp`, stops when the
   * passes left cannot remove the bad cells (RepairParameters::GiveUpWhenHopeless) and sets
   * `gaveUp`.
   */
  std::size_t Run(int maximumPasses, double threshold, const Progress& progress = Progress(),
    bool giveUp = false, bool* gaveUp = nullptr);

private:
  const CellMesh& Mesh;
  const double* OriginalPoints;
  double* Points;
  const std::vector<std::int64_t>& FreeIndex; ///< index in Nodes of each mesh node, or -1
  /// Per free node: its neighbourhood changed since its last step (a step of a node whose
  /// neighbourhood did not change would fail again, so skipping it does not change the result).
  std::vector<std::uint8_t> Dirty;
  double Threshold = 0.0;
  // Scratch buffers, reused by every node step.
  std::vector<double> Margins0;
  std::vector<double> Targets0;
  std::vector<double> Margins;
  std::vector<Vec3> CornerGradients;
  std::vector<double> Qualities0;
  std::vector<Vec3> QualityGradients;
  std::vector<Vec3> Directions;
  /// AddLatticeDirections' 26 directions in the standard basis (3D nodes), once made.
  std::vector<Vec3> StandardLattice;
  /// The tetrahedra of the node being smoothed (SmoothNode), by offset in its incident cells;
  /// FormsNode is that node's id (-1: none).
  std::vector<TetraForm> Forms;
  std::int64_t FormsNode = -1;
  /// Fills Forms for `node` from the current positions of its cells' other corners.
  void PrepareForms(const FreeNode& node);
  /// Forms in groups of four (StoreFormInGroup), starting at offset FormGroupsFirst of the node's
  /// cells and wrapping around, as TrialMinimumCube visits them; ready only when every cell of
  /// FormsNode has a usable form.
  std::vector<double> FormGroups;
  std::size_t FormGroupsFirst = 0;
  bool FormGroupsReady = false;
  /// Accept's values of the node's cells at the new position, in the order of FormGroups.
  std::vector<CellQuality> AcceptedQualities;
  /// Fills FormGroups from Forms, starting at offset `first` (nothing when a cell has no form).
  void PrepareFormGroups(const FreeNode& node, std::size_t first);
  static double Alpha3(const CornerEdges& corner, const double* corners);
  /// The cell's deformed corners with `node` at `position`.
  void GatherWith(
    const ActiveCell& cell, std::int64_t node, const Vec3& position, double* out) const;
  std::size_t CountRepairableBadCells(double threshold) const;
  /// Fills EdgeEnds and each node's EdgeBegin, EdgeEnd from its cells' edge tables.
  void CollectEdgeEnds();
  /// Fills TetraCorner, TetraIncidences and OnlyTetrahedra.
  void CollectTetraCorners();
  /// SizeSkew of the node's cell at `offset` (in its cells) with the node at `position`: from
  /// its TetraForm when the forms are this node's and it has one, else in full.
  CellQuality QualityAt(const FreeNode& node, std::size_t offset, const Vec3& position) const;
  /// SizeSkew of each of the node's cells with the node at `position`, to `qualities` (by
  /// offset in its cells; degenerate cells are not written): the forward differences of the
  /// gradients of cells without a TetraForm.
  void IncidentQualities(const FreeNode& node, const Vec3& position, double* qualities) const;
  /**
   * The cube of the minimum SizeSkew over the node's cells with the node at `position` (its
   * tetrahedra through Forms, prepared for this node), stopping once a cell's cube is at or
   * below `cutoffCube` (the caller rejects such a point anyway: at that cell, or at the end of its
   * group of four when FormGroups are ready), starting with the cell at offset `first`.
   * `inverted` tells if a cell evaluated is inverted.
   */
  double TrialMinimumCube(const FreeNode& node, const Vec3& position, bool& inverted,
    double cutoffCube, std::size_t first) const;
  /**
   * alpha_k - beta for every corner of the node's cells with the node at `position`, appended to
   * `margins` in a fixed order (and beta to `targets`). Returns Knupp's objective
   * sum_k max(0, beta - alpha_k), half of sum_k |alpha_k - beta| - (alpha_k - beta), or infinity
   * if a Jacobian is not finite. Without `margins`, stops as soon as the objective reaches
   * `cutoff`.
   */
  double CornerMargins(const FreeNode& node, const Vec3& position, std::vector<double>* margins,
    std::vector<double>* targets = nullptr, double cutoff = kInfinity) const;
  /**
   * The mean of the node's edge neighbours (Laplacian position) and the mean edge length. The
   * mean is taken relative to the first neighbour, so that a coordinate all neighbours share (z
   * in a 2D mesh) is reproduced exactly.
   */
  void Neighbourhood(const FreeNode& node, const Vec3& x, Vec3& laplacian, double& length) const;
  /// `v` restricted to the node's plane (2D), or `v` (3D). Inline, as AddDirection: called per
  /// cell and per direction of a visit, a call returned its vector through memory.
  static Vec3 InPlane(const FreeNode& node, const Vec3& v)
  {
    if (node.Dimension == 3)
    {
      return v;
    }
    return Dot(v, node.Basis[0]) * node.Basis[0] + Dot(v, node.Basis[1]) * node.Basis[1];
  }
  /// Adds the unit vector along `v` to Directions (nothing for a zero or non-finite `v`).
  void AddDirection(const Vec3& v)
  {
    const double length = Norm(v);
    if (length > 0.0 && std::isfinite(length))
    {
      this->Directions.push_back((1.0 / length) * v);
    }
  }
  /// Adds the 26 (3D) or 8 (2D) directions to the neighbours of a cubic (square) lattice.
  void AddLatticeDirections(const FreeNode& node);
  /// Moves the node to `position` and refreshes the cached quality of its cells.
  void Accept(FreeNode& node, const Vec3& position);
  /// One untangling or smoothing step of a node; true if it moved.
  bool StepNode(FreeNode& node);
  /**
   * Knupp's untangling: decreases sum_k max(0, beta - alpha_k) over the corners of the node's
   * cells. Every alpha_k is an affine function of the node's position, so the objective is convex
   * and piecewise linear; its gradients are exact finite differences. A pattern search tries steps
   * of 2 to 1/32 edge lengths along the descent direction, each violated corner's own ascent
   * direction, a descent that includes the nearly violated corners, the Laplacian direction and
   * the 26 (2D: 8) lattice directions, and keeps the best point.
   */
  bool UntangleNode(FreeNode& node);
  /**
   * Max-min smoothing: the best of the points on the segment toward the Laplacian position and
   * of steps along the ascent direction of a soft minimum of the cells' SizeSkew (and of the worst
   * cell's own), or if none of them improves, of short steps along the lattice directions;
   * accepted only if no cell is inverted there and the minimum rises.
   */
  bool SmoothNode(FreeNode& node, double minimum0);
};

} // namespace repair
} // namespace dgmf

#endif
