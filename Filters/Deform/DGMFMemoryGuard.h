/**
 * @file DGMFMemoryGuard.h
 * @brief Refuses a deformation that cannot fit in memory, before it allocates anything (private to
 * the DGMF::Filters module).
 */
#ifndef DGMFMemoryGuard_h
#define DGMFMemoryGuard_h

#include <string>

namespace dgmf_vtk
{

/**
 * Bytes a deformation of `nodes` nodes and `cells` cells needs at most. Per node: node kinds (up
 * to 3 copies), element and barycentric coordinates (36 bytes), the new points (24), r and f (16),
 * the points and displacement as doubles if they are not (48); per cell: SizeSkew and Inverted
 * (9); per boundary node, the graph (measured: about 1.5 kB). The boundary is not known yet: a
 * tenth of the nodes is assumed, which overestimates volume meshes.
 */
double EstimateDeformationBytes(double nodes, double cells);

/**
 * Bytes this process may still allocate: the smaller of the memory the system has available
 * (free, buffers and page cache: vtksys::SystemInformation) and the process's limit (`ulimit -v`,
 * `ulimit -d`) less what it uses. The environment variables DGMF_HOST_MEMORY_KIB and
 * DGMF_PROCESS_MEMORY_KIB, when set, lower the system's and the process's limits (in KiB), as
 * vtksys::SystemInformation reads them. Infinite when the system tells nothing.
 */
double AvailableBytes();

/**
 * An empty string when a deformation of `nodes` nodes and `cells` cells fits in AvailableBytes(),
 * else the message that says how much it needs and what to do.
 */
std::string CheckDeformationMemory(double nodes, double cells);

} // namespace dgmf_vtk

#endif
