/**
 * @file SlipPlanes.h
 * @brief Slip (symmetry) boundaries: their planes, and the projection that keeps their nodes in
 * them.
 */
#ifndef dgmf_SlipPlanes_h
#define dgmf_SlipPlanes_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dgmf
{

/// The plane of a slip boundary: a point on it and its unit normal.
struct SlipPlane
{
  double Point[3] = { 0.0, 0.0, 0.0 };
  double Normal[3] = { 0.0, 0.0, 1.0 };
  /// 0, 1 or 2 when the plane is normal to that coordinate axis exactly (every node has the same
  /// coordinate there): the projection then keeps that coordinate bit for bit; -1 otherwise.
  int Axis = -1;
  /// The largest distance of the boundary's nodes from the plane (0 for an axis plane): how far
  /// from flat the boundary is, at most SlipPlaneTolerance times its extent.
  double Deviation = 0.0;
};

/**
 * How far from its plane a slip boundary's node may be, relative to the boundary's extent: 1e-6,
 * above the rounding of coordinates read in single precision (about 6e-8 of their magnitude, as
 * from OpenFOAM's reader), far below any curvature meant.
 */
constexpr double SlipPlaneTolerance = 1e-6;

/**
 * The plane through the nodes `nodes[0..count)` of `points` (3 coordinates per node): their
 * centroid and the direction of least spread (the covariance's smallest eigenvector), or exactly
 * a coordinate axis when the nodes share that coordinate. Throws std::invalid_argument, naming the
 * boundary `name`, when there are fewer than 3 nodes, when they lie on a line, or when a node is
 * farther than `relativeTolerance` times the nodes' extent from the plane ("not planar").
 *
 * `dimension` 2 (a mesh in a plane z = constant): the slip boundary is a straight line of that
 * plane, and the "plane" returned is the one through it normal to the mesh's plane (normal (nx,
 * ny, 0); axis 0 or 1 when the nodes share x or y), so that the nodes slide along the line. It
 * needs at least 2 nodes that are not all at one place; a node farther than `relativeTolerance`
 * times the extent from the line is an error ("not straight").
 */
SlipPlane FitSlipPlane(const double* points, const std::int32_t* nodes, std::size_t count,
  const std::string& name, double relativeTolerance = SlipPlaneTolerance, int dimension = 3);

/**
 * True when two fitted planes are one plane (a plane cut into several patches): their normals
 * parallel (either way) to SlipPlaneTolerance, and each one's point off the other's plane by at
 * most SlipPlaneTolerance times the points' distance plus both planes' deviations.
 */
bool SamePlane(const SlipPlane& a, const SlipPlane& b);

/// The nodes of the slip boundaries and the plane each one stays in.
struct SlipConstraint
{
  std::vector<SlipPlane> Planes;
  std::vector<std::int32_t> Nodes;      ///< SlipBoundary nodes
  std::vector<std::int32_t> NodePlanes; ///< the plane of each of Nodes (index into Planes)
  /// Empty, or per node of Nodes a second plane (index into Planes) or -1: a node on two planes
  /// (the edge where two symmetry planes of a 3D mesh meet) slides along their line.
  std::vector<std::int32_t> SecondPlanes;

  /// The second plane of the k-th node, or -1.
  std::int32_t SecondPlaneOf(std::size_t k) const
  {
    return k < this->SecondPlanes.size() ? this->SecondPlanes[k] : -1;
  }

  bool Empty() const { return this->Nodes.empty(); }

  /// True when both have the same nodes in the same planes (every field equal).
  bool operator==(const SlipConstraint& other) const;

  /**
   * Moves every slip node of `deformed` back into its plane: the component of its displacement
   * (deformed - points) along the plane's normal is removed; with an axis-aligned plane the
   * node's coordinate along the axis is its original one, bit for bit. A node on two planes keeps
   * the component along their line only (both coordinates bit for bit for two axis planes).
   */
  void Apply(const double* points, double* deformed) const;
};

} // namespace dgmf

#endif
