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
  // The planes of every slip node, in the order the nodes first come.
  std::unordered_map<std::int32_t, std::size_t> slot;
  std::vector<std::int32_t> order;
  std::vector<std::vector<std::int32_t>> planesOf;
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
        if (nodes.Kinds[static_cast<std::size_t>(node)] != dgmf::NodeKind::SlipBoundary)
        {
          continue; // made static since the roles (an edge on the unread boundary): it fits only
        }
        const auto [at, first] = slot.emplace(node, order.size());
        if (first)
        {
          order.push_back(node);
          planesOf.emplace_back();
        }
        planesOf[at->second].push_back(plane);
      }
    }
  }
  // Each node on its distinct planes (two patches of one plane are one): one, it slides in it;
  // two, along their line (two lines of a 2D mesh: a point, static; a one-cell-thick mesh's
  // layer makes such a node static too); three or more (a corner), static.
  std::vector<std::int32_t> seconds;
  bool anySecond = false;
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    std::vector<std::int32_t> distinct;
    for (const std::int32_t plane : planesOf[k])
    {
      const dgmf::SlipPlane& p = nodes.Slip.Planes[static_cast<std::size_t>(plane)];
      if (std::none_of(distinct.begin(), distinct.end(),
            [&](std::int32_t d)
            { return dgmf::SamePlane(nodes.Slip.Planes[static_cast<std::size_t>(d)], p); }))
      {
        distinct.push_back(plane);
      }
    }
    if (distinct.size() >= 3 || (distinct.size() == 2 && nodes.Dimension == 2))
    {
      nodes.Kinds[static_cast<std::size_t>(order[k])] = dgmf::NodeKind::StaticBoundary;
      continue;
    }
    nodes.Slip.Nodes.push_back(order[k]);
    nodes.Slip.NodePlanes.push_back(distinct[0]);
    seconds.push_back(distinct.size() > 1 ? distinct[1] : -1);
    anySecond = anySecond || distinct.size() > 1;
  }
  if (anySecond)
  {
    nodes.Slip.SecondPlanes = std::move(seconds);
  }
}

} // namespace dgmf_vtk
