#include "DGMFSlipFitting.h"

#include "dgmf/SlipPlanes.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace dgmf_vtk
{
namespace
{
/// A fitted plane and the nodes it holds.
struct FittedPlane
{
  dgmf::SlipPlane Plane;
  const std::vector<std::int32_t>* Nodes;
  const std::vector<std::int32_t>* Moving;
  std::string Name;
};
} // namespace

void FitSlipPlanes(const std::vector<std::vector<std::int32_t>>& groups,
  const std::vector<std::string>& names, const NodeRoles* roles, InputNodes& nodes)
{
  const auto fit = [&nodes](const std::vector<std::int32_t>& ids, const std::string& name)
  {
    return dgmf::FitSlipPlane(
      nodes.Points, ids.data(), ids.size(), name, dgmf::SlipPlaneTolerance, nodes.Dimension);
  };
  static const std::vector<std::int32_t> none;
  // A node in two planes (the line where two planes meet) is one slip node with two planes.
  std::unordered_map<std::int32_t, std::size_t> listed;
  std::vector<int> planesOfNode;
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    if (groups[g].empty())
    {
      continue;
    }
    const bool blocks = roles && g < roles->SlipBlocks.size() && roles->SlipBlocks[g].size() > 1;
    const std::vector<std::int32_t>& moving =
      roles && g < roles->MovingOnSlip.size() ? roles->MovingOnSlip[g] : none;
    std::vector<FittedPlane> planes;
    try
    {
      planes.push_back({ fit(groups[g], names[g]), &groups[g], &moving, names[g] });
    }
    catch (const std::invalid_argument&)
    {
      if (!blocks)
      {
        throw;
      }
      // Several blocks that are not one plane: a plane each (each block's own message if not).
      for (const NodeRoles::SlipBlock& block : roles->SlipBlocks[g])
      {
        if (!block.Slip.empty())
        {
          planes.push_back({ fit(block.Slip, block.Name), &block.Slip, &block.Moving, block.Name });
        }
      }
    }
    for (const FittedPlane& fitted : planes)
    {
      nodes.Slip.Planes.push_back(fitted.Plane);
      const auto plane = static_cast<std::int32_t>(nodes.Slip.Planes.size() - 1);
      if (!fitted.Moving->empty())
      {
        nodes.MovingOnSlip.push_back({ plane, *fitted.Moving, fitted.Name });
      }
      for (std::int32_t node : *fitted.Nodes)
      {
        const auto [at, first] = listed.emplace(node, nodes.Slip.Nodes.size());
        if (!first)
        {
          nodes.Slip.SecondPlanes.resize(nodes.Slip.Nodes.size(), -1);
          nodes.Slip.SecondPlanes[at->second] = plane;
          ++planesOfNode[at->second];
          continue;
        }
        nodes.Slip.Nodes.push_back(node);
        nodes.Slip.NodePlanes.push_back(plane);
        planesOfNode.push_back(1);
      }
    }
  }
  if (!nodes.Slip.SecondPlanes.empty())
  {
    nodes.Slip.SecondPlanes.resize(nodes.Slip.Nodes.size(), -1);
  }
  // On three planes or more (a corner where a group's planes meet): static. (Nodes on three
  // entries were made static with the roles already.)
  if (std::find_if(planesOfNode.begin(), planesOfNode.end(), [](int p) { return p > 2; }) ==
    planesOfNode.end())
  {
    return;
  }
  dgmf::SlipConstraint kept;
  kept.Planes = nodes.Slip.Planes;
  for (std::size_t k = 0; k < nodes.Slip.Nodes.size(); ++k)
  {
    const std::int32_t node = nodes.Slip.Nodes[k];
    if (planesOfNode[k] > 2)
    {
      nodes.Kinds[static_cast<std::size_t>(node)] = dgmf::NodeKind::StaticBoundary;
      continue;
    }
    kept.Nodes.push_back(node);
    kept.NodePlanes.push_back(nodes.Slip.NodePlanes[k]);
    kept.SecondPlanes.push_back(nodes.Slip.SecondPlaneOf(k));
  }
  nodes.Slip = std::move(kept);
}

} // namespace dgmf_vtk
