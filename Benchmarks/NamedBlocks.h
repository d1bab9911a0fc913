/**
 * @file NamedBlocks.h
 * @brief The benchmark's layered mesh as a CFD reader gives it: a multiblock with the volume and
 * named boundary patches (issue 18's composite case).
 */
#ifndef dgmf_bench_NamedBlocks_h
#define dgmf_bench_NamedBlocks_h

#include "LayeredMesh.h"

#include "vtkSmartPointer.h"

class vtkMultiBlockDataSet;
class vtkUnstructuredGrid;

namespace dgmf_bench
{

/**
 * `mesh` (made by MakeLayeredMesh(size), layered numbering) as ParaView's OpenFOAM reader gives a
 * case: block "internalMesh" (the hexahedra, sharing the mesh's points and cells, without the
 * marker) and block "boundary" with the patches "body" (the sphere's quads) and "farfield" (the
 * box's), polydata with points of their own.
 */
vtkSmartPointer<vtkMultiBlockDataSet> MakeNamedBlocks(
  vtkUnstructuredGrid* mesh, const LayeredMeshSize& size);

} // namespace dgmf_bench

#endif
