// The quality guard's node steps, without the moves themselves (RepairMoves.cxx).
#include "dgmf/NodeRepairer.h"

#include "dgmf/DecomposedSizeSkew.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace dgmf
{
namespace repair
{

/// Newell normal (twice the vector area) of a triangle or quad given by its corners.
Vec3 PolygonNormal(CellShape shape, const double* corners)
{
  const Vec3 p0 = Load(corners, 0);
  if (shape == CellShape::Triangle)
  {
    return Cross(Load(corners, 1) - p0, Load(corners, 2) - p0);
  }
  return Cross(Load(corners, 2) - p0, Load(corners, 3) - Load(corners, 1));
}

NodeRepairer::NodeRepairer(const CellMesh& mesh, const double* originalPoints, double* points,
  const std::vector<std::int64_t>& freeIndex)
  : Mesh(mesh)
  , OriginalPoints(originalPoints)
  , Points(points)
  , FreeIndex(freeIndex)
{
}

void NodeRepairer::InitializeCell(
  ActiveCell& cell, std::size_t c, double quality, bool inverted) const
{
  cell.Cell = c;
  cell.Shape = this->Mesh.Shapes[c];
  cell.Tables = GetShapeTables(cell.Shape);
  cell.NumberOfNodes = GetNumberOfCorners(cell.Shape);
  cell.Nodes = this->Mesh.Connectivity.data() + this->Mesh.Offsets[c];
  GatherCorners(this->Mesh, c, this->OriginalPoints, cell.Original);
  // A degenerate input cell scores 0 even unchanged (a non-convex one is judged through its faces).
  const CellQuality self = ComputeCellSizeSkew(cell.Shape, cell.Original, cell.Original);
  cell.Degenerate = self.SizeSkew == 0.0 && !self.Inverted;
  cell.Quality = quality;
  cell.Inverted = inverted;
  if (cell.Tables.Dimension == 2)
  {
    const Vec3 n0 = PolygonNormal(cell.Shape, cell.Original);
    const double length = Norm(n0);
    if (length > 0.0 && std::isfinite(length))
    {
      cell.Normal0 = (1.0 / length) * n0;
      // Mean corner Jacobian: 2 x area (triangle), area (quad); |n0| = 2 x area.
      cell.Beta = kUntangleFraction * (cell.Shape == CellShape::Triangle ? length : 0.5 * length);
    }
    else
    {
      cell.Degenerate = true;
    }
  }
  else
  {
    double sum = 0.0;
    for (int k = 0; k < cell.Tables.NumberOfCorners; ++k)
    {
      sum += this->Alpha3(cell.Tables.Corners[k], cell.Original);
    }
    cell.Orientation = sum < 0.0 ? -1.0 : 1.0;
    cell.OriginalAlpha = cell.Orientation * sum; // a tetrahedron's one corner
    cell.Beta = kUntangleFraction * std::abs(sum) / cell.Tables.NumberOfCorners;
    if (!std::isfinite(cell.Beta))
    {
      cell.Degenerate = true;
    }
  }
}

std::size_t NodeRepairer::Run(
  int maximumPasses, double threshold, const Progress& progress, bool giveUp, bool* gaveUp)
{
  this->Threshold = threshold;
  this->FormsNode = -1;
  this->CollectEdgeEnds();
  this->CollectTetraCorners();
  std::size_t passes = 0;
  this->Dirty.assign(this->Nodes.size(), 1);
  std::size_t previous = 0, first = 0;
  for (int pass = 0; pass < maximumPasses; ++pass)
  {
    const std::size_t bad = this->CountRepairableBadCells(threshold);
    if (bad == 0)
    {
      break;
    }
    if (giveUp && pass == 1 && bad > first)
    {
      // The first pass (where the untangling does most of its work) left more bad cells than it
      // found: a step this far is beyond the repair.
      if (gaveUp != nullptr)
      {
        *gaveUp = true;
      }
      break;
    }
    if (giveUp && pass >= 3)
    {
      // Passes needed at the last pass's rate (the count falls by about as many cells a pass
      // while the repair goes well), for a count still a large part of the first one.
      const double needed =
        bad < previous ? static_cast<double>(bad) / static_cast<double>(previous - bad) : kInfinity;
      const bool large = 10 * bad >= first;
      if (large && needed > static_cast<double>(maximumPasses - pass))
      {
        if (gaveUp != nullptr)
        {
          *gaveUp = true;
        }
        break;
      }
    }
    previous = bad;
    first = pass == 0 ? bad : first;
    std::size_t moved = 0;
    for (std::size_t i = 0; i < this->Nodes.size(); ++i)
    {
      if (this->Nodes[i].Enabled && this->Dirty[i] != 0)
      {
        this->Dirty[i] = 0;
        if (this->StepNode(this->Nodes[i]))
        {
          ++moved;
        }
      }
    }
    ++passes;
    progress.Report(static_cast<double>(passes) / maximumPasses);
    if (moved == 0)
    {
      break;
    }
  }
  return passes;
}

double NodeRepairer::Alpha3(const CornerEdges& corner, const double* corners)
{
  const Vec3 o = Load(corners, corner.Origin);
  return Dot(
    Cross(Load(corners, corner.A) - o, Load(corners, corner.B) - o), Load(corners, corner.C) - o);
}

void NodeRepairer::GatherWith(
  const ActiveCell& cell, std::int64_t node, const Vec3& position, double* out) const
{
  for (int k = 0; k < cell.NumberOfNodes; ++k)
  {
    const Vec3 p = cell.Nodes[k] == node ? position : Load(this->Points, cell.Nodes[k]);
    Store(p, out, k);
  }
}

std::size_t NodeRepairer::CountRepairableBadCells(double threshold) const
{
  std::size_t count = 0;
  for (const ActiveCell& cell : this->Cells)
  {
    if (cell.FreeNodeCount > 0 && !cell.Degenerate &&
      IsBadCell(CellQuality{ cell.Quality, cell.Inverted }, threshold))
    {
      ++count;
    }
  }
  return count;
}

CellQuality NodeRepairer::QualityAt(
  const FreeNode& node, std::size_t offset, const Vec3& position) const
{
  if (this->FormsNode == node.Id && this->Forms[offset].Usable)
  {
    return this->Forms[offset].Evaluate(position);
  }
  const ActiveCell& cell = this->Cells[this->Incident[node.CellBegin + offset]];
  double corners[3 * kMaximumCorners];
  this->GatherWith(cell, node.Id, position, corners);
  return ComputeCellSizeSkew(cell.Shape, cell.Original, corners);
}

void NodeRepairer::IncidentQualities(
  const FreeNode& node, const Vec3& position, double* qualities) const
{
  const std::size_t count = node.CellEnd - node.CellBegin;
  for (std::size_t offset = 0; offset < count; ++offset)
  {
    if (!this->Cells[this->Incident[node.CellBegin + offset]].Degenerate)
    {
      qualities[offset] = this->QualityAt(node, offset, position).SizeSkew;
    }
  }
}

double NodeRepairer::TrialMinimumCube(const FreeNode& node, const Vec3& position, bool& inverted,
  double cutoffCube, std::size_t first) const
{
  const bool forms = this->FormsNode == node.Id;
  const std::size_t count = node.CellEnd - node.CellBegin;
  if (forms && this->FormGroupsReady && first == this->FormGroupsFirst)
  {
    // Only tetrahedra with forms: four at a time, the same values and the same answer.
    return MinimumCubedSizeSkew(this->FormGroups.data(), count, position, cutoffCube, inverted);
  }
  double corners[3 * kMaximumCorners];
  double minimum = kInfinity;
  inverted = false;
  for (std::size_t j = 0; j < count; ++j)
  {
    const std::size_t offset = WrappedOffset(j, first, count);
    double cube;
    if (forms && this->Forms[offset].Usable)
    {
      cube = this->Forms[offset].CubedSizeSkew(position, inverted); // the cell is not read
    }
    else
    {
      const ActiveCell& cell = this->Cells[this->Incident[node.CellBegin + offset]];
      if (cell.Degenerate)
      {
        continue;
      }
      this->GatherWith(cell, node.Id, position, corners);
      const CellQuality quality = ComputeCellSizeSkew(cell.Shape, cell.Original, corners);
      inverted = inverted || quality.Inverted;
      cube = quality.SizeSkew * quality.SizeSkew * quality.SizeSkew;
    }
    minimum = std::min(minimum, cube);
    if (minimum <= cutoffCube)
    {
      break;
    }
  }
  return minimum;
}

double NodeRepairer::CornerMargins(const FreeNode& node, const Vec3& position,
  std::vector<double>* margins, std::vector<double>* targets, double cutoff) const
{
  double corners[3 * kMaximumCorners];
  double objective = 0.0;
  if (margins != nullptr)
  {
    margins->clear();
  }
  if (targets != nullptr)
  {
    targets->clear();
  }
  for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
  {
    const ActiveCell& cell = this->Cells[this->Incident[i]];
    if (cell.Degenerate)
    {
      continue;
    }
    this->GatherWith(cell, node.Id, position, corners);
    for (int k = 0; k < cell.Tables.NumberOfCorners; ++k)
    {
      const CornerEdges& corner = cell.Tables.Corners[k];
      double alpha;
      if (cell.Tables.Dimension == 2)
      {
        const Vec3 o = Load(corners, corner.Origin);
        alpha = Dot(Cross(Load(corners, corner.A) - o, Load(corners, corner.B) - o), cell.Normal0);
      }
      else
      {
        alpha = cell.Orientation * Alpha3(corner, corners);
      }
      const double margin = alpha - cell.Beta;
      if (!std::isfinite(margin))
      {
        objective = kInfinity;
      }
      else if (margin < 0.0)
      {
        objective -= margin;
      }
      if (margins != nullptr)
      {
        margins->push_back(margin);
      }
      if (targets != nullptr)
      {
        targets->push_back(cell.Beta);
      }
    }
    if (margins == nullptr && objective >= cutoff)
    {
      break;
    }
  }
  return objective;
}

void NodeRepairer::PrepareFormGroups(const FreeNode& node, std::size_t first)
{
  this->FormGroupsReady = false;
  const std::size_t count = node.CellEnd - node.CellBegin;
  if (this->FormsNode != node.Id || count == 0 || first >= count)
  {
    return;
  }
  for (std::size_t offset = 0; offset < count; ++offset)
  {
    if (!this->Forms[offset].Usable)
    {
      return; // degenerate cells and other shapes: cell by cell
    }
  }
  StoreFormsInGroups(this->Forms.data(), count, first, this->FormGroups);
  this->FormGroupsFirst = first;
  this->FormGroupsReady = true;
}

void NodeRepairer::PrepareForms(const FreeNode& node)
{
  const std::size_t count = node.CellEnd - node.CellBegin;
  this->Forms.resize(count);
  this->FormsNode = node.Id;
  this->FormGroupsReady = false;
  for (std::size_t offset = 0; offset < count; ++offset)
  {
    const int corner = this->TetraCorner[node.CellBegin + offset];
    if (corner < 0)
    {
      this->Forms[offset].Usable = false;
      continue;
    }
    const TetraIncidence& incidence = this->TetraIncidences[node.CellBegin + offset];
    this->Forms[offset] = MakeTetraForm(Load(this->Points, incidence.Others[0]),
      Load(this->Points, incidence.Others[1]), Load(this->Points, incidence.Others[2]), corner,
      incidence.Orientation, incidence.OriginalAlpha);
  }
}

void NodeRepairer::CollectEdgeEnds()
{
  this->EdgeEnds.clear();
  this->EdgeEnds.reserve(3 * this->Incident.size()); // 3 edges a corner in 3D cells (no regrowth)
  for (FreeNode& node : this->Nodes)
  {
    node.EdgeBegin = this->EdgeEnds.size();
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      for (int e = 0; e < cell.Tables.NumberOfEdges; ++e)
      {
        const std::int64_t a = cell.Nodes[cell.Tables.Edges[e][0]];
        const std::int64_t b = cell.Nodes[cell.Tables.Edges[e][1]];
        if ((a == node.Id) != (b == node.Id)) // an edge of the node (and not a collapsed one)
        {
          this->EdgeEnds.push_back(a == node.Id ? b : a);
        }
      }
    }
    node.EdgeEnd = this->EdgeEnds.size();
  }
}

void NodeRepairer::CollectTetraCorners()
{
  this->TetraCorner.assign(this->Incident.size(), -1);
  this->TetraIncidences.resize(this->Incident.size());
  this->OnlyTetrahedra.assign(this->Nodes.size(), 0);
  for (std::size_t n = 0; n < this->Nodes.size(); ++n)
  {
    const FreeNode& node = this->Nodes[n];
    // A node without cells marks nothing on a move (it never moves: nothing to improve).
    this->OnlyTetrahedra[n] = node.CellBegin < node.CellEnd ? 1 : 0;
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      if (cell.Shape != CellShape::Tetra || cell.Degenerate)
      {
        this->OnlyTetrahedra[n] = 0;
        continue;
      }
      int corner = -1;
      for (int c = 0; c < 4; ++c)
      {
        if (cell.Nodes[c] == node.Id)
        {
          corner = corner < 0 ? c : 4; // 4: the node twice (a collapsed cell): evaluated in full
        }
      }
      this->TetraCorner[i] = static_cast<std::int8_t>(corner >= 0 && corner < 4 ? corner : -1);
      if (this->TetraCorner[i] < 0)
      {
        this->OnlyTetrahedra[n] = 0;
        continue;
      }
      TetraIncidence& incidence = this->TetraIncidences[i];
      for (int c = 0, k = 0; c < 4; ++c)
      {
        if (c != corner)
        {
          incidence.Others[k++] = cell.Nodes[c];
        }
      }
      incidence.Orientation = cell.Orientation;
      incidence.OriginalAlpha = cell.OriginalAlpha;
    }
  }
}

void NodeRepairer::Neighbourhood(
  const FreeNode& node, const Vec3& x, Vec3& laplacian, double& length) const
{
  const std::size_t count = node.EdgeEnd - node.EdgeBegin;
  if (count == 0)
  {
    laplacian = x;
    length = 0.0;
    return;
  }
  const std::int64_t* ends = this->EdgeEnds.data() + node.EdgeBegin;
  const Vec3 reference = Load(this->Points, ends[0]);
  Vec3 sum{ 0.0, 0.0, 0.0 };
  double deformedLength = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 p = Load(this->Points, ends[i]);
    sum = sum + (p - reference);
    deformedLength += Norm(p - x);
  }
  laplacian = reference + (1.0 / static_cast<double>(count)) * sum;
  length = deformedLength / static_cast<double>(count);
  if (!(length > 0.0 && std::isfinite(length)))
  {
    const Vec3 x0 = Load(this->OriginalPoints, node.Id);
    double originalLength = 0.0;
    for (std::size_t i = 0; i < count; ++i)
    {
      originalLength += Norm(Load(this->OriginalPoints, ends[i]) - x0);
    }
    length = originalLength / static_cast<double>(count);
  }
}

void NodeRepairer::AddLatticeDirections(const FreeNode& node)
{
  // A 3D node keeps the standard basis: its 26 directions are the same for every such node, so
  // they are made once (by the same operations) and copied after that.
  static const FreeNode standardNode;
  const bool standard =
    node.Dimension == 3 && std::memcmp(node.Basis, standardNode.Basis, sizeof node.Basis) == 0;
  if (standard && !this->StandardLattice.empty())
  {
    this->Directions.insert(
      this->Directions.end(), this->StandardLattice.begin(), this->StandardLattice.end());
    return;
  }
  const std::size_t first = this->Directions.size();
  for (int a = -1; a <= 1; ++a)
  {
    for (int b = -1; b <= 1; ++b)
    {
      for (int c = -1; c <= 1; ++c)
      {
        if ((a == 0 && b == 0 && c == 0) || (node.Dimension == 2 && c != 0))
        {
          continue;
        }
        this->AddDirection(static_cast<double>(a) * node.Basis[0] +
          static_cast<double>(b) * node.Basis[1] + static_cast<double>(c) * node.Basis[2]);
      }
    }
  }
  if (standard)
  {
    this->StandardLattice.assign(this->Directions.begin() + first, this->Directions.end());
  }
}

void NodeRepairer::Accept(FreeNode& node, const Vec3& position)
{
  Store(position, this->Points, node.Id);
  const auto markDirty = [this](std::int64_t id)
  {
    const std::int64_t index = this->FreeIndex[static_cast<std::size_t>(id)];
    if (index >= 0)
    {
      this->Dirty[static_cast<std::size_t>(index)] = 1;
    }
  };
  // The nodes of its cells may now move (they are marked dirty). Only tetrahedra: the node and its
  // edge ends, which lie together, instead of each cell's scattered connectivity (the same nodes).
  const bool onlyTetrahedra = this->OnlyTetrahedra[static_cast<std::size_t>(
                                this->FreeIndex[static_cast<std::size_t>(node.Id)])] != 0;
  if (onlyTetrahedra)
  {
    markDirty(node.Id);
    for (std::size_t e = node.EdgeBegin; e < node.EdgeEnd; ++e)
    {
      markDirty(this->EdgeEnds[e]);
    }
  }
  // Inside SmoothNode (the only holder of forms: it forgets them on its way out), the node's own
  // forms give its tetrahedra's values at the new position (the trials were judged by their
  // cubes), four at a time when they are in groups.
  const std::size_t count = node.CellEnd - node.CellBegin;
  const bool grouped = this->FormsNode == node.Id && this->FormGroupsReady;
  if (grouped)
  {
    this->AcceptedQualities.resize(count);
    EvaluateFormGroups(this->FormGroups.data(), count, position, this->AcceptedQualities.data());
  }
  for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
  {
    ActiveCell& cell = this->Cells[this->Incident[i]];
    const std::size_t offset = i - node.CellBegin;
    // The groups start at offset FormGroupsFirst and wrap around.
    const CellQuality quality = grouped
      ? this->AcceptedQualities[VisitOfOffset(offset, this->FormGroupsFirst, count)]
      : this->QualityAt(node, offset, position);
    cell.Quality = quality.SizeSkew;
    cell.Inverted = quality.Inverted;
    for (int k = 0; !onlyTetrahedra && k < cell.NumberOfNodes; ++k)
    {
      markDirty(cell.Nodes[k]);
    }
  }
}

bool NodeRepairer::StepNode(FreeNode& node)
{
  bool inverted = false;
  double minimum = kInfinity;
  for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
  {
    const ActiveCell& cell = this->Cells[this->Incident[i]];
    if (!cell.Degenerate)
    {
      inverted = inverted || cell.Inverted;
      minimum = std::min(minimum, cell.Quality);
    }
  }
  if (!inverted)
  {
    if (minimum >= std::min(1.0, kComfortFactor * this->Threshold))
    {
      return false; // every cell of the node is comfortably good: it need not make room
    }
    return this->SmoothNode(node, minimum);
  }
  bool moved = false;
  for (int step = 0; step < kUntangleStepsPerPass && inverted; ++step)
  {
    if (!this->UntangleNode(node))
    {
      break;
    }
    moved = true;
    inverted = false;
    for (std::size_t i = node.CellBegin; i < node.CellEnd; ++i)
    {
      const ActiveCell& cell = this->Cells[this->Incident[i]];
      inverted = inverted || (cell.Inverted && !cell.Degenerate);
    }
  }
  return moved;
}

} // namespace repair
} // namespace dgmf
