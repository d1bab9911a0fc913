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

namespace
{
/// What DeformBlock reads and writes (DeformDGMF's arguments).
struct BlockInputs
{
  const DelaunayMapping* Mapping;
  const double* F;
  const double* Displacement;
  DeformationMode Mode;
  bool Interpolate;
  const double* VertexDeformation;
  const double* Points;
  double* Deformed;
};

/**
 * The nodes [begin, end) of DeformDGMF. Interior nodes damped by the motion alone go by four
 * (ApplyFour, the same bits as Apply); the others, and the last few of the block, one at a time.
 * Written out here, not in a lambda: the AVX2 clone compiles what it inlines.
 */
DGMF_SIMD_AVX2_CLONES
void DeformBlock(
  const BlockInputs& in, const DampedRigidMotion& damped, std::size_t begin, std::size_t end)
{
  const DelaunayMapping& mapping = *in.Mapping;
  const bool withOwn = in.Mode == DeformationMode::DGMF1 && in.Displacement;
  double f[4];
  const double* x[4];
  const double* own[4];
  double* out[4];
  int waiting = 0;
  for (std::size_t i = begin; i < end; ++i)
  {
    const NodeKind kind = mapping.GetNodeKind(i);
    const double* point = in.Points + 3 * i;
    double* moved = in.Deformed + 3 * i;
    const double* displacement = in.Displacement ? in.Displacement + 3 * i : nullptr;
    if (kind == NodeKind::MovingBoundary)
    {
      damped.Apply(1.0, point, displacement, moved);
    }
    else if (kind == NodeKind::StaticBoundary || in.F[i] == 0.0)
    {
      moved[0] = point[0];
      moved[1] = point[1];
      moved[2] = point[2];
    }
    else if (!in.Interpolate)
    {
      f[waiting] = in.F[i];
      x[waiting] = point;
      own[waiting] = withOwn ? displacement : nullptr;
      out[waiting] = moved;
      if (++waiting == 4)
      {
        damped.ApplyFour(f, x, own, out);
        waiting = 0;
      }
    }
    else
    {
      double d[3];
      InterpolateMovingDeformation(
        mapping, in.VertexDeformation, mapping.GetElementOfNode(i), mapping.GetWeights(i), d);
      damped.Apply(in.F[i], point, d, moved);
    }
  }
  for (int l = 0; l < waiting; ++l)
  {
    damped.Apply(f[l], x[l], own[l], out[l]);
  }
}
} // namespace

void DeformDGMF(const DelaunayMapping& mapping, const double* f, const RigidMotion& motion,
  const double* displacement, DeformationMode mode, const double* points, double* deformed,
  const ParallelFor& parallelFor)
{
  // Without a displacement array, d = 0 and the elements need not be visited at all.
  const bool interpolate = displacement && mode == DeformationMode::DGMF2;
  const std::vector<double> vertexDeformation =
    interpolate ? GatherVertexDeformation(mapping, displacement) : std::vector<double>();
  const DampedRigidMotion damped(motion);
  const BlockInputs inputs{ &mapping, f, displacement, mode, interpolate, vertexDeformation.data(),
    points, deformed };
  mapping.ForEachNodeBlock(parallelFor,
    [&](std::size_t begin, std::size_t end) { DeformBlock(inputs, damped, begin, end); });
}

} // namespace dgmf
