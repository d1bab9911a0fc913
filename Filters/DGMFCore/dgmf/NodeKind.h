/**
 * @file NodeKind.h
 * @brief The role of a mesh node in a deformation (the values of the boundary-marker array).
 */
#ifndef dgmf_NodeKind_h
#define dgmf_NodeKind_h

#include <cstddef>
#include <cstdint>

namespace dgmf
{

/// Role of a mesh node. The numeric values are those of the boundary-marker point array.
enum class NodeKind : std::uint8_t
{
  Interior = 0,       ///< moves according to the method (not a vertex of the Delaunay graph)
  StaticBoundary = 1, ///< boundary node that stays where it is (r0 = r0s)
  MovingBoundary = 2, ///< boundary node with a prescribed motion (r0 = 0)
  /**
   * Node of a slip (symmetry) boundary: it moves as an interior node does, and then only within
   * the boundary's plane (DeformationProblem::SlipPlanes). Not a vertex of the Delaunay graph;
   * never moved by the quality guard.
   */
  SlipBoundary = 3
};

/// True for the nodes whose motion is prescribed (static or moving): the Delaunay graph's vertices.
inline bool IsBoundary(NodeKind kind)
{
  return kind == NodeKind::StaticBoundary || kind == NodeKind::MovingBoundary;
}

/// Throws std::invalid_argument for a boundary-marker value other than 0 to 3 at `node`.
[[noreturn]] void ThrowBadMarkerValue(double value, std::size_t node);

} // namespace dgmf

#endif
