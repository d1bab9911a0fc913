/**
 * @file DGMFWriterInputs.h
 * @brief What the project's writers take from their input (private to the DGMF::IO module): the
 * block with every node of the file, its points, and the reader upstream that read the file.
 */
#ifndef DGMFWriterInputs_h
#define DGMFWriterInputs_h

#include "vtkAlgorithm.h"

#include <cstdint>
#include <set>
#include <vector>

class vtkDataObject;
class vtkPointSet;

namespace dgmf_vtk
{
/// The name of the block with every node of the file (as ParaView's OpenFOAM reader names it).
constexpr const char* InternalMeshName = "internalMesh";

/// The block named internalMesh of a composite dataset, else its first unstructured grid; or the
/// point set itself; null when there is none.
vtkPointSet* InternalMeshOf(vtkDataObject* data);

/// The points of `mesh` as doubles, 3 per point.
std::vector<double> PointsOf(vtkPointSet* mesh);

/**
 * The points of a reader's blocks (ParaView's ExodusIIReader: "GlobalNodeId", its IOSSReader:
 * "ids") placed by node id: `points` (3 per file node, the file's coordinates on entry) gets,
 * for every point of every leaf of `data` that has the id array `idArray`, its position at the
 * index of its id in `fileNodeIds`. Returns the number of file nodes placed; -1 when a leaf has
 * an id the file does not have.
 */
long long PlacePointsByNodeId(vtkDataObject* data, const char* idArray,
  const std::vector<std::int64_t>& fileNodeIds, std::vector<double>& points);

/// The first algorithm upstream of `algorithm`'s inputs (breadth first) for which `accept`
/// holds, or null.
template <typename Predicate>
vtkAlgorithm* FindUpstreamIf(vtkAlgorithm* algorithm, Predicate accept)
{
  std::vector<vtkAlgorithm*> queue{ algorithm };
  std::set<vtkAlgorithm*> seen{ algorithm };
  for (std::size_t k = 0; k < queue.size(); ++k)
  {
    if (k > 0 && accept(queue[k]))
    {
      return queue[k];
    }
    for (int port = 0; port < queue[k]->GetNumberOfInputPorts(); ++port)
    {
      for (int c = 0; c < queue[k]->GetNumberOfInputConnections(port); ++c)
      {
        vtkAlgorithm* upstream = queue[k]->GetInputAlgorithm(port, c);
        if (upstream && seen.insert(upstream).second)
        {
          queue.push_back(upstream);
        }
      }
    }
  }
  return nullptr;
}

/// The first algorithm of class `Reader` upstream of `algorithm`'s inputs (breadth first), or
/// null.
template <typename Reader>
Reader* FindUpstream(vtkAlgorithm* algorithm)
{
  return Reader::SafeDownCast(
    FindUpstreamIf(algorithm, [](vtkAlgorithm* a) { return Reader::SafeDownCast(a) != nullptr; }));
}
} // namespace dgmf_vtk

#endif
