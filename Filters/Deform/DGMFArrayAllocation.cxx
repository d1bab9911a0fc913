#include "DGMFArrayAllocation.h"
#include "DGMFTupleAllocation.h"

#include "dgmf/HugePages.h"

#include "vtkDataArray.h"
#include "vtkPoints.h"

#include <cstdlib>
#include <new>
#include <sys/resource.h>

namespace dgmf_vtk
{

void AllocatePoints(vtkPoints* points, vtkIdType count)
{
  AllocateTuples(points->GetData(), count);
  points->Modified();
}

namespace
{
/// True when `bytes` bytes can be allocated now (the probe is freed at once).
bool CanAllocate(std::size_t bytes)
{
  void* probe = std::malloc(bytes);
  std::free(probe);
  return probe != nullptr;
}
} // namespace

void EnsureAvailableMemory(std::size_t bytes)
{
  if (!CanAllocate(bytes))
  {
    throw std::bad_alloc();
  }
}

bool CanStartThreads(int threads)
{
  if (threads <= 1)
  {
    return true;
  }
  // Thread stacks are mapped lazily: without an address-space limit, starting threads does not
  // fail for want of memory, and the probe (two system calls per loop) is skipped.
  rlimit space{};
  if (getrlimit(RLIMIT_AS, &space) != 0 || space.rlim_cur == RLIM_INFINITY)
  {
    return true;
  }
  rlimit stack{};
  const std::size_t stackBytes =
    getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY
    ? static_cast<std::size_t>(stack.rlim_cur)
    : std::size_t(8) << 20;
  return CanAllocate(static_cast<std::size_t>(threads) * (stackBytes + (std::size_t(1) << 20)));
}

} // namespace dgmf_vtk
