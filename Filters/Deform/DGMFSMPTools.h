/**
 * @file DGMFSMPTools.h
 * @brief Runs the core's loops on vtkSMPTools threads (private to the DGMF::Filters module).
 */
#ifndef DGMFSMPTools_h
#define DGMFSMPTools_h

#include "DGMFArrayAllocation.h"

#include "dgmf/ParallelFor.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <mutex>
#include <string>

namespace dgmf_vtk
{

/**
 * A dgmf::ParallelFor that runs on vtkSMPTools' active backend. The range is cut into at most
 * about 64 chunks: VTK 9.2's STDThread backend spends more time handing out thousands of small
 * jobs than running them (measured here: no speed-up at all with 2,000 one-item jobs).
 */
inline dgmf::ParallelFor MakeSMPParallelFor()
{
  return [](std::size_t begin, std::size_t end, std::size_t grain, const dgmf::RangeFunction& body)
  {
    const std::size_t chunk = std::max(grain, (end - begin + 63) / 64);
    // VTK 9.2's STDThread backend starts its threads for every loop, and aborts the process when
    // one cannot be started (no memory left for its stack): then the loop runs in this thread
    // (the results do not depend on the threads).
    if (!CanStartThreads(vtkSMPTools::GetEstimatedNumberOfThreads()))
    {
      dgmf::SerialFor(begin, end, grain, body);
      return;
    }
    // An exception escaping a worker of the STDThread backend would terminate the process (out of
    // memory in a worker would take ParaView down): the first one is kept, the other chunks are
    // skipped, and it is thrown again in the calling thread.
    std::exception_ptr failure;
    std::atomic<bool> failed(false);
    std::mutex lock;
    vtkSMPTools::For(static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end),
      static_cast<vtkIdType>(chunk),
      [&](vtkIdType b, vtkIdType e)
      {
        if (failed.load(std::memory_order_relaxed))
        {
          return;
        }
        try
        {
          body(static_cast<std::size_t>(b), static_cast<std::size_t>(e));
        }
        catch (...)
        {
          std::lock_guard<std::mutex> guard(lock);
          if (!failure)
          {
            failure = std::current_exception();
          }
          failed = true;
        }
      });
    if (failure)
    {
      std::rethrow_exception(failure);
    }
  };
}

/**
 * Runs `work` with `numberOfThreads` vtkSMPTools threads (0: all). When the active backend is
 * Sequential (Debian's ParaView default), the STDThread backend is used for the duration of
 * `work`.
 *
 * Two nested scopes: VTK 9.2's LocalScope applies the thread count before it switches the
 * backend, so a single scope sets the count of the backend being left (measured here: after a
 * one-thread execution, two-thread executions ran on one thread). The outer scope selects the
 * backend, the inner one sets its number of threads.
 */
template <typename Work>
void RunWithThreads(int numberOfThreads, Work&& work)
{
  const char* active = vtkSMPTools::GetBackend();
  std::string backend = active ? active : "";
  if (backend == "Sequential")
  {
    backend = "STDThread";
  }
  vtkSMPTools::Config selectBackend;
  selectBackend.Backend = backend;
  vtkSMPTools::LocalScope(selectBackend,
    [&]()
    {
      vtkSMPTools::Config setThreads;
      setThreads.MaxNumberOfThreads = numberOfThreads;
      setThreads.Backend = backend;
      vtkSMPTools::LocalScope(setThreads, std::forward<Work>(work));
    });
}

} // namespace dgmf_vtk

#endif
