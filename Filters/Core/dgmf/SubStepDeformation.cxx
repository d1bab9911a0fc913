#include "dgmf/SubStepDeformation.h"

#include "dgmf/DGMFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/RigidMotionFit.h"
#include "dgmf/SizeSkewQuality.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dgmf
{
namespace
{
/// The rotation of `motion` as one rotation about an axis (degrees).
void AxisAngleOf(const RigidMotion& motion, double axis[3], double& angleDegrees)
{
  double R[3][3];
  motion.GetRotationMatrix(1.0, R);
  RotationToAxisAngle(R, axis, angleDegrees);
}

/// Where the moving nodes are at path parameter s (0: original, 1: prescribed), 3 per node.
void PathPositions(const double* points, std::size_t n, const NodeKind* kinds, const double center[3],
  const double axis[3], double angleDegrees, const double* translation, const double* displacement,
  double s, double* out)
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

/// Lowest SizeSkew against the original points, and whether a cell is inverted.
void Quality(const CellMesh& cells, const double* original, const double* current, double& minimum,
  bool& inverted)
{
  minimum = 1.0;
  inverted = false;
  double before[8 * 3], after[8 * 3];
  for (std::size_t c = 0; c < cells.GetNumberOfCells(); ++c)
  {
    if (!cells.Covered.empty() && !cells.Covered[c])
    {
      continue;
    }
    const std::int64_t begin = cells.Offsets[c];
    const int corners = static_cast<int>(cells.Offsets[c + 1] - begin);
    if (corners > 8)
    {
      continue;
    }
    for (int k = 0; k < corners; ++k)
    {
      const auto p = static_cast<std::size_t>(cells.Connectivity[static_cast<std::size_t>(begin + k)]);
      for (int d = 0; d < 3; ++d)
      {
        before[3 * k + d] = original[3 * p + d];
        after[3 * k + d] = current[3 * p + d];
      }
    }
    const CellQuality q = ComputeSizeSkew(cells.Shapes[c], before, after);
    minimum = std::min(minimum, q.SizeSkew);
    inverted = inverted || q.Inverted;
  }
}
} // namespace

SubStepReport DeformInSubSteps(int dimension, const double* points, std::size_t n,
  const NodeKind* kinds, const CellMesh& cells, const RigidMotion& motion,
  const double* displacement, const SubStepParameters& parameters, double* deformed,
  const ParallelFor& parallelFor)
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
  const bool automatic = parameters.SubSteps == 0;
  const double minimumStep = automatic ? 1.0 / parameters.MaximumSubSteps : 0.0;
  double s = 0.0;
  double step = automatic ? 1.0 : 1.0 / parameters.SubSteps;
  while (s < 1.0)
  {
    const double next = std::min(1.0, s + step);
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
    // The graph of the current boundary, and the DGMF step.
    const DelaunayMapping mapping(dimension, current.data(), n, kinds, parallelFor);
    report.GraphSeconds += mapping.GetGraphSeconds();
    report.LocationSeconds += mapping.GetLocationSeconds();
    ComputeBoundaryDistanceField(mapping, parameters.StaticR0, r.data(), parallelFor);
    ComputeDampingFactor(mapping, parameters.Damping, r.data(), f.data(), parallelFor);
    DeformDGMF(mapping, f.data(), rigid, stepDisplacement.data(), DeformationMode::DGMF2,
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
    if (automatic && step > minimumStep)
    {
      double minimum = 0.0;
      bool inverted = false;
      Quality(cells, points, trial.data(), minimum, inverted);
      if (inverted || minimum < parameters.RepairThreshold)
      {
        // Too far for one step: halve it and try again from the same mesh.
        ++report.RejectedSteps;
        step = std::max(minimumStep, 0.5 * step);
        continue;
      }
    }
    current.swap(trial);
    if (parameters.Repair)
    {
      RepairParameters repair;
      repair.Threshold = parameters.RepairThreshold;
      repair.Layers = parameters.RepairLayers;
      repair.MaximumPasses = parameters.RepairPasses;
      const RepairReport repaired =
        RepairCells(cells, points, current.data(), kinds, repair, parallelFor);
      report.RepairedCells += repaired.BadCellsBefore;
      report.BadCellsLeft = repaired.BadCellsAfter;
    }
    ++report.SubSteps;
    s = next;
    if (automatic)
    {
      step = std::min(2.0 * step, 1.0);
    }
    if (report.SubSteps + report.RejectedSteps > 4 * parameters.MaximumSubSteps)
    {
      throw std::runtime_error("sub-steps: too many steps (the motion could not be split finely enough)");
    }
  }
  std::copy(current.begin(), current.end(), deformed);
  return report;
}

} // namespace dgmf
