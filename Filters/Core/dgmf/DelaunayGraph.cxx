#include "dgmf/DelaunayGraph.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
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
  const int n = dimension + 1;

  if (dimension == 2)
  {
    using Point = Kernel::Point_2;
    std::vector<std::pair<Point, std::int32_t>> points;
    points.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      points.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1]), static_cast<std::int32_t>(i));
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
    faces.reserve(t.number_of_faces());
    this->ElementVertices.reserve(n * t.number_of_faces());
    for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f)
    {
      f->info() = static_cast<std::int32_t>(faces.size());
      faces.push_back(f);
      for (int k = 0; k < 3; ++k)
      {
        this->ElementVertices.push_back(f->vertex(k)->info());
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
        Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), static_cast<std::int32_t>(i));
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
    cells.reserve(t.number_of_finite_cells());
    this->ElementVertices.reserve(n * t.number_of_finite_cells());
    for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c)
    {
      c->info() = static_cast<std::int32_t>(cells.size());
      cells.push_back(c);
      for (int k = 0; k < 4; ++k)
      {
        this->ElementVertices.push_back(c->vertex(k)->info());
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
  }

  this->VertexPositions.resize(3 * this->PointOfVertex.size());
  for (std::size_t v = 0; v < this->PointOfVertex.size(); ++v)
  {
    const double* p = xyz + 3 * static_cast<std::size_t>(this->PointOfVertex[v]);
    this->VertexPositions[3 * v] = p[0];
    this->VertexPositions[3 * v + 1] = p[1];
    this->VertexPositions[3 * v + 2] = dimension == 3 ? p[2] : 0.0;
  }
}

DelaunayGraph::~DelaunayGraph() = default;

bool DelaunayGraph::ComputeWeights(std::int32_t e, const double p[3], double w[4]) const
{
  const std::int32_t* vertices = this->GetElement(e);
  double total;
  if (this->Dimension == 2)
  {
    double rel[3][2];
    for (int k = 0; k < 3; ++k)
    {
      const double* x = this->GetVertexPosition(vertices[k]);
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
    return w[0] >= 0.0 && w[1] >= 0.0 && w[2] >= 0.0;
  }
  double a[3], b[3], c[3], d[3];
  const double* x0 = this->GetVertexPosition(vertices[0]);
  const double* x1 = this->GetVertexPosition(vertices[1]);
  const double* x2 = this->GetVertexPosition(vertices[2]);
  const double* x3 = this->GetVertexPosition(vertices[3]);
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
  return w[0] >= 0.0 && w[1] >= 0.0 && w[2] >= 0.0 && w[3] >= 0.0;
}

DelaunayGraph::Location DelaunayGraph::Locate(const double p[3], std::int32_t hint) const
{
  Location result;
  if (hint >= 0 && this->ComputeWeights(hint, p, result.Weights))
  {
    result.Element = hint;
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

std::size_t DelaunayGraph::CountInvertedElements(const double* positions) const
{
  std::size_t inverted = 0;
  const std::size_t elements = this->GetNumberOfElements();
  for (std::size_t e = 0; e < elements; ++e)
  {
    const std::int32_t* v = this->GetElement(static_cast<std::int32_t>(e));
    if (this->Dimension == 2)
    {
      const double* a = positions + 3 * static_cast<std::size_t>(v[0]);
      const double* b = positions + 3 * static_cast<std::size_t>(v[1]);
      const double* c = positions + 3 * static_cast<std::size_t>(v[2]);
      if (CGAL::orientation(Kernel::Point_2(a[0], a[1]), Kernel::Point_2(b[0], b[1]),
            Kernel::Point_2(c[0], c[1])) != CGAL::POSITIVE)
      {
        ++inverted;
      }
    }
    else
    {
      Kernel::Point_3 q[4];
      for (int k = 0; k < 4; ++k)
      {
        const double* x = positions + 3 * static_cast<std::size_t>(v[k]);
        q[k] = Kernel::Point_3(x[0], x[1], x[2]);
      }
      if (CGAL::orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE)
      {
        ++inverted;
      }
    }
  }
  return inverted;
}

std::size_t DelaunayGraph::GetMemorySize() const
{
  std::size_t bytes = this->VertexOfPoint.capacity() * sizeof(std::int32_t) +
    this->PointOfVertex.capacity() * sizeof(std::int32_t) +
    this->VertexPositions.capacity() * sizeof(double) +
    this->ElementVertices.capacity() * sizeof(std::int32_t);
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
