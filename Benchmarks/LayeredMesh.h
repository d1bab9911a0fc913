/**
 * @file LayeredMesh.h
 * @brief Procedural 3D meshes with the sizes of the paper's Table 3, for the benchmark.
 */
#ifndef dgmf_bench_LayeredMesh_h
#define dgmf_bench_LayeredMesh_h

#include "vtkSmartPointer.h"

#include <string>

class vtkUnstructuredGrid;

namespace dgmf_bench
{

/**
 * A body (the unit sphere) inside a far-field box, meshed with hexahedra in layers: a box-surface
 * grid of A x B x C nodes per edge, mapped onto the sphere (layer 0, moving) and onto the box
 * [-Scale, Scale]^3 (last layer, static), with Layers layers of nodes in between (linear spacing).
 * Nodes per layer: ABC - (A-2)(B-2)(C-2); boundary nodes: twice that; nodes: Layers times that.
 * Node numbering is layer by layer, face by face and row by row within a layer. The point array
 * BoundaryMarker marks the sphere 2 and the box 1.
 */
struct LayeredMeshSize
{
  std::string Name;
  int A, B, C, Layers;
  double Scale = 10.0;

  long long NodesPerLayer() const
  {
    return static_cast<long long>(A) * B * C - static_cast<long long>(A - 2) * (B - 2) * (C - 2);
  }
  long long Nodes() const { return this->NodesPerLayer() * this->Layers; }
  long long BoundaryNodes() const { return 2 * this->NodesPerLayer(); }
};

/// The paper's four sizes: 201,920 / 403,840 / 826,080 / 8,260,800 nodes with 10,096 / 10,096 /
/// 41,304 / 41,304 boundary nodes.
LayeredMeshSize PaperSize(int index);

/// Builds the mesh (deterministic; double-precision points).
vtkSmartPointer<vtkUnstructuredGrid> MakeLayeredMesh(const LayeredMeshSize& size);

} // namespace dgmf_bench

#endif
