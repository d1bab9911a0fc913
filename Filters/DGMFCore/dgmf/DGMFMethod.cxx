// DGMF behind the method interface: one body (DGMFDeformation), several bodies or extracted
// motions (MultiBodyDeformation), or large motions in sub-steps (SubStepDeformation).
#include "dgmf/DGMFMethod.h"

#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/MultiBodyDeformation.h"
#include "dgmf/ResultNames.h"
#include "dgmf/RigidMotionFit.h"
#include "dgmf/SubStepDeformation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dgmf
{
namespace
{
/// The key of a multi-body f: it is not the single-body f, so it never matches that.
const FieldKey SeveralBodiesKey{ -2.0, -1 };

/// Paper steps 4-5 for one body: r and f, taken from the store when they are current.
const double* UpdateDampingField(const DelaunayMapping& mapping, const MethodParameters& p,
  FieldStore& store, const ParallelFor& parallelFor)
{
  const FieldKey rKey{ p.StaticR0, 0 };
  const FieldKey fKey{ p.StaticR0, static_cast<int>(p.Damping) };
  const double* r = store.Find(names::R, rKey);
  if (!r && !store.Find(names::F, fKey)) // a new mapping, as a rule: both in one pass
  {
    double* rWritten = store.Store(names::R, rKey);
    double* fWritten = store.Store(names::F, fKey);
    ComputeDampingField(mapping, p.StaticR0, p.Damping, rWritten, fWritten, parallelFor);
    return fWritten;
  }
  if (!r)
  {
    double* written = store.Store(names::R, rKey);
    ComputeBoundaryDistanceField(mapping, p.StaticR0, written, parallelFor);
    r = written;
  }
  const double* f = store.Find(names::F, fKey);
  if (!f)
  {
    double* written = store.Store(names::F, fKey);
    ComputeDampingFactor(mapping, p.Damping, r, written, parallelFor);
    f = written;
  }
  return f;
}

/// The body of every node: its body id, or 1 for the moving nodes when there are no ids.
std::vector<std::int32_t> BodiesOf(const DeformationProblem& problem)
{
  if (problem.BodyIds)
  {
    return std::vector<std::int32_t>(problem.BodyIds, problem.BodyIds + problem.NumberOfNodes);
  }
  std::vector<std::int32_t> ids(problem.NumberOfNodes, 0);
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    ids[i] = problem.Kinds[i] == NodeKind::MovingBoundary ? 1 : 0;
  }
  return ids;
}

/// Fits each body's rigid motion to the displacements (RigidMotionMode Extracted).
std::vector<BodyMotion> ExtractMotions(const DeformationProblem& problem,
  const std::vector<std::int32_t>& ids, std::int32_t bodies, std::vector<double>& residual,
  DeformationReport& report)
{
  if (!problem.Displacement)
  {
    throw std::invalid_argument(
      "RigidMotionMode EXTRACTED fits the motion to the displacement array: select one.");
  }
  const std::size_t n = problem.NumberOfNodes;
  residual.resize(3 * n);
  std::vector<FittedMotion> fits = ExtractBodyMotions(problem.Dimension, problem.Points,
    problem.Displacement, n, ids.data(), bodies, residual.data(), problem.FitDistinctPositions);
  // Each body turns about its rotation axis (not its centroid): a rotation given as displacements
  // about some centre is recovered about that centre. Near-translations (an axis farther than 100
  // body sizes) keep the centroid.
  std::vector<double> size(fits.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (ids[i] > 0)
    {
      const auto k = static_cast<std::size_t>(ids[i] - 1);
      const double* x = problem.Points + 3 * i;
      const double* c = fits[k].Center;
      const double d = std::sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
        (x[2] - c[2]) * (x[2] - c[2]));
      size[k] = std::max(size[k], d);
    }
  }
  ReportedValue translation{ names::FittedTranslation, false, 3, {} };
  ReportedValue center{ names::FittedRotationCenter, false, 3, {} };
  ReportedValue axis{ names::FittedRotationAxis, false, 3, {} };
  ReportedValue angle{ names::FittedRotationAngle, false, 1, {} };
  ReportedValue rms{ names::FittedResidualRMS, false, 1, {} };
  std::vector<BodyMotion> motions(fits.size());
  for (std::size_t k = 0; k < fits.size(); ++k)
  {
    CentreOnRotationAxis(fits[k], 100.0 * size[k]);
    motions[k].Motion = fits[k].ToRigidMotion();
    motions[k].Displacement = residual.data();
    translation.Values.insert(
      translation.Values.end(), fits[k].Translation, fits[k].Translation + 3);
    center.Values.insert(center.Values.end(), fits[k].Center, fits[k].Center + 3);
    axis.Values.insert(axis.Values.end(), fits[k].Axis, fits[k].Axis + 3);
    angle.Values.push_back(fits[k].AngleDegrees);
    rms.Values.push_back(fits[k].ResidualRMS);
  }
  for (ReportedValue* value : { &translation, &center, &axis, &angle, &rms })
  {
    report.Values.push_back(std::move(*value));
  }
  return motions;
}

/// Several bodies, or one with extracted motion: one damping field per body, summed.
void DeformBodies(const DeformationProblem& problem, const DelaunayMapping& mapping,
  const MethodParameters& p, const DeformationOutputs& outputs, const ParallelFor& parallelFor,
  DeformationReport& report)
{
  const std::vector<std::int32_t> ids = BodiesOf(problem);
  const std::int32_t bodies = std::max<std::int32_t>(problem.NumberOfBodies, 1);
  std::vector<double> residual;
  std::vector<BodyMotion> motions;
  if (problem.ExtractRigidMotion)
  {
    motions = ExtractMotions(problem, ids, bodies, residual, report);
  }
  else
  {
    motions.resize(static_cast<std::size_t>(bodies));
    for (std::size_t k = 0; k < motions.size(); ++k)
    {
      motions[k].Motion = problem.Motions[k];
      motions[k].Displacement = problem.Displacement;
    }
  }
  // f is min(1, sum of the bodies' damping factors); r has no single meaning with several bodies.
  double* f = outputs.Fields->Store(names::F, SeveralBodiesKey);
  DeformMultiBody(mapping, ids.data(), motions, p.StaticR0, p.Damping, p.Mode, problem.Points,
    outputs.Points, f, parallelFor);
}

/// Large motions: the graph is rebuilt along the path, and the quality guard repairs each step.
void DeformLargeMotion(const DeformationProblem& problem, const DelaunayMapping& mapping,
  const MethodParameters& p, const DeformationOutputs& outputs, const ParallelFor& parallelFor,
  DeformationReport& report)
{
  if (problem.UsesBodies())
  {
    throw std::invalid_argument("Sub-steps and the quality guard work with one body whose motion "
                                "is given by the properties (no body-id array, RigidMotionMode "
                                "Properties).");
  }
  if (!problem.Cells)
  {
    throw std::invalid_argument("Sub-steps and the quality guard need the mesh's cells.");
  }
  SubStepParameters parameters;
  parameters.SubSteps = p.SubSteps;
  parameters.RepairThreshold = p.RepairThreshold;
  parameters.Repair = p.RepairThreshold > 0.0;
  parameters.RepairLayers = p.RepairLayers;
  parameters.RepairPasses = p.RepairPasses;
  parameters.Damping = p.Damping;
  parameters.StaticR0 = p.StaticR0;
  parameters.Progress = problem.Progress;
  if (!problem.Slip.Empty())
  {
    // Every step keeps the slip nodes in their planes (before the quality guard sees the step).
    parameters.Constrain = [&problem](double* deformed)
    { problem.Slip.Apply(problem.Points, deformed); };
    parameters.Slip = &problem.Slip;
  }
  const SubStepReport steps = DeformInSubSteps(problem.Dimension, problem.Points,
    problem.NumberOfNodes, problem.Kinds, *problem.Cells, problem.Motions.front(),
    problem.Displacement, parameters, outputs.Points, parallelFor, &mapping);
  report.AddCount(names::SubStepsUsed, steps.SubSteps);
  report.AddCount(names::RejectedSubSteps, steps.RejectedSteps);
  if (parameters.Repair)
  {
    // The guard's counts, only with the guard: sub-steps alone count no bad cell in fixed mode
    // and only the last step's in automatic mode (until 2026-11-30 "found 0, left 414" there,
    // and "found 0, left 0" with 415 inverted cells in fixed mode).
    report.AddCount(names::RepairedCellCount, static_cast<double>(steps.RepairedCells));
    report.AddCount(names::UnrepairedCellCount, static_cast<double>(steps.BadCellsLeft));
  }
  report.GraphSeconds += steps.GraphSeconds;
  report.LocationSeconds += steps.LocationSeconds;
  // r and f describe the input mesh's graph (the first step).
  UpdateDampingField(mapping, p, *outputs.Fields, parallelFor);
}

class DGMFMethod final : public DeformationMethod
{
public:
  explicit DGMFMethod(const MethodParameters& parameters)
    : Parameters(parameters)
  {
  }

  const MethodInfo& GetInfo() const override { return GetMethodInfo(Method::DGMF); }

  MethodNeeds GetNeeds(const DeformationProblem& problem) const override
  {
    MethodNeeds needs;
    needs.Graph = true;
    needs.Cells = this->Parameters.UsesSubSteps();
    needs.R = !problem.UsesBodies();
    needs.F = true;
    needs.DisplacementEverywhere = this->Parameters.Mode == DeformationMode::DGMF1;
    return needs;
  }

protected:
  DeformationReport DeformNodes(const DeformationProblem& problem, const DelaunayMapping* mapping,
    const DeformationOutputs& outputs, const ParallelFor& parallelFor) const override
  {
    DeformationReport report;
    if (!outputs.Fields)
    {
      throw std::invalid_argument("DGMF needs a store for r and f (DeformationOutputs::Fields)");
    }
    const MethodParameters& p = this->Parameters;
    if (p.UsesSubSteps())
    {
      DeformLargeMotion(problem, *mapping, p, outputs, parallelFor, report);
    }
    else if (problem.UsesBodies())
    {
      DeformBodies(problem, *mapping, p, outputs, parallelFor, report);
    }
    else
    {
      const double* f = UpdateDampingField(*mapping, p, *outputs.Fields, parallelFor);
      DeformDGMF(*mapping, f, problem.Motions.front(), problem.Displacement, p.Mode, problem.Points,
        outputs.Points, parallelFor);
    }
    report.AddCount(
      names::OutsideNodeCount, static_cast<double>(mapping->GetNumberOfOutsideNodes()));
    return report;
  }

private:
  MethodParameters Parameters;
};
} // namespace

std::unique_ptr<DeformationMethod> MakeDGMFMethod(const MethodParameters& parameters)
{
  return std::make_unique<DGMFMethod>(parameters);
}

} // namespace dgmf
