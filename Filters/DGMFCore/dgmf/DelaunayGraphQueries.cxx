// The queries on a built DelaunayGraph: barycentric weights, CGAL's exact location, the count of
// inverted elements, the memory kept.
#include "dgmf/DelaunayGraph.h"

#include "dgmf/DelaunayGraphCgal.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace dgmf
{
using namespace graph_cgal;

DelaunayGraph::~DelaunayGraph() = default;

bool DelaunayGraph::ComputeWeights(std::int32_t e, const double p[3], double w[4]) const
{
  return BarycentricWeights(this->Records[static_cast<std::size_t>(e)], this->Dimension, p, w);
}

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
      f = f->neighbor(f->index(t.infinite_vertex()));
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
