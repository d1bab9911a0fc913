#include "DGMFDistributedSlip.h"

#include "DGMFDistributed.h"
#include "DGMFInputNodes.h"

#include "dgmf/SlipPlanes.h"

#include "vtkMultiProcessController.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace dgmf_vtk
{
namespace
{
using Position = std::array<double, 3>;

/// Every process's (x, y, z, entry) of its slip nodes, this process's included. Collective.
std::vector<double> GatherSlipNodes(vtkMultiProcessController* controller, const InputNodes& nodes)
{
  std::vector<double> send;
  for (std::size_t g = 0; g < nodes.SlipGroups.size(); ++g)
  {
    for (const std::int32_t node : nodes.SlipGroups[g])
    {
      if (nodes.Kinds[static_cast<std::size_t>(node)] != dgmf::NodeKind::SlipBoundary)
      {
        continue; // moving or static on another piece's block (AppendRemoteBoundaryNodes)
      }
      const double* p = nodes.Points + 3 * static_cast<std::size_t>(node);
      send.insert(send.end(), { p[0], p[1], p[2], static_cast<double>(g) });
    }
  }
  std::vector<std::size_t> offsets;
  return AllGatherDoubles(controller, send, offsets);
}
} // namespace

std::string AgreeOnSlipPlanes(vtkMultiProcessController* controller, InputNodes& nodes)
{
  const std::vector<double> all = GatherSlipNodes(controller, nodes);
  // Per entry, its distinct positions in increasing order (a node on two pieces counts once, and
  // every process sums them in the same order); per position, its entries in increasing order.
  std::vector<std::vector<Position>> entries(nodes.SlipGroups.size());
  std::map<Position, std::vector<std::size_t>> entriesAt;
  for (std::size_t k = 0; k + 3 < all.size(); k += 4)
  {
    const auto g = static_cast<std::size_t>(all[k + 3]);
    if (g < entries.size())
    {
      entries[g].push_back({ all[k], all[k + 1], all[k + 2] });
    }
  }
  nodes.Slip = dgmf::SlipConstraint();
  std::string error;
  std::vector<std::int32_t> planeOf(entries.size(), -1);
  for (std::size_t g = 0; g < entries.size(); ++g)
  {
    std::vector<Position>& positions = entries[g];
    std::sort(positions.begin(), positions.end());
    positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
    if (positions.empty())
    {
      continue; // an entry without slip nodes anywhere (the serial run skips it too)
    }
    std::vector<std::int32_t> ids(positions.size());
    std::iota(ids.begin(), ids.end(), 0);
    try
    {
      nodes.Slip.Planes.push_back(dgmf::FitSlipPlane(positions.front().data(), ids.data(),
        ids.size(), nodes.SlipNames[g], dgmf::SlipPlaneTolerance, nodes.Dimension));
    }
    catch (const std::invalid_argument& e)
    {
      error = e.what();
      break;
    }
    planeOf[g] = static_cast<std::int32_t>(nodes.Slip.Planes.size() - 1);
    for (const Position& p : positions)
    {
      entriesAt[p].push_back(g);
    }
  }
  // Every process fits the same positions, but an empty piece may have gathered no entry.
  if (!AllProcessesAgree(controller, error.empty()))
  {
    nodes.Slip = dgmf::SlipConstraint();
    return error.empty() ? "A slip boundary is not a plane (said on another process)." : error;
  }
  // Per position, its distinct planes (two entries of one plane, a plane cut into patches named
  // apart, are one: dgmf::SamePlane), as the serial FitSlipPlanes counts them.
  for (auto& [position, at] : entriesAt)
  {
    std::vector<std::size_t> distinct;
    for (const std::size_t g : at)
    {
      const dgmf::SlipPlane& plane = nodes.Slip.Planes[static_cast<std::size_t>(planeOf[g])];
      if (std::none_of(distinct.begin(), distinct.end(),
            [&](std::size_t d) {
              return dgmf::SamePlane(
                nodes.Slip.Planes[static_cast<std::size_t>(planeOf[d])], plane);
            }))
      {
        distinct.push_back(g);
      }
    }
    at = std::move(distinct);
  }
  // On three planes, or on two lines of a 2D mesh, a node cannot move (the serial rule; a piece
  // may know only one of its planes): static, in this piece and in the other pieces' copies
  // alike (a static node is a vertex of the graph every process builds).
  for (std::size_t i = 0; i < nodes.NumberOfNodes; ++i)
  {
    if (nodes.Kinds[i] == dgmf::NodeKind::SlipBoundary)
    {
      const double* p = nodes.Points + 3 * i;
      const auto found = entriesAt.find({ p[0], p[1], p[2] });
      if (found != entriesAt.end() &&
        (found->second.size() >= 3 || (found->second.size() == 2 && nodes.Dimension == 2)))
      {
        nodes.Kinds[i] = dgmf::NodeKind::StaticBoundary;
      }
    }
  }
  // This piece's slip nodes, with the planes of the entries they are on (the first two, as the
  // serial gathering gives them).
  bool second = false;
  for (std::size_t i = 0; i < nodes.LocalNodes; ++i)
  {
    if (nodes.Kinds[i] != dgmf::NodeKind::SlipBoundary)
    {
      continue;
    }
    const double* p = nodes.Points + 3 * i;
    const auto found = entriesAt.find({ p[0], p[1], p[2] });
    if (found == entriesAt.end())
    {
      continue;
    }
    nodes.Slip.Nodes.push_back(static_cast<std::int32_t>(i));
    nodes.Slip.NodePlanes.push_back(planeOf[found->second[0]]);
    const std::int32_t other = found->second.size() > 1 ? planeOf[found->second[1]] : -1;
    if (other >= 0 && !second)
    {
      nodes.Slip.SecondPlanes.assign(nodes.Slip.Nodes.size() - 1, -1);
      second = true;
    }
    if (second)
    {
      nodes.Slip.SecondPlanes.push_back(other);
    }
  }
  return "";
}

} // namespace dgmf_vtk
