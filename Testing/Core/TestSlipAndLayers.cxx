// Slip (symmetry) boundaries and one-cell-thick meshes in the core: slip nodes stay in their
// planes to the bit or to round-off, a plane that is not one is refused, and the two layers of an
// extruded mesh get the same in-plane motion bit for bit.
#include "SyntheticNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/DeformationMethod.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/ExtrudedLayers.h"
#include "dgmf/ResultNames.h"
#include "dgmf/SlipPlanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// A half model: a unit half sphere (moving, y >= 0) on the symmetry plane y = 0 of the half box
/// [-5, 5] x [0, 5] x [-5, 5]: the box faces static but the y = 0 face, which slips; random
/// interior nodes.
dgmf_test::NodeSet HalfSphereInHalfBox(int interior = 2500)
{
  dgmf_test::NodeSet set;
  set.Dimension = 3;
  set.Add(0, 0, 1, dgmf::NodeKind::MovingBoundary);
  set.Add(0, 0, -1, dgmf::NodeKind::MovingBoundary);
  for (int i = 1; i < 8; ++i) // the half sphere y >= 0, its rim on the plane y = 0
  {
    const double theta = Pi * i / 8;
    for (int j = 0; j <= 12; ++j)
    {
      const double phi = Pi * j / 12;
      const double y = j == 0 || j == 12 ? 0.0 : std::sin(theta) * std::sin(phi);
      set.Add(std::sin(theta) * std::cos(phi), y, std::cos(theta), dgmf::NodeKind::MovingBoundary);
    }
  }
  const int m = 10;
  for (int i = 0; i <= m; ++i)
  {
    for (int j = 0; j <= m / 2; ++j)
    {
      for (int k = 0; k <= m; ++k)
      {
        const bool face = i == 0 || i == m || j == 0 || j == m / 2 || k == 0 || k == m;
        if (!face)
        {
          continue;
        }
        const double x = -5.0 + 10.0 * i / m, y = 10.0 * j / m, z = -5.0 + 10.0 * k / m;
        const bool plane = j == 0 && i > 0 && i < m && k > 0 && k < m;
        if (plane && x * x + z * z < 1.2 * 1.2)
        {
          continue; // the sphere's footprint
        }
        set.Add(x, y, z, plane ? dgmf::NodeKind::SlipBoundary : dgmf::NodeKind::StaticBoundary);
      }
    }
  }
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-4.9, 4.9);
  int added = 0;
  while (added < interior)
  {
    const double x = coordinate(random), y = 0.5 * (coordinate(random) + 4.9),
                 z = coordinate(random);
    if (x * x + y * y + z * z > 1.15 * 1.15 && y > 0.01)
    {
      set.Add(x, y, z, dgmf::NodeKind::Interior);
      ++added;
    }
  }
  return set;
}

dgmf::SlipConstraint SlipOf(const dgmf_test::NodeSet& set)
{
  dgmf::SlipConstraint slip;
  std::vector<std::int32_t> nodes;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.Kinds[i] == dgmf::NodeKind::SlipBoundary)
    {
      nodes.push_back(static_cast<std::int32_t>(i));
    }
  }
  slip.Planes.push_back(dgmf::FitSlipPlane(set.Points.data(), nodes.data(), nodes.size(), "plane"));
  slip.Nodes = nodes;
  slip.NodePlanes.assign(nodes.size(), 0);
  return slip;
}

template <typename Call>
std::string Message(const Call& call)
{
  try
  {
    call();
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "no error";
}
} // namespace

TEST(SlipPlanes, AnAxisPlaneIsExactAndATiltedOneIsFitted)
{
  // Nodes on y = 0: the normal is exactly y.
  std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 0, 1, 2, 0, 3 };
  const std::vector<std::int32_t> nodes = { 0, 1, 2, 3 };
  dgmf::SlipPlane plane = dgmf::FitSlipPlane(points.data(), nodes.data(), 4, "y0");
  EXPECT_EQ(plane.Axis, 1);
  EXPECT_EQ(plane.Normal[1], 1.0);
  // A tilted plane x + y + z = 1.
  points = { 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0.5, 0, 0.2, 0.3, 0.5 };
  const std::vector<std::int32_t> five = { 0, 1, 2, 3, 4 };
  plane = dgmf::FitSlipPlane(points.data(), five.data(), 5, "tilted");
  EXPECT_EQ(plane.Axis, -1);
  EXPECT_NEAR(std::abs(plane.Normal[0]), 1.0 / std::sqrt(3.0), 1e-15);
  // Rounding to single precision (1e-8 of the size) is accepted, and measured...
  points[3 * 4 + 2] += 1e-8;
  plane = dgmf::FitSlipPlane(points.data(), five.data(), 5, "float");
  EXPECT_GT(plane.Deviation, 1e-9);
  EXPECT_LT(plane.Deviation, 1e-8);
  // ... but a curved surface and a line are refused, with the boundary's name.
  points[3 * 4 + 2] += 0.01;
  EXPECT_NE(Message([&]() { dgmf::FitSlipPlane(points.data(), five.data(), 5, "wall"); })
              .find("The slip boundary 'wall' is not planar"),
    std::string::npos);
  const std::vector<double> line = { 0, 0, 0, 1, 1, 1, 2, 2, 2 };
  EXPECT_NE(Message([&]() { dgmf::FitSlipPlane(line.data(), nodes.data(), 3, "edge"); })
              .find("does not span a plane"),
    std::string::npos);
}

TEST(SlipPlanes, ASlipBoundaryOfA2DMeshIsAStraightLineItsNodesSlideAlong)
{
  // A 2D mesh's slip boundary on the tilted line y = 2x + 1 (z = 0.5 for every node).
  const std::vector<double> points = { 0, 1, 0.5, 1, 3, 0.5, 2, 5, 0.5, 0.5, 2, 0.5 };
  const std::vector<std::int32_t> nodes = { 0, 1, 2, 3 };
  dgmf::SlipPlane line = dgmf::FitSlipPlane(points.data(), nodes.data(), 4, "tilted", 1e-9, 2);
  EXPECT_EQ(line.Axis, -1);
  EXPECT_EQ(line.Normal[2], 0.0);
  EXPECT_NEAR(std::abs(line.Normal[0]), 2.0 / std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(std::abs(line.Normal[1]), 1.0 / std::sqrt(5.0), 1e-15);
  // A node pushed off the line comes back onto it, keeping z; its move along the line stays.
  dgmf::SlipConstraint slip;
  slip.Planes.push_back(line);
  slip.Nodes = { 1 };
  slip.NodePlanes = { 0 };
  std::vector<double> deformed = points;
  deformed[3] += 0.3;  // x
  deformed[4] += 0.45; // y: 0.15 off the line's direction (1, 2)
  slip.Apply(points.data(), deformed.data());
  EXPECT_NEAR(deformed[4] - (2.0 * deformed[3] + 1.0), 0.0, 1e-14);
  EXPECT_GT(deformed[3], 1.0);
  EXPECT_EQ(deformed[5], 0.5);
  // On x = 1 (two nodes are enough for a line): the axis, exactly.
  const std::vector<double> vertical = { 1, 0, 0, 1, 2, 0 };
  const std::vector<std::int32_t> two = { 0, 1 };
  line = dgmf::FitSlipPlane(vertical.data(), two.data(), 2, "x1", 1e-9, 2);
  EXPECT_EQ(line.Axis, 0);
  EXPECT_EQ(line.Normal[0], 1.0);
  // The whole outer square of a 2D mesh is not a line: refused, where a plane z = 0 took it.
  const std::vector<double> square = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  EXPECT_NE(Message([&]() { dgmf::FitSlipPlane(square.data(), nodes.data(), 4, "box", 1e-9, 2); })
              .find("The slip boundary 'box' is not straight"),
    std::string::npos);
  EXPECT_NO_THROW(dgmf::FitSlipPlane(square.data(), nodes.data(), 4, "box"));
  const std::vector<double> point = { 0.5, 0.5, 0, 0.5, 0.5, 0 };
  EXPECT_NE(Message([&]() { dgmf::FitSlipPlane(point.data(), two.data(), 2, "dot", 1e-9, 2); })
              .find("does not span a line"),
    std::string::npos);
}

TEST(SlipPlanes, SlipNodesStayInTheirPlaneAndSlideWithTheBody)
{
  const dgmf_test::NodeSet set = HalfSphereInHalfBox();
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  dgmf::DeformationProblem problem;
  problem.Dimension = 3;
  problem.NumberOfNodes = set.Size();
  problem.Points = set.Points.data();
  problem.Kinds = set.Kinds.data();
  problem.Motions[0].AnglesDegrees[1] = 30.0; // pitching about the plane's normal
  problem.Slip = SlipOf(set);
  ASSERT_EQ(problem.Slip.Planes[0].Axis, 1);
  for (dgmf::Method method : { dgmf::Method::DGMF, dgmf::Method::DGM, dgmf::Method::IDW })
  {
    std::vector<double> deformed(set.Points.size());
    dgmf::VectorFieldStore fields(set.Size());
    dgmf::CreateMethod(method, dgmf::MethodParameters())
      ->Deform(
        problem, &mapping, dgmf::DeformationOutputs{ deformed.data(), &fields }, dgmf::SerialFor);
    double slid = 0.0;
    for (std::int32_t node : problem.Slip.Nodes)
    {
      const auto i = static_cast<std::size_t>(node);
      ASSERT_EQ(deformed[3 * i + 1], set.Points[3 * i + 1]) << "node " << i; // y kept, bit for bit
      slid = std::max(slid,
        std::hypot(
          deformed[3 * i] - set.Points[3 * i], deformed[3 * i + 2] - set.Points[3 * i + 2]));
    }
    EXPECT_GT(slid, 0.05) << dgmf::GetMethodInfo(method).Name; // they follow the body in the plane
  }
  // A tilted plane: the projection leaves them on it to round-off.
  dgmf::SlipConstraint tilted;
  dgmf::SlipPlane plane;
  plane.Normal[0] = plane.Normal[1] = plane.Normal[2] = 1.0 / std::sqrt(3.0);
  tilted.Planes.push_back(plane);
  const std::vector<double> points = { 1, 0, 0 };
  std::vector<double> moved = { 1.3, 0.2, -0.1 };
  tilted.Nodes = { 0 };
  tilted.NodePlanes = { 0 };
  tilted.Apply(points.data(), moved.data());
  EXPECT_NEAR((moved[0] + moved[1] + moved[2]) / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 1e-15);

  // A node on two planes keeps the part of its displacement along their line: two axis planes
  // keep both coordinates bit for bit; two tilted ones, the projection onto their line.
  dgmf::SlipConstraint corner;
  dgmf::SlipPlane yPlane, zPlane;
  yPlane.Normal[1] = 1.0;
  yPlane.Normal[2] = 0.0;
  yPlane.Axis = 1;
  zPlane.Axis = 2;
  corner.Planes = { yPlane, zPlane, plane };
  corner.Nodes = { 0 };
  corner.NodePlanes = { 0 };
  corner.SecondPlanes = { 1 };
  std::vector<double> edge = { 1.3, 0.2, -0.1 };
  corner.Apply(points.data(), edge.data());
  EXPECT_EQ(edge, (std::vector<double>{ 1.3, 0.0, 0.0 }));
  corner.SecondPlanes = { 2 }; // y = 0 and x + y + z = 1: the line along (1, 0, -1)
  edge = { 1.3, 0.2, -0.1 };
  corner.Apply(points.data(), edge.data());
  EXPECT_NEAR(edge[0], 1.2, 1e-15);
  EXPECT_NEAR(edge[1], 0.0, 1e-15);
  EXPECT_NEAR(edge[2], -0.2, 1e-15);
}

namespace
{
/// `problem` deformed with DGMF: 3 coordinates per node. Its mapping locates the slip nodes with
/// the problem's slip planes (`outside`, if given: the mapping's count of nodes outside the graph).
std::vector<double> DeformWithDGMF(
  const dgmf::DeformationProblem& problem, std::size_t* outside = nullptr)
{
  const dgmf::DelaunayMapping mapping(problem.Dimension, problem.Points, problem.NumberOfNodes,
    problem.Kinds, dgmf::SerialFor, 0, {}, &problem.Slip);
  if (outside)
  {
    *outside = mapping.GetNumberOfOutsideNodes();
  }
  std::vector<double> deformed(3 * problem.NumberOfNodes);
  dgmf::VectorFieldStore fields(problem.NumberOfNodes);
  dgmf::CreateMethod(dgmf::Method::DGMF, dgmf::MethodParameters())
    ->Deform(
      problem, &mapping, dgmf::DeformationOutputs{ deformed.data(), &fields }, dgmf::SerialFor);
  return deformed;
}
} // namespace

TEST(SlipPlanes, ATiltedNoisyPlaneGivesTheResultOfTheAxisPlane)
{
  // The half model, and the same turned by 37 degrees about (1, 2, 0.5), its slip nodes off their
  // plane by up to 5e-10 (rounding): on the graph's hull, they used to take the barycentric
  // coordinates of whichever flat element they fell in: 40 nodes outside the graph, and nodes up
  // to 0.77 off the axis plane's result (5e-8 now: the noise, through different graphs).
  const dgmf_test::NodeSet set = HalfSphereInHalfBox();
  const double axis[3] = { 1.0 / std::sqrt(5.25), 2.0 / std::sqrt(5.25), 0.5 / std::sqrt(5.25) };
  const double a = 37.0 * Pi / 180.0, c = std::cos(a), s = std::sin(a);
  double turn[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const double cross = i == j ? 0.0 : ((j - i + 3) % 3 == 1 ? -1.0 : 1.0) * axis[3 - i - j];
      turn[i][j] = (i == j ? c : 0.0) + (1.0 - c) * axis[i] * axis[j] + s * cross;
    }
  }
  dgmf_test::NodeSet tilted = set;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> noise(-5e-10, 5e-10);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const double off = set.Kinds[i] == dgmf::NodeKind::SlipBoundary ? noise(random) : 0.0;
    for (int r = 0; r < 3; ++r)
    {
      tilted.Points[3 * i + r] = turn[r][1] * off;
      for (int k = 0; k < 3; ++k)
      {
        tilted.Points[3 * i + r] += turn[r][k] * set.Points[3 * i + k];
      }
    }
  }
  dgmf::DeformationProblem axisProblem;
  axisProblem.NumberOfNodes = set.Size();
  axisProblem.Points = set.Points.data();
  axisProblem.Kinds = set.Kinds.data();
  axisProblem.Motions[0].AxisAngleDegrees = 30.0; // pitching about the plane's normal
  axisProblem.Motions[0].Axis[2] = 0.0;
  axisProblem.Motions[0].Axis[1] = 1.0;
  axisProblem.Slip = SlipOf(set);
  dgmf::DeformationProblem tiltedProblem = axisProblem;
  tiltedProblem.Points = tilted.Points.data();
  for (int r = 0; r < 3; ++r)
  {
    tiltedProblem.Motions[0].Axis[r] = turn[r][1];
  }
  tiltedProblem.Slip = SlipOf(tilted);
  ASSERT_EQ(tiltedProblem.Slip.Planes[0].Axis, -1);
  ASSERT_GT(tiltedProblem.Slip.Planes[0].Deviation, 0.0);
  std::size_t axisOutside = 0, tiltedOutside = 0;
  const std::vector<double> expected = DeformWithDGMF(axisProblem, &axisOutside);
  const std::vector<double> deformed = DeformWithDGMF(tiltedProblem, &tiltedOutside);
  EXPECT_EQ(axisOutside, 0u);
  EXPECT_EQ(tiltedOutside, 0u); // the noise put slip nodes outside the graph
  double largest = 0.0, slid = 0.0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    for (int k = 0; k < 3; ++k) // turned back
    {
      const double back = turn[0][k] * deformed[3 * i] + turn[1][k] * deformed[3 * i + 1] +
        turn[2][k] * deformed[3 * i + 2];
      largest = std::max(largest, std::abs(back - expected[3 * i + k]));
      slid = std::max(slid, std::abs(expected[3 * i + k] - set.Points[3 * i + k]));
    }
  }
  EXPECT_GT(slid, 0.3);
  EXPECT_LT(largest, 1e-6) << "the tilted plane's result, turned back, is the axis plane's";
}

namespace
{
/// The problem of `nodes` (3D) turned by `degrees` about `axis`.
dgmf::DeformationProblem Turned(const dgmf_test::NodeSet& nodes, int axis, double degrees)
{
  dgmf::DeformationProblem problem;
  problem.Dimension = nodes.Dimension;
  problem.NumberOfNodes = nodes.Size();
  problem.Points = nodes.Points.data();
  problem.Kinds = nodes.Kinds.data();
  problem.Motions[0].AnglesDegrees[axis] = degrees;
  return problem;
}

/// `problem` deformed with DGMF through the 2D problem of its `layers`: 3 coordinates per node.
std::vector<double> DeformThroughLayer(
  const dgmf::ExtrudedLayers& layers, const dgmf::DeformationProblem& problem)
{
  dgmf::LayerProblemStorage storage;
  const std::vector<double> layerDeformed =
    DeformWithDGMF(dgmf::ReduceToLayer(layers, problem, storage));
  std::vector<double> deformed(3 * problem.NumberOfNodes);
  dgmf::ExpandFromLayer(layers, problem.Points, layerDeformed.data(), deformed.data());
  return deformed;
}
} // namespace

TEST(ExtrudedLayers, TheTwoLayersArePairedAndMoveTogether)
{
  // The circle in a square, extruded along x from -0.5 to 0.25: a one-cell-thick mesh.
  const dgmf_test::NodeSet flat = dgmf_test::CircleInSquare(32, 10, 400);
  dgmf_test::NodeSet layered;
  layered.Dimension = 3;
  for (double x : { -0.5, 0.25 })
  {
    for (std::size_t i = 0; i < flat.Size(); ++i)
    {
      // The 2D point (u, v) sits at (y, z) = (u, v): axis x, layer coordinates (y, z, x).
      layered.Add(x, flat.Points[3 * i], flat.Points[3 * i + 1], flat.Kinds[i]);
    }
  }
  const dgmf::ExtrudedLayers layers =
    dgmf::FindExtrudedLayers(layered.Points.data(), layered.Size());
  ASSERT_TRUE(layers.Found());
  EXPECT_EQ(layers.Axis, 0);
  EXPECT_EQ(layers.Low, -0.5);
  EXPECT_EQ(layers.High, 0.25);
  ASSERT_EQ(layers.Front.size(), flat.Size());
  EXPECT_EQ(layers.Layer[flat.Size() + 7], 7); // node 7's partner on the other plane
  // Not one cell thick: a node off the two planes.
  dgmf_test::NodeSet broken = layered;
  broken.Points[3 * 5] = 0.0;
  EXPECT_FALSE(dgmf::FindExtrudedLayers(broken.Points.data(), broken.Size()).Found());

  // A rotation about x of the layered mesh, through the layer: the same in-plane motion as the 2D
  // mesh rotated about z, both layers alike, x kept.
  const dgmf::DeformationProblem problem = Turned(layered, 0, 40.0);
  dgmf::LayerProblemStorage storage;
  const dgmf::DeformationProblem layer = dgmf::ReduceToLayer(layers, problem, storage);
  EXPECT_EQ(layer.Dimension, 2);
  EXPECT_EQ(layer.Motions[0].AnglesDegrees[2], 40.0);
  const std::vector<double> deformed = DeformThroughLayer(layers, problem);
  const std::size_t m = flat.Size();
  for (std::size_t i = 0; i < m; ++i)
  {
    ASSERT_EQ(deformed[3 * i], -0.5);
    ASSERT_EQ(deformed[3 * (m + i)], 0.25);
    ASSERT_EQ(std::memcmp(&deformed[3 * i + 1], &deformed[3 * (m + i) + 1], 2 * sizeof(double)), 0);
  }
  // The moving circle turned by 40 degrees about x (y towards z).
  const double y = deformed[3 * 0 + 1], z = deformed[3 * 0 + 2];
  EXPECT_NEAR(y, std::cos(40.0 * Pi / 180.0), 1e-12);
  EXPECT_NEAR(z, std::sin(40.0 * Pi / 180.0), 1e-12);
}

TEST(ExtrudedLayers, TheLayersOfAMeshWithRoundOffAreFoundWithinTheTolerance)
{
  // The extruded circle in a square with the round-off of a transform (OpenFOAM's
  // transformPoints turning an x-y mesh into the x-z plane): every coordinate off by up to
  // 3e-14, so no two nodes share a plane or a partner's in-plane coordinates bit for bit. Found
  // within the tolerance, deformed as the exact mesh is (until 2026-11-30 it was taken for a 3D
  // mesh: 35 inverted cells with its planes static). Off by 1e-6, it is no such mesh.
  const dgmf::NodeKind none = dgmf::NodeKind::Interior;
  const dgmf_test::NodeSet flat = dgmf_test::CircleInSquare(32, 10, 400);
  dgmf_test::NodeSet exact, noisy, far;
  exact.Dimension = noisy.Dimension = far.Dimension = 3;
  std::uint64_t state = 12345;
  const auto noise = [&state](double size)
  {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return size * (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
  };
  for (double x : { -0.5, 0.25 })
  {
    for (std::size_t i = 0; i < flat.Size(); ++i)
    {
      const double u = flat.Points[3 * i], v = flat.Points[3 * i + 1];
      exact.Add(x, u, v, flat.Kinds[i]);
      noisy.Add(x + noise(6e-14), u + noise(6e-14), v + noise(6e-14), flat.Kinds[i]);
      far.Add(x + noise(2e-6), u, v, none);
    }
  }
  const dgmf::ExtrudedLayers layers = dgmf::FindExtrudedLayers(noisy.Points.data(), noisy.Size());
  ASSERT_TRUE(layers.Found());
  EXPECT_EQ(layers.Axis, 0);
  EXPECT_GT(layers.Tolerance, 0.0);
  EXPECT_EQ(layers.Front.size(), flat.Size());
  EXPECT_EQ(layers.Layer[flat.Size() + 7], 7);
  EXPECT_EQ(dgmf::FindExtrudedLayers(exact.Points.data(), exact.Size()).Tolerance, 0.0);
  EXPECT_FALSE(dgmf::FindExtrudedLayers(far.Points.data(), far.Size()).Found());
  const std::vector<double> expected = DeformThroughLayer(
    dgmf::FindExtrudedLayers(exact.Points.data(), exact.Size()), Turned(exact, 0, 40.0));
  const std::vector<double> deformed = DeformThroughLayer(layers, Turned(noisy, 0, 40.0));
  double largest = 0.0;
  for (std::size_t k = 0; k < deformed.size(); ++k)
  {
    largest = std::max(largest, std::abs(deformed[k] - expected[k]));
  }
  EXPECT_LT(largest, 1e-10); // the round-off, through the graph's weights (5e-12 measured)
}

TEST(ExtrudedLayers, TheFirstPassGivesTheSameAnswerOnTwoThreadsOverManyBlocks)
{
  // Two planes z = -0.5 and z = 2 of a 300 x 300 grid, the nodes of both planes interleaved so
  // that every block of the first pass (65,536 nodes) holds some of each plane's extremes.
  const std::size_t side = 300;
  std::vector<double> points;
  for (std::size_t k = 0; k < side * side; ++k)
  {
    for (double z : { -0.5, 2.0 })
    {
      points.insert(points.end(), { double(k % side), double(k / side), z });
    }
  }
  const std::size_t n = points.size() / 3;
  const auto find = [&](const std::vector<double>& xyz, const dgmf::ParallelFor& parallelFor)
  { return dgmf::FindExtrudedLayers(xyz.data(), n, parallelFor); };
  const dgmf::ParallelFor two = dgmf_test::TwoThreadFor;
  const dgmf::ExtrudedLayers serial = find(points, dgmf::SerialFor);
  const dgmf::ExtrudedLayers threaded = find(points, two);
  ASSERT_TRUE(serial.Found());
  ASSERT_TRUE(threaded.Found());
  EXPECT_EQ(threaded.Axis, 2);
  EXPECT_EQ(threaded.Low, -0.5);
  EXPECT_EQ(threaded.High, 2.0);
  EXPECT_EQ(threaded.Pairs, side * side);
  EXPECT_EQ(threaded.Front, serial.Front);
  EXPECT_EQ(threaded.Layer, serial.Layer);

  // One node of the last block below the lower plane: that plane is then a single node, and
  // nothing is paired, whatever the threads.
  std::vector<double> lowered = points;
  lowered[3 * (n - 2) + 2] = -0.75;
  EXPECT_FALSE(find(lowered, dgmf::SerialFor).Found());
  EXPECT_FALSE(find(lowered, two).Found());
  // A NaN coordinate: ignored by the extremes (its plane then has a node fewer than the other:
  // not paired), and as the first node's it keeps its axis out.
  std::vector<double> nan = points;
  nan[3 * 70000 + 2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(find(nan, dgmf::SerialFor).Found());
  EXPECT_FALSE(find(nan, two).Found());
  nan = points;
  nan[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(find(nan, dgmf::SerialFor).Found());
  EXPECT_FALSE(find(nan, two).Found());
}

TEST(ExtrudedLayers, CellCentresBetweenThePlanesAreInnerNodesAThirdLayerIsNot)
{
  // The reader's decomposed polyhedra add their cell centres between the planes: inner nodes,
  // deformed as 2D interior nodes at their in-plane point, keeping their own coordinate.
  const dgmf_test::NodeSet flat = dgmf_test::CircleInSquare(32, 10, 400);
  dgmf_test::NodeSet layered;
  layered.Dimension = 3;
  for (double z : { 0.1, 0.15 })
  {
    for (std::size_t i = 0; i < flat.Size(); ++i)
    {
      layered.Add(flat.Points[3 * i], flat.Points[3 * i + 1], z, flat.Kinds[i]);
    }
  }
  const std::size_t m = flat.Size();
  layered.Add(1.7, 0.3, 0.125, dgmf::NodeKind::Interior);  // not above any plane node
  layered.Add(-2.2, 1.1, 0.125, dgmf::NodeKind::Interior); // and another
  const dgmf::ExtrudedLayers layers =
    dgmf::FindExtrudedLayers(layered.Points.data(), layered.Size());
  ASSERT_TRUE(layers.Found());
  EXPECT_EQ(layers.Axis, 2);
  EXPECT_EQ(layers.Pairs, m);
  ASSERT_EQ(layers.Front.size(), m + 2);
  EXPECT_EQ(layers.Front[m], static_cast<std::int32_t>(2 * m));
  EXPECT_EQ(layers.Layer[2 * m + 1], static_cast<std::int32_t>(m + 1));

  const dgmf::DeformationProblem problem = Turned(layered, 2, 25.0);
  const std::vector<double> deformed = DeformThroughLayer(layers, problem);
  // The inner nodes moved in the plane, as the same point of the 2D mesh does, and kept z.
  dgmf_test::NodeSet flatWithCentres = flat;
  flatWithCentres.Add(1.7, 0.3, 0.0, dgmf::NodeKind::Interior);
  flatWithCentres.Add(-2.2, 1.1, 0.0, dgmf::NodeKind::Interior);
  dgmf::DeformationProblem flatProblem = problem;
  flatProblem.Dimension = 2;
  flatProblem.NumberOfNodes = flatWithCentres.Size();
  flatProblem.Points = flatWithCentres.Points.data();
  flatProblem.Kinds = flatWithCentres.Kinds.data();
  const std::vector<double> flatDeformed = DeformWithDGMF(flatProblem);
  for (std::size_t c = 0; c < 2; ++c)
  {
    EXPECT_EQ(deformed[3 * (2 * m + c)], flatDeformed[3 * (m + c)]);
    EXPECT_EQ(deformed[3 * (2 * m + c) + 1], flatDeformed[3 * (m + c) + 1]);
    EXPECT_EQ(deformed[3 * (2 * m + c) + 2], 0.125);
    EXPECT_NE(deformed[3 * (2 * m + c)], layered.Points[3 * (2 * m + c)]);
  }

  // Two cells thick: a middle plane of nodes above the others' is a layer, not inner nodes.
  dgmf_test::NodeSet thick;
  thick.Dimension = 3;
  for (double z : { 0.1, 0.125, 0.15 })
  {
    for (std::size_t i = 0; i < flat.Size(); ++i)
    {
      thick.Add(flat.Points[3 * i], flat.Points[3 * i + 1], z, flat.Kinds[i]);
    }
  }
  EXPECT_FALSE(dgmf::FindExtrudedLayers(thick.Points.data(), thick.Size()).Found());
}
