/**
 * @file DGMFSMPTools.h
 * @brief Runs the core's loops on vtkSMPTools threads (private to the DGMF::Filters module).
 */
#ifndef DGMFSMPTools_h
#define DGMFSMPTools_h

#include "dgmf/ParallelFor.h"

#include "vtkSMPTools.h"

#include <cstring>
#include <string>

namespace dgmf_vtk
{

/// A dgmf::ParallelFor that runs on vtkSMPTools' active backend.
inline dgmf::ParallelFor MakeSMPParallelFor()
{
  return [](std::size_t begin, std::size_t end, std::size_t grain, const dgmf::RangeFunction& body)
  {
    vtkSMPTools::For(static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end),
      static_cast<vtkIdType>(grain),
      [&body](vtkIdType b, vtkIdType e)
      { body(static_cast<std::size_t>(b), static_cast<std::size_t>(e)); });
  };
}

/**
 * Runs `work` with `numberOfThreads` vtkSMPTools threads (0: all). When the active backend is
 * Sequential (Debian's ParaView default) and more than one thread is wanted, the STDThread
 * backend is used for the duration of `work`. One thread always runs Sequential.
 */
template <typename Work>
void RunWithThreads(int numberOfThreads, Work&& work)
{
  vtkSMPTools::Config config;
  config.MaxNumberOfThreads = numberOfThreads;
  const char* backend = vtkSMPTools::GetBackend();
  std::string wanted = backend ? backend : "";
  if (numberOfThreads == 1)
  {
    wanted = "Sequential";
  }
  else if (wanted == "Sequential")
  {
    wanted = "STDThread";
  }
  config.Backend = wanted;
  vtkSMPTools::LocalScope(config, std::forward<Work>(work));
}

} // namespace dgmf_vtk

#endif
