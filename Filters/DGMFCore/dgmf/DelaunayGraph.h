/**
 * @file DelaunayGraph.h
 * @brief The Delaunay triangulation (2D) or tetrahedralization (3D) of the boundary nodes.
 */
#ifndef dgmf_DelaunayGraph_h
#define dgmf_DelaunayGraph_h

#include "dgmf/FirstTouch.h"
#include "dgmf/ParallelFor.h"
#include "dgmf/Simd.h"
#include "dgmf/WalkRecord.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace dgmf
{

/**
 * @class DelaunayGraph
 * @brief Delaunay graph of a set of points, built with CGAL (exact predicates, inexact
 * constructions), with the element records the point location walks on (LocateNodes) and CGAL's
 * exact location as its fallback.
 *
 * Vertices are the distinct input points; coincident input points share one vertex (see
 * GetVertexOfPoint). Elements are the finite triangles (2D) or tetrahedra (3D), numbered
 * 0..GetNumberOfElements()-1; an element's vertices are positively oriented.
 *
 * The graph is built on the points moved by GraphPerturbation (1e-11) of their nearest-neighbour
 * distance, which removes the exact degeneracies of grid-like and cospherical boundary points
 * (see GraphPerturbation.h); GetVertexPosition gives these graph coordinates, and barycentric
 * coordinates refer to them. Elements that are flat in the original coordinates (coplanar or
 * cospherical artefacts) are counted by GetNumberOfFlatElements.
 *
 * In 2D only x and y are used. Building throws std::invalid_argument when the points do not span
 * the dimension (fewer than 3 (2D) or 4 (3D) points, or all collinear (2D) or coplanar (3D)), and
 * when a coordinate is not finite.
 *
 * LocateExactly() and ComputeWeights() are const and may be called from several threads at once.
 */
class DelaunayGraph
{
public:
  /// Result of a point location.
  struct Location
  {
    /// Element containing the point (outside: the one under the hull facet it projects onto).
    std::int32_t Element = -1;
    double Weights[4] = { 0, 0, 0, 0 }; ///< barycentric coordinates, >= 0, sum 1 (dim+1 used)
    bool Outside = false; ///< outside the graph's convex hull (the facet's weights, clamped)
  };

  /**
   * Builds the graph of `count` points, `xyz` holding 3 coordinates per point, on the calling
   * thread.
   * @param dimension 2 or 3
   */
  DelaunayGraph(int dimension, const double* xyz, std::size_t count);

  /**
   * Work done beside the graph's insertion, job by job: each runs once, on a second task while
   * the points are perturbed and CGAL inserts them (on one thread), and on both tasks once the
   * insertion is done (with one thread, all after it). Independent jobs of similar sizes keep
   * both threads busy until the end (page-faulting first touches, hashes, checks).
   */
  using SideJobs = std::vector<std::function<void()>>;

  /**
   * Builds the same graph (the same bits), its loops over the elements (their order, records
   * and flat-element count) run through `parallelFor`, and runs `duringInsertion` (SideJobs) beside
   * the insertion. An exception of a job (the first in the list's order) is thrown in preference
   * to the graph's own, which the caller's work may explain (its own checks of the input). The
   * jobs run even when the graph's input is rejected.
   */
  DelaunayGraph(int dimension, const double* xyz, std::size_t count, const ParallelFor& parallelFor,
    const SideJobs& duringInsertion);
  ~DelaunayGraph();
  DelaunayGraph(const DelaunayGraph&) = delete;
  DelaunayGraph& operator=(const DelaunayGraph&) = delete;

  /// 2 or 3.
  int GetDimension() const { return this->Dimension; }
  /// Number of vertices of an element: 3 in 2D, 4 in 3D.
  int GetVerticesPerElement() const { return this->Dimension + 1; }
  /// Number of distinct points.
  std::size_t GetNumberOfVertices() const { return this->PointOfVertex.size(); }
  /// Number of finite elements.
  std::size_t GetNumberOfElements() const
  {
    return this->ElementVertices.size() / static_cast<std::size_t>(this->Dimension + 1);
  }
  /// The vertex of each input point (coincident input points share a vertex).
  const std::vector<std::int32_t>& GetVertexOfPoint() const { return this->VertexOfPoint; }
  /// The first input point at each vertex.
  const std::vector<std::int32_t>& GetPointOfVertex() const { return this->PointOfVertex; }
  /// The dim+1 vertices of element `e`.
  const std::int32_t* GetElement(std::int32_t e) const
  {
    return this->ElementVertices.data() + static_cast<std::size_t>(e) * (this->Dimension + 1);
  }
  /// Graph coordinates (x, y, z) of vertex `v` (the perturbed point; z is 0 in 2D).
  const double* GetVertexPosition(std::int32_t v) const
  {
    return this->VertexPositions.data() + 3 * static_cast<std::size_t>(v);
  }

  /**
   * Barycentric coordinates of `p` in element `e` (sub-element volume over element volume).
   * Returns true when all are >= 0, i.e. `p` is in the element up to round-off.
   */
  bool ComputeWeights(std::int32_t e, const double p[3], double weights[4]) const;

  /**
   * Number of elements, positively oriented in the original coordinates, whose orientation is not
   * positive when every vertex is displaced by `vertexDisplacements` (3 doubles per vertex): the
   * graph inversions that make DGM fail. Exact predicates; the elements are visited through
   * `parallelFor`.
   */
  std::size_t CountInvertedElements(
    const double* vertexDisplacements, const ParallelFor& parallelFor = SerialFor) const;

  /// Number of elements that are flat in the original (unperturbed) coordinates.
  std::size_t GetNumberOfFlatElements() const { return this->FlatElements; }

  /// Corners and neighbours of element `e`, as the walk reads them.
  const WalkRecord& GetWalkRecord(std::int32_t e) const
  {
    return this->Records[static_cast<std::size_t>(e)];
  }

  /// Asks the processor to start loading element `e`'s record (no effect on results).
  void PrefetchElement(std::int32_t e) const
  {
    const WalkRecord* record = &this->Records[static_cast<std::size_t>(e)];
    simd::Prefetch(record);
    simd::Prefetch(reinterpret_cast<const char*>(record) + 64);
  }

  /**
   * An element near `p` from which to start a walk: the graph keeps a uniform grid over its
   * bounding box, with an element whose centroid lies in (or, for empty grid cells, near) each
   * grid cell. It depends only on the graph, so walks started from it are deterministic.
   */
  std::int32_t GetSeedElement(const double p[3]) const;

  /// The seed grid's cell containing `p` (clamped to the grid): i + nx (j + ny k) for the cell
  /// (i, j, k) of a grid of nx x ny x nz cells (GetSeedGridGeometry).
  std::size_t GetSeedCell(const double p[3]) const;

  /// The seed grid's geometry: cell (i, j, k) spans Origin + [i, i + 1) / InverseCellSize along x,
  /// and so on; Cells per axis (1 along z in 2D). The graph's vertices span Origin to Upper (0
  /// along z in 2D); the last cell of an axis may reach beyond Upper.
  struct SeedGridGeometry
  {
    double Origin[3];
    double InverseCellSize;
    std::int64_t Cells[3];
    double Upper[3];
  };
  SeedGridGeometry GetSeedGridGeometry() const
  {
    SeedGridGeometry grid{};
    std::copy(this->SeedOrigin, this->SeedOrigin + 3, grid.Origin);
    grid.InverseCellSize = this->SeedInverseSize;
    std::copy(this->SeedCells, this->SeedCells + 3, grid.Cells);
    std::copy(this->SeedUpper, this->SeedUpper + 3, grid.Upper);
    return grid;
  }

  /**
   * Locates `p` with CGAL's exact walk, starting from element `hint` (or CGAL's default start
   * when `hint` < 0). A point outside the convex hull gets the hull element across the hull face
   * it lies beyond, with its barycentric coordinates clamped to >= 0 and normalised, and
   * Outside = true. The fast location of many points is LocateNodes's walks; this is their exact
   * fallback.
   */
  Location LocateExactly(const double p[3], std::int32_t hint) const;

  /// Steps of the visibility walk before CGAL takes over.
  static constexpr int MaximumWalkSteps = 4096;

  /// Approximate memory used by the graph, in bytes.
  std::size_t GetMemorySize() const;

private:
  struct Impl2;
  struct Impl3;
  int Dimension;
  std::unique_ptr<Impl2> Triangulation2;
  std::unique_ptr<Impl3> Triangulation3;
  std::vector<std::int32_t> VertexOfPoint;
  std::vector<std::int32_t> PointOfVertex;
  UninitializedVector<double> VertexPositions;
  UninitializedVector<double> OriginalPositions;
  std::size_t FlatElements = 0;
  UninitializedVector<std::int32_t> ElementVertices;
  UninitializedVector<WalkRecord> Records; ///< corners and neighbours of each element
  /// Seed grid (see GetSeedElement): origin, inverse cell size, cells per axis, element per cell.
  double SeedOrigin[3] = { 0, 0, 0 };
  double SeedUpper[3] = { 0, 0, 0 }; ///< the far corner of the vertices' bounding box
  double SeedInverseSize = 1.0;
  std::int64_t SeedCells[3] = { 1, 1, 1 };
  std::vector<std::int32_t> SeedGrid;
  /// An empty CGAL triangulation with storage for the elements of `count` points.
  void ReserveTriangulation(std::size_t count);
  /// CGAL's triangulation (made by ReserveTriangulation) of the perturbed points (3 coordinates
  /// each).
  void InsertPoints(const std::vector<double>& moved, std::size_t count);
  /// The vertices' numbers, the elements' order, records and seed grid, and the flat elements.
  void BuildElements(
    const double* xyz, const std::vector<double>& moved, const ParallelFor& parallelFor);
  void BuildSeedGrid(const ParallelFor& parallelFor);
};

/// Appends to `jobs` one side job per part of `parts`: its first touch (FirstTouch).
void AppendFirstTouchJobs(const std::vector<FirstTouchPart>& parts, DelaunayGraph::SideJobs& jobs);

} // namespace dgmf

#endif
