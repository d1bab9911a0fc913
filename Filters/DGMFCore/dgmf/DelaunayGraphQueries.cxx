// The queries on a built DelaunayGraph: barycentric weights, CGAL's exact location, the count of
// inverted elements, the memory kept.
#include "dgmf/DelaunayGraph.h"

#include "dgmf/CellGeometry.h"
#include "dgmf/DelaunayGraphCgal.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_set>
#include <vector>

namespace dgmf
{
using namespace graph_cgal;

DelaunayGraph::~DelaunayGraph() = default;

bool DelaunayGraph::ComputeWeights(std::int32_t e, const double p[3], double w[4]) const
{
  return BarycentricWeights(this->Records[static_cast<std::size_t>(e)], this->Dimension, p, w);
}

namespace
{
/// Largest number of hull facets (edges in 2D) a walk to a point's projection crosses.
constexpr int HullWalkSteps = 100000;

/**
 * The weights of `p` projected onto the hull facet of `record` opposite corner `opposite` (3D:
 * a triangle; 2D: an edge), the corner `opposite` getting 0: unnormalised, the facet's own
 * barycentric coordinates. Returns the smallest of them over the facet's size (>= 0: the
 * projection is in the facet) and its corner in `most`.
 */
double FacetWeights(
  const WalkRecord& record, int dimension, int opposite, const double p[3], double w[4], int& most)
{
  int corner[3];
  int count = 0;
  std::fill(w, w + 4, 0.0);
  for (int k = 0; k <= dimension; ++k)
  {
    if (k != opposite)
    {
      corner[count++] = k;
    }
  }
  const auto at = [&](int k, int c) { return record.Corners[corner[k]][c]; };
  double smallest = 0.0;
  most = corner[0];
  if (dimension == 2)
  {
    // The edge A B: p's projection at A + s (B - A).
    const double e[2] = { at(1, 0) - at(0, 0), at(1, 1) - at(0, 1) };
    const double length2 = e[0] * e[0] + e[1] * e[1];
    const double s = ((p[0] - at(0, 0)) * e[0] + (p[1] - at(0, 1)) * e[1]) / length2;
    w[corner[0]] = 1.0 - s;
    w[corner[1]] = s;
    smallest = std::min(1.0 - s, s);
    most = 1.0 - s < s ? corner[0] : corner[1];
    return smallest;
  }
  // The triangle A B C: the areas of p's sub-triangles along the facet's normal.
  const auto corner3 = [&](int k) { return Vec3{ at(k, 0), at(k, 1), at(k, 2) }; };
  const Vec3 v[3] = { corner3(0), corner3(1), corner3(2) };
  const Vec3 q{ p[0], p[1], p[2] };
  const Vec3 normal = Cross(v[1] - v[0], v[2] - v[0]);
  const double area2 = Dot(normal, normal);
  for (int k = 0; k < 3; ++k)
  {
    const double lambda = Dot(Cross(v[(k + 1) % 3] - q, v[(k + 2) % 3] - q), normal) / area2;
    w[corner[k]] = lambda;
    if (k == 0 || lambda < smallest)
    {
      smallest = lambda;
      most = corner[k];
    }
  }
  return smallest;
}

/**
 * From the infinite element `outer` of `t` (CGAL's answer for a point `p` outside the hull),
 * walks over the hull's facets to the one `p` projects onto (on a flat face, CGAL's answer is any
 * facet `p` is beyond): crosses the facet edge opposite the corner with the most negative
 * coordinate, keeping the best, until a facet is visited again (`p` projects onto no facet but
 * beyond the hull's edges or corners: the walk goes round them) or after HullWalkSteps facets.
 * Returns the finite element under the facet and `p`'s weights in it (the corner off the facet 0;
 * clamped, summing to 1).
 */
template <typename Triangulation, typename Handle>
std::int32_t ProjectOntoHull(const Triangulation& t, Handle outer, int dimension,
  const UninitializedVector<WalkRecord>& records, const double p[3], double weights[4])
{
  double best = -std::numeric_limits<double>::infinity();
  std::int32_t bestElement = -1;
  double bestWeights[4] = { 0, 0, 0, 0 };
  // The facets visited, each as its element and the corner opposite it (an element can have
  // two or three facets on the hull, and the walk can go from one to the next).
  std::unordered_set<std::int64_t> visited;
  for (int step = 0; step < HullWalkSteps; ++step)
  {
    const Handle inner = outer->neighbor(outer->index(t.infinite_vertex()));
    const std::int32_t element = inner->info();
    const int opposite = inner->index(outer);
    if (!visited.insert(std::int64_t(element) * 4 + opposite).second)
    {
      break; // round a hull edge or corner: the best facet so far is the nearest
    }
    double w[4];
    int most = 0;
    const double smallest =
      FacetWeights(records[static_cast<std::size_t>(element)], dimension, opposite, p, w, most);
    if (smallest > best)
    {
      best = smallest;
      bestElement = element;
      std::copy(w, w + 4, bestWeights);
    }
    if (!(smallest < 0.0))
    {
      break; // the projection is in this facet (or a weight is NaN: stop)
    }
    // Across the facet edge opposite `most`: the infinite element sharing that edge.
    outer = outer->neighbor(outer->index(inner->vertex(most)));
  }
  std::copy(bestWeights, bestWeights + 4, weights);
  ClampWeights(weights, dimension + 1);
  return bestElement;
}
} // namespace

DelaunayGraph::Location DelaunayGraph::LocateExactly(const double p[3], std::int32_t hint) const
{
  Location result;
  std::int32_t element = -1;
  if (this->Dimension == 2)
  {
    const Delaunay2& t = this->Triangulation2->Triangulation;
    Delaunay2::Locate_type lt;
    int li;
    Delaunay2::Face_handle start = hint >= 0
      ? this->Triangulation2->Faces[static_cast<std::size_t>(hint)]
      : Delaunay2::Face_handle();
    Delaunay2::Face_handle f = t.locate(Kernel::Point_2(p[0], p[1]), lt, li, start);
    if (t.is_infinite(f))
    {
      result.Outside = true;
      result.Element = ProjectOntoHull(t, f, 2, this->Records, p, result.Weights);
      return result;
    }
    element = f->info();
  }
  else
  {
    const Delaunay3& t = this->Triangulation3->Triangulation;
    Delaunay3::Locate_type lt;
    int li, lj;
    Delaunay3::Cell_handle start = hint >= 0
      ? this->Triangulation3->Cells[static_cast<std::size_t>(hint)]
      : Delaunay3::Cell_handle();
    Delaunay3::Cell_handle c = t.locate(Kernel::Point_3(p[0], p[1], p[2]), lt, li, lj, start);
    if (t.is_infinite(c))
    {
      result.Outside = true;
      result.Element = ProjectOntoHull(t, c, 3, this->Records, p, result.Weights);
      return result;
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

std::size_t DelaunayGraph::CountInvertedElements(
  const double* displacements, const ParallelFor& parallelFor) const
{
  const std::size_t elements = this->GetNumberOfElements();
  const int n = this->Dimension + 1;
  const std::size_t blocks = (elements + ElementBlock - 1) / ElementBlock;
  std::vector<std::size_t> invertedInBlock(blocks, 0);
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      const std::size_t end = std::min(elements, (block + 1) * ElementBlock);
      for (std::size_t e = block * ElementBlock; e < end; ++e)
      {
        const std::int32_t* v = this->GetElement(static_cast<std::int32_t>(e));
        double before[4][3], after[4][3];
        for (int k = 0; k < n; ++k)
        {
          const double* x = this->OriginalPositions.data() + 3 * static_cast<std::size_t>(v[k]);
          const double* d =
            displacements ? displacements + 3 * static_cast<std::size_t>(v[k]) : nullptr;
          for (int c = 0; c < 3; ++c)
          {
            before[k][c] = x[c];
            after[k][c] = d ? x[c] + d[c] : x[c];
          }
        }
        auto orientation = [this](const double(*q)[3])
        {
          if (this->Dimension == 2)
          {
            return CGAL::orientation(Kernel::Point_2(q[0][0], q[0][1]),
              Kernel::Point_2(q[1][0], q[1][1]), Kernel::Point_2(q[2][0], q[2][1]));
          }
          return CGAL::orientation(Kernel::Point_3(q[0][0], q[0][1], q[0][2]),
            Kernel::Point_3(q[1][0], q[1][1], q[1][2]), Kernel::Point_3(q[2][0], q[2][1], q[2][2]),
            Kernel::Point_3(q[3][0], q[3][1], q[3][2]));
        };
        if (!displacements)
        {
          // counting flat elements
          invertedInBlock[block] += orientation(before) != CGAL::POSITIVE ? 1 : 0;
        }
        else if (orientation(before) == CGAL::POSITIVE && orientation(after) != CGAL::POSITIVE)
        {
          ++invertedInBlock[block];
        }
      }
    });
  return std::accumulate(invertedInBlock.begin(), invertedInBlock.end(), std::size_t(0));
}

std::size_t DelaunayGraph::GetMemorySize() const
{
  std::size_t bytes = this->VertexOfPoint.capacity() * sizeof(std::int32_t) +
    this->PointOfVertex.capacity() * sizeof(std::int32_t) +
    (this->VertexPositions.capacity() + this->OriginalPositions.capacity()) * sizeof(double) +
    this->ElementVertices.capacity() * sizeof(std::int32_t) +
    this->Records.capacity() * sizeof(WalkRecord) +
    this->SeedGrid.capacity() * sizeof(std::int32_t);
  if (this->Triangulation2)
  {
    const Delaunay2& t = this->Triangulation2->Triangulation;
    // CGAL's containers as allocated (the reserve of ReserveTriangulation included).
    bytes += t.tds().vertices().capacity() * sizeof(Delaunay2::Vertex) +
      t.tds().faces().capacity() * sizeof(Delaunay2::Face) +
      this->Triangulation2->Faces.capacity() * sizeof(Delaunay2::Face_handle);
  }
  if (this->Triangulation3)
  {
    const Delaunay3& t = this->Triangulation3->Triangulation;
    bytes += t.tds().vertices().capacity() * sizeof(Delaunay3::Vertex) +
      t.tds().cells().capacity() * sizeof(Delaunay3::Cell) +
      this->Triangulation3->Cells.capacity() * sizeof(Delaunay3::Cell_handle);
  }
  return bytes;
}

} // namespace dgmf
