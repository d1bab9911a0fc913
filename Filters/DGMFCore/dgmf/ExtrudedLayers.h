/**
 * @file ExtrudedLayers.h
 * @brief One-cell-thick meshes (OpenFOAM's 2D meshes, between two `empty` patches): the two
 * layers of nodes, and the 2D problem of one layer whose motion both layers take.
 */
#ifndef dgmf_ExtrudedLayers_h
#define dgmf_ExtrudedLayers_h

#include "dgmf/DeformationProblem.h"
#include "dgmf/NodeKind.h"
#include "dgmf/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/**
 * The two layers of a one-cell-thick mesh: every node lies on one of two planes normal to a
 * coordinate axis (the extrusion axis), and each node of one plane has exactly one partner on the
 * other with the same two other coordinates (bit for bit, or within Tolerance: a mesh turned into
 * another plane by a transform, such as OpenFOAM's transformPoints, carries round-off). Nodes
 * strictly between the planes whose in-plane coordinates are no plane node's (the cell centres
 * VTK's OpenFOAM reader adds when it decomposes polyhedra) are inner nodes: each is a layer node of
 * its own, and keeps its coordinate along the axis.
 */
struct ExtrudedLayers
{
  int Axis = -1;     ///< the extrusion axis (0 x, 1 y, 2 z); -1: the mesh is not one cell thick
  double Low = 0.0;  ///< the coordinate of the first plane along Axis
  double High = 0.0; ///< and of the second
  /// How far from its plane (and from its partner, in the other two coordinates) a node may be:
  /// 0 when every node is exactly on a plane, else ExtrudedLayersTolerance of the mesh's size
  double Tolerance = 0.0;
  /// The layer nodes: the nodes on the Low plane in increasing order, then the inner nodes.
  std::vector<std::int32_t> Front;
  std::size_t Pairs = 0;           ///< the number of nodes on each plane (the first of Front)
  std::vector<std::int32_t> Layer; ///< per node: the index in Front of itself or of its partner

  bool Found() const { return this->Axis >= 0; }
  /// True when node coordinate `value` along Axis is one of the two planes.
  bool OnPlane(double value) const
  {
    return std::abs(value - this->Low) <= this->Tolerance ||
      std::abs(value - this->High) <= this->Tolerance;
  }

  /**
   * The plane the nodes `ids[0..count)` of `points` (3 coordinates each) all lie on, a face or
   * cell of one layer: 0 Low, 1 High; -1 for nodes across the layer, or when not Found(). No
   * node: 0.
   */
  template <typename Id>
  int PlaneOf(const double* points, const Id* ids, std::size_t count) const
  {
    for (int side = 0; side < 2 && this->Found(); ++side)
    {
      const double plane = side == 0 ? this->Low : this->High;
      if (std::all_of(ids, ids + count,
            [&](Id id)
            {
              return std::abs(points[3 * static_cast<std::size_t>(id) + this->Axis] - plane) <=
                this->Tolerance;
            }))
      {
        return side;
      }
    }
    return -1;
  }
};

/// The tolerance of a one-cell-thick mesh's planes and pairs whose coordinates carry round-off,
/// relative to the diagonal of the nodes' bounding box.
constexpr double ExtrudedLayersTolerance = 1e-9;

/**
 * Finds the layers of a one-cell-thick mesh among `n` nodes (3 coordinates each): the first axis
 * along which the nodes' coordinates lie between two values, every node at those two values
 * paired, and the nodes between them (if any) inner nodes (see ExtrudedLayers). When no axis has
 * exact planes and pairs, a thin axis (at most a quarter of the largest extent) is tried again
 * within ExtrudedLayersTolerance (one more pass over the nodes; Tolerance is then set). Not
 * Found() when there is none. O(n) with a hash of the in-plane coordinates; the first pass (every
 * axis's extremes) on `parallelFor`'s threads (none: the calling thread), in fixed blocks.
 */
ExtrudedLayers FindExtrudedLayers(
  const double* points, std::size_t n, const ParallelFor& parallelFor = {});

/**
 * The in-plane coordinates of an extruded mesh's layer: (u, v, w) with w along `axis` and (u, v)
 * the two other axes in cyclic order (x: (y, z); y: (z, x); z: (x, y)), so that a rotation about
 * the extrusion axis is a rotation about w, with the same sense. ToLayer and FromLayer are
 * inverses, bit for bit.
 */
void ToLayer(int axis, const double in[3], double out[3]);
void FromLayer(int axis, const double in[3], double out[3]);

/**
 * The 2D problem of an extruded mesh's layer nodes (in the coordinates of ToLayer, all at
 * w = Low): its nodes' points, kinds (a node and its partner are the same 2D node: moving wins
 * over static, static over slip, slip over interior), displacements, body ids (the first
 * non-zero), motions and slip planes, all turned by ToLayer. `storage` keeps the arrays the
 * returned problem points to. Cells and boundary weights are the caller's (2D ones).
 */
struct LayerProblemStorage
{
  std::vector<double> Points, Displacement;
  std::vector<NodeKind> Kinds;
  std::vector<std::int32_t> BodyIds;
};
DeformationProblem ReduceToLayer(
  const ExtrudedLayers& layers, const DeformationProblem& problem, LayerProblemStorage& storage);

/**
 * The 3D positions from the deformed layer (3 per front node, layer coordinates): every node
 * takes its layer node's in-plane position, and keeps its own coordinate along the extrusion axis
 * bit for bit, so both layers get the same in-plane motion.
 */
void ExpandFromLayer(const ExtrudedLayers& layers, const double* points,
  const double* deformedLayer, double* deformed);

/// Per-node values of the layer (one per front node) for every node of both layers.
void ExpandValuesFromLayer(const ExtrudedLayers& layers, const double* layerValues, double* values);

} // namespace dgmf

#endif
