#include "dgmf/DGMDeformation.h"

#include <algorithm>
#include <stdexcept>

namespace dgmf
{

std::vector<double> GatherVertexDisplacement(
  const DelaunayMapping& mapping, const BoundaryMotion& boundary)
{
  const std::vector<std::int32_t>& nodes = mapping.GetBoundaryNodes();
  if (boundary.Nodes != nodes)
  {
    throw std::invalid_argument(
      "the boundary motion and the Delaunay mapping list different boundary nodes");
  }
  const DelaunayGraph& graph = mapping.GetGraph();
  std::vector<double> displacement(3 * graph.GetNumberOfVertices(), 0.0);
  const std::vector<std::int32_t>& vertexOfPoint = graph.GetVertexOfPoint();
  for (std::size_t b = 0; b < nodes.size(); ++b)
  {
    const std::int32_t v = vertexOfPoint[b];
    if (mapping.GetVertexNode(v) == nodes[b])
    {
      std::copy(boundary.Displacements.begin() + 3 * b, boundary.Displacements.begin() + 3 * b + 3,
        displacement.begin() + 3 * static_cast<std::size_t>(v));
    }
  }
  return displacement;
}

std::size_t DeformDGM(const DelaunayMapping& mapping, const BoundaryMotion& boundary,
  const double* points, double* deformed, const ParallelFor& parallelFor)
{
  const std::vector<double> vertexDisplacement = GatherVertexDisplacement(mapping, boundary);
  const DelaunayGraph& graph = mapping.GetGraph();
  const int n = graph.GetVerticesPerElement();
  mapping.ForEachNode(parallelFor,
    [&](std::size_t i)
    {
      double d[3] = { 0.0, 0.0, 0.0 };
      if (!mapping.IsBoundaryNode(i))
      {
        const std::int32_t* vertices = graph.GetElement(mapping.GetElementOfNode(i));
        const double* w = mapping.GetWeights(i);
        for (int k = 0; k < n; ++k)
        {
          const double* dk = vertexDisplacement.data() + 3 * static_cast<std::size_t>(vertices[k]);
          d[0] += w[k] * dk[0];
          d[1] += w[k] * dk[1];
          d[2] += w[k] * dk[2];
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        deformed[3 * i + c] = points[3 * i + c] + d[c];
      }
    });
  // Boundary nodes: their own prescribed displacement (coincident nodes may differ from their
  // vertex).
  ApplyBoundaryMotion(boundary, points, deformed);

  return graph.CountInvertedElements(vertexDisplacement.data());
}

} // namespace dgmf
