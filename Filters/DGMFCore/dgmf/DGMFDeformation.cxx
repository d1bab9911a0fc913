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
  // The nodes waiting for a group of four. Their inputs are read when the group is full, not
  // copied into arrays as they come: four scalar stores read back as one vector had to wait for
  // the stores to land (no store-to-load forwarding from several stores to one load).
  std::size_t waitingNode[4];
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
      waitingNode[waiting] = i;
      if (++waiting == 4)
      {
        // Written here, not in a lambda (see above).
        const double f[4] = { in.F[waitingNode[0]], in.F[waitingNode[1]], in.F[waitingNode[2]],
          in.F[waitingNode[3]] };
        const double* const x[4] = { in.Points + 3 * waitingNode[0], in.Points + 3 * waitingNode[1],
          in.Points + 3 * waitingNode[2], in.Points + 3 * waitingNode[3] };
        const double* const own[4] = { withOwn ? in.Displacement + 3 * waitingNode[0] : nullptr,
          withOwn ? in.Displacement + 3 * waitingNode[1] : nullptr,
          withOwn ? in.Displacement + 3 * waitingNode[2] : nullptr,
          withOwn ? in.Displacement + 3 * waitingNode[3] : nullptr };
        double* const out[4] = { in.Deformed + 3 * waitingNode[0], in.Deformed + 3 * waitingNode[1],
          in.Deformed + 3 * waitingNode[2], in.Deformed + 3 * waitingNode[3] };
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
    const std::size_t node = waitingNode[l];
    damped.Apply(in.F[node], in.Points + 3 * node, withOwn ? in.Displacement + 3 * node : nullptr,
      in.Deformed + 3 * node);
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
