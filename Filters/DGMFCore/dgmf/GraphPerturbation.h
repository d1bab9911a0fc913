/**
 * @file GraphPerturbation.h
 * @brief Tiny deterministic perturbation of the boundary points before the Delaunay graph is
 * built, and the exact check that the points span their dimension.
 *
 * Boundary nodes of real meshes are degenerate for Delaunay: far-field boxes are coplanar grids,
 * bodies are spheres and cylinders (cospherical points). CGAL then resolves every degenerate
 * predicate in exact arithmetic (symbolic perturbation), which made the graph of 41,304 such
 * points take 1.1-1.4 s here instead of 0.4 s. Moving each point by 1e-11 of the distance to its
 * nearest neighbour removes the exact degeneracies while changing the geometry far below any
 * mesh tolerance; the graph is the Delaunay graph of the moved points.
 */
#ifndef dgmf_GraphPerturbation_h
#define dgmf_GraphPerturbation_h

#include <cstddef>
#include <vector>

namespace dgmf
{

/// The perturbation used for the Delaunay graph, relative to the nearest-neighbour distance.
constexpr double GraphPerturbation = 1e-11;

/**
 * Copies of `count` points (3 coordinates each; in 2D z is ignored and set to 0), each moved by at
 * most `relative` times the distance to its nearest distinct neighbour (per coordinate), in a
 * direction that is a hash of its coordinates rounded to the nearest point of a grid of 2^-33 of
 * the points' bounding box: deterministic, coincident points stay coincident, and the same mesh
 * written with other round-off (an ASCII and a binary file: last-bit differences) gets the same
 * directions but where a coordinate lies within its round-off of a half-way line (a mesh's round
 * values lie on grid points) (the directions followed the coordinates'
 * bits until 2026-11-30: a degenerate boundary, such as a structured grid's, then took another
 * of its equally valid graphs, and interior nodes moved differently).
 */
std::vector<double> PerturbPoints(
  int dimension, const double* xyz, std::size_t count, double relative);

/// True when the points span the dimension (not all collinear in 2D, not all coplanar in 3D),
/// decided with CGAL's exact predicates.
bool SpansDimension(int dimension, const double* xyz, std::size_t count);

} // namespace dgmf

#endif
