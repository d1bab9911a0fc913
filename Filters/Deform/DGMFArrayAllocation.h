/**
 * @file DGMFArrayAllocation.h
 * @brief Memory for VTK arrays that fails into the filter's error path.
 *
 * When an allocation fails, VTK 9.2's arrays print "Unable to allocate" and, as Debian builds
 * them (without NDEBUG), call abort(): ParaView itself would go down. The filter's arrays are
 * therefore allocated here, with malloc, and handed to VTK: a failure throws std::bad_alloc, which
 * the filter reports as "Out of memory" with an empty output.
 */
#ifndef DGMFArrayAllocation_h
#define DGMFArrayAllocation_h

#include "vtkType.h"

#include <cstddef>

class vtkDataArray;
class vtkPoints;

namespace dgmf_vtk
{
// AllocateTuples: DGMFTupleAllocation.h, shared with the mesh-file module and dgmf-deform.

/// AllocateTuples on the points' data array.
void AllocatePoints(vtkPoints* points, vtkIdType count);

/**
 * Throws std::bad_alloc unless `bytes` bytes can be allocated now (the probe is freed at once):
 * a guard before VTK code that grows arrays one insertion at a time (merging blocks, copying
 * cells), whose own failure would abort.
 */
void EnsureAvailableMemory(std::size_t bytes);

/**
 * True when `threads` threads could get their stacks now (a probe of that much memory, freed at
 * once; always true for one thread): VTK 9.2's STDThread backend aborts the process when it cannot
 * start a thread.
 */
bool CanStartThreads(int threads);
} // namespace dgmf_vtk

#endif
