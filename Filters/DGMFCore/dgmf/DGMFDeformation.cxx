#include "dgmf/DGMFDeformation.h"

#include "dgmf/DampedRigidMotion.h"

#include <algorithm>

namespace dgmf
{

std::vector<double> GatherVertexDeformation(
  const DelaunayMapping& mapping, const double* displacement)
{
  const std::size_t vertices = mapping.GetGraph().GetNumberOfVertices();
  std::vector<double> d(3 * vertices, 0.0);
  if (!displacement)
  {
    return d;
  }
  for (std::size_t v = 0; v < vertices; ++v)
  {
    const auto vertex = static_cast<std::int32_t>(v);
    if (mapping.GetVertexKind(vertex) == NodeKind::MovingBoundary)
    {
      const double* source =
        displacement + 3 * static_cast<std::size_t>(mapping.GetVertexNode(vertex));
      std::copy(source, source + 3, d.begin() + 3 * v);
    }
  }
  return d;
}

void InterpolateMovingDeformation(const DelaunayMapping& mapping, const double* vertexDeformation,
  std::int32_t element, const double* weights, double d[3])
{
  const DelaunayGraph& graph = mapping.GetGraph();
  InterpolateSourceDeformation(
    graph.GetElement(element), weights, graph.GetVerticesPerElement(), vertexDeformation,
    [&](std::int32_t v) { return mapping.GetVertexKind(v) == NodeKind::MovingBoundary; }, d);
}

void DeformDGMF(const DelaunayMapping& mapping, const double* f, const RigidMotion& motion,
  const double* displacement, DeformationMode mode, const double* points, double* deformed,
  const ParallelFor& parallelFor)
{
  // Without a displacement array, d = 0 and the elements need not be visited at all.
  const bool interpolate = displacement && mode == DeformationMode::DGMF2;
  const std::vector<double> vertexDeformation =
    interpolate ? GatherVertexDeformation(mapping, displacement) : std::vector<double>();
  const DampedRigidMotion damped(motion);
  mapping.ForEachNodeBlock(parallelFor,
    [&](std::size_t begin, std::size_t end)
    {
      // Interior nodes damped by the motion alone go by two (ApplyPair, the same bits as Apply):
      // `pending` is one waiting for its partner.
      std::size_t pending = end;
      for (std::size_t i = begin; i < end; ++i)
      {
        const double* x = points + 3 * i;
        double* out = deformed + 3 * i;
        const NodeKind kind = mapping.GetNodeKind(i);
        const double* own = displacement ? displacement + 3 * i : nullptr;
        if (kind == NodeKind::MovingBoundary)
        {
          damped.Apply(1.0, x, own, out);
        }
        else if (kind == NodeKind::StaticBoundary || f[i] == 0.0)
        {
          out[0] = x[0];
          out[1] = x[1];
          out[2] = x[2];
        }
        else if (!interpolate)
        {
          if (pending == end)
          {
            pending = i;
            continue;
          }
          const double pair[2] = { f[pending], f[i] };
          const bool withOwn = mode == DeformationMode::DGMF1 && displacement;
          damped.ApplyPair(pair, points + 3 * pending, x,
            withOwn ? displacement + 3 * pending : nullptr, withOwn ? own : nullptr,
            deformed + 3 * pending, out);
          pending = end;
        }
        else
        {
          double d[3];
          InterpolateMovingDeformation(mapping, vertexDeformation.data(),
            mapping.GetElementOfNode(i), mapping.GetWeights(i), d);
          damped.Apply(f[i], x, d, out);
        }
      }
      if (pending < end)
      {
        damped.Apply(f[pending], points + 3 * pending,
          mode == DeformationMode::DGMF1 && displacement ? displacement + 3 * pending : nullptr,
          deformed + 3 * pending);
      }
    });
}

} // namespace dgmf
