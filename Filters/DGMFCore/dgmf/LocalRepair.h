/**
 * @file LocalRepair.h
 * @brief The quality guard: local untangling and smoothing of the cells a deformation step made
 * bad (inverted, or SizeSkew below a threshold), moving only nearby interior nodes.
 */
#ifndef dgmf_LocalRepair_h
#define dgmf_LocalRepair_h

#include "dgmf/CellMesh.h"
#include "dgmf/NodeKind.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/Progress.h"
#include "dgmf/SizeSkewQuality.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/// Settings of RepairCells.
struct RepairParameters
{
  /// Cells with SizeSkew below this value (and every inverted cell) are bad; in [0, 1].
  double Threshold = 0.2;
  /**
   * Size of the region that may move: the interior nodes of the bad cells and of the cells up to
   * this many node-neighbour layers around them (0: the bad cells' own interior nodes only).
   */
  int Layers = 2;
  /// Most Gauss-Seidel passes over the free nodes (0: only count the bad cells).
  int MaximumPasses = 20;
  /**
   * Stop early when the passes left cannot remove the bad cells: after the first pass, when it
   * left more bad cells than it found; before each pass from the fourth on, when the
   * bad cells' count, falling by as many cells a pass as in the last pass, would not reach 0
   * within the passes left (or did not fall at all), while it is still at least a tenth of the
   * count before the first pass. For callers that have something better
   * to do with such a step (sub-steps: halve it); off by default (every pass is run). See
   * GaveUp.
   */
  bool GiveUpWhenHopeless = false;
  /// Told after each pass (the fraction of MaximumPasses); may stop the repair (Aborted).
  dgmf::Progress Progress;
};

/// What RepairCells found and did. Counts are over the cells the metric covers.
struct RepairReport
{
  std::size_t BadCellsBefore = 0; ///< cells inverted or below the threshold before the repair
  std::size_t BadCellsAfter = 0;  ///< the same after the repair
  std::size_t InvertedBefore = 0; ///< inverted cells before the repair
  std::size_t InvertedAfter = 0;  ///< inverted cells after the repair
  std::size_t FreeNodes = 0;      ///< interior nodes the repair was allowed to move
  std::size_t MovedNodes = 0;     ///< nodes whose position changed
  std::size_t Passes = 0;         ///< passes run over the free nodes
  bool GaveUp = false;            ///< stopped by GiveUpWhenHopeless, with bad cells left
  double MinimumBefore = 0.0;     ///< lowest SizeSkew before the repair (0 if no covered cell)
  double MinimumAfter = 0.0;      ///< lowest SizeSkew after the repair
};

/**
 * Repairs, in place, the cells of a deformed mesh that are inverted or whose SizeSkew
 * (ComputeSizeSkew against the same cell of the original mesh) is below
 * `parameters.Threshold`, by moving nearby interior nodes only (Documentation/repair.md).
 *
 * The free nodes are the interior nodes of the bad cells and of the cells up to
 * `parameters.Layers` node-neighbour layers around them. Nodes of cells the metric does not
 * cover, nodes shared by 2D and 3D cells, and nodes of 2D cells that are not coplanar stay
 * fixed, as do all boundary nodes (StaticBoundary, MovingBoundary): their coordinates are never
 * written. Then, in Gauss-Seidel passes over the free nodes in increasing index order, a node
 * with an inverted cell takes up to 4 untangling steps, and a node whose worst cell scores below
 * 1.5 x the threshold takes one smoothing step:
 * - untangling: Knupp's objective sum_k (|alpha_k - beta| - (alpha_k - beta)) over the corner
 *   Jacobians alpha_k of the node's cells (P. Knupp, "Hexahedral and tetrahedral mesh
 *   untangling", Engineering with Computers 17, 2001), beta a tenth of the cell's original mean
 *   corner Jacobian, decreased by a pattern search (descent directions and a fixed lattice);
 * - smoothing: the node goes to the best of the points toward the mean of its edge neighbours
 *   (Laplacian) and along the ascent direction of its worst cells, if that raises the minimum
 *   SizeSkew of its cells: the "smart Laplacian" with an optimisation step of L. Freitag, "On
 *   combining Laplacian and optimization-based mesh smoothing techniques" (AMD Trends in
 *   Unstructured Mesh Generation, 1997), the max-min criterion of Freitag and Plassmann, "Local
 *   optimization-based simplicial mesh untangling and improvement" (IJNME 49, 2000).
 * A move is accepted only if it strictly improves the objective, so a smoothing move never lowers
 * the minimum SizeSkew of the node's cells, and the minimum over the mesh never decreases.
 * The passes stop when no bad cell with a free node is left, when a pass moves no node, or after
 * `parameters.MaximumPasses`. Nodes of 2D cells move in their cells' plane (z is kept bit for bit
 * in a mesh at constant z). Threshold 0 only untangles.
 *
 * Deterministic: the passes run in the calling thread; `parallelFor` (SerialFor if empty) only
 * evaluates the quality of all cells, in fixed blocks, so the result does not depend on it.
 * Cost: one quality evaluation of every cell, Layers + 5 scans of the connectivity, 9 bytes per
 * node and per cell; the passes cost in proportion to the free region. A mesh without bad cells
 * is left untouched (bit for bit).
 *
 * @param mesh cells and their shapes
 * @param originalPoints 3 coordinates per node before deformation (the reference of SizeSkew)
 * @param points 3 coordinates per node after deformation; free nodes are updated in place
 * @param kinds role of each node; only NodeKind::Interior nodes may move
 * @param parameters threshold, layers and passes
 * @param parallelFor how to run the quality evaluation of all cells
 * @return counts and minimum SizeSkew before and after
 * @throws std::invalid_argument for inconsistent connectivity (offsets, indices out of range, a
 * covered cell whose corner count does not match its shape) or parameters out of range
 */
RepairReport RepairCells(const CellMesh& mesh, const double* originalPoints, double* points,
  const NodeKind* kinds, const RepairParameters& parameters, const ParallelFor& parallelFor);

/// True for a cell RepairCells counts as bad: inverted, or SizeSkew below `threshold`.
inline bool IsBadCell(const CellQuality& quality, double threshold)
{
  return quality.Inverted || quality.SizeSkew < threshold;
}

} // namespace dgmf

#endif
