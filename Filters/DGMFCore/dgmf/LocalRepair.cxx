// The quality guard (Documentation/repair.md): cells a deformation step left inverted or below a
// SizeSkew threshold are repaired by moving nearby interior nodes, one node at a time, with
// Knupp's untangling objective (Engineering with Computers 17, 2001) where a cell is inverted and
// max-min SizeSkew smoothing (Freitag's smart Laplacian with an optimisation step) elsewhere.
#include "dgmf/LocalRepair.h"

#include "dgmf/DecomposedSizeSkew.h"
#include "dgmf/NodeRepairer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace dgmf
{
namespace
{
using namespace repair;

/// Cells per block of the quality evaluation (fixed, so the result does not depend on threads).
constexpr std::size_t kCellsPerBlock = 2048;
/// 2D cells around a node are coplanar if the sines between their normals are below this.
constexpr double kCoplanarTolerance = 1e-8;

void Validate(const CellMesh& mesh, const double* originalPoints, const double* points,
  const NodeKind* kinds, const RepairParameters& parameters)
{
  if (!(parameters.Threshold >= 0.0 && parameters.Threshold <= 1.0))
  {
    throw std::invalid_argument("RepairCells: the threshold must be a number in [0, 1]");
  }
  if (parameters.Layers < 0 || parameters.MaximumPasses < 0)
  {
    throw std::invalid_argument("RepairCells: Layers and MaximumPasses must be >= 0");
  }
  const std::size_t cells = mesh.GetNumberOfCells();
  if (cells == 0)
  {
    return;
  }
  if (mesh.Shapes.size() != cells || (!mesh.Covered.empty() && mesh.Covered.size() != cells))
  {
    throw std::invalid_argument(
      "RepairCells: Shapes (and Covered, if given) need one entry per cell");
  }
  if (originalPoints == nullptr || points == nullptr || kinds == nullptr)
  {
    throw std::invalid_argument("RepairCells: points, original points and node kinds are required");
  }
  if (mesh.Offsets[0] < 0 ||
    static_cast<std::size_t>(mesh.Offsets[cells]) > mesh.Connectivity.size())
  {
    throw std::invalid_argument("RepairCells: the offsets do not fit the connectivity");
  }
  const auto numberOfPoints = static_cast<std::int64_t>(mesh.NumberOfPoints);
  for (std::size_t c = 0; c < cells; ++c)
  {
    const std::int64_t begin = mesh.Offsets[c];
    const std::int64_t end = mesh.Offsets[c + 1];
    if (end < begin)
    {
      throw std::invalid_argument("RepairCells: the offsets must not decrease");
    }
    if (IsCovered(mesh, c) && end - begin != GetNumberOfCorners(mesh.Shapes[c]))
    {
      throw std::invalid_argument("RepairCells: a cell's corner count does not match its shape");
    }
    for (std::int64_t k = begin; k < end; ++k)
    {
      const std::int64_t node = mesh.Connectivity[static_cast<std::size_t>(k)];
      if (node < 0 || node >= numberOfPoints)
      {
        throw std::invalid_argument("RepairCells: a node index is out of range");
      }
    }
  }
}

/// Unit normal of the plane the node's 2D cells share, or false if they are not coplanar.
bool FindPlane(const std::vector<ActiveCell>& cells, const std::size_t* incident, std::size_t count,
  const double* points, Vec3& normal)
{
  // The deformed cells' normals; the original ones if none is usable (a lost node).
  for (int configuration = 0; configuration < 2; ++configuration)
  {
    bool found = false;
    Vec3 reference{ 0.0, 0.0, 0.0 };
    double referenceLength = 0.0;
    for (std::size_t i = 0; i < count; ++i)
    {
      const ActiveCell& cell = cells[incident[i]];
      Vec3 n;
      if (configuration == 0)
      {
        double corners[3 * kMaximumCorners];
        for (int k = 0; k < cell.NumberOfNodes; ++k)
        {
          Store(Load(points, cell.Nodes[k]), corners, k);
        }
        n = PolygonNormal(cell.Shape, corners);
      }
      else
      {
        n = PolygonNormal(cell.Shape, cell.Original);
      }
      const double length = Norm(n);
      if (!(length > 0.0 && std::isfinite(length)))
      {
        continue;
      }
      if (!found)
      {
        reference = n;
        referenceLength = length;
        found = true;
      }
      else if (Norm(Cross(n, reference)) > kCoplanarTolerance * length * referenceLength)
      {
        return false;
      }
    }
    if (found)
    {
      normal = (1.0 / referenceLength) * reference;
      // Keep the axis exact for a plane normal to an axis (z kept bit for bit in x-y meshes).
      if (normal.X == 0.0 && normal.Y == 0.0)
      {
        normal.Z = normal.Z > 0.0 ? 1.0 : -1.0;
      }
      else if (normal.X == 0.0 && normal.Z == 0.0)
      {
        normal.Y = normal.Y > 0.0 ? 1.0 : -1.0;
      }
      else if (normal.Y == 0.0 && normal.Z == 0.0)
      {
        normal.X = normal.X > 0.0 ? 1.0 : -1.0;
      }
      return true;
    }
  }
  return false;
}

/// Two orthonormal vectors spanning the plane normal to the unit vector `n`: the projected
/// coordinate axis that is longest, then n x it (the x and y axes for n = +-z, exactly).
void PlaneBasis(const Vec3& n, Vec3& u, Vec3& v)
{
  const Vec3 axes[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  Vec3 longest{ 0.0, 0.0, 0.0 };
  double longestLength = -1.0;
  for (const Vec3& axis : axes)
  {
    const Vec3 projected = axis - Dot(axis, n) * n;
    const double length = Norm(projected);
    if (length > longestLength)
    {
      longest = projected;
      longestLength = length;
    }
  }
  u = (1.0 / longestLength) * longest;
  v = Cross(n, u);
}

} // namespace

RepairReport RepairCells(const CellMesh& mesh, const double* originalPoints, double* points,
  const NodeKind* kinds, const RepairParameters& parameters, const ParallelFor& parallelFor)
{
  Validate(mesh, originalPoints, points, kinds, parameters);
  RepairReport report;
  const std::size_t numberOfCells = mesh.GetNumberOfCells();
  if (numberOfCells == 0)
  {
    return report;
  }

  // 1. Quality of every cell, in fixed blocks.
  std::vector<double> quality(numberOfCells, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint8_t> inverted(numberOfCells, 0);
  const std::size_t blocks = (numberOfCells + kCellsPerBlock - 1) / kCellsPerBlock;
  ForEachBlock(parallelFor, blocks,
    [&](std::size_t block)
    {
      double original[3 * kMaximumCorners];
      double deformed[3 * kMaximumCorners];
      const std::size_t end = std::min(numberOfCells, (block + 1) * kCellsPerBlock);
      for (std::size_t c = block * kCellsPerBlock; c < end; ++c)
      {
        if (IsCovered(mesh, c))
        {
          GatherCorners(mesh, c, originalPoints, original);
          GatherCorners(mesh, c, points, deformed);
          const CellQuality q = ComputeCellSizeSkew(mesh.Shapes[c], original, deformed);
          quality[c] = q.SizeSkew;
          inverted[c] = q.Inverted ? 1 : 0;
        }
      }
    });
  const auto summarize = [&](std::size_t& bad, std::size_t& invertedCount, double& minimum)
  {
    bad = 0;
    invertedCount = 0;
    minimum = kInfinity;
    for (std::size_t c = 0; c < numberOfCells; ++c)
    {
      if (IsCovered(mesh, c))
      {
        bad += IsBadCell(CellQuality{ quality[c], inverted[c] != 0 }, parameters.Threshold) ? 1 : 0;
        invertedCount += inverted[c];
        minimum = std::min(minimum, quality[c]);
      }
    }
    if (minimum == kInfinity)
    {
      minimum = 0.0;
    }
  };
  summarize(report.BadCellsBefore, report.InvertedBefore, report.MinimumBefore);
  report.BadCellsAfter = report.BadCellsBefore;
  report.InvertedAfter = report.InvertedBefore;
  report.MinimumAfter = report.MinimumBefore;
  if (report.BadCellsBefore == 0 || parameters.MaximumPasses == 0)
  {
    return report;
  }

  // 2. Nodes that never move: boundary nodes, and the nodes of cells the metric does not cover.
  const std::size_t numberOfPoints = mesh.NumberOfPoints;
  std::vector<std::uint8_t> fixed(numberOfPoints, 0);
  for (std::size_t n = 0; n < numberOfPoints; ++n)
  {
    fixed[n] = kinds[n] != NodeKind::Interior ? 1 : 0;
  }
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    if (!IsCovered(mesh, c))
    {
      for (std::int64_t k = mesh.Offsets[c]; k < mesh.Offsets[c + 1]; ++k)
      {
        fixed[static_cast<std::size_t>(mesh.Connectivity[static_cast<std::size_t>(k)])] = 1;
      }
    }
  }

  // 3. The region: seeds are the bad cells that can change (a movable node, not degenerate),
  // grown by `Layers` node-neighbour layers. slot[n] holds the layer of node n (-1: outside).
  std::vector<std::int64_t> slot(numberOfPoints, -1);
  const auto nodesOf = [&](std::size_t c)
  {
    return std::make_pair(
      mesh.Connectivity.data() + mesh.Offsets[c], mesh.Connectivity.data() + mesh.Offsets[c + 1]);
  };
  bool anySeed = false;
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    if (!IsCovered(mesh, c) ||
      !IsBadCell(CellQuality{ quality[c], inverted[c] != 0 }, parameters.Threshold))
    {
      continue;
    }
    if (quality[c] == 0.0 && inverted[c] == 0)
    {
      continue; // degenerate original cell: no move changes its score
    }
    const auto range = nodesOf(c);
    const bool movable = std::any_of(range.first, range.second,
      [&](std::int64_t n) { return fixed[static_cast<std::size_t>(n)] == 0; });
    if (movable)
    {
      anySeed = true;
      for (const std::int64_t* n = range.first; n != range.second; ++n)
      {
        slot[static_cast<std::size_t>(*n)] = 0;
      }
    }
  }
  if (!anySeed)
  {
    return report;
  }
  for (int layer = 1; layer <= parameters.Layers; ++layer)
  {
    bool grew = false;
    for (std::size_t c = 0; c < numberOfCells; ++c)
    {
      const auto range = nodesOf(c);
      const bool touches = std::any_of(range.first, range.second,
        [&](std::int64_t n)
        {
          const std::int64_t level = slot[static_cast<std::size_t>(n)];
          return level >= 0 && level < layer;
        });
      if (touches)
      {
        for (const std::int64_t* n = range.first; n != range.second; ++n)
        {
          if (slot[static_cast<std::size_t>(*n)] < 0)
          {
            slot[static_cast<std::size_t>(*n)] = layer;
            grew = true;
          }
        }
      }
    }
    if (!grew)
    {
      break;
    }
  }

  // 4. Free nodes (slot becomes their index) and the cells around them.
  NodeRepairer repairer(mesh, originalPoints, points, slot);
  std::vector<FreeNode>& nodes = repairer.Nodes;
  for (std::size_t n = 0; n < numberOfPoints; ++n)
  {
    if (slot[n] >= 0 && fixed[n] == 0)
    {
      slot[n] = static_cast<std::int64_t>(nodes.size());
      FreeNode node;
      node.Id = static_cast<std::int64_t>(n);
      nodes.push_back(node);
    }
    else
    {
      slot[n] = -1;
    }
  }
  std::vector<std::size_t> counts(nodes.size() + 1, 0);
  std::vector<std::size_t> activeCells; // the cells with a free node, then made once (no regrowth)
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    const auto range = nodesOf(c);
    bool active = false;
    for (const std::int64_t* n = range.first; n != range.second; ++n)
    {
      const std::int64_t index = slot[static_cast<std::size_t>(*n)];
      if (index >= 0 && std::find(range.first, n, *n) == n) // count a repeated node once
      {
        ++counts[static_cast<std::size_t>(index) + 1];
        active = true;
      }
    }
    if (active)
    {
      activeCells.push_back(c);
    }
  }
  std::vector<ActiveCell>& cells = repairer.Cells;
  cells.resize(activeCells.size());
  for (std::size_t a = 0; a < activeCells.size(); ++a)
  {
    // Only covered cells: a free node has no uncovered cell (its nodes are fixed).
    const std::size_t c = activeCells[a];
    repairer.InitializeCell(cells[a], c, quality[c], inverted[c] != 0);
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    counts[i + 1] += counts[i];
    nodes[i].CellBegin = counts[i];
    nodes[i].CellEnd = counts[i];
  }
  repairer.Incident.resize(counts.back());
  for (std::size_t a = 0; a < cells.size(); ++a)
  {
    const ActiveCell& cell = cells[a];
    for (int k = 0; k < cell.NumberOfNodes; ++k)
    {
      const std::int64_t index = slot[static_cast<std::size_t>(cell.Nodes[k])];
      if (index >= 0 && std::find(cell.Nodes, cell.Nodes + k, cell.Nodes[k]) == cell.Nodes + k)
      {
        repairer.Incident[nodes[static_cast<std::size_t>(index)].CellEnd++] = a;
      }
    }
  }

  // 5. Move space of each node: all directions among 3D cells, the plane of its 2D cells.
  for (FreeNode& node : nodes)
  {
    int dimensions = 0; // bit 0: a 2D cell, bit 1: a 3D cell
    bool anyValid = false;
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = cells[repairer.Incident[i]];
      dimensions |= cell.Tables.Dimension == 2 ? 1 : 2;
      anyValid = anyValid || !cell.Degenerate;
    }
    if (!anyValid || dimensions == 3)
    {
      node.Enabled = false;
    }
    else if (dimensions == 1)
    {
      node.Dimension = 2;
      if (FindPlane(cells, repairer.Incident.data() + node.CellBegin, node.CellEnd - node.CellBegin,
            points, node.Normal))
      {
        PlaneBasis(node.Normal, node.Basis[0], node.Basis[1]);
      }
      else
      {
        node.Enabled = false;
      }
    }
    if (node.Enabled)
    {
      ++report.FreeNodes;
      for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
      {
        ++cells[repairer.Incident[i]].FreeNodeCount;
      }
    }
  }

  // 6. The passes, then the report.
  std::vector<double> before(3 * nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    std::copy(points + 3 * nodes[i].Id, points + 3 * nodes[i].Id + 3, before.begin() + 3 * i);
  }
  report.Passes = repairer.Run(parameters.MaximumPasses, parameters.Threshold, parameters.Progress,
    parameters.GiveUpWhenHopeless, &report.GaveUp);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    const double* p = points + 3 * nodes[i].Id;
    if (std::memcmp(p, before.data() + 3 * i, 3 * sizeof(double)) != 0)
    {
      ++report.MovedNodes;
    }
  }
  // The passes judge tetrahedra through their forms (equal up to round-off); the cells' values
  // are taken again from the full metric, so that they are the bits the mesh's quality gives.
  double corners[3 * kMaximumCorners];
  for (const ActiveCell& cell : cells)
  {
    GatherCorners(mesh, cell.Cell, points, corners);
    const CellQuality q = ComputeCellSizeSkew(cell.Shape, cell.Original, corners);
    quality[cell.Cell] = q.SizeSkew;
    inverted[cell.Cell] = q.Inverted ? 1 : 0;
  }
  summarize(report.BadCellsAfter, report.InvertedAfter, report.MinimumAfter);
  return report;
}

} // namespace dgmf
