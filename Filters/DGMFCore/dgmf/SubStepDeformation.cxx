#include "dgmf/SubStepDeformation.h"

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/RigidMotionFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace dgmf
{
namespace
{
/// The rotation of `motion` as one rotation about an axis (degrees). A rotation given about an
/// axis, or by one Euler angle, keeps its angle (which may exceed 180 degrees, as the single step
/// allows); a combination of Euler angles becomes the equivalent rotation of at most 180 degrees.
void AxisAngleOf(const RigidMotion& motion, double axis[3], double& angleDegrees)
{
  if (!motion.HasEulerAngles())
  {
    motion.GetUnitAxis(axis);
    angleDegrees = motion.AxisAngleDegrees;
    return;
  }
  int nonZero = 0, last = 0;
  for (int c = 0; c < 3; ++c)
  {
    if (motion.AnglesDegrees[c] != 0.0)
    {
      ++nonZero;
      last = c;
    }
  }
  if (nonZero == 1 && !motion.HasAxisRotation())
  {
    axis[0] = axis[1] = axis[2] = 0.0;
    axis[last] = 1.0;
    angleDegrees = motion.AnglesDegrees[last];
    return;
  }
  double R[3][3];
  motion.GetRotationMatrix(1.0, R);
  RotationToAxisAngle(R, axis, angleDegrees);
}

/// Where the moving nodes are at path parameter s (0: original, 1: prescribed), 3 per node.
void PathPositions(const double* points, std::size_t n, const NodeKind* kinds,
  const double center[3], const double axis[3], double angleDegrees, const double* translation,
  const double* displacement, double s, double* out)
{
  RigidMotion rotation;
  for (int c = 0; c < 3; ++c)
  {
    rotation.Center[c] = center[c];
    rotation.Axis[c] = axis[c];
  }
  rotation.AxisAngleDegrees = s * angleDegrees;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* x = points + 3 * i;
    if (kinds[i] != NodeKind::MovingBoundary)
    {
      std::copy(x, x + 3, out + 3 * i);
      continue;
    }
    rotation.Apply(1.0, x, nullptr, out + 3 * i);
    for (int c = 0; c < 3; ++c)
    {
      out[3 * i + c] += s * (translation[c] + (displacement ? displacement[3 * i + c] : 0.0));
    }
  }
}

} // namespace

SubStepReport DeformInSubSteps(int dimension, const double* points, std::size_t n,
  const NodeKind* kinds, const CellMesh& cells, const RigidMotion& motion,
  const double* displacement, const SubStepParameters& parameters, double* deformed,
  const ParallelFor& parallelFor, const DelaunayMapping* initialMapping)
{
  if (parameters.SubSteps < 0 || parameters.MaximumSubSteps < 1)
  {
    throw std::invalid_argument("sub-steps: SubSteps must be >= 0 and MaximumSubSteps >= 1");
  }
  SubStepReport report;
  double axis[3] = { 0.0, 0.0, 1.0 };
  double angle = 0.0;
  AxisAngleOf(motion, axis, angle);
  if (dimension == 2)
  {
    axis[0] = axis[1] = 0.0; // round-off must not tilt a planar mesh
    axis[2] = axis[2] < 0.0 ? -1.0 : 1.0;
  }

  std::vector<double> current(points, points + 3 * n);
  std::vector<double> nextPath(3 * n), trial(3 * n), stepDisplacement(3 * n), f(n), r(n);
  std::unique_ptr<DelaunayMapping> built;
  const DelaunayMapping* mapping = initialMapping;
  if (mapping)
  {
    if (mapping->GetNumberOfNodes() != n)
    {
      throw std::invalid_argument("sub-steps: the initial graph is not the mesh's");
    }
    ComputeBoundaryDistanceField(*mapping, parameters.StaticR0, r.data(), parallelFor);
    ComputeDampingFactor(*mapping, parameters.Damping, r.data(), f.data(), parallelFor);
  }
  const bool automatic = parameters.SubSteps == 0;
  const double minimumStep = automatic ? 1.0 / parameters.MaximumSubSteps : 0.0;
  double s = 0.0;
  double step = 1.0; // automatic mode: the next step's length in s
  struct Attempt     // automatic mode: the last step rejected from the current mesh
  {
    std::vector<double> Points;
    RepairReport Repair;
    double Next = 0.0; // its end; 0: none
  } rejected;
  if (automatic)
  {
    rejected.Points.resize(3 * n); // swapped with trial: both keep 3 n values
  }
  while (s < 1.0)
  {
    // Fixed mode: s_k = k / SubSteps exactly (a sum of 1/SubSteps would miss 1 by round-off).
    double next = automatic ? std::min(1.0, s + step)
                            : (report.SubSteps + 1 == parameters.SubSteps
                                  ? 1.0
                                  : static_cast<double>(report.SubSteps + 1) / parameters.SubSteps);
    // The step's rigid part: the rotation by (next - s) angle about the current centre, and the
    // translation; the moving nodes' path decides the rest (the step's shape deformation).
    PathPositions(points, n, kinds, motion.Center, axis, angle, motion.Translation, displacement,
      next, nextPath.data());
    RigidMotion rigid;
    for (int c = 0; c < 3; ++c)
    {
      rigid.Center[c] = motion.Center[c] + s * motion.Translation[c];
      rigid.Translation[c] = (next - s) * motion.Translation[c];
      rigid.Axis[c] = axis[c];
    }
    rigid.AxisAngleDegrees = (next - s) * angle;
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        stepDisplacement[3 * i + c] = 0.0;
      }
      if (kinds[i] == NodeKind::MovingBoundary)
      {
        double moved[3];
        rigid.Apply(1.0, current.data() + 3 * i, nullptr, moved);
        for (int c = 0; c < 3; ++c)
        {
          stepDisplacement[3 * i + c] = nextPath[3 * i + c] - moved[c];
        }
      }
    }
    // The graph of the current boundary (built once per accepted mesh: a rejected step's retry
    // and the first step, when the caller has the input's graph, reuse it), and the DGMF step.
    if (!mapping)
    {
      built = std::make_unique<DelaunayMapping>(dimension, current.data(), n, kinds, parallelFor, 0,
        DelaunayGraph::SideJobs(), parameters.Slip);
      mapping = built.get();
      report.GraphSeconds += mapping->GetGraphSeconds();
      report.LocationSeconds += mapping->GetLocationSeconds();
      ComputeBoundaryDistanceField(*mapping, parameters.StaticR0, r.data(), parallelFor);
      ComputeDampingFactor(*mapping, parameters.Damping, r.data(), f.data(), parallelFor);
    }
    DeformDGMF(*mapping, f.data(), rigid, stepDisplacement.data(), DeformationMode::DGMF2,
      current.data(), trial.data(), parallelFor);
    // Moving nodes exactly on their path (the step's rigid part plus its residual gives it up to
    // round-off; the path itself does not accumulate round-off over the steps).
    for (std::size_t i = 0; i < n; ++i)
    {
      if (kinds[i] == NodeKind::MovingBoundary)
      {
        std::copy(nextPath.begin() + 3 * i, nextPath.begin() + 3 * i + 3, trial.begin() + 3 * i);
      }
    }
    if (parameters.Constrain)
    {
      parameters.Constrain(trial.data());
    }
    // The quality guard (with 0 passes it only counts the bad cells), then in automatic mode the
    // step's acceptance: a step is too long when the mesh it leaves, repaired if the guard is on,
    // still has a bad cell, and halving it is worth trying.
    RepairParameters repair;
    repair.Threshold = parameters.RepairThreshold;
    repair.Layers = parameters.RepairLayers;
    repair.MaximumPasses = parameters.Repair ? parameters.RepairPasses : 0;
    repair.Progress = parameters.Progress.Part(s, next);
    // A step the guard cannot clean is halved anyway: the guard gives it up as soon as its passes
    // show that, instead of running them all (unless the step cannot be halved any more). A step
    // given up is halved, or, when it is itself a halving and has at least as many bad cells left
    // after its few passes as the longer step after all of its own, shows that halving does not
    // help: the longer step is then taken, as before. It is never taken itself.
    repair.GiveUpWhenHopeless = automatic && step > minimumStep;
    RepairReport repaired;
    if (parameters.Repair || automatic)
    {
      repaired = RepairCells(cells, points, trial.data(), kinds, repair, parallelFor);
    }
    if (automatic && repaired.BadCellsAfter > 0)
    {
      if (rejected.Next > s && repaired.BadCellsAfter >= rejected.Repair.BadCellsAfter)
      {
        // Halving did not help (rotations: each step's damping field is nearly the same, so
        // shorter steps add up to the same shear): take the longer step tried before.
        trial.swap(rejected.Points);
        repaired = rejected.Repair;
        next = rejected.Next;
      }
      else if (step > minimumStep)
      {
        // Too far for one step: halve it and try again from the same mesh.
        ++report.RejectedSteps;
        rejected.Points.swap(trial);
        rejected.Repair = repaired;
        if (repaired.GaveUp)
        {
          // Not repaired as far as it could be: never taken as the longer step.
          rejected.Repair.BadCellsAfter = std::numeric_limits<std::size_t>::max();
        }
        rejected.Next = next;
        step = std::max(minimumStep, 0.5 * (next - s));
        continue;
      }
    }
    current.swap(trial);
    mapping = nullptr; // the mesh moved: the next step needs its graph
    rejected.Next = 0.0;
    if (parameters.Repair)
    {
      report.RepairedCells += repaired.BadCellsBefore;
    }
    report.BadCellsLeft = repaired.BadCellsAfter;
    ++report.SubSteps;
    if (automatic)
    {
      // After a clean step, try twice as far; after a step accepted with bad cells, as far.
      step = repaired.BadCellsAfter == 0 ? std::min(2.0 * (next - s), 1.0) : next - s;
    }
    s = next;
    parameters.Progress.Report(s);
    // Fixed mode takes exactly SubSteps steps; automatic mode is bounded by its halvings.
    if (automatic && report.SubSteps + report.RejectedSteps > 4 * parameters.MaximumSubSteps)
    {
      throw std::runtime_error(
        "sub-steps: too many steps (the motion could not be split finely enough)");
    }
  }
  std::copy(current.begin(), current.end(), deformed);
  return report;
}

} // namespace dgmf
