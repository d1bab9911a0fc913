#include "dgmf/BoundaryMotion.h"

namespace dgmf
{

BoundaryMotion GatherBoundaryMotion(int dimension, const double* points, std::size_t numberOfNodes,
  const NodeKind* kinds, const RigidMotion& motion, const double* displacement)
{
  BoundaryMotion boundary;
  boundary.Dimension = dimension;
  for (std::size_t i = 0; i < numberOfNodes; ++i)
  {
    if (!IsBoundary(kinds[i]))
    {
      continue;
    }
    const double* x = points + 3 * i;
    double moved[3] = { x[0], x[1], x[2] };
    if (kinds[i] == NodeKind::MovingBoundary)
    {
      motion.Apply(1.0, x, displacement ? displacement + 3 * i : nullptr, moved);
    }
    boundary.Nodes.push_back(static_cast<std::int32_t>(i));
    for (int c = 0; c < 3; ++c)
    {
      boundary.Positions.push_back(x[c]);
      boundary.Displacements.push_back(moved[c] - x[c]);
    }
  }
  return boundary;
}

void ApplyBoundaryMotion(const BoundaryMotion& boundary, const double* points, double* deformed)
{
  for (std::size_t b = 0; b < boundary.Size(); ++b)
  {
    const auto node = static_cast<std::size_t>(boundary.Nodes[b]);
    for (int c = 0; c < 3; ++c)
    {
      deformed[3 * node + c] = points[3 * node + c] + boundary.Displacements[3 * b + c];
    }
  }
}

} // namespace dgmf
