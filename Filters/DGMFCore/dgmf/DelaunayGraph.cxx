#include "dgmf/DelaunayGraph.h"

#include "dgmf/DelaunayGraphCgal.h"
#include "dgmf/Finite.h"

#include "dgmf/GraphPerturbation.h"

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace dgmf
{
using namespace graph_cgal;

namespace
{
/// Why no graph can be built on points that do not span the dimension (checked before CGAL, and
/// after it for what the exact predicates alone see).
const char* NotSpanningMessage(int dimension)
{
  return dimension == 2
    ? "DelaunayGraph: the 2D boundary points are all collinear (or fewer than 3 distinct "
      "points): no triangle can be built"
    : "DelaunayGraph: the 3D boundary points are all coplanar (or fewer than 4 distinct "
      "points): no tetrahedron can be built";
}

void CheckFinite(const double* xyz, std::size_t count, int dimension)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < dimension; ++c)
    {
      if (!(std::abs(xyz[3 * i + c]) < kLargestMagnitude))
      {
        throw std::invalid_argument("DelaunayGraph: boundary point " + std::to_string(i) +
          " has a non-finite coordinate, or one of magnitude " + kLargestMagnitudeText +
          " or more");
      }
    }
  }
}
} // namespace

namespace
{
/**
 * Shared part of the 2D and 3D construction: numbers the vertices in the order of their first
 * input point, so vertex numbering follows the input order and does not depend on CGAL's.
 */
template <typename Triangulation, typename VertexHandle, typename LocatePoint>
void NumberVertices(Triangulation& t, std::size_t count, const LocatePoint& locateVertex,
  std::vector<std::int32_t>& vertexOfPoint, std::vector<std::int32_t>& pointOfVertex)
{
  std::vector<VertexHandle> handleOfPoint(count);
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
  {
    handleOfPoint[static_cast<std::size_t>(v->info())] = v;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (handleOfPoint[i] == VertexHandle() ||
      static_cast<std::size_t>(handleOfPoint[i]->info()) != i)
    {
      // A point coincident with another one: CGAL kept a single vertex for both.
      handleOfPoint[i] = locateVertex(i);
    }
  }
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
  {
    v->info() = -1;
  }
  vertexOfPoint.assign(count, -1);
  pointOfVertex.clear();
  pointOfVertex.reserve(t.number_of_vertices());
  for (std::size_t i = 0; i < count; ++i)
  {
    VertexHandle v = handleOfPoint[i];
    if (v->info() < 0)
    {
      v->info() = static_cast<std::int32_t>(pointOfVertex.size());
      pointOfVertex.push_back(static_cast<std::int32_t>(i));
    }
    vertexOfPoint[i] = v->info();
  }
}
/// The traits CGAL's Hilbert sort needs for (point, handle) pairs of a 2D or 3D kernel point.
template <typename Point, typename Handle>
using PairSortTraits = std::conditional_t<std::is_same<Point, Kernel::Point_2>::value,
  CGAL::Spatial_sort_traits_adapter_2<Kernel,
    CGAL::First_of_pair_property_map<std::pair<Point, Handle>>>,
  CGAL::Spatial_sort_traits_adapter_3<Kernel,
    CGAL::First_of_pair_property_map<std::pair<Point, Handle>>>>;

/**
 * Orders the finite elements (triangles or tetrahedra, `corners` vertices) by the vertices' order
 * along CGAL's Hilbert curve through them: each element goes with its first vertex on the curve
 * (a counting sort), so elements close in space are close in memory and a walk mostly stays in
 * cache. Sorting the vertices instead of the elements' centroids (6 times as many, the order of
 * issue 5) cut the ordering from 87 to 17 ms on the wing-body's 260,759 elements, for the same
 * location time within 10 %. Elements with the same first vertex follow the order of their other
 * vertices on the curve, and the curve is drawn through the vertices given in the order of their
 * coordinates, so the order is a function of the points alone: not of CGAL's storage (whose
 * iteration order changes with ReserveTriangulation), nor of the input's numbering. The
 * vertices' info() must be their numbers 0 .. vertices - 1; `atMost` bounds the number of
 * elements (storage reserved once).
 */
template <typename Handle, typename Triangulation, typename ElementIterator>
UninitializedVector<Handle> HilbertOrderedElements(Triangulation& t, ElementIterator begin,
  ElementIterator end, std::size_t atMost, int corners, const ParallelFor& parallelFor)
{
  using Vertex = typename Triangulation::Vertex_handle;
  using Point = typename Triangulation::Point;
  UninitializedVector<std::pair<Point, Vertex>> vertices;
  vertices.reserve(t.number_of_vertices());
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
  {
    vertices.emplace_back(v->point(), v);
  }
  // CGAL's Hilbert sort leaves a box's points in their given order when they all fall in one
  // quarter of it: given in the order of their coordinates, not in CGAL's storage order.
  std::sort(vertices.begin(), vertices.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  CGAL::hilbert_sort(vertices.begin(), vertices.end(), PairSortTraits<Point, Vertex>(),
    CGAL::Hilbert_sort_middle_policy());
  UninitializedVector<std::size_t> rank(vertices.size()); // every vertex's, below
  for (std::size_t r = 0; r < vertices.size(); ++r)
  {
    rank[static_cast<std::size_t>(vertices[r].second->info())] = r;
  }
  UninitializedVector<Handle> elements;
  elements.reserve(atMost);
  for (ElementIterator e = begin; e != end; ++e)
  {
    elements.push_back(e);
  }
  // Each element's vertices' ranks in increasing order (an element is its vertex set): the
  // first picks its place on the curve, the others order the elements that share that first
  // vertex, so the order does not depend on where CGAL keeps the elements.
  // The first rank in `first`, the other three packed for the tie-break (Keyed).
  struct Keyed
  {
    std::uint64_t Second = 0; ///< the second and third ranks
    std::uint32_t Fourth = 0;
    std::uint32_t Element = 0;
    bool operator<(const Keyed& other) const
    {
      return this->Second < other.Second ||
        (this->Second == other.Second && this->Fourth < other.Fourth);
    }
  };
  // The arrays on huge pages (HugePages.h), written by the threads.
  UninitializedVector<std::uint32_t> first(elements.size());
  UninitializedVector<Keyed> keyed(elements.size());
  ForEachIndex(parallelFor, elements.size(), ElementBlock,
    [&](std::size_t e)
    {
      std::uint32_t r[4] = { std::numeric_limits<std::uint32_t>::max(),
        std::numeric_limits<std::uint32_t>::max(), std::numeric_limits<std::uint32_t>::max(),
        std::numeric_limits<std::uint32_t>::max() };
      for (int k = 0; k < corners; ++k)
      {
        r[k] = static_cast<std::uint32_t>(
          rank[static_cast<std::size_t>(elements[e]->vertex(k)->info())]);
      }
      // A sorting network of four.
      const auto order = [&r](int a, int b)
      {
        const std::uint32_t low = std::min(r[a], r[b]);
        r[b] = std::max(r[a], r[b]);
        r[a] = low;
      };
      order(0, 1);
      order(2, 3);
      order(0, 2);
      order(1, 3);
      order(1, 2);
      first[e] = r[0];
      keyed[e] = { (std::uint64_t(r[1]) << 32) | r[2], r[3], static_cast<std::uint32_t>(e) };
    });
  std::vector<std::size_t> start(vertices.size() + 1, 0);
  for (const std::uint32_t r : first)
  {
    ++start[r + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  // Each vertex's few elements, in contiguous memory, put in order by an insertion sort.
  UninitializedVector<Keyed> sorted(elements.size());
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e < elements.size(); ++e)
    {
      sorted[next[first[e]]++] = keyed[e];
    }
  }
  ForEachIndex(parallelFor, (vertices.size() + ElementBlock - 1) / ElementBlock, 1,
    [&](std::size_t block)
    {
      const std::size_t end = std::min(vertices.size(), (block + 1) * ElementBlock);
      for (std::size_t r = block * ElementBlock; r < end; ++r)
      {
        for (std::size_t i = start[r] + 1; i < start[r + 1]; ++i)
        {
          const Keyed moving = sorted[i];
          std::size_t j = i;
          for (; j > start[r] && moving < sorted[j - 1]; --j)
          {
            sorted[j] = sorted[j - 1];
          }
          sorted[j] = moving;
        }
      }
    });
  UninitializedVector<Handle> ordered(elements.size());
  ForEachIndex(parallelFor, elements.size(), ElementBlock,
    [&](std::size_t e) { ordered[e] = elements[sorted[e].Element]; });
  return ordered;
}

/// Numbers the ordered elements (their info() becomes their index) and lists their `corners`
/// vertices, element after element.
template <typename Handle>
void NumberElements(const UninitializedVector<Handle>& elements, int corners,
  UninitializedVector<std::int32_t>& elementVertices, const ParallelFor& parallelFor)
{
  const auto n = static_cast<std::size_t>(corners);
  elementVertices.resize(n * elements.size());
  ForEachIndex(parallelFor, elements.size(), ElementBlock,
    [&](std::size_t e)
    {
      elements[e]->info() = static_cast<std::int32_t>(e);
      for (std::size_t k = 0; k < n; ++k)
      {
        elementVertices[n * e + k] = elements[e]->vertex(static_cast<int>(k))->info();
      }
    });
}
} // namespace

DelaunayGraph::DelaunayGraph(int dimension, const double* xyz, std::size_t count)
  : DelaunayGraph(dimension, xyz, count, SerialFor, SideJobs())
{
}

DelaunayGraph::DelaunayGraph(int dimension, const double* xyz, std::size_t count,
  const ParallelFor& parallelFor, const SideJobs& duringInsertion)
  : Dimension(dimension)
{
  // The graph is built on the points moved by GraphPerturbation of their nearest-neighbour
  // distance: see GraphPerturbation.h.
  std::vector<double> moved;
  std::exception_ptr failure[2];
  try
  {
    if (dimension != 2 && dimension != 3)
    {
      throw std::invalid_argument("DelaunayGraph: dimension must be 2 or 3");
    }
    if (count > static_cast<std::size_t>(INT32_MAX))
    {
      throw std::invalid_argument("DelaunayGraph: too many boundary points");
    }
    CheckFinite(xyz, count, dimension);
    if (!SpansDimension(dimension, xyz, count))
    {
      throw std::invalid_argument(NotSpanningMessage(dimension));
    }
  }
  catch (...)
  {
    failure[0] = std::current_exception();
  }
  // The perturbation and CGAL's insertion are sequential (CGAL's parallel insertion, with TBB,
  // was no faster on 2 threads: speed.md): the caller's jobs run beside them, then on both tasks.
  std::atomic<std::size_t> nextJob{ 0 };
  std::vector<std::exception_ptr> jobFailures(duringInsertion.size());
  const auto runJobs = [&]()
  {
    for (std::size_t j = nextJob++; j < duringInsertion.size(); j = nextJob++)
    {
      try
      {
        if (duringInsertion[j])
        {
          duringInsertion[j]();
        }
      }
      catch (...)
      {
        jobFailures[j] = std::current_exception();
      }
    }
  };
  ForEachBlock(parallelFor, 2,
    [&](std::size_t task)
    {
      if (task == 0 && !failure[0])
      {
        try
        {
          // CGAL's storage first, before the side jobs' first touches get going (see
          // ReserveStorage).
          this->ReserveTriangulation(count);
          moved = PerturbPoints(dimension, xyz, count, GraphPerturbation);
          this->InsertPoints(moved, count);
        }
        catch (...)
        {
          failure[0] = std::current_exception();
        }
      }
      runJobs();
    });
  jobFailures.push_back(failure[0]);
  for (const std::exception_ptr& thrown : jobFailures)
  {
    if (thrown)
    {
      std::rethrow_exception(thrown);
    }
  }
  this->BuildElements(xyz, moved, parallelFor);
}

namespace
{
/// Elements (finite and infinite) per point that CGAL's storage is given before the insertion:
/// a Delaunay tetrahedralisation has about 6.2 to 6.8 per point (the benchmark's boundary 6.19,
/// the wing-body's 6.39, uniform random points 6.77), a triangulation about 2.
constexpr double CellsPerPoint3 = 6.5;
constexpr double FacesPerPoint2 = 2.0;

/**
 * Gives CGAL's element and vertex containers the storage of `perPoint` elements per point before
 * the insertion (the same triangulation; CGAL's iteration order differs, see speed.md, "In a new
 * process"). Growing the heap during the insertion takes the address space's lock, which the other
 * thread's first touches (FirstTouch, MADV_POPULATE_WRITE) hold in turns: in a new process that
 * made the insertion 0.15 s slower at 8.26M nodes. More elements than reserved are allocated as
 * usual.
 */
template <typename Elements, typename Vertices>
void ReserveStorage(Elements& elements, Vertices& vertices, double perPoint, std::size_t count)
{
  elements.reserve(static_cast<std::size_t>(perPoint * static_cast<double>(count)) + 16);
  vertices.reserve(count + 1); // and the infinite vertex
}
} // namespace

void AppendFirstTouchJobs(const std::vector<FirstTouchPart>& parts, DelaunayGraph::SideJobs& jobs)
{
  for (const FirstTouchPart& part : parts)
  {
    jobs.emplace_back([part]() { FirstTouch(part.Begin, part.Bytes); });
  }
}

void DelaunayGraph::ReserveTriangulation(std::size_t count)
{
  if (this->Dimension == 2)
  {
    this->Triangulation2 = std::make_unique<Impl2>();
    Delaunay2& t = this->Triangulation2->Triangulation;
    ReserveStorage(t.tds().faces(), t.tds().vertices(), FacesPerPoint2, count);
    return;
  }
  this->Triangulation3 = std::make_unique<Impl3>();
  Delaunay3& t = this->Triangulation3->Triangulation;
  ReserveStorage(t.tds().cells(), t.tds().vertices(), CellsPerPoint3, count);
}

void DelaunayGraph::InsertPoints(const std::vector<double>& moved, std::size_t count)
{
  if (this->Dimension == 2)
  {
    using Point = Kernel::Point_2;
    std::vector<std::pair<Point, std::int32_t>> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      points.emplace_back(Point(moved[3 * i], moved[3 * i + 1]), static_cast<std::int32_t>(i));
    }
    Delaunay2& t = this->Triangulation2->Triangulation;
    t.insert(points.begin(), points.end());
    if (t.dimension() < 2)
    {
      throw std::invalid_argument(NotSpanningMessage(2));
    }
    return;
  }
  using Point = Kernel::Point_3;
  std::vector<std::pair<Point, std::int32_t>> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    points.emplace_back(
      Point(moved[3 * i], moved[3 * i + 1], moved[3 * i + 2]), static_cast<std::int32_t>(i));
  }
  Delaunay3& t = this->Triangulation3->Triangulation;
  t.insert(points.begin(), points.end());
  if (t.dimension() < 3)
  {
    throw std::invalid_argument(NotSpanningMessage(3));
  }
}

void DelaunayGraph::BuildElements(
  const double* xyz, const std::vector<double>& moved, const ParallelFor& parallelFor)
{
  const int dimension = this->Dimension;
  const int n = dimension + 1;
  const std::size_t count = moved.size() / 3;
  if (dimension == 2)
  {
    Delaunay2& t = this->Triangulation2->Triangulation;
    NumberVertices<Delaunay2, Delaunay2::Vertex_handle>(
      t, count,
      [&](std::size_t i)
      {
        Delaunay2::Locate_type lt;
        int li;
        Delaunay2::Face_handle f =
          t.locate(Kernel::Point_2(moved[3 * i], moved[3 * i + 1]), lt, li);
        return f->vertex(li);
      },
      this->VertexOfPoint, this->PointOfVertex);
    UninitializedVector<Delaunay2::Face_handle>& faces = this->Triangulation2->Faces;
    faces = HilbertOrderedElements<Delaunay2::Face_handle>(
      t, t.finite_faces_begin(), t.finite_faces_end(), t.tds().number_of_faces(), 3, parallelFor);
    NumberElements(faces, n, this->ElementVertices, parallelFor);
    this->Records.resize(faces.size());
    ForEachIndex(parallelFor, faces.size(), ElementBlock,
      [&](std::size_t e)
      {
        for (int k = 0; k < 3; ++k)
        {
          const Delaunay2::Face_handle g = faces[e]->neighbor(k);
          this->Records[e].Neighbors[k] = t.is_infinite(g) ? -1 : g->info();
        }
        this->Records[e].Neighbors[3] = -1;
      });
  }
  else
  {
    Delaunay3& t = this->Triangulation3->Triangulation;
    NumberVertices<Delaunay3, Delaunay3::Vertex_handle>(
      t, count,
      [&](std::size_t i)
      {
        Delaunay3::Locate_type lt;
        int li, lj;
        Delaunay3::Cell_handle c =
          t.locate(Kernel::Point_3(moved[3 * i], moved[3 * i + 1], moved[3 * i + 2]), lt, li, lj);
        return c->vertex(li);
      },
      this->VertexOfPoint, this->PointOfVertex);
    UninitializedVector<Delaunay3::Cell_handle>& cells = this->Triangulation3->Cells;
    cells = HilbertOrderedElements<Delaunay3::Cell_handle>(
      t, t.finite_cells_begin(), t.finite_cells_end(), t.number_of_cells(), 4, parallelFor);
    // Infinite cells keep -1, so a walk ending outside the hull is recognised.
    for (auto c = t.all_cells_begin(); c != t.all_cells_end(); ++c)
    {
      c->info() = -1;
    }
    NumberElements(cells, n, this->ElementVertices, parallelFor);
    this->Records.resize(cells.size());
    ForEachIndex(parallelFor, cells.size(), ElementBlock,
      [&](std::size_t e)
      {
        for (int k = 0; k < 4; ++k)
        {
          this->Records[e].Neighbors[k] = cells[e]->neighbor(k)->info();
        }
      });
  }

  this->VertexPositions.resize(3 * this->PointOfVertex.size());
  this->OriginalPositions.resize(3 * this->PointOfVertex.size());
  for (std::size_t v = 0; v < this->PointOfVertex.size(); ++v)
  {
    const auto point = static_cast<std::size_t>(this->PointOfVertex[v]);
    for (int c = 0; c < 3; ++c)
    {
      this->VertexPositions[3 * v + c] = moved[3 * point + c];
      this->OriginalPositions[3 * v + c] = c < dimension ? xyz[3 * point + c] : 0.0;
    }
  }
  // Each element's corner coordinates, stored with the element: a walk step reads one record
  // instead of chasing the vertex indices.
  ForEachIndex(parallelFor, this->GetNumberOfElements(), ElementBlock,
    [&](std::size_t e)
    {
      const std::int32_t* v = this->GetElement(static_cast<std::int32_t>(e));
      WalkRecord& record = this->Records[e];
      for (int k = 0; k < 4; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          record.Corners[k][c] = k < n ? this->GetVertexPosition(v[k])[c] : 0.0;
        }
      }
    });
  this->BuildSeedGrid(parallelFor);
  // Elements that are flat in the original coordinates: artefacts of coplanar or cospherical
  // boundary points, given a tiny volume by the perturbation.
  this->FlatElements = this->CountInvertedElements(nullptr, parallelFor);
}

} // namespace dgmf
