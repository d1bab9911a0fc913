/**
 * @file DGMFDistributedSlip.h
 * @brief The slip planes of a distributed run fitted once to every piece's slip nodes (private to
 * the DGMF::Filters module).
 */
#ifndef DGMFDistributedSlip_h
#define DGMFDistributedSlip_h

#include <string>

class vtkMultiProcessController;

namespace dgmf_vtk
{
struct InputNodes;

/**
 * Fits every slip boundary of a distributed mesh to the slip nodes of all pieces, and gives this
 * piece's slip nodes their planes (`nodes.Slip`). Every process fits the same distinct positions
 * in the same order, so every process gets the same planes, the serial run's up to the sums'
 * rounding: a piece that holds two nodes of a plane, or a line of it, or noisy nodes of it, no
 * longer fits a plane of its own (or fails). The groups are `nodes.SlipGroups` (this piece's
 * nodes per slip entry, `nodes.SlipNames` naming them, the same entries on every process); a
 * node of this piece whose kind is slip but is in no local group (a ghost node whose owner found
 * it on the slip boundary) gets its planes from the owner's groups. Call after
 * AppendRemoteBoundaryNodes. Returns "" or the error, the same on every process, for a boundary
 * that is not a plane. Collective.
 */
std::string AgreeOnSlipPlanes(vtkMultiProcessController* controller, InputNodes& nodes);

} // namespace dgmf_vtk

#endif
