#include "dgmf/DeformationProblem.h"

#include "dgmf/Finite.h"
#include "dgmf/NumberText.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
{
std::string Number(double value)
{
  return NumberText(value);
}
} // namespace

void ThrowBadMarkerValue(double value, std::size_t node)
{
  throw std::invalid_argument("has the value " + Number(value) + " at point " +
    std::to_string(node) +
    "; allowed values are 0 (interior), 1 (static boundary), 2 (moving boundary) and 3 (slip "
    "boundary)");
}

std::string OutOfRangePointsMessage(std::size_t value)
{
  return "The input mesh has NaN or infinite point coordinates, or coordinates of magnitude " +
    std::string(kLargestMagnitudeText) + " or more (point " + std::to_string(value / 3) + ").";
}

void ValidateMotion(
  const DeformationProblem& problem, const RigidMotion& motion, const std::string& which)
{
  try
  {
    motion.Check();
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument(which + e.what());
  }
  if (problem.Dimension == 2 && !motion.KeepsPlane() && problem.LayerAxis >= 0)
  {
    const char axis = "xyz"[problem.LayerAxis];
    throw std::invalid_argument(which + "This is a one-cell-thick mesh (two planes normal to " +
      axis + "): it can only rotate about " + axis + " and translate within the planes. Set the " +
      "other rotations and the " + axis + " translation to 0.");
  }
  if (problem.Dimension == 2 && !motion.KeepsPlane())
  {
    throw std::invalid_argument(which + "This is a 2D mesh (all points at z = " +
      Number(problem.Points[2]) + "): it can only rotate about z" +
      (motion.HasAxisRotation() ? " (a Rotation Axis of 0 0 1)" : "") +
      " and translate in x and y. Set the rotation angles about x and y and the z translation to "
      "0.");
  }
}

std::vector<std::string> ValidateProblem(
  const DeformationProblem& problem, bool checkPoints, bool displacementEverywhere)
{
  const std::size_t n = problem.NumberOfNodes;
  if (problem.Dimension != 2 && problem.Dimension != 3)
  {
    throw std::invalid_argument("the dimension must be 2 or 3");
  }
  if (n == 0 || !problem.Points || !problem.Kinds)
  {
    throw std::invalid_argument("the mesh is empty (no nodes, or no points or node kinds given)");
  }
  if (checkPoints && FirstOutOfRange(problem.Points, 3 * n) < 3 * n)
  {
    throw std::invalid_argument(OutOfRangePointsMessage(FirstOutOfRange(problem.Points, 3 * n)));
  }
  if (problem.Displacement)
  {
    const std::size_t bad = FirstOutOfRange(problem.Displacement, 3 * n);
    if (bad < 3 * n)
    {
      throw std::invalid_argument("The displacement has NaN or infinite values, or values of "
                                  "magnitude " +
        std::string(kLargestMagnitudeText) + " or more (point " + std::to_string(bad / 3) + ").");
    }
    for (std::size_t i = 0; problem.Dimension == 2 && i < n; ++i)
    {
      if (problem.Displacement[3 * i + 2] != 0.0)
      {
        throw std::invalid_argument(
          "This is a 2D mesh (all points at z = " + Number(problem.Points[2]) +
          "), but the displacement has a non-zero z component (point " + std::to_string(i) + ").");
      }
    }
  }
  if (!problem.ExtractRigidMotion)
  {
    const auto bodies = static_cast<std::size_t>(std::max<std::int32_t>(problem.NumberOfBodies, 1));
    if (problem.Motions.size() < bodies)
    {
      throw std::invalid_argument(std::to_string(bodies) + " bodies but " +
        std::to_string(problem.Motions.size()) + " rigid motions");
    }
    for (std::size_t k = 0; k < bodies; ++k)
    {
      ValidateMotion(
        problem, problem.Motions[k], bodies > 1 ? "Body " + std::to_string(k + 1) + ": " : "");
    }
  }
  const SlipConstraint& slip = problem.Slip;
  if (slip.NodePlanes.size() != slip.Nodes.size() ||
    (!slip.SecondPlanes.empty() && slip.SecondPlanes.size() != slip.Nodes.size()))
  {
    throw std::invalid_argument("every slip node needs its plane");
  }
  for (std::int32_t second : slip.SecondPlanes)
  {
    if (second < -1 || (second >= 0 && static_cast<std::size_t>(second) >= slip.Planes.size()))
    {
      throw std::invalid_argument("a slip node's second plane is not one of the planes");
    }
  }
  for (std::size_t k = 0; k < slip.Nodes.size(); ++k)
  {
    const auto node = static_cast<std::size_t>(slip.Nodes[k]);
    if (slip.Nodes[k] < 0 || node >= n || problem.Kinds[node] != NodeKind::SlipBoundary ||
      slip.NodePlanes[k] < 0 || static_cast<std::size_t>(slip.NodePlanes[k]) >= slip.Planes.size())
    {
      throw std::invalid_argument("slip node " + std::to_string(slip.Nodes[k]) +
        " is not a slip boundary node, or has no plane");
    }
  }
  if (std::all_of(
        problem.Kinds, problem.Kinds + n, [](NodeKind kind) { return kind == NodeKind::Interior; }))
  {
    throw std::invalid_argument(NoBoundaryNodeMessage);
  }
  std::vector<std::string> warnings;
  if (std::find(problem.Kinds, problem.Kinds + n, NodeKind::MovingBoundary) == problem.Kinds + n)
  {
    warnings.push_back("No node is marked as moving: the output has the input's points.");
  }
  if (problem.Displacement)
  {
    // A non-zero displacement where the method does not read it contradicts the marker (a static
    // node meant to move, or the wrong array): elsewhere than on the moving nodes, or, for a
    // method that reads every node's value (DGMF1), on the static nodes, which never move.
    const auto ignores = [&](NodeKind kind)
    {
      return displacementEverywhere ? kind == NodeKind::StaticBoundary
                                    : kind != NodeKind::MovingBoundary;
    };
    std::size_t ignored = 0, largestAt = 0;
    double largest = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double* d = problem.Displacement + 3 * i;
      const double size = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (size > 0.0 && ignores(problem.Kinds[i]))
      {
        ++ignored;
        if (size > largest)
        {
          largest = size;
          largestAt = i;
        }
      }
    }
    if (ignored > 0)
    {
      warnings.push_back(std::to_string(ignored) +
        (displacementEverywhere ? " static nodes" : " nodes not marked as moving") +
        " have a non-zero displacement (the largest, " + Number(largest) + ", at point " +
        std::to_string(largestAt) + "); it is ignored: " +
        (displacementEverywhere ? "static nodes do not move."
                                : "only moving nodes follow the displacement array."));
    }
  }
  return warnings;
}

BoundaryMotion GatherTotalBoundaryMotion(const DeformationProblem& problem)
{
  if (!problem.UsesBodies())
  {
    return GatherBoundaryMotion(problem.Dimension, problem.Points, problem.NumberOfNodes,
      problem.Kinds, problem.Motions.front(), problem.Displacement);
  }
  // Each moving node's total displacement: its body's motion, or (extracted) the array itself.
  const std::size_t n = problem.NumberOfNodes;
  std::vector<double> total(3 * n, 0.0);
  if (problem.ExtractRigidMotion)
  {
    if (problem.Displacement)
    {
      std::copy(problem.Displacement, problem.Displacement + 3 * n, total.begin());
    }
  }
  else
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::int32_t body = problem.BodyIds
        ? problem.BodyIds[i]
        : (problem.Kinds[i] == NodeKind::MovingBoundary ? 1 : 0);
      if (body > 0)
      {
        const double* x = problem.Points + 3 * i;
        double moved[3];
        problem.Motions[static_cast<std::size_t>(body - 1)].Apply(
          1.0, x, problem.Displacement ? problem.Displacement + 3 * i : nullptr, moved);
        for (int c = 0; c < 3; ++c)
        {
          total[3 * i + c] = moved[c] - x[c];
        }
      }
    }
  }
  return GatherBoundaryMotion(
    problem.Dimension, problem.Points, n, problem.Kinds, RigidMotion(), total.data());
}

std::int32_t ResolveBodyIds(const double* values, std::size_t numberOfNodes, bool markerGiven,
  NodeKind* kinds, std::int32_t* bodyIds)
{
  std::int32_t largest = 0;
  for (std::size_t i = 0; i < numberOfNodes; ++i)
  {
    const double value = values[i];
    if (!(value >= 0.0) || value != std::floor(value) || value > 1e6)
    {
      throw std::invalid_argument("has the value " + Number(value) + " at point " +
        std::to_string(i) + "; body ids are 0 (no body) or 1, 2, ...");
    }
    const auto id = static_cast<std::int32_t>(value);
    bodyIds[i] = id;
    largest = std::max(largest, id);
    // A node on a body is a moving boundary node; the other boundary nodes are static.
    NodeKind& kind = kinds[i];
    if (id > 0 && kind == NodeKind::Interior)
    {
      throw std::invalid_argument("gives point " + std::to_string(i) + " the body id " +
        std::to_string(id) + ", but it is not a boundary node (marker 0, or not on the boundary).");
    }
    if (id > 0)
    {
      kind = NodeKind::MovingBoundary;
    }
    else if (kind == NodeKind::MovingBoundary)
    {
      if (markerGiven)
      {
        throw std::invalid_argument(
          "gives point " + std::to_string(i) + ", marked moving (2), the body id 0 (no body).");
      }
      kind = NodeKind::StaticBoundary; // no body: static, whatever its displacement
    }
  }
  return largest;
}

} // namespace dgmf
