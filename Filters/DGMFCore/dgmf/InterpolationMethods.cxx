// The paper's comparison methods behind the method interface: DGM (DGMDeformation), DGRBF
// (DGRBFDeformation), RBF (RBFDeformation) and IDW (IDWDeformation).
#include "dgmf/InterpolationMethods.h"

#include "dgmf/DGMDeformation.h"
#include "dgmf/DGRBFDeformation.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ResultNames.h"

#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
{
/// IDW's A_i of every boundary node; a marked node on no boundary facet counts as an average one.
void SetBoundaryWeights(const DeformationProblem& problem, BoundaryMotion& boundary)
{
  if (!problem.BoundaryWeights)
  {
    return; // every node counts as 1
  }
  boundary.Weights.resize(boundary.Size());
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t b = 0; b < boundary.Size(); ++b)
  {
    const double w = problem.BoundaryWeights[static_cast<std::size_t>(boundary.Nodes[b])];
    boundary.Weights[b] = w;
    sum += w;
    count += w > 0.0 ? 1 : 0;
  }
  const double mean = count > 0 ? sum / static_cast<double>(count) : 1.0;
  for (double& w : boundary.Weights)
  {
    w = w > 0.0 ? w : mean;
  }
}

class InterpolationMethod final : public DeformationMethod
{
public:
  InterpolationMethod(Method method, const MethodParameters& parameters)
    : Id(method)
    , Parameters(parameters)
  {
    if (method == Method::DGMF)
    {
      throw std::invalid_argument("DGMF is not an interpolation method (MakeDGMFMethod)");
    }
  }

  const MethodInfo& GetInfo() const override { return GetMethodInfo(this->Id); }

  MethodNeeds GetNeeds(const DeformationProblem&) const override
  {
    MethodNeeds needs;
    needs.Graph = this->GetInfo().UsesGraph;
    needs.BoundaryWeights = this->Id == Method::IDW;
    return needs;
  }

protected:
  DeformationReport DeformNodes(const DeformationProblem& problem, const DelaunayMapping* mapping,
    const DeformationOutputs& outputs, const ParallelFor& parallelFor) const override
  {
    const bool graph = this->GetInfo().UsesGraph;
    DeformationReport report;
    BoundaryMotion boundary = GatherTotalBoundaryMotion(problem);
    const MethodParameters& p = this->Parameters;
    const std::size_t n = problem.NumberOfNodes;
    switch (this->Id)
    {
      case Method::DGM:
      {
        const std::size_t inverted =
          DeformDGM(*mapping, boundary, problem.Points, outputs.Points, parallelFor);
        report.AddCount(names::InvertedGraphElementCount, static_cast<double>(inverted));
        if (inverted > 0)
        {
          report.Warnings.push_back(std::to_string(inverted) +
            " Delaunay graph elements are inverted by the motion: DGM's mesh may be invalid (see "
            "InvertedCellCount).");
        }
        break;
      }
      case Method::DGRBF:
        DeformDGRBF(
          *mapping, boundary, p.SupportRadius, problem.Points, outputs.Points, parallelFor);
        break;
      case Method::RBF:
      {
        RBFParameters parameters;
        parameters.SupportRadius = p.SupportRadius;
        parameters.Greedy = p.RBFGreedy;
        parameters.GreedyTolerance = p.RBFGreedyTolerance;
        parameters.GreedyMaximumPoints = p.RBFGreedyMaximumPoints;
        const RBFInterpolation rbf(boundary, parameters);
        DeformRBF(rbf, problem.Points, n, outputs.Points, parallelFor);
        report.AddCount(names::RBFCentreCount, static_cast<double>(rbf.GetNumberOfCentres()));
        report.AddValue(names::RBFBoundaryError, rbf.GetBoundaryError());
        break;
      }
      case Method::IDW:
      {
        SetBoundaryWeights(problem, boundary);
        IDWParameters parameters;
        parameters.Alpha = p.IDWAlpha;
        parameters.ReferenceLength = p.IDWReferenceLength;
        report.AddValue(names::IDWReferenceLength,
          DeformIDW(boundary, parameters, problem.Points, n, outputs.Points, parallelFor));
        break;
      }
      case Method::DGMF:
        break;
    }
    if (graph)
    {
      report.AddCount(
        names::OutsideNodeCount, static_cast<double>(mapping->GetNumberOfOutsideNodes()));
    }
    return report;
  }

private:
  Method Id;
  MethodParameters Parameters;
};
} // namespace

std::unique_ptr<DeformationMethod> MakeInterpolationMethod(
  Method method, const MethodParameters& parameters)
{
  return std::make_unique<InterpolationMethod>(method, parameters);
}

} // namespace dgmf
