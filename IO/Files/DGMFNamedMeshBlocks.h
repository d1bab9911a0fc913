/**
 * @file DGMFNamedMeshBlocks.h
 * @brief A dgmf::meshfile::NamedMesh as VTK blocks: the shape vtkDGMFMeshFileReader gives
 * (private to the DGMF::IO module).
 */
#ifndef DGMFNamedMeshBlocks_h
#define DGMFNamedMeshBlocks_h

#include "dgmf/meshfile/NamedMesh.h"

#include "vtkSmartPointer.h"

class vtkMultiBlockDataSet;

namespace dgmf_vtk
{
/**
 * The multiblock of `mesh`: `internalMesh` (every node, the volume cells, the point array
 * FileNodeId), then `boundary` with one block per named boundary (its faces on the nodes they
 * use); the named groups that are not boundaries in its field data
 * (dgmf::names::NonBoundaryGroups).
 * Throws std::bad_alloc when memory runs out.
 */
vtkSmartPointer<vtkMultiBlockDataSet> ToBlocks(const dgmf::meshfile::NamedMesh& mesh);

} // namespace dgmf_vtk

#endif
