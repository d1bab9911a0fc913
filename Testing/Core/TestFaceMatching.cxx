// The core's face matching: internal faces (two cells) and boundary faces (one cell), the same
// with one and two threads, faces of more than 4 points compared point by point, bad ids refused.
// The faces' parity: a mesh closed by its boundary patches, told from one that is not.
#include "dgmf/CellFaces.h"
#include "dgmf/FaceMatching.h"
#include "dgmf/FaceParity.h"
#include "dgmf/NonOrthogonality.h"
#include "dgmf/SizeSkewQuality.h"

#include "TwoThreadFor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace
{
/// Cells given by their face streams (any faces, any number of points per face).
class StreamCells : public dgmf::FaceCells
{
public:
  std::vector<std::vector<std::int64_t>> Streams;

  std::size_t GetNumberOfCells() const override { return this->Streams.size(); }
  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override
  {
    stream = this->Streams[cell];
  }
  void AddHexahedron(const std::vector<std::int64_t>& corners)
  {
    const std::int64_t* local = dgmf::GetShapeFaceStream(dgmf::CellShape::Hexahedron);
    std::vector<std::int64_t> stream(local, local + dgmf::FaceStreamLength(local));
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        stream[at + 1 + k] = corners[local[at + 1 + k]];
      }
    }
    this->Streams.push_back(stream);
  }
};

/// An n x n x n block of hexahedra, cells numbered along x, then y, then z.
StreamCells Block(int n)
{
  StreamCells cells;
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        cells.AddHexahedron({ id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) });
      }
    }
  }
  return cells;
}
} // namespace

TEST(FaceMatching, ABlockOfHexahedraHasItsInnerFacesOnceAndItsOuterFacesAsBoundary)
{
  const int n = 6;
  const StreamCells cells = Block(n);
  const std::size_t points = static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1));
  const dgmf::InternalFaces inner = dgmf::FindInternalFaces(cells, points, dgmf::SerialFor);
  const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(cells, points, dgmf::SerialFor);
  EXPECT_EQ(inner.Size(), static_cast<std::size_t>(3 * n * n * (n - 1)));
  EXPECT_EQ(outer.Size(), static_cast<std::size_t>(6 * n * n));
  // Each cell's 6 faces: inside (as owner or neighbour) or on the boundary, exactly once.
  std::vector<int> uses(cells.GetNumberOfCells(), 0);
  for (std::size_t f = 0; f < inner.Size(); ++f)
  {
    EXPECT_LT(inner.Owner[f], inner.Neighbour[f]);
    ++uses[static_cast<std::size_t>(inner.Owner[f])];
    ++uses[static_cast<std::size_t>(inner.Neighbour[f])];
    if (f > 0) // by owner, then by face
    {
      EXPECT_TRUE(inner.Owner[f - 1] < inner.Owner[f] ||
        (inner.Owner[f - 1] == inner.Owner[f] && inner.Face[f - 1] < inner.Face[f]));
    }
  }
  for (std::size_t f = 0; f < outer.Size(); ++f)
  {
    ++uses[static_cast<std::size_t>(outer.Cell[f])];
  }
  for (std::size_t c = 0; c < uses.size(); ++c)
  {
    EXPECT_EQ(uses[c], 6) << "cell " << c;
  }
  // The x-neighbour of cell 0 shares its face 1 (+x) with its face 0 (-x).
  EXPECT_EQ(inner.Owner[0], 0);
  EXPECT_EQ(inner.Face[0], 1);
  EXPECT_EQ(inner.Neighbour[0], 1);
}

TEST(FaceMatching, TheSameFacesWithOneAndTwoThreads)
{
  const StreamCells cells = Block(20);
  const std::size_t points = 21 * 21 * 21;
  const dgmf::InternalFaces one = dgmf::FindInternalFaces(cells, points, dgmf::SerialFor);
  const dgmf::InternalFaces two = dgmf::FindInternalFaces(cells, points, dgmf_test::TwoThreadFor);
  EXPECT_EQ(one.Owner, two.Owner);
  EXPECT_EQ(one.Neighbour, two.Neighbour);
  EXPECT_EQ(one.Face, two.Face);
  const dgmf::BoundaryFaces outerOne = dgmf::FindBoundaryFaces(cells, points, dgmf::SerialFor);
  const dgmf::BoundaryFaces outerTwo =
    dgmf::FindBoundaryFaces(cells, points, dgmf_test::TwoThreadFor);
  EXPECT_EQ(outerOne.Cell, outerTwo.Cell);
  EXPECT_EQ(outerOne.Face, outerTwo.Face);
}

TEST(FaceMatching, ShuffledIdsInManyGroupsGiveTheFacesAMapOfSortedPointsGives)
{
  // 9,261 points and 8,000 cells, both numbered at random: the faces' buckets fall in groups of
  // several points and the owners in groups of several cells, in no order. The matching must give
  // what a map from each face's sorted points to its cells gives.
  const int n = 20;
  const std::size_t points = (n + 1) * (n + 1) * (n + 1);
  const StreamCells block = Block(n);
  std::vector<std::int64_t> newPoint(points);
  std::iota(newPoint.begin(), newPoint.end(), std::int64_t{ 0 });
  std::shuffle(newPoint.begin(), newPoint.end(), std::mt19937(5));
  std::vector<std::size_t> oldCell(block.Streams.size());
  std::iota(oldCell.begin(), oldCell.end(), std::size_t{ 0 });
  std::shuffle(oldCell.begin(), oldCell.end(), std::mt19937(6));
  StreamCells cells;
  for (const std::size_t c : oldCell)
  {
    std::vector<std::int64_t> stream = block.Streams[c];
    for (std::int64_t f = 0, at = 1; f < stream[0]; ++f, at += 1 + stream[at])
    {
      for (std::int64_t k = 0; k < stream[at]; ++k)
      {
        stream[at + 1 + k] = newPoint[static_cast<std::size_t>(stream[at + 1 + k])];
      }
    }
    cells.Streams.push_back(stream);
  }
  // The map: sorted points -> (cell, face) in cell order.
  std::map<std::vector<std::int64_t>, std::vector<std::pair<std::int64_t, std::int32_t>>> byPoints;
  for (std::size_t c = 0; c < cells.Streams.size(); ++c)
  {
    const std::vector<std::int64_t>& stream = cells.Streams[c];
    for (std::int64_t f = 0, at = 1; f < stream[0]; ++f, at += 1 + stream[at])
    {
      std::vector<std::int64_t> face(stream.begin() + at + 1, stream.begin() + at + 1 + stream[at]);
      std::sort(face.begin(), face.end());
      byPoints[face].emplace_back(static_cast<std::int64_t>(c), static_cast<std::int32_t>(f));
    }
  }
  std::vector<std::tuple<std::int64_t, std::int32_t, std::int64_t>> expectedInner;
  std::vector<std::pair<std::int64_t, std::int32_t>> expectedOuter;
  for (const auto& entry : byPoints)
  {
    ASSERT_LE(entry.second.size(), 2u);
    if (entry.second.size() == 2)
    {
      expectedInner.emplace_back(
        entry.second[0].first, entry.second[0].second, entry.second[1].first);
    }
    else
    {
      expectedOuter.push_back(entry.second[0]);
    }
  }
  std::sort(expectedInner.begin(), expectedInner.end());
  std::sort(expectedOuter.begin(), expectedOuter.end());
  ASSERT_EQ(expectedInner.size(), static_cast<std::size_t>(3 * n * n * (n - 1)));
  for (const dgmf::ParallelFor& parallelFor :
    { dgmf::ParallelFor(dgmf::SerialFor), dgmf::ParallelFor(dgmf_test::TwoThreadFor) })
  {
    const dgmf::InternalFaces inner = dgmf::FindInternalFaces(cells, points, parallelFor);
    std::vector<std::tuple<std::int64_t, std::int32_t, std::int64_t>> found;
    for (std::size_t f = 0; f < inner.Size(); ++f)
    {
      found.emplace_back(inner.Owner[f], inner.Face[f], inner.Neighbour[f]);
    }
    EXPECT_EQ(found, expectedInner); // in this order: by owner, then by face
    const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(cells, points, parallelFor);
    std::vector<std::pair<std::int64_t, std::int32_t>> foundOuter;
    for (std::size_t f = 0; f < outer.Size(); ++f)
    {
      foundOuter.emplace_back(outer.Cell[f], outer.Face[f]);
    }
    EXPECT_EQ(foundOuter, expectedOuter);
  }
}

TEST(FaceMatching, FacesOfMoreThanFourPointsArePairedOnlyWhenAllTheirPointsAgree)
{
  // Three one-face "cells": hexagons 0-5, the same hexagon listed the other way round, and a
  // hexagon with the same three smallest ids but other points.
  StreamCells cells;
  cells.Streams.push_back({ 1, 6, 0, 1, 2, 3, 4, 5 });
  cells.Streams.push_back({ 1, 6, 5, 4, 3, 2, 1, 0 });
  cells.Streams.push_back({ 1, 6, 0, 1, 2, 6, 7, 8 });
  const dgmf::InternalFaces inner = dgmf::FindInternalFaces(cells, 9, dgmf_test::TwoThreadFor);
  ASSERT_EQ(inner.Size(), 1u);
  EXPECT_EQ(inner.Owner[0], 0);
  EXPECT_EQ(inner.Neighbour[0], 1);
  const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(cells, 9, dgmf_test::TwoThreadFor);
  ASSERT_EQ(outer.Size(), 1u);
  EXPECT_EQ(outer.Cell[0], 2);
}

TEST(FaceMatching, TrianglesAndQuadrilateralsOnTheSamePointsAreDifferentFaces)
{
  StreamCells cells;
  cells.Streams.push_back({ 1, 4, 0, 1, 2, 3 });
  cells.Streams.push_back({ 1, 3, 0, 1, 2 });
  cells.Streams.push_back({ 1, 3, 2, 1, 0 });
  const dgmf::InternalFaces inner = dgmf::FindInternalFaces(cells, 4, dgmf::SerialFor);
  ASSERT_EQ(inner.Size(), 1u);
  EXPECT_EQ(inner.Owner[0], 1);
  EXPECT_EQ(inner.Neighbour[0], 2);
  const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(cells, 4, dgmf::SerialFor);
  ASSERT_EQ(outer.Size(), 1u);
  EXPECT_EQ(outer.Cell[0], 0);
}

TEST(FaceMatching, AFaceOfThreeCellsPairsTheFirstTwoAndLeavesTheThird)
{
  StreamCells cells;
  for (int c = 0; c < 3; ++c)
  {
    cells.Streams.push_back({ 1, 3, 0, 1, 2 });
  }
  const dgmf::InternalFaces inner = dgmf::FindInternalFaces(cells, 3, dgmf::SerialFor);
  ASSERT_EQ(inner.Size(), 1u);
  EXPECT_EQ(inner.Owner[0], 0);
  EXPECT_EQ(inner.Neighbour[0], 1);
  const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(cells, 3, dgmf::SerialFor);
  ASSERT_EQ(outer.Size(), 1u);
  EXPECT_EQ(outer.Cell[0], 2);
}

TEST(FaceMatching, PointIdsOutsideTheMeshAreRefusedWithTheCellNamed)
{
  StreamCells cells;
  cells.Streams.push_back({ 1, 3, 0, 1, 2 });
  cells.Streams.push_back({ 1, 3, 0, 1, 7 });
  try
  {
    dgmf::FindBoundaryFaces(cells, 3, dgmf::SerialFor);
    FAIL() << "an id outside the points was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("Cell 1 uses point id 7"), std::string::npos) << e.what();
  }
}

namespace
{
/// `cells` and their boundary faces as one-face cells (boundary patches), the faces' points as the
/// cells give them or `reversed` (the other way round, from another point).
StreamCells WithPatches(const StreamCells& cells, std::size_t points, bool reversed)
{
  StreamCells closed = cells;
  const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(cells, points, dgmf::SerialFor);
  for (std::size_t f = 0; f < outer.Size(); ++f)
  {
    std::int64_t count = 0;
    const std::vector<std::int64_t>& stream =
      cells.Streams[static_cast<std::size_t>(outer.Cell[f])];
    const std::int64_t* ids = dgmf::FaceOfStream(stream.data(), outer.Face[f], count);
    std::vector<std::int64_t> patch{ 1, count };
    patch.insert(patch.end(), ids, ids + count);
    if (reversed) // another starting point and the other way round: the same face
    {
      std::reverse(patch.begin() + 2, patch.end());
      std::rotate(patch.begin() + 2, patch.begin() + 3, patch.end());
    }
    closed.Streams.push_back(patch);
  }
  return closed;
}
} // namespace

TEST(FaceParity, ABlockPairsUpOnlyWhenItsBoundaryPatchesCoverItsBoundaryExactly)
{
  const int n = 5;
  const std::size_t points = static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1));
  const StreamCells block = Block(n);
  EXPECT_FALSE(dgmf::FacesPairUp(block, points, dgmf::SerialFor)) << "the open block";
  for (bool reversed : { false, true })
  {
    StreamCells closed = WithPatches(block, points, reversed);
    ASSERT_EQ(closed.Streams.size(), block.Streams.size() + 6 * n * n);
    EXPECT_TRUE(dgmf::FacesPairUp(closed, points, dgmf::SerialFor)) << "reversed " << reversed;
    EXPECT_TRUE(dgmf::FacesPairUp(closed, points, dgmf_test::TwoThreadFor))
      << "reversed " << reversed;
    const std::vector<std::int64_t> last = closed.Streams.back();
    closed.Streams.pop_back(); // a boundary face without its patch
    EXPECT_FALSE(dgmf::FacesPairUp(closed, points, dgmf::SerialFor));
    closed.Streams.push_back(last);
    closed.Streams.push_back(last); // a patch given twice: three faces there
    EXPECT_FALSE(dgmf::FacesPairUp(closed, points, dgmf::SerialFor));
    closed.Streams.pop_back();
    closed.Streams.back()[2] += 1; // a patch on other points
    EXPECT_FALSE(dgmf::FacesPairUp(closed, points, dgmf::SerialFor));
  }
}

TEST(FaceParity, TheSameAnswerWhenTheCellsSpanSeveralBlocksOnTwoThreads)
{
  // 27^3 = 19,683 hexahedra and their patches: more cells than one block of the pass.
  const int n = 27;
  const std::size_t points = static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1));
  StreamCells closed = WithPatches(Block(n), points, true);
  EXPECT_TRUE(dgmf::FacesPairUp(closed, points, dgmf::SerialFor));
  EXPECT_TRUE(dgmf::FacesPairUp(closed, points, dgmf_test::TwoThreadFor));
  std::swap(closed.Streams.front(), closed.Streams.back()); // a patch in the first block
  closed.Streams.pop_back(); // and a hexahedron fewer in the last: its 6 faces unpaired
  EXPECT_FALSE(dgmf::FacesPairUp(closed, points, dgmf::SerialFor));
  EXPECT_FALSE(dgmf::FacesPairUp(closed, points, dgmf_test::TwoThreadFor));
}

TEST(FaceParity, FacesPairOnlyWithTheSameSetOfPoints)
{
  StreamCells cells;
  cells.Streams.push_back({ 1, 6, 0, 1, 2, 3, 4, 5 });
  cells.Streams.push_back({ 1, 6, 3, 2, 1, 0, 5, 4 });
  EXPECT_TRUE(dgmf::FacesPairUp(cells, 9, dgmf::SerialFor)) << "one hexagon, two ways round";
  cells.Streams.back() = { 1, 6, 0, 1, 2, 6, 7, 8 };
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 9, dgmf::SerialFor)) << "hexagons on other points";
  cells.Streams = { { 1, 4, 0, 1, 2, 3 }, { 1, 3, 0, 1, 2 } };
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 9, dgmf::SerialFor)) << "a quad and a triangle";
  cells.Streams = { { 0 }, { 1, 3, 0, 1, 2 }, { 0 }, { 1, 3, 2, 0, 1 } };
  EXPECT_TRUE(dgmf::FacesPairUp(cells, 9, dgmf::SerialFor)) << "cells without faces take no part";
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 2, dgmf::SerialFor)) << "point id 2 outside the points";
}

TEST(FaceParity, ACellWithTwoFacesOfTheSamePointsIsNotClosed)
{
  // The face matching counts both faces of such a (collapsed) cell as boundary faces.
  StreamCells cells;
  cells.Streams.push_back({ 2, 3, 0, 1, 2, 3, 2, 1, 0 });
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 9, dgmf::SerialFor));
  EXPECT_EQ(dgmf::FindBoundaryFaces(cells, 3, dgmf::SerialFor).Size(), 2u);
}

namespace
{
/**
 * The same cells as StreamCells, the first ones also given as runs of one shape whose corners
 * follow one another (FaceCells::GetCornerRun), at most `RunLength` cells a run: the faces' parity
 * must not depend on which way it reads them.
 */
class RunCells : public StreamCells
{
public:
  dgmf::CellShape Shape = dgmf::CellShape::Hexahedron;
  std::vector<std::int64_t> Corners; ///< the run cells' corners, cell after cell
  std::size_t RunLength = 1000;

  /// A cell of `Shape` with these corners, in the runs and as a stream.
  void Add(const std::vector<std::int64_t>& corners)
  {
    const std::int64_t* local = dgmf::GetShapeFaceStream(this->Shape);
    std::vector<std::int64_t> stream(local, local + dgmf::FaceStreamLength(local));
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        stream[at + 1 + k] = corners[static_cast<std::size_t>(local[at + 1 + k])];
      }
    }
    this->Streams.push_back(stream);
    this->Corners.insert(this->Corners.end(), corners.begin(), corners.end());
  }

  const std::int64_t* GetCornerRun(std::size_t cell, std::size_t maxCells, const void*& ids,
    std::size_t& count, int& cornersPerCell) const override
  {
    const int n = dgmf::GetNumberOfCorners(this->Shape);
    const std::size_t cells = this->Corners.size() / static_cast<std::size_t>(n);
    if (cell >= cells)
    {
      return nullptr;
    }
    count = std::min({ maxCells, this->RunLength - cell % this->RunLength, cells - cell });
    ids = this->Corners.data() + static_cast<std::size_t>(n) * cell;
    cornersPerCell = n;
    return dgmf::GetShapeFaceStream(this->Shape);
  }
};

/// An n x n x n block of cubes, each as one hexahedron, two wedges or six tetrahedra (faces that
/// match across the cubes), in runs.
RunCells RunBlock(int n, dgmf::CellShape shape)
{
  RunCells cells;
  cells.Shape = shape;
  const auto id = [n](int i, int j, int k) -> std::int64_t
  { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const std::int64_t c[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        if (shape == dgmf::CellShape::Hexahedron)
        {
          cells.Add({ c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7] });
        }
        else if (shape == dgmf::CellShape::Wedge)
        {
          cells.Add({ c[0], c[1], c[2], c[4], c[5], c[6] });
          cells.Add({ c[0], c[2], c[3], c[4], c[6], c[7] });
        }
        else // the cube's six tetrahedra around its diagonal 0-6
        {
          for (const auto& t : { std::vector<int>{ 0, 1, 2, 6 }, { 0, 1, 5, 6 }, { 0, 3, 2, 6 },
                 { 0, 3, 7, 6 }, { 0, 4, 5, 6 }, { 0, 4, 7, 6 } })
          {
            cells.Add({ c[t[0]], c[t[1]], c[t[2]], c[t[3]] });
          }
        }
      }
    }
  }
  return cells;
}
} // namespace

TEST(FaceParity, RunsOfOneShapeGiveTheAnswerOfTheCellByCellReading)
{
  // Hexahedra and tetrahedra (their sizes fixed at compile time) and wedges (any shape), in runs
  // that cross the pass's blocks of cells, on one and two threads.
  for (const dgmf::CellShape shape :
    { dgmf::CellShape::Hexahedron, dgmf::CellShape::Wedge, dgmf::CellShape::Tetra })
  {
    const int n = shape == dgmf::CellShape::Hexahedron ? 27 : 16;
    const std::size_t points = static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1));
    const RunCells block = RunBlock(n, shape);
    StreamCells patches = WithPatches(block, points, true);
    RunCells closed = block;
    closed.Streams = patches.Streams; // the cells (as runs too), then their patches
    const auto answers = [&](const RunCells& cells)
    {
      const StreamCells streams = cells; // the same cells, sliced: without runs
      const bool expected = dgmf::FacesPairUp(streams, points, dgmf::SerialFor);
      EXPECT_EQ(dgmf::FacesPairUp(cells, points, dgmf::SerialFor), expected);
      EXPECT_EQ(dgmf::FacesPairUp(cells, points, dgmf_test::TwoThreadFor), expected);
      return expected;
    };
    EXPECT_TRUE(answers(closed)) << "closed, shape " << static_cast<int>(shape);
    EXPECT_FALSE(answers(block)) << "open";
    RunCells changed = closed;
    changed.Streams.pop_back(); // a patch fewer
    EXPECT_FALSE(answers(changed));
    changed = closed;
    // An id out of range in a run (the cells' streams, not read for run cells, do not have it).
    changed.Corners[changed.Corners.size() / 2] = static_cast<std::int64_t>(points);
    EXPECT_FALSE(dgmf::FacesPairUp(changed, points, dgmf::SerialFor));
    EXPECT_FALSE(dgmf::FacesPairUp(changed, points, dgmf_test::TwoThreadFor));
  }
}

TEST(FaceParity, AnIdOutOfRangeInARunIsRefused)
{
  // Two hexahedra on the same 8 points: every face in pairs. With 7 points only, point 7 is out of
  // range: only the range check can make the answer "no".
  RunCells cells;
  cells.Add({ 0, 1, 2, 3, 4, 5, 6, 7 });
  cells.Add({ 0, 1, 2, 3, 4, 5, 6, 7 });
  EXPECT_TRUE(dgmf::FacesPairUp(cells, 8, dgmf::SerialFor));
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 7, dgmf::SerialFor));
  cells.Corners[3] = cells.Corners[11] = -1; // both cells, so their faces still pair
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 8, dgmf::SerialFor));
}

TEST(FaceParity, ACollapsedCellInARunIsNotClosed)
{
  // A hexahedron whose top is its bottom: its two caps are twin faces.
  RunCells cells;
  cells.Add({ 0, 1, 2, 3, 0, 1, 2, 3 });
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 4, dgmf::SerialFor));
  const StreamCells streams = cells; // sliced: without runs
  EXPECT_FALSE(dgmf::FacesPairUp(streams, 4, dgmf::SerialFor));
}

TEST(FaceParity, ACollapsedCellIsNotClosedByPolygonsOnItsOtherFaces)
{
  // The same cell with a polygon on each of its four other faces: every face then occurs twice
  // (the caps with each other), so only the check for twin faces in one cell refuses it.
  RunCells cells;
  cells.Add({ 0, 1, 2, 3, 0, 1, 2, 3 });
  for (const std::vector<std::int64_t>& quad :
    { std::vector<std::int64_t>{ 0, 0, 3, 3 }, { 1, 2, 2, 1 }, { 0, 1, 1, 0 }, { 3, 3, 2, 2 } })
  {
    std::vector<std::int64_t> polygon{ 1, 4 }; // one face of four points
    polygon.insert(polygon.end(), quad.begin(), quad.end());
    cells.Streams.push_back(polygon);
  }
  EXPECT_FALSE(dgmf::FacesPairUp(cells, 4, dgmf::SerialFor));
  const StreamCells streams = cells; // sliced: without runs
  EXPECT_FALSE(dgmf::FacesPairUp(streams, 4, dgmf::SerialFor));
}

// The internal and boundary faces, and OpenFOAM's non-orthogonality (whose cell centres read the
// faces by runs too), are the same when the cells come as runs of one shape as when they come as
// face streams, for hexahedra, wedges and tetrahedra, on one and two threads.
TEST(FaceMatching, RunsOfOneShapeGiveTheFacesOfTheCellByCellReading)
{
  for (const dgmf::CellShape shape :
    { dgmf::CellShape::Hexahedron, dgmf::CellShape::Wedge, dgmf::CellShape::Tetra })
  {
    const int n = 9;
    const std::size_t points = static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1));
    RunCells runs = RunBlock(n, shape);
    runs.RunLength = 37;              // runs that end inside the passes' blocks of cells
    const StreamCells streams = runs; // the same cells, sliced: without runs
    const dgmf::InternalFaces expected = dgmf::FindInternalFaces(streams, points, dgmf::SerialFor);
    ASSERT_GT(expected.Size(), 0u);
    std::vector<double> xyz(3 * points);
    for (std::size_t p = 0; p < points; ++p)
    {
      const double i = static_cast<double>(p % (n + 1)),
                   j = static_cast<double>(p / (n + 1) % (n + 1)),
                   k = static_cast<double>(p / ((n + 1) * (n + 1)));
      // A sheared, bent block: angles that are neither 0 nor the same everywhere.
      xyz[3 * p] = i + 0.3 * j + 0.02 * k * k;
      xyz[3 * p + 1] = j + 0.1 * std::sin(i);
      xyz[3 * p + 2] = k + 0.05 * i * j;
    }
    const dgmf::InputOrientation orientation =
      dgmf::OrientCells(streams, expected, xyz.data(), dgmf::SerialFor);
    const dgmf::NonOrthogonalityResult angles =
      dgmf::ComputeNonOrthogonality(streams, expected, orientation, xyz.data(), dgmf::SerialFor);
    ASSERT_GT(angles.Maximum, 1.0);
    for (const dgmf::ParallelFor& parallelFor :
      { dgmf::ParallelFor(dgmf::SerialFor), dgmf::ParallelFor(dgmf_test::TwoThreadFor) })
    {
      const dgmf::InternalFaces faces = dgmf::FindInternalFaces(runs, points, parallelFor);
      EXPECT_EQ(faces.Owner, expected.Owner);
      EXPECT_EQ(faces.Neighbour, expected.Neighbour);
      EXPECT_EQ(faces.Face, expected.Face);
      const dgmf::BoundaryFaces outer = dgmf::FindBoundaryFaces(runs, points, parallelFor);
      const dgmf::BoundaryFaces expectedOuter =
        dgmf::FindBoundaryFaces(streams, points, dgmf::SerialFor);
      EXPECT_EQ(outer.Cell, expectedOuter.Cell);
      EXPECT_EQ(outer.Face, expectedOuter.Face);
      const dgmf::InputOrientation runOrientation =
        dgmf::OrientCells(runs, faces, xyz.data(), parallelFor);
      EXPECT_EQ(runOrientation.CellSign, orientation.CellSign);
      EXPECT_EQ(runOrientation.InputMaximum, orientation.InputMaximum);
      const dgmf::NonOrthogonalityResult runAngles =
        dgmf::ComputeNonOrthogonality(runs, faces, runOrientation, xyz.data(), parallelFor);
      EXPECT_EQ(runAngles.CellMaximum, angles.CellMaximum); // the same bits
      EXPECT_EQ(runAngles.Maximum, angles.Maximum);
    }
  }
}
