#include "DGMFMappingCache.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace dgmf_vtk
{

namespace
{
std::uint64_t HashPoints(const dgmf::DeformationProblem& problem)
{
  return HashBytes(problem.Points, 3 * problem.NumberOfNodes * sizeof(double));
}
} // namespace

bool MappingCache::Matches(const dgmf::DeformationProblem& problem, vtkDataArray* pointsArray)
{
  const std::size_t n = problem.NumberOfNodes;
  return this->Mapping && this->Dimension == problem.Dimension &&
    this->Mapping->GetNumberOfNodes() == n &&
    std::memcmp(problem.Kinds, this->Mapping->GetNodeKinds().data(), n * sizeof(dgmf::NodeKind)) ==
    0 &&
    this->Points.Matches(pointsArray, [&]() { return HashPoints(problem); });
}

const dgmf::DelaunayMapping& MappingCache::Build(const dgmf::DeformationProblem& problem,
  vtkDataArray* pointsArray, std::size_t hintStride, const std::function<void()>& alongside,
  const dgmf::ParallelFor& parallelFor)
{
  this->Mapping.reset();
  this->Points.Reset();
  // The cache key's hash of the points is computed on the second thread too.
  std::uint64_t pointsHash = 0;
  auto work = [&]()
  {
    if (alongside)
    {
      alongside();
    }
    pointsHash = HashPoints(problem);
  };
  this->Mapping = std::make_unique<dgmf::DelaunayMapping>(problem.Dimension, problem.Points,
    problem.NumberOfNodes, problem.Kinds, parallelFor, hintStride, work);
  this->Points.Set(pointsArray, [pointsHash]() { return pointsHash; });
  this->Dimension = problem.Dimension;
  return *this->Mapping;
}

const dgmf::DelaunayMapping& MappingCache::Update(const dgmf::DeformationProblem& problem,
  vtkDataArray* pointsArray, const std::function<std::size_t()>& hintStride,
  const std::function<std::vector<vtkDoubleArray*>()>& beforeBuild,
  const dgmf::ParallelFor& parallelFor, bool& reused, std::vector<std::string>& warnings)
{
  reused = this->Matches(problem, pointsArray);
  if (reused)
  {
    return *this->Mapping;
  }
  const std::vector<vtkDoubleArray*> arrays = beforeBuild();
  const dgmf::DelaunayMapping& built = this->Build(
    problem, pointsArray, hintStride(),
    [&arrays]()
    {
      for (vtkDoubleArray* array : arrays)
      {
        std::memset(
          array->GetPointer(0), 0, static_cast<std::size_t>(array->GetDataSize()) * sizeof(double));
      }
    },
    parallelFor);
  if (built.GetNumberOfConflictingNodes() > 0)
  {
    warnings.push_back(std::to_string(built.GetNumberOfConflictingNodes()) +
      " static boundary nodes coincide with moving ones; they stay in place, and their shared "
      "graph vertex moves.");
  }
  if (built.GetNumberOfOutsideNodes() > 0)
  {
    warnings.push_back(std::to_string(built.GetNumberOfOutsideNodes()) +
      " nodes lie outside the Delaunay graph of the boundary nodes (is the whole outer boundary "
      "marked?); they use the nearest hull element.");
  }
  return built;
}

std::size_t MappingCache::GetMemorySize() const
{
  return this->Mapping ? this->Mapping->GetMemorySize() : 0;
}

} // namespace dgmf_vtk
