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

namespace
{
/// The static-boundary value r0s of every graph vertex: 0 on moving vertices.
std::vector<double> VertexR0(const DelaunayMapping& mapping, double staticR0)
{
  std::vector<double> vertexR0(mapping.GetGraph().GetNumberOfVertices());
  for (std::size_t v = 0; v < vertexR0.size(); ++v)
  {
    vertexR0[v] = mapping.GetVertexKind(static_cast<std::int32_t>(v)) == NodeKind::MovingBoundary
      ? 0.0
      : staticR0;
  }
  return vertexR0;
}

/**
 * r of the nodes of each block (ComputeBoundaryDistanceField), and `atNode(i, r_i)` after each:
 * the one pass over the nodes' elements and weights that both r alone and r with f make.
 */
template <typename AtNode>
void ForEachR(const DelaunayMapping& mapping, double staticR0, double* r,
  const ParallelFor& parallelFor, const AtNode& atNode)
{
  CheckStaticR0(staticR0);
  const DelaunayGraph& graph = mapping.GetGraph();
  const std::vector<double> vertexR0 = VertexR0(mapping, staticR0);
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
        }
        else
        {
          r[i] = InterpolateR(graph.GetElement(mapping.GetElementOfNode(i)), mapping.GetWeights(i),
            n, staticR0, [&](std::int32_t v) { return vertexR0[static_cast<std::size_t>(v)]; });
        }
        atNode(i, r[i]);
      }
    });
}

/// f of node i from its r (ComputeDampingFactor), the function `U` fixed at compile time.
template <DampingFunction U>
inline double DampingOfNode(const DelaunayMapping& mapping, std::size_t i, double r)
{
  if (mapping.IsBoundaryNode(i))
  {
    return mapping.GetNodeKind(i) == NodeKind::MovingBoundary ? 1.0 : 0.0;
  }
  return EvaluateDampingOf<U>(r);
}
} // namespace

void ComputeBoundaryDistanceField(
  const DelaunayMapping& mapping, double staticR0, double* r, const ParallelFor& parallelFor)
{
  ForEachR(mapping, staticR0, r, parallelFor, [](std::size_t, double) {});
}

void ComputeDampingFactor(const DelaunayMapping& mapping, DampingFunction u, const double* r,
  double* f, const ParallelFor& parallelFor)
{
  WithDampingFunction(u,
    [&](auto function)
    {
      constexpr DampingFunction U = decltype(function)::value;
      mapping.ForEachNode(
        parallelFor, [&](std::size_t i) { f[i] = DampingOfNode<U>(mapping, i, r[i]); });
    });
}

void ComputeDampingField(const DelaunayMapping& mapping, double staticR0, DampingFunction u,
  double* r, double* f, const ParallelFor& parallelFor)
{
  WithDampingFunction(u,
    [&](auto function)
    {
      constexpr DampingFunction U = decltype(function)::value;
      ForEachR(mapping, staticR0, r, parallelFor,
        [&](std::size_t i, double ri) { f[i] = DampingOfNode<U>(mapping, i, ri); });
    });
}

} // namespace dgmf
