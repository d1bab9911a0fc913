#include "DGMFMappingCache.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"

#include "dgmf/FirstTouch.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace dgmf_vtk
{

namespace
{
/// `onThreads` false inside a side job (already one of the threads' tasks).
std::uint64_t HashPoints(const dgmf::DeformationProblem& problem, bool onThreads)
{
  return HashBytes(
    problem.Points, 3 * problem.NumberOfNodes * sizeof(double), DefaultHashSeed, onThreads);
}
} // namespace

bool MappingCache::Matches(const dgmf::DeformationProblem& problem, vtkDataArray* pointsArray)
{
  const std::size_t n = problem.NumberOfNodes;
  return this->Mapping && this->Dimension == problem.Dimension && this->Slip == problem.Slip &&
    this->Mapping->GetNumberOfNodes() == n &&
    std::memcmp(problem.Kinds, this->Mapping->GetNodeKinds().data(), n * sizeof(dgmf::NodeKind)) ==
    0 &&
    this->Points.Matches(pointsArray, [&]() { return HashPoints(problem, true); });
}

const dgmf::DelaunayMapping& MappingCache::Build(const dgmf::DeformationProblem& problem,
  vtkDataArray* pointsArray, std::size_t hintStride, const dgmf::DelaunayGraph::SideJobs& alongside,
  const dgmf::ParallelFor& parallelFor)
{
  this->Mapping.reset();
  this->Points.Reset();
  // The cache key's hash of the points is one more job beside the graph's insertion, early in
  // the list: a single job of 0.02 s at 8.26M nodes, it left a thread idle when it came last.
  std::uint64_t pointsHash = 0;
  dgmf::DelaunayGraph::SideJobs jobs;
  jobs.emplace_back([&pointsHash, &problem]() { pointsHash = HashPoints(problem, false); });
  jobs.insert(jobs.end(), alongside.begin(), alongside.end());
  this->Mapping = std::make_unique<dgmf::DelaunayMapping>(problem.Dimension, problem.Points,
    problem.NumberOfNodes, problem.Kinds, parallelFor, hintStride, jobs, &problem.Slip);
  this->Points.Set(pointsArray, [pointsHash]() { return pointsHash; });
  this->Dimension = problem.Dimension;
  this->Slip = problem.Slip;
  return *this->Mapping;
}

const dgmf::DelaunayMapping& MappingCache::Update(const dgmf::DeformationProblem& problem,
  vtkDataArray* pointsArray, const std::function<std::size_t()>& hintStride,
  const std::function<std::vector<vtkDoubleArray*>()>& beforeBuild,
  const dgmf::DelaunayGraph::SideJobs& alongside, const dgmf::ParallelFor& parallelFor,
  bool& reused, std::vector<std::string>& warnings)
{
  reused = this->Matches(problem, pointsArray);
  if (reused)
  {
    for (const std::function<void()>& job : alongside)
    {
      job();
    }
    return *this->Mapping;
  }
  const std::vector<vtkDoubleArray*> arrays = beforeBuild();
  // The arrays' first touch in parts, so that both threads share it once the graph's insertion
  // is done: their pages faulted in, no values written (the mapping writes them all).
  std::vector<dgmf::FirstTouchPart> parts;
  for (vtkDoubleArray* array : arrays)
  {
    dgmf::AppendFirstTouchParts(
      array->GetPointer(0), static_cast<std::size_t>(array->GetDataSize()) * sizeof(double), parts);
  }
  dgmf::DelaunayGraph::SideJobs touches = alongside; // single jobs of their own first
  dgmf::AppendFirstTouchJobs(parts, touches);
  const dgmf::DelaunayMapping& built =
    this->Build(problem, pointsArray, hintStride(), touches, parallelFor);
  if (built.GetNumberOfConflictingNodes() > 0)
  {
    warnings.push_back(std::to_string(built.GetNumberOfConflictingNodes()) +
      " static boundary nodes coincide with moving ones; they stay in place, and their shared "
      "graph vertex moves.");
  }
  if (built.GetNumberOfOutsideNodes() > 0)
  {
    const std::size_t slipOutside = built.GetNumberOfSlipOutsideNodes();
    warnings.push_back(std::to_string(built.GetNumberOfOutsideNodes()) +
      " nodes lie outside the Delaunay graph of the boundary nodes (is the whole outer boundary "
      "marked?); they use the hull facet they project onto." +
      (slipOutside == 0 ? std::string()
                        : " " + std::to_string(slipOutside) +
            " of them are slip nodes: where a slip boundary meets the static boundary, mark the "
            "nodes of their common edges static (1), or the slip boundary lies outside the graph "
            "of the static and moving nodes and its nodes barely move."));
  }
  return built;
}

std::size_t MappingCache::GetMemorySize() const
{
  const std::size_t slip = (this->Slip.Nodes.capacity() + this->Slip.NodePlanes.capacity() +
                             this->Slip.SecondPlanes.capacity()) *
      sizeof(std::int32_t) +
    this->Slip.Planes.capacity() * sizeof(dgmf::SlipPlane);
  return (this->Mapping ? this->Mapping->GetMemorySize() : 0) + slip;
}

} // namespace dgmf_vtk
