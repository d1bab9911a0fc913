/**
 * @file MultiBodyDeformation.h
 * @brief DGMF with several moving bodies: one damping field per body, the bodies' displacements
 * summed; and the extraction of every body's rigid motion from a displacement field.
 */
#ifndef dgmf_MultiBodyDeformation_h
#define dgmf_MultiBodyDeformation_h

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingFunction.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/RigidMotion.h"
#include "dgmf/RigidMotionFit.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/// The prescribed motion of one moving body.
struct BodyMotion
{
  RigidMotion Motion; ///< its rigid part (Euler angles or an axis rotation)
  /**
   * Its shape deformation d, 3 components per mesh node, or null (none). DGMF2: read at the
   * body's own nodes and interpolated by paper Eq. 7 over the body's vertices of a node's Delaunay
   * element (the other bodies' vertices do not count). DGMF1: read at every node the body moves.
   * Several bodies may share one array (each reads its own nodes), e.g. the residual of
   * ExtractBodyMotions.
   */
  const double* Displacement = nullptr;
};

/**
 * Checks a body-id array (one value per node of the mapping) against the mapping's node kinds and
 * returns the largest id (0 when no node is on a body). Id 0: not on a moving body; 1..K: the
 * body. Throws std::invalid_argument when `bodyIds` is null, an id is negative, a node with an id
 * > 0 is not a MovingBoundary node of the mapping (interior or static), or a MovingBoundary node
 * has id 0. The mapping must have been built with exactly the body nodes marked MovingBoundary.
 */
std::int32_t CheckBodyIds(const DelaunayMapping& mapping, const std::int32_t* bodyIds);

/**
 * The damping factor f_k of body `body` (>= 1) at every node, written into `f`: f_k = u(r_k) with
 * r_k = sum_i e_i r0_i, r0 = 0 on body k's vertices and r0 = staticR0 on every other graph vertex
 * (static ones and the other bodies'). f_k is exactly 1 on body k's nodes and exactly 0 on every
 * other boundary node and wherever a node's Delaunay element has no vertex of body k (r_k = r0s
 * there). For a single body this is ComputeDampingFactor(ComputeBoundaryDistanceField(...)).
 * Throws std::invalid_argument as CheckBodyIds, for body < 1, and for staticR0 < 1 or not finite.
 */
void ComputeBodyDampingFactor(const DelaunayMapping& mapping, const std::int32_t* bodyIds,
  std::int32_t body, double staticR0, DampingFunction u, double* f, const ParallelFor& parallelFor);

/**
 * Moves every node with several bodies (paper Eqs. 3-7 per body, summed):
 *
 *   x' = x + sum_k [ M_k(f_k; x) - x ],  M_k(f; x) = c_k + R_k(f angles)(x - c_k) + f t_k + f d_k,
 *
 * f_k the damping factor of body k (ComputeBodyDampingFactor) and d_k its shape deformation
 * (DGMF1: the node's own value of bodies[k-1].Displacement; DGMF2: Eq. 7 over the body's vertices
 * of the node's element). Bodies with f_k = 0 at a node do not enter the sum; a node moved by one
 * body only gets M_k(f_k; x) itself, so a single body gives the same bits as DeformDGMF (up to
 * nodes whose element has no moving vertex, where DeformDGMF may apply an f of order 1e-32 and
 * this function applies none). Body k's nodes get exactly body k's motion, M_k(1; x) with their
 * own displacement; static nodes do not move. Bodies are summed in increasing id, so the result
 * does not depend on threads.
 *
 * Why a sum: it does not depend on the order of the bodies (composition M_2(M_1(x)) does), it is
 * what the interpolation methods (DGM, RBF, IDW) do with several bodies, and with the paper's
 * damping functions sum_k f_k <= 1 at every node (see Documentation/bodies.md), so the sum never
 * overshoots: two bodies translating together by t move no node by more than |t|.
 *
 * @param bodyIds one id per node (CheckBodyIds)
 * @param bodies the motion of body k at bodies[k - 1]; there must be at least as many as the
 * largest id (bodies without nodes do nothing)
 * @param deformed 3 coordinates per node; may not alias `points`
 * @param dampingFactor if not null, receives per node min(1, sum_k f_k) for visualisation: 1 on
 * the bodies, 0 on the static boundary, f itself with one body
 * Throws std::invalid_argument as CheckBodyIds, when a body id exceeds bodies.size(), for staticR0
 * < 1 or not finite, and for an invalid motion (DampedRigidMotion).
 */
void DeformMultiBody(const DelaunayMapping& mapping, const std::int32_t* bodyIds,
  const std::vector<BodyMotion>& bodies, double staticR0, DampingFunction u, DeformationMode mode,
  const double* points, double* deformed, double* dampingFactor, const ParallelFor& parallelFor);

/**
 * Fits the rigid motion of every body to a displacement field (FitRigidMotion over the nodes of
 * each body id 1..numberOfBodies) and writes the residuals, the shape deformation for DGMF2.
 * @param displacement 3 components per node, the prescribed displacement of the body nodes
 * (other nodes are not read)
 * @param residual if not null, 3 per node: each body node's residual (ComputeFitResidual), 0 at
 * nodes with id 0. May alias `displacement`.
 * @return the fit of body k at index k - 1 (an Undetermined identity fit for a body without nodes)
 * @param distinctPositions fit each body to its distinct positions in increasing order (x, then
 * y, then z; a position held by several nodes counts once, with its first node's displacement):
 * the fit of a set of nodes that does not depend on their numbering or copies (a distributed run,
 * where each process holds its piece's nodes first and the other pieces' copies after them).
 * Default: every node in its order.
 * Throws std::invalid_argument for ids below 0 or above numberOfBodies, and as FitRigidMotion.
 */
std::vector<FittedMotion> ExtractBodyMotions(int dimension, const double* points,
  const double* displacement, std::size_t numberOfNodes, const std::int32_t* bodyIds,
  std::int32_t numberOfBodies, double* residual, bool distinctPositions = false);

} // namespace dgmf

#endif
