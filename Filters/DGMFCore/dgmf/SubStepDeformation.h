/**
 * @file SubStepDeformation.h
 * @brief Large motions in sub-steps: the graph is rebuilt on the current mesh after each step,
 * and a quality guard repairs the cells that fell below a threshold.
 */
#ifndef dgmf_SubStepDeformation_h
#define dgmf_SubStepDeformation_h

#include "dgmf/DampingFunction.h"
#include "dgmf/LocalRepair.h"
#include "dgmf/NodeKind.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/Progress.h"
#include "dgmf/RigidMotion.h"
#include "dgmf/SlipPlanes.h"

#include <cstddef>
#include <functional>

namespace dgmf
{
class DelaunayMapping;

/// Settings of DeformInSubSteps.
struct SubStepParameters
{
  /// Number of sub-steps (step k ends at s = k / SubSteps); 0: automatic: a step is tried,
  /// repaired when the guard is on, and halved (down to 1/MaximumSubSteps of the motion) while
  /// the mesh it leaves still has an inverted cell or a cell below RepairThreshold; the step after
  /// an accepted one tries twice as far. The first step tries the whole motion.
  int SubSteps = 1;
  int MaximumSubSteps = 64; ///< most sub-steps in automatic mode
  double RepairThreshold =
    0.0;                 ///< repair cells below this SizeSkew after each step (0: only inverted)
  bool Repair = false;   ///< run the quality guard (LocalRepair) after each step
  int RepairLayers = 2;  ///< RepairParameters::Layers
  int RepairPasses = 20; ///< RepairParameters::MaximumPasses
  DampingFunction Damping = DampingFunction::U1;
  double StaticR0 = 1.0;
  /// If set, applied to the mesh after each step's deformation, before the quality guard (e.g.
  /// SlipConstraint::Apply: slip nodes back into their planes).
  std::function<void(double* deformed)> Constrain;
  /// The slip boundaries whose nodes Constrain keeps in their planes, or null: each step's graph
  /// locates them as the input's does (DelaunayMapping's `slip`).
  const SlipConstraint* Slip = nullptr;
  /// Told the fraction of the motion done after each step and during the repairs; may stop the
  /// run (Aborted).
  dgmf::Progress Progress;
};

/// What DeformInSubSteps did.
struct SubStepReport
{
  int SubSteps = 0;              ///< steps taken
  int RejectedSteps = 0;         ///< automatic mode: steps tried, found too bad, and halved
  std::size_t RepairedCells = 0; ///< bad cells before the repairs, summed over the accepted steps
  std::size_t BadCellsLeft = 0;  ///< bad cells after the last repair
  double GraphSeconds = 0.0;     ///< summed over the steps
  double LocationSeconds = 0.0;
};

/**
 * DGMF in sub-steps. The moving nodes' prescribed path is c + R(s angle)(x - c) + s (t + d) for
 * s from 0 to 1, with the rotation R of `motion` taken about its axis (so that the steps compose
 * to R exactly, whatever its Euler angles). Step k moves the mesh from s_{k-1} to s_k: the graph of
 * the current boundary is built, each node gets its damping factor, the step's rigid part (the
 * rotation by (s_k - s_{k-1}) angle about the current centre, and the translation) is scaled by f
 * as in DGMF, and what the rigid part misses at the moving nodes is the step's shape deformation
 * (DGMF2). Moving nodes end exactly on their path; static nodes never move. After each step, the
 * quality guard (when on) repairs the cells whose SizeSkew relative to the ORIGINAL mesh fell below
 * RepairThreshold, and every inverted cell, moving only interior nodes.
 *
 * @param dimension 2 or 3; `points`, `deformed`: 3 per node; `displacement`: the shape
 * deformation d at the moving nodes (3 per node, may be null); `cells`: the mesh's cells for the
 * quality metric and the repair; `initialMapping` (may be null): the graph of `points` with
 * these `kinds`, if the caller has it (the first step then does not build it again).
 */
SubStepReport DeformInSubSteps(int dimension, const double* points, std::size_t numberOfNodes,
  const NodeKind* kinds, const CellMesh& cells, const RigidMotion& motion,
  const double* displacement, const SubStepParameters& parameters, double* deformed,
  const ParallelFor& parallelFor, const DelaunayMapping* initialMapping = nullptr);

} // namespace dgmf

#endif
