#include "dgmf/MultiBodyDeformation.h"

#include "dgmf/DampedRigidMotion.h"
#include "dgmf/DampingField.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace dgmf
{
namespace
{
/// The body of every graph vertex: that of the node whose motion it carries; 0 when static.
std::vector<std::int32_t> VertexBodies(const DelaunayMapping& mapping, const std::int32_t* bodyIds)
{
  std::vector<std::int32_t> bodies(mapping.GetGraph().GetNumberOfVertices(), 0);
  for (std::size_t v = 0; v < bodies.size(); ++v)
  {
    const auto vertex = static_cast<std::int32_t>(v);
    if (mapping.GetVertexKind(vertex) == NodeKind::MovingBoundary)
    {
      bodies[v] = bodyIds[static_cast<std::size_t>(mapping.GetVertexNode(vertex))];
    }
  }
  return bodies;
}

/// The distinct bodies among an element's vertices, in increasing order; returns how many.
int ElementBodies(
  const std::int32_t* vertexBody, const std::int32_t* vertices, int n, std::int32_t bodies[4])
{
  int count = 0;
  for (int k = 0; k < n; ++k)
  {
    const std::int32_t body = vertexBody[static_cast<std::size_t>(vertices[k])];
    if (body == 0 || std::find(bodies, bodies + count, body) != bodies + count)
    {
      continue;
    }
    int j = count++;
    for (; j > 0 && bodies[j - 1] > body; --j)
    {
      bodies[j] = bodies[j - 1];
    }
    bodies[j] = body;
  }
  return count;
}

/// r_k of `body` at a node of an element: paper Eq. 1 with the body's vertices as the moving ones.
double BodyDistance(const std::int32_t* vertexBody, const std::int32_t* vertices, const double* w,
  int n, std::int32_t body, double staticR0)
{
  return InterpolateR(vertices, w, n, staticR0,
    [&](std::int32_t v)
    { return vertexBody[static_cast<std::size_t>(v)] == body ? 0.0 : staticR0; });
}

/// d_k of `body` at a node of an element: paper Eq. 7 over the body's vertices.
void BodyDeformation(const std::int32_t* vertexBody, const double* vertexDeformation,
  const std::int32_t* vertices, const double* w, int n, std::int32_t body, double d[3])
{
  InterpolateSourceDeformation(
    vertices, w, n, vertexDeformation,
    [&](std::int32_t v) { return vertexBody[static_cast<std::size_t>(v)] == body; }, d);
}

/**
 * f_k of `body` at an interior node in an element whose bodies are `present` (ElementBodies):
 * 0 when the body has no vertex there, u(r_k) otherwise.
 */
double BodyDamping(const std::int32_t* vertexBody, const std::int32_t* vertices, const double* w,
  int n, const std::int32_t* present, int count, std::int32_t body, double staticR0,
  DampingFunction u)
{
  if (std::find(present, present + count, body) == present + count)
  {
    return 0.0;
  }
  return EvaluateDamping(u, BodyDistance(vertexBody, vertices, w, n, body, staticR0));
}
} // namespace

std::int32_t CheckBodyIds(const DelaunayMapping& mapping, const std::int32_t* bodyIds)
{
  if (!bodyIds)
  {
    throw std::invalid_argument("a body-id array is required");
  }
  std::int32_t largest = 0;
  const std::size_t nodes = mapping.GetNumberOfNodes();
  for (std::size_t i = 0; i < nodes; ++i)
  {
    const std::int32_t id = bodyIds[i];
    const bool moving = mapping.GetNodeKind(i) == NodeKind::MovingBoundary;
    if (id < 0)
    {
      throw std::invalid_argument(
        "negative body id at node " + std::to_string(i) + ": ids are 0 (no body) or 1, 2, ...");
    }
    if (id > 0 && !moving)
    {
      throw std::invalid_argument("node " + std::to_string(i) + " has body id " +
        std::to_string(id) + " but is not a moving boundary node of the Delaunay mapping");
    }
    if (id == 0 && moving)
    {
      throw std::invalid_argument(
        "moving boundary node " + std::to_string(i) + " has body id 0 (no body)");
    }
    largest = std::max(largest, id);
  }
  return largest;
}

void ComputeBodyDampingFactor(const DelaunayMapping& mapping, const std::int32_t* bodyIds,
  std::int32_t body, double staticR0, DampingFunction u, double* f, const ParallelFor& parallelFor)
{
  CheckStaticR0(staticR0);
  if (body < 1)
  {
    throw std::invalid_argument("body ids start at 1");
  }
  CheckBodyIds(mapping, bodyIds);
  const std::vector<std::int32_t> vertexBody = VertexBodies(mapping, bodyIds);
  const DelaunayGraph& graph = mapping.GetGraph();
  const int n = graph.GetVerticesPerElement();
  mapping.ForEachNode(parallelFor,
    [&](std::size_t i)
    {
      if (mapping.IsBoundaryNode(i))
      {
        f[i] = bodyIds[i] == body ? 1.0 : 0.0;
        return;
      }
      const std::int32_t* vertices = graph.GetElement(mapping.GetElementOfNode(i));
      std::int32_t present[4];
      const int count = ElementBodies(vertexBody.data(), vertices, n, present);
      f[i] = BodyDamping(
        vertexBody.data(), vertices, mapping.GetWeights(i), n, present, count, body, staticR0, u);
    });
}

void DeformMultiBody(const DelaunayMapping& mapping, const std::int32_t* bodyIds,
  const std::vector<BodyMotion>& bodies, double staticR0, DampingFunction u, DeformationMode mode,
  const double* points, double* deformed, double* dampingFactor, const ParallelFor& parallelFor)
{
  CheckStaticR0(staticR0);
  const std::int32_t largest = CheckBodyIds(mapping, bodyIds);
  if (static_cast<std::size_t>(largest) > bodies.size())
  {
    throw std::invalid_argument("body id " + std::to_string(largest) + " but only " +
      std::to_string(bodies.size()) + " body motions");
  }
  std::vector<DampedRigidMotion> damped;
  damped.reserve(bodies.size());
  for (const BodyMotion& body : bodies)
  {
    damped.emplace_back(body.Motion);
  }
  const std::vector<std::int32_t> vertexBody = VertexBodies(mapping, bodyIds);

  // DGMF2: the deformation of every moving vertex, from its own body's array (a vertex belongs to
  // one body, so one array serves all bodies).
  const bool anyDisplacement = std::any_of(
    bodies.begin(), bodies.end(), [](const BodyMotion& body) { return body.Displacement; });
  std::vector<double> vertexDeformation;
  if (anyDisplacement && mode == DeformationMode::DGMF2)
  {
    vertexDeformation.assign(3 * vertexBody.size(), 0.0);
    for (std::size_t v = 0; v < vertexBody.size(); ++v)
    {
      const std::int32_t body = vertexBody[v];
      const double* source =
        body > 0 ? bodies[static_cast<std::size_t>(body - 1)].Displacement : nullptr;
      if (source)
      {
        source += 3 * static_cast<std::size_t>(mapping.GetVertexNode(static_cast<std::int32_t>(v)));
        std::copy(source, source + 3, vertexDeformation.begin() + 3 * v);
      }
    }
  }

  const DelaunayGraph& graph = mapping.GetGraph();
  const int n = graph.GetVerticesPerElement();
  mapping.ForEachNode(parallelFor,
    [&](std::size_t i)
    {
      const double* x = points + 3 * i;
      double* out = deformed + 3 * i;
      const NodeKind kind = mapping.GetNodeKind(i);
      if (kind == NodeKind::MovingBoundary)
      {
        const auto k = static_cast<std::size_t>(bodyIds[i] - 1);
        const double* own = bodies[k].Displacement ? bodies[k].Displacement + 3 * i : nullptr;
        damped[k].Apply(1.0, x, own, out);
        if (dampingFactor)
        {
          dampingFactor[i] = 1.0;
        }
        return;
      }
      std::copy(x, x + 3, out);
      if (dampingFactor)
      {
        dampingFactor[i] = 0.0;
      }
      if (kind == NodeKind::StaticBoundary)
      {
        return;
      }
      const std::int32_t* vertices = graph.GetElement(mapping.GetElementOfNode(i));
      const double* w = mapping.GetWeights(i);
      std::int32_t present[4];
      const int count = ElementBodies(vertexBody.data(), vertices, n, present);
      double displacement[3] = { 0.0, 0.0, 0.0 };
      double sumF = 0.0;
      int contributing = 0;
      for (int b = 0; b < count; ++b)
      {
        const std::int32_t body = present[b];
        const double f =
          BodyDamping(vertexBody.data(), vertices, w, n, present, count, body, staticR0, u);
        if (f == 0.0)
        {
          continue;
        }
        const auto k = static_cast<std::size_t>(body - 1);
        const double* own = bodies[k].Displacement ? bodies[k].Displacement + 3 * i : nullptr;
        double moved[3];
        if (own && mode == DeformationMode::DGMF2)
        {
          double d[3];
          BodyDeformation(vertexBody.data(), vertexDeformation.data(), vertices, w, n, body, d);
          damped[k].Apply(f, x, d, moved);
        }
        else
        {
          damped[k].Apply(f, x, mode == DeformationMode::DGMF1 ? own : nullptr, moved);
        }
        if (contributing++ == 0)
        {
          std::copy(moved, moved + 3, out); // one body: its motion itself, no round-off
        }
        for (int c = 0; c < 3; ++c)
        {
          displacement[c] += moved[c] - x[c];
        }
        sumF += f;
      }
      if (contributing > 1)
      {
        for (int c = 0; c < 3; ++c)
        {
          out[c] = x[c] + displacement[c];
        }
      }
      if (dampingFactor)
      {
        dampingFactor[i] = std::min(1.0, sumF);
      }
    });
}

namespace
{
/// `nodes` sorted by position (x, then y, then z; equal positions by node), one per position.
std::vector<std::int32_t> DistinctPositionsOf(
  const double* points, const std::vector<std::int32_t>& nodes)
{
  const auto at = [points](std::int32_t i)
  {
    const double* p = points + 3 * static_cast<std::size_t>(i);
    return std::array<double, 3>{ p[0], p[1], p[2] };
  };
  std::vector<std::int32_t> sorted = nodes;
  std::sort(sorted.begin(), sorted.end(),
    [&at](std::int32_t a, std::int32_t b)
    { return std::make_pair(at(a), a) < std::make_pair(at(b), b); });
  sorted.erase(std::unique(sorted.begin(), sorted.end(),
                 [&at](std::int32_t a, std::int32_t b) { return at(a) == at(b); }),
    sorted.end());
  return sorted;
}
} // namespace

std::vector<FittedMotion> ExtractBodyMotions(int dimension, const double* points,
  const double* displacement, std::size_t numberOfNodes, const std::int32_t* bodyIds,
  std::int32_t numberOfBodies, double* residual, bool distinctPositions)
{
  if (numberOfBodies < 0)
  {
    throw std::invalid_argument("the number of bodies must not be negative");
  }
  if (!bodyIds && numberOfNodes > 0)
  {
    throw std::invalid_argument("a body-id array is required");
  }
  std::vector<std::vector<std::int32_t>> members(static_cast<std::size_t>(numberOfBodies));
  for (std::size_t i = 0; i < numberOfNodes; ++i)
  {
    const std::int32_t id = bodyIds[i];
    if (id < 0 || id > numberOfBodies)
    {
      throw std::invalid_argument("body id " + std::to_string(id) + " at node " +
        std::to_string(i) + " is outside 0.." + std::to_string(numberOfBodies));
    }
    if (id > 0)
    {
      members[static_cast<std::size_t>(id - 1)].push_back(static_cast<std::int32_t>(i));
    }
    else if (residual)
    {
      std::fill(residual + 3 * i, residual + 3 * i + 3, 0.0);
    }
  }
  std::vector<FittedMotion> fits;
  fits.reserve(members.size());
  for (const std::vector<std::int32_t>& nodes : members)
  {
    const std::vector<std::int32_t> fitted =
      distinctPositions ? DistinctPositionsOf(points, nodes) : std::vector<std::int32_t>();
    const std::vector<std::int32_t>& fitNodes = distinctPositions ? fitted : nodes;
    fits.push_back(
      FitRigidMotion(dimension, points, displacement, fitNodes.data(), fitNodes.size()));
    if (residual)
    {
      ComputeFitResidual(fits.back(), points, displacement, nodes.data(), nodes.size(), residual);
    }
  }
  return fits;
}

} // namespace dgmf
