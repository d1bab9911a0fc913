#include "dgmf/DampingField.h"

#include "dgmf/Simd.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dgmf
{
namespace
{
/// How many nodes ahead the distance field asks for a node's element's vertices.
constexpr std::size_t ElementsAhead = 8;
} // namespace

void CheckStaticR0(double staticR0)
{
  if (!(staticR0 >= 1.0) || !std::isfinite(staticR0))
  {
    throw std::invalid_argument("the static-boundary value r0s must be a finite number >= 1");
  }
}

void ComputeBoundaryDistanceField(
  const DelaunayMapping& mapping, double staticR0, double* r, const ParallelFor& parallelFor)
{
  CheckStaticR0(staticR0);
  const DelaunayGraph& graph = mapping.GetGraph();
  std::vector<double> vertexR0(graph.GetNumberOfVertices());
  for (std::size_t v = 0; v < vertexR0.size(); ++v)
  {
    vertexR0[v] = mapping.GetVertexKind(static_cast<std::int32_t>(v)) == NodeKind::MovingBoundary
      ? 0.0
      : staticR0;
  }
  const int n = graph.GetVerticesPerElement();
  mapping.ForEachNodeBlock(parallelFor,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        // The vertices of the element of the node ElementsAhead on: an element's vertices are
        // a cache miss into the graph when consecutive nodes lie in different elements.
        if (i + ElementsAhead < end && !mapping.IsBoundaryNode(i + ElementsAhead))
        {
          simd::Prefetch(graph.GetElement(mapping.GetElementOfNode(i + ElementsAhead)));
        }
        if (mapping.IsBoundaryNode(i))
        {
          r[i] = mapping.GetNodeKind(i) == NodeKind::MovingBoundary ? 0.0 : staticR0;
          continue;
        }
        r[i] = InterpolateR(graph.GetElement(mapping.GetElementOfNode(i)), mapping.GetWeights(i), n,
          staticR0, [&](std::int32_t v) { return vertexR0[static_cast<std::size_t>(v)]; });
      }
    });
}

void ComputeDampingFactor(const DelaunayMapping& mapping, DampingFunction u, const double* r,
  double* f, const ParallelFor& parallelFor)
{
  mapping.ForEachNode(parallelFor,
    [&](std::size_t i)
    {
      if (mapping.IsBoundaryNode(i))
      {
        f[i] = mapping.GetNodeKind(i) == NodeKind::MovingBoundary ? 1.0 : 0.0;
      }
      else
      {
        f[i] = EvaluateDamping(u, r[i]);
      }
    });
}

} // namespace dgmf
