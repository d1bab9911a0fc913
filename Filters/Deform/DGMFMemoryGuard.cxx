#include "DGMFMemoryGuard.h"

#include <vtksys/SystemInformation.hxx>

#include <algorithm>
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
  // Free memory plus buffers and page cache (the system gives those back), in MiB.
  double available = static_cast<double>(system.GetAvailablePhysicalMemory()) * 1048576.0;
  // The process's share, in KiB: its limit (rlimit, or the variables) less what it uses.
  const long long processLimit =
    system.GetProcMemoryAvailable("DGMF_HOST_MEMORY_KIB", "DGMF_PROCESS_MEMORY_KIB");
  const long long used = system.GetProcMemoryUsed();
  if (processLimit > 0)
  {
    available = std::min(
      available, static_cast<double>(std::max(0LL, processLimit - std::max(0LL, used))) * 1024.0);
  }
  return available;
}

std::string CheckDeformationMemory(double nodes, double cells)
{
  const double needed = EstimateDeformationBytes(nodes, cells);
  const double available = AvailableBytes();
  if (!(available > 0.0) || needed <= available)
  {
    return std::string(); // an unreadable figure does not stop a deformation
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
