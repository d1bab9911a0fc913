#include "DGMFMemoryGuard.h"

#include <vtksys/SystemInformation.hxx>

#include <algorithm>
#include <limits>
#include <sstream>

namespace dgmf_vtk
{

double EstimateDeformationBytes(double nodes, double cells)
{
  return nodes * (3 + 36 + 24 + 16 + 48) + cells * 9 + 0.1 * nodes * 1500.0;
}

double AvailableBytes()
{
  vtksys::SystemInformation system;
  system.RunMemoryCheck();
  // Free memory plus buffers and page cache (the system gives those back), in MiB; 0 if unknown.
  const double physical = static_cast<double>(system.GetAvailablePhysicalMemory()) * 1048576.0;
  double available = physical > 0.0 ? physical : std::numeric_limits<double>::infinity();
  // The process's share, in KiB: its limit (rlimit, or the variables) less what it uses.
  const long long processLimit =
    system.GetProcMemoryAvailable("DGMF_HOST_MEMORY_KIB", "DGMF_PROCESS_MEMORY_KIB");
  if (processLimit > 0)
  {
    const long long left = std::max(0LL, processLimit - std::max(0LL, system.GetProcMemoryUsed()));
    available = std::min(available, static_cast<double>(left) * 1024.0);
  }
  return available;
}

std::string CheckDeformationMemory(double nodes, double cells)
{
  const double needed = EstimateDeformationBytes(nodes, cells);
  const double available = AvailableBytes();
  if (needed <= available)
  {
    return std::string();
  }
  std::ostringstream message;
  message.precision(3);
  message << "Deforming " << static_cast<long long>(nodes) << " points needs about "
          << needed / 1073741824.0 << " GiB; only " << available / 1073741824.0
          << " GiB of memory is available. Deform the mesh in parts, or on a machine with more "
             "memory.";
  return message.str();
}

} // namespace dgmf_vtk
