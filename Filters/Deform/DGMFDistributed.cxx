#include "DGMFDistributed.h"

#include "vtkCellTypes.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <limits>

namespace dgmf_vtk
{

bool IsDistributed(vtkMultiProcessController* controller)
{
  return controller && controller->GetNumberOfProcesses() > 1;
}

int AgreeOnDimension(vtkMultiProcessController* controller, vtkUnstructuredGrid* piece, double& z)
{
  // Maxima: the dimension of the piece's cells (0 without cells) and its largest z; minimum: its
  // smallest z.
  double maxima[2] = { 0.0, -std::numeric_limits<double>::infinity() };
  double minimum = std::numeric_limits<double>::infinity();
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
    const double pz = piece->GetPoint(i)[2];
    maxima[1] = std::max(maxima[1], pz);
    minimum = std::min(minimum, pz);
  }
  double globalMaxima[2];
  double globalMinimum = 0.0;
  controller->AllReduce(maxima, globalMaxima, 2, vtkCommunicator::MAX_OP);
  controller->AllReduce(&minimum, &globalMinimum, 1, vtkCommunicator::MIN_OP);
  const int dimension = static_cast<int>(globalMaxima[0]);
  z = globalMinimum;
  return dimension == 2 && globalMinimum != globalMaxima[1] ? -1 : dimension;
}

bool AllProcessesAgree(vtkMultiProcessController* controller, bool ok)
{
  int local = ok ? 1 : 0;
  int global = 0;
  controller->AllReduce(&local, &global, 1, vtkCommunicator::MIN_OP);
  return global == 1;
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
  const vtkIdType length = static_cast<vtkIdType>(send.size());
  std::vector<vtkIdType> lengths(static_cast<std::size_t>(processes), 0);
  controller->AllGather(&length, lengths.data(), 1);
  std::vector<vtkIdType> offsets(static_cast<std::size_t>(processes), 0);
  vtkIdType total = 0;
  for (int p = 0; p < processes; ++p)
  {
    offsets[static_cast<std::size_t>(p)] = total;
    total += lengths[static_cast<std::size_t>(p)];
  }
  std::vector<double> received(static_cast<std::size_t>(std::max<vtkIdType>(total, 1)));
  controller->AllGatherV(
    send.empty() ? nullptr : send.data(), received.data(), length, lengths.data(), offsets.data());
  std::vector<RemoteBoundaryNode> remote;
  for (int p = 0; p < processes; ++p)
  {
    if (p == self)
    {
      continue;
    }
    const double* values = received.data() + offsets[static_cast<std::size_t>(p)];
    for (vtkIdType k = 0; k < lengths[static_cast<std::size_t>(p)]; k += 8)
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
  double sums[6] = { ok ? 0.0 : 1.0, summary.Sum, static_cast<double>(summary.Evaluated),
    static_cast<double>(summary.Inverted), static_cast<double>(summary.NotComputed),
    static_cast<double>(outsideNodes) };
  double total[6];
  controller->AllReduce(sums, total, 6, vtkCommunicator::SUM_OP);
  double minimum =
    summary.Evaluated > 0 ? summary.Minimum : std::numeric_limits<double>::infinity();
  double globalMinimum = 0.0;
  controller->AllReduce(&minimum, &globalMinimum, 1, vtkCommunicator::MIN_OP);
  ok = total[0] == 0.0;
  summary.Sum = total[1];
  summary.Evaluated = static_cast<std::size_t>(total[2]);
  summary.Inverted = static_cast<std::size_t>(total[3]);
  summary.NotComputed = static_cast<std::size_t>(total[4]);
  summary.Mean = summary.Evaluated > 0 ? summary.Sum / static_cast<double>(summary.Evaluated) : 0.0;
  summary.Minimum = summary.Evaluated > 0 ? globalMinimum : 0.0;
  outsideNodes = static_cast<std::size_t>(total[5]);
}

} // namespace dgmf_vtk
