/**
 * @file DGMFSlipFitting.h
 * @brief The slip planes of a serial run, fitted to their nodes: one plane per slip entry, or,
 * for an entry of several blocks whose nodes are not one plane (an OpenFOAM patch group such as
 * "wedge" or "symmetryPlane", "front|back"), one plane per block.
 */
#ifndef DGMFSlipFitting_h
#define DGMFSlipFitting_h

#include "DGMFInputNodes.h"

#include <cstdint>
#include <string>
#include <vector>

namespace dgmf_vtk
{

/**
 * Fits nodes.Slip (its planes, nodes and second planes) and nodes.MovingOnSlip to the slip nodes
 * `groups` of each entry (`names` for messages). An entry whose nodes fit one plane is that plane
 * (a plane cut into several patches); one of several blocks (roles->SlipBlocks) that does not is a
 * plane per block, so that a wedge's two planes, or two symmetry planes named by their group, are
 * each a plane. A node's planes are then counted once per distinct plane (dgmf::SamePlane: two
 * patches of one plane named apart are one): on one it slides in it, on two along their line (a
 * 2D mesh's two lines meet in a point: static), on three or more (a corner) it is made static
 * (nodes.Kinds). `roles` is null for a boundary marker (one entry). Throws
 * std::invalid_argument (FitSlipPlane's message) when an entry, or one of its blocks, is not a
 * plane.
 */
void FitSlipPlanes(const std::vector<std::vector<std::int32_t>>& groups,
  const std::vector<std::string>& names, const NodeRoles* roles, InputNodes& nodes);

} // namespace dgmf_vtk

#endif
