#include "dgmf/DeformationMethod.h"

#include "dgmf/DGMFMethod.h"
#include "dgmf/DampingField.h"
#include "dgmf/InterpolationMethods.h"
#include "dgmf/ResultNames.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace dgmf
{
namespace
{
void Require(bool condition, const char* message)
{
  if (!condition)
  {
    throw std::invalid_argument(message);
  }
}

/// The one check of the methods' parameters (the filter's properties are clamped to the same).
void CheckParameters(const MethodParameters& p)
{
  Require(IsValidDampingFunction(static_cast<int>(p.Damping)),
    "the damping function must be one of u1 to u7");
  CheckStaticR0(p.StaticR0);
  Require(p.Mode == DeformationMode::DGMF1 || p.Mode == DeformationMode::DGMF2,
    "the deformation mode must be DGMF1 or DGMF2");
  Require(p.SubSteps >= 0, "the number of sub-steps must be >= 0 (0: automatic)");
  Require(
    p.RepairThreshold >= 0.0 && p.RepairThreshold <= 1.0, "the repair threshold must be in [0, 1]");
  Require(p.RepairLayers >= 0 && p.RepairPasses >= 0, "repair layers and passes must be >= 0");
  Require(p.SupportRadius >= 0.0 && std::isfinite(p.SupportRadius),
    "the support radius must be a finite number >= 0 (0: automatic)");
  Require(p.RBFGreedyTolerance >= 0.0 && p.RBFGreedyTolerance <= 1.0,
    "the RBF greedy tolerance must be in [0, 1]");
  Require(p.RBFGreedyMaximumPoints >= 1, "the RBF greedy selection needs at least one point");
  Require(p.IDWAlpha >= 0.0 && std::isfinite(p.IDWAlpha), "IDW's alpha must be >= 0");
  Require(p.IDWReferenceLength >= 0.0 && std::isfinite(p.IDWReferenceLength),
    "IDW's reference length must be >= 0 (0: automatic)");
}
} // namespace

DeformationReport DeformationMethod::Deform(const DeformationProblem& problem,
  const DelaunayMapping* mapping, const DeformationOutputs& outputs,
  const ParallelFor& parallelFor) const
{
  const MethodNeeds needs = this->GetNeeds(problem);
  const std::vector<std::string> warnings =
    ValidateProblem(problem, !needs.Graph, needs.DisplacementEverywhere);
  if (!outputs.Points || (this->GetNeeds(problem).Graph && !mapping))
  {
    throw std::invalid_argument(std::string(this->GetInfo().Name) + " needs the output points" +
      (this->GetNeeds(problem).Graph ? " and the Delaunay mapping" : ""));
  }
  DeformationReport report = this->DeformNodes(problem, mapping, outputs, parallelFor);
  problem.Slip.Apply(problem.Points, outputs.Points);
  report.Warnings.insert(report.Warnings.begin(), warnings.begin(), warnings.end());
  return report;
}

std::unique_ptr<DeformationMethod> CreateMethod(Method method, const MethodParameters& parameters)
{
  CheckParameters(parameters);
  if (method == Method::DGMF)
  {
    return MakeDGMFMethod(parameters);
  }
  GetMethodInfo(method); // throws for a value outside the table
  return MakeInterpolationMethod(method, parameters);
}

VectorFieldStore::Field& VectorFieldStore::Select(const char* field)
{
  if (std::strcmp(field, names::R) == 0)
  {
    return this->R;
  }
  if (std::strcmp(field, names::F) == 0)
  {
    return this->F;
  }
  throw std::invalid_argument(std::string("no per-node field named ") + field);
}

const double* VectorFieldStore::Find(const char* field, const FieldKey& key)
{
  Field& stored = this->Select(field);
  return stored.Values.size() == this->Size && stored.Key == key ? stored.Values.data() : nullptr;
}

double* VectorFieldStore::Store(const char* field, const FieldKey& key)
{
  Field& stored = this->Select(field);
  stored.Values.resize(this->Size);
  stored.Key = key;
  return stored.Values.data();
}

const std::vector<double>& VectorFieldStore::Get(const char* field) const
{
  return const_cast<VectorFieldStore*>(this)->Select(field).Values;
}

} // namespace dgmf
