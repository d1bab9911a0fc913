#include "DGMFDistributed.h"

#include "DGMFMeshConversion.h"

#include "DGMFBoundaryNames.h"
#include "DGMFDistributedSlip.h"

#include "DGMFInputNodes.h"
#include "DGMFOutputArrays.h"
#include "DGMFSMPTools.h"

#include "dgmf/ExtrudedLayers.h"
#include "dgmf/ResultNames.h"

#include "vtkCellTypes.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace dgmf_vtk
{

bool IsDistributed(vtkMultiProcessController* controller)
{
  return controller && controller->GetNumberOfProcesses() > 1;
}

int AgreeOnDimension(vtkMultiProcessController* controller, vtkUnstructuredGrid* piece, double& z)
{
  // Maxima: the dimension of the piece's cells (0 without cells) and its largest x, y, z; minima:
  // its smallest x, y, z.
  const double infinity = std::numeric_limits<double>::infinity();
  double maxima[4] = { 0.0, -infinity, -infinity, -infinity };
  double minima[3] = { infinity, infinity, infinity };
  for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
  {
    const int type = piece->GetCellType(c);
    if (type != VTK_EMPTY_CELL)
    {
      const bool volume = vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 3;
      maxima[0] = std::max(maxima[0], volume ? 3.0 : 2.0);
    }
  }
  for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
  {
    const double* p = piece->GetPoint(i);
    for (int c = 0; c < 3; ++c)
    {
      maxima[1 + c] = std::max(maxima[1 + c], p[c]);
      minima[c] = std::min(minima[c], p[c]);
    }
  }
  double globalMaxima[4];
  double globalMinima[3];
  controller->AllReduce(maxima, globalMaxima, 4, vtkCommunicator::MAX_OP);
  controller->AllReduce(minima, globalMinima, 3, vtkCommunicator::MIN_OP);
  const int dimension = static_cast<int>(globalMaxima[0]);
  z = globalMinima[2];
  // The serial rule (DetectDimension): z may spread over PlanarZTolerance of the x-y extent.
  const double spread = globalMaxima[3] - globalMinima[2];
  const double extent =
    std::hypot(globalMaxima[1] - globalMinima[0], globalMaxima[2] - globalMinima[1]);
  return dimension == 2 && spread > 0.0 && !(spread <= PlanarZTolerance * extent) ? -1 : dimension;
}

void RequestOneGhostLevel(vtkInformation* inputInformation)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int requested = inputInformation->Has(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS())
    ? inputInformation->Get(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
  inputInformation->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), std::max(requested, 1));
}

bool AllProcessesAgree(vtkMultiProcessController* controller, bool ok)
{
  int local = ok ? 1 : 0;
  int global = 0;
  controller->AllReduce(&local, &global, 1, vtkCommunicator::MIN_OP);
  return global == 1;
}

std::vector<double> AllGatherDoubles(vtkMultiProcessController* controller,
  const std::vector<double>& send, std::vector<std::size_t>& offsets)
{
  const int processes = controller->GetNumberOfProcesses();
  const auto length = static_cast<vtkIdType>(send.size());
  std::vector<vtkIdType> lengths(static_cast<std::size_t>(processes), 0);
  controller->AllGather(&length, lengths.data(), 1);
  std::vector<vtkIdType> starts(static_cast<std::size_t>(processes), 0);
  offsets.assign(static_cast<std::size_t>(processes) + 1, 0);
  vtkIdType total = 0;
  for (int p = 0; p < processes; ++p)
  {
    starts[static_cast<std::size_t>(p)] = total;
    total += lengths[static_cast<std::size_t>(p)];
    offsets[static_cast<std::size_t>(p) + 1] = static_cast<std::size_t>(total);
  }
  std::vector<double> received(static_cast<std::size_t>(std::max<vtkIdType>(total, 1)));
  controller->AllGatherV(
    send.empty() ? nullptr : send.data(), received.data(), length, lengths.data(), starts.data());
  received.resize(static_cast<std::size_t>(total));
  return received;
}

std::vector<RemoteBoundaryNode> ExchangeBoundaryNodes(
  vtkMultiProcessController* controller, const std::vector<RemoteBoundaryNode>& local)
{
  // Each node as 8 doubles: position, displacement, kind, body id.
  const int processes = controller->GetNumberOfProcesses();
  const int self = controller->GetLocalProcessId();
  std::vector<double> send;
  send.reserve(8 * local.size());
  for (const RemoteBoundaryNode& node : local)
  {
    send.insert(send.end(), node.Position, node.Position + 3);
    send.insert(send.end(), node.Displacement, node.Displacement + 3);
    send.push_back(static_cast<double>(node.Kind));
    send.push_back(static_cast<double>(node.BodyId));
  }
  std::vector<std::size_t> offsets;
  const std::vector<double> received = AllGatherDoubles(controller, send, offsets);
  std::vector<RemoteBoundaryNode> remote;
  for (int p = 0; p < processes; ++p)
  {
    const auto process = static_cast<std::size_t>(p);
    if (p == self)
    {
      continue;
    }
    const double* values = received.data() + offsets[process];
    for (std::size_t k = 0; k < offsets[process + 1] - offsets[process]; k += 8)
    {
      RemoteBoundaryNode node;
      for (int c = 0; c < 3; ++c)
      {
        node.Position[c] = values[k + c];
        node.Displacement[c] = values[k + 3 + c];
      }
      node.Kind = static_cast<std::int32_t>(values[k + 6]);
      node.BodyId = static_cast<std::int32_t>(values[k + 7]);
      remote.push_back(node);
    }
  }
  return remote;
}

void ReduceSummary(vtkMultiProcessController* controller, bool& ok, dgmf::QualitySummary& summary,
  std::size_t& outsideNodes)
{
  double sums[7] = { ok ? 0.0 : 1.0, summary.Sum, static_cast<double>(summary.Evaluated),
    static_cast<double>(summary.Inverted), static_cast<double>(summary.NotComputed),
    static_cast<double>(outsideNodes), static_cast<double>(summary.InputInvalid) };
  double total[7];
  controller->AllReduce(sums, total, 7, vtkCommunicator::SUM_OP);
  double minimum =
    summary.Evaluated > 0 ? summary.Minimum : std::numeric_limits<double>::infinity();
  double globalMinimum = 0.0;
  controller->AllReduce(&minimum, &globalMinimum, 1, vtkCommunicator::MIN_OP);
  ok = total[0] == 0.0;
  summary.Sum = total[1];
  summary.Evaluated = static_cast<std::size_t>(total[2]);
  summary.Inverted = static_cast<std::size_t>(total[3]);
  summary.NotComputed = static_cast<std::size_t>(total[4]);
  const double none = std::numeric_limits<double>::quiet_NaN(); // no cell evaluated anywhere
  summary.Mean =
    summary.Evaluated > 0 ? summary.Sum / static_cast<double>(summary.Evaluated) : none;
  summary.Minimum = summary.Evaluated > 0 ? globalMinimum : none;
  outsideNodes = static_cast<std::size_t>(total[5]);
  summary.InputInvalid = static_cast<std::size_t>(total[6]);
}

std::string AgreeOnNamedBoundaries(
  vtkMultiProcessController* controller, const BoundarySelection& selection, const NodeRoles* roles)
{
  std::vector<std::string> entries = selection.Moving;
  entries.insert(entries.end(), selection.Static.begin(), selection.Static.end());
  entries.insert(entries.end(), selection.Slip.begin(), selection.Slip.end());
  std::vector<int> here(entries.size(), 0), anywhere(entries.size(), 0);
  for (std::size_t e = 0; roles && e < entries.size() && e < roles->Found.size(); ++e)
  {
    here[e] = roles->Found[e];
  }
  if (entries.empty())
  {
    return "";
  }
  controller->AllReduce(
    here.data(), anywhere.data(), static_cast<vtkIdType>(entries.size()), vtkCommunicator::MAX_OP);
  for (std::size_t e = 0; e < entries.size(); ++e)
  {
    if (!anywhere[e])
    {
      return "No block of any piece of the input is named '" + entries[e] +
        "'. This piece's blocks are: " +
        (roles && !roles->BlockNames.empty() ? roles->BlockNames : std::string("(none)")) + ".";
    }
  }
  return "";
}

std::string CheckOneCellThickPieces(vtkMultiProcessController* controller, const InputNodes& nodes)
{
  const std::size_t n = nodes.LocalNodes;
  const dgmf::ExtrudedLayers layers = n > 0 && nodes.Dimension == 3
    ? dgmf::FindExtrudedLayers(nodes.Points, n, MakeSMPParallelFor())
    : dgmf::ExtrudedLayers();
  bool slip = false, interior = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    slip = slip || nodes.Kinds[i] == dgmf::NodeKind::SlipBoundary;
    interior = interior || nodes.Kinds[i] == dgmf::NodeKind::Interior;
  }
  // Over the non-empty pieces: all one cell thick between the same planes; any slip node; any
  // interior node.
  const double inf = std::numeric_limits<double>::infinity();
  const bool empty = n == 0;
  double low[4] = { empty ? inf : static_cast<double>(layers.Axis), empty ? inf : layers.Low,
    empty ? inf : layers.High, empty ? inf : -static_cast<double>(layers.Axis) };
  double high[5] = { empty ? -inf : layers.Low, empty ? -inf : layers.High, slip ? 1.0 : 0.0,
    interior ? 1.0 : 0.0, layers.Tolerance };
  double lowest[4], highest[5];
  controller->AllReduce(low, lowest, 4, vtkCommunicator::MIN_OP);
  controller->AllReduce(high, highest, 5, vtkCommunicator::MAX_OP);
  const bool sameAxis = lowest[0] >= 0.0 && lowest[0] == -lowest[3];
  // (Within the pieces' tolerance: each piece of a mesh with round-off has its own extremes.)
  const bool samePlanes = std::isfinite(lowest[1]) && highest[0] - lowest[1] <= 2 * highest[4] &&
    highest[1] - lowest[2] <= 2 * highest[4];
  // Frozen: no slip node, and every node a boundary node (a marker that marks the planes, or
  // names whose unnamed patches are static; the roles are those of all pieces by now).
  const bool frozen = highest[2] == 0.0 && highest[3] == 0.0;
  if (!sameAxis || !samePlanes || !frozen)
  {
    return "";
  }
  return "The mesh is one cell thick (a 2D case between two planes normal to " +
    std::string(1, "xyz"[static_cast<int>(lowest[0])]) +
    "): a distributed run deforms it as a 3D mesh, where its two planes are static boundaries "
    "unless they are slip ones, and nothing would move. Name its two planes as Slip Boundaries "
    "(OpenFOAM's front and back), or deform it in a serial run, which deforms it as 2D.";
}

std::string JoinPieces(vtkMultiProcessController* controller, const JoinOptions& options,
  vtkUnstructuredGrid* piece, InputNodes& nodes)
{
  std::string error = AgreeOnNamedBoundaries(controller, *options.Selection, options.Roles);
  if (!error.empty())
  {
    return error;
  }
  AppendRemoteBoundaryNodes(controller, nodes); // every copy of a node with the same role
  if (options.CheckLayers && !(error = CheckOneCellThickPieces(controller, nodes)).empty())
  {
    return error;
  }
  if (options.NonOrthogonality && piece->GetNumberOfCells() > 0 && !piece->GetCellGhostArray())
  {
    nodes.Warnings.emplace_back(
      "This piece has no ghost cells: the faces between it and the other pieces are left out of "
      "the non-orthogonality (MaximumNonOrthogonality may be below checkMesh's); a Ghost Cells "
      "Generator before DGMF Deform adds them (not with boundaries chosen by name).");
  }
  return AgreeOnSlipPlanes(controller, nodes);
}

void AppendRemoteBoundaryNodes(vtkMultiProcessController* controller, InputNodes& nodes)
{
  const std::size_t n = nodes.LocalNodes;
  nodes.Distributed = true;
  std::vector<RemoteBoundaryNode> local;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (nodes.Kinds[i] == dgmf::NodeKind::Interior)
    {
      continue;
    }
    RemoteBoundaryNode node;
    for (int c = 0; c < 3; ++c)
    {
      node.Position[c] = nodes.Points[3 * i + c];
      node.Displacement[c] = nodes.Displacement ? nodes.Displacement[3 * i + c] : 0.0;
    }
    node.Kind = static_cast<std::int32_t>(nodes.Kinds[i]);
    node.BodyId = nodes.BodyIds.empty() ? 0 : nodes.BodyIds[i];
    local.push_back(node);
  }
  const std::vector<RemoteBoundaryNode> remote = ExchangeBoundaryNodes(controller, local);
  if (remote.empty())
  {
    return;
  }
  // Every copy of a node takes the role the serial run gives it from all its copies: moving
  // (the first body listed: the smallest id) over static over slip over interior. A piece knows
  // only its own blocks (a node where a moving patch meets another patch held by another piece
  // was moving on one and static on the other until 2026-11-30: the mesh tore apart), and a
  // ghost node on the mesh's boundary may look interior (its boundary face is a ghost cell's).
  struct Role
  {
    dgmf::NodeKind Kind = dgmf::NodeKind::Interior;
    std::int32_t Body = 0;
  };
  const auto rank = [](dgmf::NodeKind kind)
  {
    return kind == dgmf::NodeKind::MovingBoundary ? 3
      : kind == dgmf::NodeKind::StaticBoundary    ? 2
      : kind == dgmf::NodeKind::SlipBoundary      ? 1
                                                  : 0;
  };
  std::map<std::array<double, 3>, Role> roles;
  const auto consider = [&](const double* p, dgmf::NodeKind kind, std::int32_t body)
  {
    Role& role = roles[{ p[0], p[1], p[2] }];
    if (rank(kind) > rank(role.Kind) ||
      (kind == role.Kind && body > 0 && (role.Body == 0 || body < role.Body)))
    {
      role = Role{ kind, body };
    }
  };
  for (const RemoteBoundaryNode& node : remote)
  {
    consider(node.Position, static_cast<dgmf::NodeKind>(node.Kind), node.BodyId);
  }
  for (const RemoteBoundaryNode& node : local)
  {
    consider(node.Position, static_cast<dgmf::NodeKind>(node.Kind), node.BodyId);
  }
  const auto roleAt = [&roles](const double* p) { return roles.find({ p[0], p[1], p[2] }); };
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto found = roleAt(nodes.Points + 3 * i);
    if (found != roles.end())
    {
      nodes.Kinds[i] = found->second.Kind;
      if (!nodes.BodyIds.empty())
      {
        nodes.BodyIds[i] = found->second.Body;
      }
    }
  }
  std::vector<RemoteBoundaryNode> agreed = remote;
  for (RemoteBoundaryNode& node : agreed)
  {
    const Role& role = roleAt(node.Position)->second;
    node.Kind = static_cast<std::int32_t>(role.Kind);
    node.BodyId = role.Body;
  }
  // The other pieces' boundary nodes follow this piece's nodes (coincident copies of the same
  // node, on several pieces, share one graph vertex).
  if (nodes.PointCopy.empty())
  {
    nodes.PointCopy.assign(nodes.Points, nodes.Points + 3 * n);
  }
  if (nodes.Displacement && nodes.DisplacementCopy.empty())
  {
    nodes.DisplacementCopy.assign(nodes.Displacement, nodes.Displacement + 3 * n);
  }
  for (const RemoteBoundaryNode& node : agreed)
  {
    nodes.PointCopy.insert(nodes.PointCopy.end(), node.Position, node.Position + 3);
    if (nodes.Displacement)
    {
      nodes.DisplacementCopy.insert(
        nodes.DisplacementCopy.end(), node.Displacement, node.Displacement + 3);
    }
    nodes.Kinds.push_back(static_cast<dgmf::NodeKind>(node.Kind));
    if (!nodes.BodyIds.empty())
    {
      nodes.BodyIds.push_back(node.BodyId);
      nodes.NumberOfBodies = std::max(nodes.NumberOfBodies, node.BodyId);
    }
  }
  nodes.Points = nodes.PointCopy.data();
  if (nodes.Displacement)
  {
    nodes.Displacement = nodes.DisplacementCopy.data();
  }
  nodes.NumberOfNodes = n + remote.size();
}

void ReduceFieldData(
  vtkMultiProcessController* controller, bool& ok, vtkFieldData* fieldData, bool nonOrthogonality)
{
  namespace names = dgmf::names;
  dgmf::QualitySummary summary;
  summary.Evaluated =
    static_cast<std::size_t>(GetFieldValue(fieldData, names::SizeSkewEvaluatedCells));
  // A piece without evaluated cells has NaN mean and minimum (SetQualitySummary).
  summary.Sum = summary.Evaluated > 0
    ? GetFieldValue(fieldData, names::SizeSkewMean) * static_cast<double>(summary.Evaluated)
    : 0.0;
  summary.Minimum = summary.Evaluated > 0 ? GetFieldValue(fieldData, names::SizeSkewMinimum) : 0.0;
  summary.Inverted = static_cast<std::size_t>(GetFieldValue(fieldData, names::InvertedCellCount));
  summary.InputInvalid =
    static_cast<std::size_t>(GetFieldValue(fieldData, names::InputInvalidCellCount));
  std::size_t outside = static_cast<std::size_t>(GetFieldValue(fieldData, names::OutsideNodeCount));
  ReduceSummary(controller, ok, summary, outside);
  double angles[2] = { GetFieldValue(fieldData, names::MaximumNonOrthogonality),
    GetFieldValue(fieldData, names::InputMaximumNonOrthogonality) };
  double largest[2] = { 0.0, 0.0 };
  if (nonOrthogonality) // the same on every process: the collective is called by all or none
  {
    controller->AllReduce(angles, largest, 2, vtkCommunicator::MAX_OP);
  }
  if (!ok)
  {
    return;
  }
  const auto set = [fieldData](const char* name, double value)
  {
    if (vtkDataArray* array = fieldData->GetArray(name))
    {
      array->SetTuple1(0, value);
    }
  };
  set(names::SizeSkewMean, summary.Mean);
  set(names::SizeSkewMinimum, summary.Minimum);
  set(names::InvertedCellCount, static_cast<double>(summary.Inverted));
  set(names::SizeSkewEvaluatedCells, static_cast<double>(summary.Evaluated));
  set(names::InputInvalidCellCount, static_cast<double>(summary.InputInvalid));
  set(names::OutsideNodeCount, static_cast<double>(outside));
  set(names::MaximumNonOrthogonality, largest[0]);
  set(names::InputMaximumNonOrthogonality, largest[1]);
}

} // namespace dgmf_vtk
