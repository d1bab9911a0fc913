// Tests of the quality judged through faces: the size-skew of polyhedra, polygons and cells
// invalid in the input (DecomposedSizeSkew), and OpenFOAM's face non-orthogonality
// (NonOrthogonality), on cells whose answers are known by hand.
#include "dgmf/CellFaces.h"
#include "dgmf/DecomposedSizeSkew.h"
#include "dgmf/NonOrthogonality.h"

#include "HexFaceCells.h"
#include "TwoThreadFor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
const double Pi = 3.14159265358979323846;

/// The unit cube, VTK hexahedron corner order.
std::vector<double> Cube(double x0 = 0.0)
{
  return { x0, 0, 0, x0 + 1, 0, 0, x0 + 1, 1, 0, x0, 1, 0, x0, 0, 1, x0 + 1, 0, 1, x0 + 1, 1, 1, x0,
    1, 1 };
}

/// A rigid motion of every point: rotation by `degrees` about z, then a translation.
std::vector<double> Moved(std::vector<double> points, double degrees)
{
  const double c = std::cos(degrees * Pi / 180), s = std::sin(degrees * Pi / 180);
  for (std::size_t k = 0; k < points.size(); k += 3)
  {
    const double x = points[k], y = points[k + 1];
    points[k] = c * x - s * y + 3.0;
    points[k + 1] = s * x + c * y - 2.0;
    points[k + 2] += 0.5;
  }
  return points;
}

dgmf::CellQuality Decomposed(const std::vector<double>& original,
  const std::vector<double>& deformed, const std::int64_t* faces)
{
  return dgmf::ComputeDecomposedSizeSkew(
    static_cast<int>(original.size() / 3), original.data(), deformed.data(), faces);
}

const std::int64_t* HexFaces()
{
  return dgmf::GetShapeFaceStream(dgmf::CellShape::Hexahedron);
}
} // namespace

TEST(DecomposedSizeSkew, AnUnchangedOrRigidlyMovedCellScoresOne)
{
  const std::vector<double> cube = Cube();
  for (double degrees : { 0.0, 30.0, 200.0 })
  {
    const dgmf::CellQuality quality = Decomposed(cube, Moved(cube, degrees), HexFaces());
    EXPECT_NEAR(quality.SizeSkew, 1.0, 1e-12) << degrees;
    EXPECT_FALSE(quality.Inverted);
  }
  // A pentagon (VTK_POLYGON): one face, triangles about its centre.
  const std::vector<double> pentagon = { 0, 0, 0, 2, 0, 0, 2.5, 1, 0, 1, 2, 0, -0.5, 1, 0 };
  const std::int64_t one[] = { 1, 5, 0, 1, 2, 3, 4 };
  EXPECT_NEAR(Decomposed(pentagon, Moved(pentagon, 75.0), one).SizeSkew, 1.0, 1e-12);
}

TEST(DecomposedSizeSkew, SquashingHalvesTheScoreAndTurningACornerInsideOutInverts)
{
  const std::vector<double> cube = Cube();
  std::vector<double> squashed = cube;
  for (std::size_t k = 2; k < squashed.size(); k += 3)
  {
    squashed[k] *= 0.5;
  }
  const dgmf::CellQuality half = Decomposed(cube, squashed, HexFaces());
  EXPECT_LE(half.SizeSkew, 0.5 + 1e-12); // every piece's volume halves
  EXPECT_GT(half.SizeSkew, 0.2);
  EXPECT_FALSE(half.Inverted);
  std::vector<double> through = cube;
  through[3 * 6 + 2] = -1.0; // corner 6 pushed through the bottom face
  const dgmf::CellQuality inverted = Decomposed(cube, through, HexFaces());
  EXPECT_TRUE(inverted.Inverted);
  EXPECT_EQ(inverted.SizeSkew, 0.0);
  // A mirrored pentagon is inverted.
  const std::vector<double> pentagon = { 0, 0, 0, 2, 0, 0, 2.5, 1, 0, 1, 2, 0, -0.5, 1, 0 };
  std::vector<double> mirrored = pentagon;
  for (std::size_t k = 0; k < mirrored.size(); k += 3)
  {
    mirrored[k] = -mirrored[k];
  }
  const std::int64_t one[] = { 1, 5, 0, 1, 2, 3, 4 };
  EXPECT_TRUE(Decomposed(pentagon, mirrored, one).Inverted);
}

TEST(DecomposedSizeSkew, ANonConvexInputCellIsJudgedByWhatTheDeformationDoes)
{
  // A hexahedron with its top corner 6 pushed down below the mid-plane: a corner Jacobian is
  // negative, so the corner metric calls it inverted before any motion; OpenFOAM accepts it.
  std::vector<double> dented = Cube();
  dented[3 * 6 + 2] = 0.3;
  dented[3 * 6 + 0] = 0.6;
  dented[3 * 6 + 1] = 0.6;
  ASSERT_TRUE(
    dgmf::ComputeSizeSkew(dgmf::CellShape::Hexahedron, dented.data(), dented.data()).InputInvalid);
  const dgmf::CellQuality corners =
    dgmf::ComputeSizeSkew(dgmf::CellShape::Hexahedron, dented.data(), dented.data());
  EXPECT_TRUE(corners.InputInvalid); // no corner metric: not called inverted, score 0
  EXPECT_FALSE(corners.Inverted);
  EXPECT_EQ(corners.SizeSkew, 0.0);
  // The metric the filters and the guard use judges it through its faces.
  const dgmf::CellQuality judged = dgmf::ComputeCellSizeSkew(
    dgmf::CellShape::Hexahedron, dented.data(), Moved(dented, 10.0).data());
  EXPECT_TRUE(judged.InputInvalid);
  EXPECT_NEAR(judged.SizeSkew, 1.0, 1e-12);
  EXPECT_FALSE(
    dgmf::ComputeSizeSkew(dgmf::CellShape::Hexahedron, Cube().data(), Cube().data()).InputInvalid);
  // Unchanged or moved rigidly: valid, score 1.
  const dgmf::CellQuality same = Decomposed(dented, Moved(dented, 40.0), HexFaces());
  EXPECT_FALSE(same.Inverted);
  EXPECT_NEAR(same.SizeSkew, 1.0, 1e-12);
  // The dent pushed through the bottom face: inverted by the deformation.
  std::vector<double> through = dented;
  through[3 * 6 + 2] = -0.5;
  EXPECT_TRUE(Decomposed(dented, through, HexFaces()).Inverted);
}

namespace
{
using HexCells = dgmf_test::HexFaceCells;

/// Two unit cubes side by side along x (12 points), sharing the face x = 1.
HexCells TwoCubes(std::vector<double>& points)
{
  points.clear();
  for (double x : { 0.0, 1.0, 2.0 })
  {
    for (double z : { 0.0, 1.0 })
    {
      for (double y : { 0.0, 1.0 })
      {
        points.insert(points.end(), { x, y, z });
      }
    }
  }
  // Point (i, y, z) is 4 i + 2 z + y.
  const auto id = [](int i, int y, int z) { return static_cast<std::int64_t>(4 * i + 2 * z + y); };
  HexCells cells;
  for (int i = 0; i < 2; ++i)
  {
    cells.Corners.push_back({ id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0),
      id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1) });
  }
  return cells;
}
} // namespace

TEST(NonOrthogonality, TheSharedFaceIsFoundAndTheAnglesAreCheckMeshs)
{
  std::vector<double> points;
  HexCells cells = TwoCubes(points);
  const dgmf::InternalFaces faces = dgmf::FindInternalFaces(cells, 12, dgmf_test::TwoThreadFor);
  ASSERT_EQ(faces.Size(), 1u);
  EXPECT_EQ(faces.Owner[0], 0);
  EXPECT_EQ(faces.Neighbour[0], 1);
  const dgmf::InputOrientation orientation =
    dgmf::OrientCells(cells, faces, points.data(), dgmf_test::TwoThreadFor);
  EXPECT_NEAR(orientation.InputMaximum, 0.0, 1e-12);
  EXPECT_NEAR(
    dgmf::ComputeNonOrthogonality(cells, faces, orientation, points.data(), dgmf_test::TwoThreadFor)
      .Maximum,
    0.0, 1e-12);

  // The second cube sheared into a parallelepiped: its outer face moved by t along y. Its centre
  // moves by t/2: the angle is atan(t / 2) (45 degrees for t = 2).
  for (double t : { 1.0, 2.0 })
  {
    std::vector<double> sheared = points;
    for (std::size_t p = 8; p < 12; ++p)
    {
      sheared[3 * p + 1] += t;
    }
    const dgmf::NonOrthogonalityResult result = dgmf::ComputeNonOrthogonality(
      cells, faces, orientation, sheared.data(), dgmf_test::TwoThreadFor);
    EXPECT_NEAR(result.Maximum, std::atan(t / 2) * 180 / Pi, 1e-10) << t;
    EXPECT_EQ(result.CellMaximum[0], result.Maximum);
    EXPECT_EQ(result.CellMaximum[1], result.Maximum);
  }
  // The outer face pulled back behind the shared one: the neighbour's centre is behind the face,
  // 180 degrees (checkMesh's "non-orthogonality errors").
  std::vector<double> folded = points;
  for (std::size_t p = 8; p < 12; ++p)
  {
    folded[3 * p] = -0.5;
  }
  EXPECT_NEAR(
    dgmf::ComputeNonOrthogonality(cells, faces, orientation, folded.data(), dgmf_test::TwoThreadFor)
      .Maximum,
    180.0, 1e-9);

  // A cell listed inside out (its faces turn inwards) has the same angles: the orientation is
  // the input's.
  HexCells mirrored = cells;
  auto& c = mirrored.Corners[1];
  c = { c[4], c[5], c[6], c[7], c[0], c[1], c[2], c[3] };
  const dgmf::InternalFaces mirroredFaces =
    dgmf::FindInternalFaces(mirrored, 12, dgmf_test::TwoThreadFor);
  ASSERT_EQ(mirroredFaces.Size(), 1u);
  const dgmf::InputOrientation mirroredOrientation =
    dgmf::OrientCells(mirrored, mirroredFaces, points.data(), dgmf_test::TwoThreadFor);
  EXPECT_EQ(mirroredOrientation.CellSign[1], -1);
  EXPECT_EQ(mirroredOrientation.CellSign[0], 1);
  std::vector<double> sheared = points;
  for (std::size_t p = 8; p < 12; ++p)
  {
    sheared[3 * p + 1] += 2.0;
  }
  EXPECT_NEAR(dgmf::ComputeNonOrthogonality(mirrored, mirroredFaces, mirroredOrientation,
                sheared.data(), dgmf_test::TwoThreadFor)
                .Maximum,
    45.0, 1e-10);
}
