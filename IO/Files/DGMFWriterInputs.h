/**
 * @file DGMFWriterInputs.h
 * @brief What the project's writers take from their input (private to the DGMF::IO module): the
 * block with every node of the file, its points, and the reader upstream that read the file.
 */
#ifndef DGMFWriterInputs_h
#define DGMFWriterInputs_h

#include "vtkAlgorithm.h"

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

/// The first algorithm of class `Reader` upstream of `algorithm`'s inputs (breadth first), or
/// null.
template <typename Reader>
Reader* FindUpstream(vtkAlgorithm* algorithm)
{
  std::vector<vtkAlgorithm*> queue{ algorithm };
  std::set<vtkAlgorithm*> seen{ algorithm };
  for (std::size_t k = 0; k < queue.size(); ++k)
  {
    if (auto* reader = Reader::SafeDownCast(queue[k]))
    {
      return reader;
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
} // namespace dgmf_vtk

#endif
