// DGM and DGRBF: the comparison methods that share DGMF's Delaunay graph.
#include "SyntheticNodes.h"
#include "TwoThreadFor.h"

#include "dgmf/BoundaryMotion.h"
#include "dgmf/DGMDeformation.h"
#include "dgmf/DGRBFDeformation.h"
#include "dgmf/DelaunayMapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

namespace
{
enum class GraphMethod
{
  DGM,
  DGRBF
};

std::vector<double> RunMethod(GraphMethod method, const dgmf_test::NodeSet& set,
  const dgmf::BoundaryMotion& boundary, std::size_t* inverted = nullptr,
  const dgmf::ParallelFor& parallelFor = dgmf::SerialFor)
{
  dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), parallelFor);
  std::vector<double> deformed(set.Points.size());
  if (method == GraphMethod::DGM)
  {
    const std::size_t count =
      dgmf::DeformDGM(mapping, boundary, set.Points.data(), deformed.data(), parallelFor);
    if (inverted)
      *inverted = count;
  }
  else
  {
    dgmf::DeformDGRBF(mapping, boundary, 0.0, set.Points.data(), deformed.data(), parallelFor);
  }
  return deformed;
}

/// Boundary motion from a field: every boundary node displaced by field(x).
template <typename Field>
dgmf::BoundaryMotion MotionFromField(const dgmf_test::NodeSet& set, Field field)
{
  dgmf::RigidMotion none;
  dgmf::BoundaryMotion boundary = dgmf::GatherBoundaryMotion(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), none, nullptr);
  for (std::size_t b = 0; b < boundary.Size(); ++b)
  {
    field(boundary.Positions.data() + 3 * b, boundary.Displacements.data() + 3 * b);
  }
  return boundary;
}

using dgmf_test::TwoThreadFor;
} // namespace

TEST(GraphMethods, BoundaryReproducedAndTranslationExact)
{
  for (const dgmf_test::NodeSet& set : { dgmf_test::CircleInSquare(), dgmf_test::SphereInBox() })
  {
    for (GraphMethod method : { GraphMethod::DGM, GraphMethod::DGRBF })
    {
      const dgmf::BoundaryMotion translation = MotionFromField(set,
        [&](const double*, double* d)
        {
          d[0] = 0.7;
          d[1] = -0.3;
          d[2] = set.Dimension == 3 ? 0.2 : 0.0;
        });
      const std::vector<double> moved = RunMethod(method, set, translation);
      for (std::size_t i = 0; i < set.Size(); ++i)
      {
        EXPECT_NEAR(moved[3 * i], set.Points[3 * i] + 0.7, 1e-12);
        EXPECT_NEAR(moved[3 * i + 1], set.Points[3 * i + 1] - 0.3, 1e-12);
      }
      // A boundary field that is not linear: boundary nodes still get exactly their value.
      const dgmf::BoundaryMotion wavy = MotionFromField(set,
        [](const double* x, double* d)
        {
          d[0] = 0.1 * std::sin(x[1]);
          d[1] = 0.05 * x[0] * x[0];
        });
      const std::vector<double> result = RunMethod(method, set, wavy);
      for (std::size_t b = 0; b < wavy.Size(); ++b)
      {
        const std::size_t node = static_cast<std::size_t>(wavy.Nodes[b]);
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_EQ(result[3 * node + c], set.Points[3 * node + c] + wavy.Displacements[3 * b + c]);
        }
      }
    }
  }
}

TEST(GraphMethods, DGMReproducesAnAffineMotion)
{
  // Barycentric coordinates reproduce linear functions: an affine boundary motion moves every
  // interior node by the same affine map.
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox();
  auto field = [](const double* x, double* d)
  {
    d[0] = 0.01 * x[0] + 0.02 * x[1] - 0.01 * x[2] + 0.1;
    d[1] = -0.03 * x[0] + 0.01 * x[2];
    d[2] = 0.02 * x[1] + 0.2;
  };
  const std::vector<double> moved = RunMethod(GraphMethod::DGM, set, MotionFromField(set, field));
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    double d[3];
    field(set.Points.data() + 3 * i, d);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(moved[3 * i + c], set.Points[3 * i + c] + d[c], 1e-12) << "node " << i;
    }
  }
}

TEST(GraphMethods, DGMReportsInvertedGraphElementsForALargeRotation)
{
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::RigidMotion rotation;
  rotation.AnglesDegrees[2] = 90.0;
  const dgmf::BoundaryMotion boundary = dgmf::GatherBoundaryMotion(
    2, set.Points.data(), set.Size(), set.Kinds.data(), rotation, nullptr);
  std::size_t inverted = 0;
  RunMethod(GraphMethod::DGM, set, boundary, &inverted);
  EXPECT_GT(inverted, 0u);
  rotation.AnglesDegrees[2] = 1.0;
  const dgmf::BoundaryMotion small = dgmf::GatherBoundaryMotion(
    2, set.Points.data(), set.Size(), set.Kinds.data(), rotation, nullptr);
  RunMethod(GraphMethod::DGM, set, small, &inverted);
  EXPECT_EQ(inverted, 0u);
}

TEST(GraphMethods, DGRBFIsSmoothInsideAnElementAndCloseToDGMForSmallMotions)
{
  // For a small rotation both methods interpolate the same vertex data: they stay close.
  const dgmf_test::NodeSet set = dgmf_test::CircleInSquare();
  dgmf::RigidMotion rotation;
  rotation.AnglesDegrees[2] = 2.0;
  const dgmf::BoundaryMotion boundary = dgmf::GatherBoundaryMotion(
    2, set.Points.data(), set.Size(), set.Kinds.data(), rotation, nullptr);
  const std::vector<double> dgm = RunMethod(GraphMethod::DGM, set, boundary);
  const std::vector<double> dgrbf = RunMethod(GraphMethod::DGRBF, set, boundary);
  double largest = 0.0;
  for (std::size_t k = 0; k < dgm.size(); ++k)
  {
    largest = std::max(largest, std::abs(dgm[k] - dgrbf[k]));
  }
  // Largest boundary displacement: 2 degrees on the unit circle, about 0.035.
  EXPECT_LT(largest, 0.035);
  EXPECT_GT(largest, 0.0); // they are different methods
}

TEST(GraphMethods, SameBitsWithOneAndTwoThreads)
{
  const dgmf_test::NodeSet set = dgmf_test::SphereInBox(20000);
  dgmf::RigidMotion rotation;
  rotation.AnglesDegrees[0] = 25.0;
  const dgmf::BoundaryMotion boundary = dgmf::GatherBoundaryMotion(
    3, set.Points.data(), set.Size(), set.Kinds.data(), rotation, nullptr);
  for (GraphMethod method : { GraphMethod::DGM, GraphMethod::DGRBF })
  {
    const std::vector<double> serial = RunMethod(method, set, boundary, nullptr, dgmf::SerialFor);
    const std::vector<double> threaded = RunMethod(method, set, boundary, nullptr, TwoThreadFor);
    EXPECT_EQ(std::memcmp(serial.data(), threaded.data(), serial.size() * sizeof(double)), 0);
  }
}
