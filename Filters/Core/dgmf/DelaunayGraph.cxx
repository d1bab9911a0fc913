#include "dgmf/DelaunayGraph.h"

#include "dgmf/GraphPerturbation.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace dgmf
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, Kernel>;
using Fb2 = CGAL::Triangulation_face_base_with_info_2<std::int32_t, Kernel>;
using Tds2 = CGAL::Triangulation_data_structure_2<Vb2, Fb2>;
using Delaunay2 = CGAL::Delaunay_triangulation_2<Kernel, Tds2>;

using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, Kernel>;
using Cb3 = CGAL::Triangulation_cell_base_with_info_3<std::int32_t, Kernel,
  CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3, Cb3>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<Kernel, Tds3>;

/**
 * A point whose barycentric coordinates are all >= -WeightTolerance is taken to be in the element:
 * points on a shared face (common in structured meshes, where nodes lie on the segments between
 * boundary nodes) come out a few ulps negative in one of the two elements, and must not send every
 * such node on a walk. Such weights are clamped to 0 afterwards.
 */
constexpr double WeightTolerance = 1e-12;

inline double Cross2(const double a[2], const double b[2])
{
  return a[0] * b[1] - a[1] * b[0];
}

inline void Cross3(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

inline double Dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Makes weights non-negative and summing to 1 (used for points outside the hull or round-off).
void ClampWeights(double* w, int n)
{
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    w[i] = w[i] > 0.0 ? w[i] : 0.0;
    sum += w[i];
  }
  if (sum > 0.0)
  {
    for (int i = 0; i < n; ++i)
    {
      w[i] /= sum;
    }
  }
  else
  {
    for (int i = 0; i < n; ++i)
    {
      w[i] = 1.0 / n;
    }
  }
}

void CheckFinite(const double* xyz, std::size_t count, int dimension)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < dimension; ++c)
    {
      if (!std::isfinite(xyz[3 * i + c]))
      {
        throw std::invalid_argument(
          "DelaunayGraph: boundary point " + std::to_string(i) + " has a non-finite coordinate");
      }
    }
  }
}
} // namespace

struct DelaunayGraph::Impl2
{
  Delaunay2 Triangulation;
  std::vector<Delaunay2::Face_handle> Faces;
};

struct DelaunayGraph::Impl3
{
  Delaunay3 Triangulation;
  std::vector<Delaunay3::Cell_handle> Cells;
};

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
    if (handleOfPoint[i] == VertexHandle() || static_cast<std::size_t>(handleOfPoint[i]->info()) != i)
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
/**
 * Orders the finite elements along a Hilbert curve through their centroids, so elements close in
 * space are close in memory: a walk then mostly stays in cache.
 */
template <typename Triangulation, typename Handle, typename Iterator>
std::vector<Handle> HilbertOrderedElements(Iterator begin, Iterator end, int corners)
{
  std::vector<Handle> handles;
  for (Iterator it = begin; it != end; ++it)
  {
    handles.push_back(it);
  }
  std::vector<std::size_t> order(handles.size());
  std::iota(order.begin(), order.end(), 0);
  if (corners == 3)
  {
    std::vector<Kernel::Point_2> centroids;
    centroids.reserve(handles.size());
    for (const Handle& h : handles)
    {
      centroids.push_back(CGAL::centroid(h->vertex(0)->point(), h->vertex(1)->point(), h->vertex(2)->point()));
    }
    using Traits = CGAL::Spatial_sort_traits_adapter_2<Kernel,
      CGAL::Pointer_property_map<Kernel::Point_2>::type>;
    CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(centroids.data())));
  }
  std::vector<Handle> ordered;
  ordered.reserve(handles.size());
  for (std::size_t k : order)
  {
    ordered.push_back(handles[k]);
  }
  return ordered;
}

template <typename Handle, typename Iterator>
std::vector<Handle> HilbertOrderedCells(Iterator begin, Iterator end)
{
  std::vector<Handle> handles;
  std::vector<Kernel::Point_3> centroids;
  for (Iterator it = begin; it != end; ++it)
  {
    handles.push_back(it);
    centroids.push_back(CGAL::centroid(it->vertex(0)->point(), it->vertex(1)->point(),
      it->vertex(2)->point(), it->vertex(3)->point()));
  }
  std::vector<std::size_t> order(handles.size());
  std::iota(order.begin(), order.end(), 0);
  using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel,
    CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(centroids.data())));
  std::vector<Handle> ordered;
  ordered.reserve(handles.size());
  for (std::size_t k : order)
  {
    ordered.push_back(handles[k]);
  }
  return ordered;
}
} // namespace

DelaunayGraph::DelaunayGraph(int dimension, const double* xyz, std::size_t count)
  : Dimension(dimension)
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
    throw std::invalid_argument(dimension == 2
        ? "DelaunayGraph: the 2D boundary points are all collinear (or fewer than 3 distinct "
          "points): no triangle can be built"
        : "DelaunayGraph: the 3D boundary points are all coplanar (or fewer than 4 distinct "
          "points): no tetrahedron can be built");
  }
  const int n = dimension + 1;
  // The graph is built on the points moved by GraphPerturbation of their nearest-neighbour
  // distance: see GraphPerturbation.h.
  const std::vector<double> moved = PerturbPoints(dimension, xyz, count, GraphPerturbation);

  if (dimension == 2)
  {
    using Point = Kernel::Point_2;
    std::vector<std::pair<Point, std::int32_t>> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      points.emplace_back(Point(moved[3 * i], moved[3 * i + 1]), static_cast<std::int32_t>(i));
    }
    this->Triangulation2 = std::make_unique<Impl2>();
    Delaunay2& t = this->Triangulation2->Triangulation;
    t.insert(points.begin(), points.end());
    if (t.dimension() < 2)
    {
      throw std::invalid_argument("DelaunayGraph: the 2D boundary points are all collinear "
                                  "(or fewer than 3 distinct points): no triangle can be built");
    }
    NumberVertices<Delaunay2, Delaunay2::Vertex_handle>(
      t, count,
      [&](std::size_t i)
      {
        Delaunay2::Locate_type lt;
        int li;
        Delaunay2::Face_handle f = t.locate(points[i].first, lt, li);
        return f->vertex(li);
      },
      this->VertexOfPoint, this->PointOfVertex);
    std::vector<Delaunay2::Face_handle>& faces = this->Triangulation2->Faces;
    faces = HilbertOrderedElements<Delaunay2, Delaunay2::Face_handle>(
      t.finite_faces_begin(), t.finite_faces_end(), 3);
    this->ElementVertices.reserve(n * faces.size());
    for (std::size_t e = 0; e < faces.size(); ++e)
    {
      faces[e]->info() = static_cast<std::int32_t>(e);
      for (int k = 0; k < 3; ++k)
      {
        this->ElementVertices.push_back(faces[e]->vertex(k)->info());
      }
    }
    this->ElementNeighbors.reserve(this->ElementVertices.size());
    for (const Delaunay2::Face_handle& f : faces)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Delaunay2::Face_handle g = f->neighbor(k);
        this->ElementNeighbors.push_back(t.is_infinite(g) ? -1 : g->info());
      }
    }
  }
  else
  {
    using Point = Kernel::Point_3;
    std::vector<std::pair<Point, std::int32_t>> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      points.emplace_back(
        Point(moved[3 * i], moved[3 * i + 1], moved[3 * i + 2]), static_cast<std::int32_t>(i));
    }
    this->Triangulation3 = std::make_unique<Impl3>();
    Delaunay3& t = this->Triangulation3->Triangulation;
    t.insert(points.begin(), points.end());
    if (t.dimension() < 3)
    {
      throw std::invalid_argument("DelaunayGraph: the 3D boundary points are all coplanar "
                                  "(or fewer than 4 distinct points): no tetrahedron can be built");
    }
    NumberVertices<Delaunay3, Delaunay3::Vertex_handle>(
      t, count,
      [&](std::size_t i)
      {
        Delaunay3::Locate_type lt;
        int li, lj;
        Delaunay3::Cell_handle c = t.locate(points[i].first, lt, li, lj);
        return c->vertex(li);
      },
      this->VertexOfPoint, this->PointOfVertex);
    std::vector<Delaunay3::Cell_handle>& cells = this->Triangulation3->Cells;
    cells = HilbertOrderedCells<Delaunay3::Cell_handle>(t.finite_cells_begin(), t.finite_cells_end());
    this->ElementVertices.reserve(n * cells.size());
    for (std::size_t e = 0; e < cells.size(); ++e)
    {
      cells[e]->info() = static_cast<std::int32_t>(e);
      for (int k = 0; k < 4; ++k)
      {
        this->ElementVertices.push_back(cells[e]->vertex(k)->info());
      }
    }
    // Infinite cells get -1, so a walk ending outside the hull is recognised.
    for (auto c = t.all_cells_begin(); c != t.all_cells_end(); ++c)
    {
      if (t.is_infinite(c))
      {
        c->info() = -1;
      }
    }
    this->ElementNeighbors.reserve(this->ElementVertices.size());
    for (const Delaunay3::Cell_handle& c : cells)
    {
      for (int k = 0; k < 4; ++k)
      {
        this->ElementNeighbors.push_back(c->neighbor(k)->info());
      }
    }
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
  // instead of chasing four vertex indices.
  const std::size_t elements = this->GetNumberOfElements();
  this->ElementCorners.resize(elements * 3 * static_cast<std::size_t>(n));
  for (std::size_t e = 0; e < elements; ++e)
  {
    const std::int32_t* v = this->GetElement(static_cast<std::int32_t>(e));
    for (int k = 0; k < n; ++k)
    {
      std::copy(this->GetVertexPosition(v[k]), this->GetVertexPosition(v[k]) + 3,
        this->ElementCorners.begin() + (e * n + k) * 3);
    }
  }
  // Elements that are flat in the original coordinates: artefacts of coplanar or cospherical
  // boundary points, given a tiny volume by the perturbation.
  this->FlatElements = this->CountInvertedElements(nullptr);
}

DelaunayGraph::~DelaunayGraph() = default;

bool DelaunayGraph::ComputeWeights(std::int32_t e, const double p[3], double w[4]) const
{
  const double* corners = this->ElementCorners.data() + static_cast<std::size_t>(e) * 3 * (this->Dimension + 1);
  double total;
  if (this->Dimension == 2)
  {
    double rel[3][2];
    for (int k = 0; k < 3; ++k)
    {
      const double* x = corners + 3 * k;
      rel[k][0] = x[0] - p[0];
      rel[k][1] = x[1] - p[1];
    }
    // Twice the signed areas of the sub-triangles opposite each vertex.
    w[0] = Cross2(rel[1], rel[2]);
    w[1] = Cross2(rel[2], rel[0]);
    w[2] = Cross2(rel[0], rel[1]);
    total = w[0] + w[1] + w[2];
    if (!(total > 0.0))
    {
      return false;
    }
    const double inv = 1.0 / total;
    w[0] *= inv;
    w[1] *= inv;
    w[2] *= inv;
    return w[0] >= -WeightTolerance && w[1] >= -WeightTolerance && w[2] >= -WeightTolerance;
  }
  double a[3], b[3], c[3], d[3];
  const double* x0 = corners;
  const double* x1 = corners + 3;
  const double* x2 = corners + 6;
  const double* x3 = corners + 9;
  for (int k = 0; k < 3; ++k)
  {
    a[k] = x0[k] - p[k];
    b[k] = x1[k] - p[k];
    c[k] = x2[k] - p[k];
    d[k] = x3[k] - p[k];
  }
  // Six times the signed volumes of the sub-tetrahedra opposite each vertex.
  double cd[3], ab[3];
  Cross3(c, d, cd);
  Cross3(a, b, ab);
  w[0] = Dot3(b, cd);
  w[1] = -Dot3(a, cd);
  w[2] = Dot3(ab, d);
  w[3] = -Dot3(ab, c);
  total = w[0] + w[1] + w[2] + w[3];
  if (!(total > 0.0))
  {
    return false;
  }
  const double inv = 1.0 / total;
  for (int k = 0; k < 4; ++k)
  {
    w[k] *= inv;
  }
  return w[0] >= -WeightTolerance && w[1] >= -WeightTolerance && w[2] >= -WeightTolerance &&
    w[3] >= -WeightTolerance;
}

bool DelaunayGraph::Walk(const double p[3], std::int32_t start, int maximumSteps, Location& result) const
{
  // Visibility walk: cross the face opposite the most negative barycentric coordinate.
  const int n = this->Dimension + 1;
  std::int32_t e = start;
  for (int step = 0; step <= maximumSteps; ++step)
  {
    if (this->ComputeWeights(e, p, result.Weights))
    {
      result.Element = e;
      result.Outside = false;
      ClampWeights(result.Weights, n);
      return true;
    }
    int most = 0;
    for (int k = 1; k < n; ++k)
    {
      most = result.Weights[k] < result.Weights[most] ? k : most;
    }
    const std::int32_t next = this->GetNeighbors(e)[most];
    if (next < 0)
    {
      return false; // leaving the hull: CGAL decides exactly
    }
    e = next;
  }
  return false;
}

DelaunayGraph::Location DelaunayGraph::Locate(const double p[3], std::int32_t hint) const
{
  Location result;
  if (hint >= 0 && this->Walk(p, hint, MaximumWalkSteps, result))
  {
    return result;
  }
  std::int32_t element = -1;
  if (this->Dimension == 2)
  {
    const Delaunay2& t = this->Triangulation2->Triangulation;
    Delaunay2::Locate_type lt;
    int li;
    Delaunay2::Face_handle start =
      hint >= 0 ? this->Triangulation2->Faces[static_cast<std::size_t>(hint)] : Delaunay2::Face_handle();
    Delaunay2::Face_handle f = t.locate(Kernel::Point_2(p[0], p[1]), lt, li, start);
    if (t.is_infinite(f))
    {
      result.Outside = true;
      f = f->neighbor(f->index(t.infinite_vertex()));
    }
    element = f->info();
  }
  else
  {
    const Delaunay3& t = this->Triangulation3->Triangulation;
    Delaunay3::Locate_type lt;
    int li, lj;
    Delaunay3::Cell_handle start =
      hint >= 0 ? this->Triangulation3->Cells[static_cast<std::size_t>(hint)] : Delaunay3::Cell_handle();
    Delaunay3::Cell_handle c = t.locate(Kernel::Point_3(p[0], p[1], p[2]), lt, li, lj, start);
    if (t.is_infinite(c))
    {
      result.Outside = true;
      c = c->neighbor(c->index(t.infinite_vertex()));
    }
    element = c->info();
  }
  result.Element = element;
  if (!this->ComputeWeights(element, p, result.Weights))
  {
    // Inside according to CGAL's exact predicates, but round-off made a weight slightly negative
    // (or the point is outside the hull): project onto the element.
    ClampWeights(result.Weights, this->Dimension + 1);
  }
  return result;
}

std::size_t DelaunayGraph::CountInvertedElements(const double* displacements) const
{
  std::size_t inverted = 0;
  const std::size_t elements = this->GetNumberOfElements();
  const int n = this->Dimension + 1;
  for (std::size_t e = 0; e < elements; ++e)
  {
    const std::int32_t* v = this->GetElement(static_cast<std::int32_t>(e));
    double before[4][3], after[4][3];
    for (int k = 0; k < n; ++k)
    {
      const double* x = this->OriginalPositions.data() + 3 * static_cast<std::size_t>(v[k]);
      const double* d = displacements ? displacements + 3 * static_cast<std::size_t>(v[k]) : nullptr;
      for (int c = 0; c < 3; ++c)
      {
        before[k][c] = x[c];
        after[k][c] = d ? x[c] + d[c] : x[c];
      }
    }
    auto orientation = [this](const double (*q)[3])
    {
      if (this->Dimension == 2)
      {
        return CGAL::orientation(Kernel::Point_2(q[0][0], q[0][1]), Kernel::Point_2(q[1][0], q[1][1]),
          Kernel::Point_2(q[2][0], q[2][1]));
      }
      return CGAL::orientation(Kernel::Point_3(q[0][0], q[0][1], q[0][2]),
        Kernel::Point_3(q[1][0], q[1][1], q[1][2]), Kernel::Point_3(q[2][0], q[2][1], q[2][2]),
        Kernel::Point_3(q[3][0], q[3][1], q[3][2]));
    };
    if (!displacements)
    {
      inverted += orientation(before) != CGAL::POSITIVE ? 1 : 0; // counting flat elements
    }
    else if (orientation(before) == CGAL::POSITIVE && orientation(after) != CGAL::POSITIVE)
    {
      ++inverted;
    }
  }
  return inverted;
}

std::size_t DelaunayGraph::GetMemorySize() const
{
  std::size_t bytes = this->VertexOfPoint.capacity() * sizeof(std::int32_t) +
    this->PointOfVertex.capacity() * sizeof(std::int32_t) +
    (this->VertexPositions.capacity() + this->OriginalPositions.capacity()) * sizeof(double) +
    this->ElementVertices.capacity() * sizeof(std::int32_t) +
    this->ElementNeighbors.capacity() * sizeof(std::int32_t) +
    this->ElementCorners.capacity() * sizeof(double);
  if (this->Triangulation2)
  {
    const Delaunay2& t = this->Triangulation2->Triangulation;
    bytes += t.number_of_vertices() * sizeof(Delaunay2::Vertex) +
      t.number_of_faces() * 2 * sizeof(Delaunay2::Face) +
      this->Triangulation2->Faces.capacity() * sizeof(Delaunay2::Face_handle);
  }
  if (this->Triangulation3)
  {
    const Delaunay3& t = this->Triangulation3->Triangulation;
    bytes += t.number_of_vertices() * sizeof(Delaunay3::Vertex) +
      t.number_of_cells() * sizeof(Delaunay3::Cell) +
      this->Triangulation3->Cells.capacity() * sizeof(Delaunay3::Cell_handle);
  }
  return bytes;
}

} // namespace dgmf
