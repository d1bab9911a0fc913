/**
 * @file SameMesh.h
 * @brief The gmsh readers' tests (TestMshReader41.cxx, TestMshReader22.cxx): two readings of a
 * file compared field by field, and every generated test mesh of one version.
 */
#ifndef dgmf_meshfile_test_SameMesh_h
#define dgmf_meshfile_test_SameMesh_h

#include "GmshTestMeshes.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace dgmf
{
namespace meshfile
{
namespace test
{

inline void ExpectSameCells(const Cells& a, const Cells& b)
{
  EXPECT_EQ(a.Types, b.Types);
  EXPECT_EQ(a.Offsets, b.Offsets);
  EXPECT_EQ(a.Connectivity, b.Connectivity);
}

/// Everything the same: nodes (bit for bit), cells, boundaries in order with their names.
inline void ExpectIdentical(const NamedMesh& a, const NamedMesh& b)
{
  EXPECT_EQ(a.Dimension, b.Dimension);
  EXPECT_EQ(a.NodeIds, b.NodeIds);
  ASSERT_EQ(a.Points.size(), b.Points.size());
  EXPECT_EQ(std::memcmp(a.Points.data(), b.Points.data(), a.Points.size() * sizeof(double)), 0);
  ExpectSameCells(a.Volume, b.Volume);
  ASSERT_EQ(a.Boundaries.size(), b.Boundaries.size());
  for (std::size_t k = 0; k < a.Boundaries.size(); ++k)
  {
    EXPECT_EQ(a.Boundaries[k].Name, b.Boundaries[k].Name);
    ExpectSameCells(a.Boundaries[k].Faces, b.Boundaries[k].Faces);
  }
}

/**
 * Writes each of the 16 test meshes of `version` to `path` (ASCII and binary, with and without
 * SaveAll: the box with a hole, the rectangle with a hole, the same with an entity in two groups,
 * a prism and a pyramid in one entity) and calls `check(binary)` with a trace naming it; returns
 * how many it checked.
 */
template <typename Check>
int ForEachTestMesh(double version, const std::string& path, Check check)
{
  int checked = 0;
  for (bool binary : { false, true })
  {
    for (bool saveAll : { false, true })
    {
      const MshFlavour flavour{ version, binary, saveAll };
      for (int kind = 0; kind < 4; ++kind)
      {
        SCOPED_TRACE(
          std::to_string(kind) + (binary ? " binary" : " ASCII") + (saveAll ? " SaveAll" : ""));
        switch (kind)
        {
          case 0:
            WriteBoxWithHole(path, flavour);
            break;
          case 1:
            WriteRectangleWithHole(path, flavour);
            break;
          case 2:
            WriteRectangleWithHole(path, flavour, true); // an entity in two groups
            break;
          default:
            WritePrismAndPyramid(path, flavour); // two types in one entity
        }
        check(binary);
        ++checked;
      }
    }
  }
  return checked;
}

} // namespace test
} // namespace meshfile
} // namespace dgmf

#endif
