// DGMF in sub-steps (dgmf::DeformInSubSteps), on a procedural 2D annulus: an inner circle that
// moves, an outer circle that stays, triangles between them.
#include "dgmf/DelaunayMapping.h"
#include "dgmf/SubStepDeformation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

using dgmf::CellMesh;
using dgmf::CellShape;
using dgmf::NodeKind;

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Annulus
{
  std::vector<double> Points;
  std::vector<NodeKind> Kinds;
  CellMesh Cells;
};

/// Rings of `sectors` nodes at radii from 1 (moving) to 5 (static), geometrically spaced; each
/// ring segment pair is split into two triangles (listed clockwise, stored counter-clockwise).
Annulus MakeAnnulus(int rings, int sectors)
{
  Annulus mesh;
  for (int j = 0; j < rings; ++j)
  {
    const double radius = std::pow(5.0, static_cast<double>(j) / (rings - 1));
    for (int i = 0; i < sectors; ++i)
    {
      const double a = 2.0 * Pi * (i + 0.5 * (j % 2)) / sectors;
      mesh.Points.insert(mesh.Points.end(), { radius * std::cos(a), radius * std::sin(a), 0.0 });
      mesh.Kinds.push_back(j == 0
          ? NodeKind::MovingBoundary
          : (j == rings - 1 ? NodeKind::StaticBoundary : NodeKind::Interior));
    }
  }
  mesh.Cells.NumberOfPoints = mesh.Kinds.size();
  mesh.Cells.Offsets.push_back(0);
  const auto id = [sectors](int i, int j)
  { return static_cast<std::int64_t>(j * sectors + (i % sectors + sectors) % sectors); };
  const auto add = [&mesh](std::int64_t a, std::int64_t b, std::int64_t c)
  {
    mesh.Cells.Connectivity.insert(mesh.Cells.Connectivity.end(), { a, c, b }); // counter-clockwise
    mesh.Cells.Offsets.push_back(static_cast<std::int64_t>(mesh.Cells.Connectivity.size()));
    mesh.Cells.Shapes.push_back(CellShape::Triangle);
  };
  for (int j = 0; j + 1 < rings; ++j)
  {
    for (int i = 0; i < sectors; ++i)
    {
      if (j % 2 == 0) // the outer ring is shifted by half a sector forward
      {
        add(id(i, j), id(i + 1, j), id(i, j + 1));
        add(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      }
      else // the inner ring is shifted forward
      {
        add(id(i, j), id(i + 1, j + 1), id(i, j + 1));
        add(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      }
    }
  }
  return mesh;
}

dgmf::RigidMotion Rotation(double degrees, double tx = 0.0, double ty = 0.0)
{
  dgmf::RigidMotion motion;
  motion.AnglesDegrees[2] = degrees;
  motion.Translation[0] = tx;
  motion.Translation[1] = ty;
  return motion;
}

std::vector<double> Deform(const Annulus& mesh, const dgmf::RigidMotion& motion,
  const dgmf::SubStepParameters& parameters, dgmf::SubStepReport* report = nullptr,
  const dgmf::DelaunayMapping* initial = nullptr)
{
  std::vector<double> out(mesh.Points.size());
  const dgmf::SubStepReport r =
    dgmf::DeformInSubSteps(2, mesh.Points.data(), mesh.Kinds.size(), mesh.Kinds.data(), mesh.Cells,
      motion, nullptr, parameters, out.data(), dgmf::SerialFor, initial);
  if (report)
  {
    *report = r;
  }
  return out;
}

/// Moving nodes at c + R(x - c) + t (c = 0), static ones where they were, z = 0 everywhere.
void ExpectBoundaryExact(const Annulus& mesh, const std::vector<double>& out, double degrees,
  double tx = 0.0, double ty = 0.0)
{
  const double a = degrees * Pi / 180.0;
  for (std::size_t i = 0; i < mesh.Kinds.size(); ++i)
  {
    const double* x = &mesh.Points[3 * i];
    const double* y = &out[3 * i];
    ASSERT_EQ(y[2], 0.0) << i;
    if (mesh.Kinds[i] == NodeKind::StaticBoundary)
    {
      ASSERT_TRUE(y[0] == x[0] && y[1] == x[1]) << "static node " << i << " moved";
    }
    else if (mesh.Kinds[i] == NodeKind::MovingBoundary)
    {
      ASSERT_NEAR(y[0], std::cos(a) * x[0] - std::sin(a) * x[1] + tx, 1e-12) << i;
      ASSERT_NEAR(y[1], std::sin(a) * x[0] + std::cos(a) * x[1] + ty, 1e-12) << i;
    }
  }
}

/// Number of triangles with a non-positive area.
int CountInverted(const Annulus& mesh, const std::vector<double>& p)
{
  int inverted = 0;
  const auto& c = mesh.Cells.Connectivity;
  for (std::size_t k = 0; k + 2 < c.size(); k += 3)
  {
    const double* a = &p[3 * c[k]];
    const double* b = &p[3 * c[k + 1]];
    const double* d = &p[3 * c[k + 2]];
    const double area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    inverted += area <= 0.0 ? 1 : 0;
  }
  return inverted;
}
} // namespace

TEST(SubStepDeformation, TheAnnulusIsValid)
{
  const Annulus mesh = MakeAnnulus(12, 40);
  EXPECT_EQ(CountInverted(mesh, mesh.Points), 0);
}

TEST(SubStepDeformation, FixedStepsEndExactlyOnThePrescribedMotion)
{
  const Annulus mesh = MakeAnnulus(12, 40);
  dgmf::SubStepParameters parameters;
  parameters.SubSteps = 3;
  dgmf::SubStepReport report;
  const std::vector<double> out = Deform(mesh, Rotation(120.0, 0.3, -0.2), parameters, &report);
  EXPECT_EQ(report.SubSteps, 3);
  EXPECT_EQ(report.RejectedSteps, 0);
  ExpectBoundaryExact(mesh, out, 120.0, 0.3, -0.2);
}

// The step count is exact even when 1/SubSteps is not a binary fraction (a sum of 1/6 would
// stop just short of 1 and take a seventh, tiny step).
TEST(SubStepDeformation, StepCountIsExactForAnyNumber)
{
  const Annulus mesh = MakeAnnulus(8, 24);
  // 300: more than the automatic mode's bound (4 x MaximumSubSteps = 256), which once also
  // stopped fixed mode with "too many steps".
  for (const int steps : { 3, 6, 7, 10, 300 })
  {
    dgmf::SubStepParameters parameters;
    parameters.SubSteps = steps;
    dgmf::SubStepReport report;
    const std::vector<double> out = Deform(mesh, Rotation(30.0), parameters, &report);
    EXPECT_EQ(report.SubSteps, steps);
    ExpectBoundaryExact(mesh, out, 30.0);
  }
}

// A large translation (the gap between the circle and the outer boundary closes from 4 to 1):
// in one step, the damping field of the initial mesh squeezes cells on the closing side until
// they invert; each sub-step rebuilds the graph on the current mesh, so the field follows the gap.
TEST(SubStepDeformation, StepsFollowALargeTranslationWithoutInvertedCells)
{
  const Annulus mesh = MakeAnnulus(12, 40);
  const dgmf::RigidMotion motion = Rotation(0.0, 3.0, 0.0);
  const std::vector<double> single = Deform(mesh, motion, dgmf::SubStepParameters());
  EXPECT_GT(CountInverted(mesh, single), 0) << "the premise: one step inverts cells";

  dgmf::SubStepParameters fixed;
  fixed.SubSteps = 8;
  const std::vector<double> out = Deform(mesh, motion, fixed);
  EXPECT_EQ(CountInverted(mesh, out), 0);
  ExpectBoundaryExact(mesh, out, 0.0, 3.0, 0.0);
}

// Automatic mode halves a step that leaves an inverted cell, and stops when none is left.
TEST(SubStepDeformation, AutomaticModeHalvesBadSteps)
{
  const Annulus mesh = MakeAnnulus(20, 40);
  const dgmf::RigidMotion motion = Rotation(90.0, 3.0, 0.0);
  EXPECT_GT(CountInverted(mesh, Deform(mesh, motion, dgmf::SubStepParameters())), 0);
  dgmf::SubStepParameters automatic;
  automatic.SubSteps = 0;
  dgmf::SubStepReport report;
  const std::vector<double> out = Deform(mesh, motion, automatic, &report);
  EXPECT_GT(report.RejectedSteps, 0);
  EXPECT_GT(report.SubSteps, 1);
  EXPECT_LE(report.SubSteps, 8) << "more steps than needed";
  EXPECT_EQ(report.BadCellsLeft, 0u);
  EXPECT_EQ(CountInverted(mesh, out), 0);
  ExpectBoundaryExact(mesh, out, 90.0, 3.0, 0.0);
}

// With the guard, the steps the damping field alone cannot make valid are repaired.
TEST(SubStepDeformation, GuardRepairsWhatStepsCannot)
{
  const Annulus mesh = MakeAnnulus(12, 40);
  const dgmf::RigidMotion motion = Rotation(90.0, 3.5, 0.0);
  dgmf::SubStepParameters fixed;
  fixed.SubSteps = 8;
  EXPECT_GT(CountInverted(mesh, Deform(mesh, motion, fixed)), 0) << "the premise";
  fixed.Repair = true;
  fixed.RepairThreshold = 0.05;
  dgmf::SubStepReport report;
  const std::vector<double> out = Deform(mesh, motion, fixed, &report);
  EXPECT_EQ(CountInverted(mesh, out), 0);
  EXPECT_GT(report.RepairedCells, 0u);
  EXPECT_EQ(report.SubSteps, 8);
  ExpectBoundaryExact(mesh, out, 90.0, 3.5, 0.0);
}

// A rotation given by one Euler angle keeps its angle beyond 180 degrees, as the single step does.
TEST(SubStepDeformation, RotationsBeyondHalfATurnKeepTheirDirection)
{
  const Annulus mesh = MakeAnnulus(20, 40);
  dgmf::SubStepParameters fixed;
  fixed.SubSteps = 4;
  const std::vector<double> out = Deform(mesh, Rotation(-270.0), fixed);
  ExpectBoundaryExact(mesh, out, -270.0);
  // The interior nodes turn the same way as the single step, about as far.
  const std::vector<double> single = Deform(mesh, Rotation(-270.0), dgmf::SubStepParameters());
  const std::size_t node = 5 * 40; // first node of ring 5
  const double a0 = std::atan2(mesh.Points[3 * node + 1], mesh.Points[3 * node]);
  const double a1 = std::atan2(out[3 * node + 1], out[3 * node]);
  const double a2 = std::atan2(single[3 * node + 1], single[3 * node]);
  EXPECT_LT(std::abs(std::remainder(a1 - a2, 2.0 * Pi)), 0.2) << a0 << " " << a1 << " " << a2;
}

// Giving the input's graph for the first step changes nothing but the time.
TEST(SubStepDeformation, InitialGraphGivesTheSameBits)
{
  const Annulus mesh = MakeAnnulus(10, 32);
  const dgmf::DelaunayMapping mapping(
    2, mesh.Points.data(), mesh.Kinds.size(), mesh.Kinds.data(), dgmf::SerialFor);
  dgmf::SubStepParameters parameters;
  parameters.SubSteps = 2;
  parameters.Repair = true;
  parameters.RepairThreshold = 0.2;
  const std::vector<double> without = Deform(mesh, Rotation(80.0), parameters);
  const std::vector<double> with = Deform(mesh, Rotation(80.0), parameters, nullptr, &mapping);
  ASSERT_EQ(without.size(), with.size());
  for (std::size_t i = 0; i < with.size(); ++i)
  {
    ASSERT_EQ(without[i], with[i]) << i;
  }
}

TEST(SubStepDeformation, BadParametersThrow)
{
  const Annulus mesh = MakeAnnulus(6, 16);
  dgmf::SubStepParameters parameters;
  parameters.SubSteps = -1;
  EXPECT_THROW(Deform(mesh, Rotation(10.0), parameters), std::invalid_argument);
  parameters.SubSteps = 0;
  parameters.MaximumSubSteps = 0;
  EXPECT_THROW(Deform(mesh, Rotation(10.0), parameters), std::invalid_argument);
  const Annulus other = MakeAnnulus(5, 16);
  const dgmf::DelaunayMapping mapping(
    2, other.Points.data(), other.Kinds.size(), other.Kinds.data(), dgmf::SerialFor);
  parameters.MaximumSubSteps = 64;
  EXPECT_THROW(Deform(mesh, Rotation(10.0), parameters, nullptr, &mapping), std::invalid_argument);
}
