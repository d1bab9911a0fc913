// The Exodus II reader and writer (ExodusFile.h): files made in the test with the Exodus library
// itself (ParaView's vtkexodusII), read back field by field; write-back; files the reader refuses.
#include "dgmf/meshfile/ExodusFile.h"

#include "ByteMutations.h"
#include "NamedMeshTestHelpers.h"

#include <vtkexodusII/include/exodusII.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace mf = dgmf::meshfile;
namespace fs = std::filesystem;

namespace
{
using Ids = std::vector<std::int64_t>;

fs::path WorkDirectory()
{
  return dgmf_test::WorkDirectory("exodus");
}

/// What the test writes as an Exodus file.
struct ExodusContent
{
  int Dimension = 3;
  int WordSize = 8; // 4: float coordinates
  std::vector<double> X, Y, Z;
  std::string BlockType = "HEX8";
  int NodesPerElement = 8;
  std::vector<std::int64_t> Connectivity; // 1-based
  struct SideSet
  {
    std::int64_t Id;
    std::string Name; // "" : unnamed
    std::vector<std::int64_t> Elements, Sides;
  };
  std::vector<SideSet> SideSets;
  struct NodeSet
  {
    std::int64_t Id;
    std::string Name;
    std::vector<std::int64_t> Nodes;
  };
  std::vector<NodeSet> NodeSets;
  std::vector<std::int64_t> NodeMap; // empty: none
};

void Check(int status, const char* what)
{
  if (status < 0)
  {
    throw std::runtime_error(std::string("the test could not write ") + what);
  }
}

/// Writes `content` with the Exodus library.
void WriteExodus(const fs::path& path, const ExodusContent& c)
{
  int cpu = 8, io = c.WordSize;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  Check(id, "the file");
  ex_set_int64_status(id, EX_ALL_INT64_API);
  ex_init_params p{};
  std::snprintf(p.title, sizeof(p.title), "dgmf test");
  p.num_dim = c.Dimension;
  p.num_nodes = static_cast<std::int64_t>(c.X.size());
  p.num_elem = static_cast<std::int64_t>(c.Connectivity.size()) / c.NodesPerElement;
  p.num_elem_blk = 1;
  p.num_side_sets = static_cast<std::int64_t>(c.SideSets.size());
  p.num_node_sets = static_cast<std::int64_t>(c.NodeSets.size());
  Check(ex_put_init_ext(id, &p), "the header");
  Check(ex_put_coord(id, c.X.data(), c.Y.data(), c.Dimension == 3 ? c.Z.data() : nullptr),
    "the coordinates");
  if (!c.NodeMap.empty())
  {
    Check(ex_put_id_map(id, EX_NODE_MAP, c.NodeMap.data()), "the node map");
  }
  Check(ex_put_block(
          id, EX_ELEM_BLOCK, 10, c.BlockType.c_str(), p.num_elem, c.NodesPerElement, 0, 0, 0),
    "the block");
  Check(ex_put_conn(id, EX_ELEM_BLOCK, 10, c.Connectivity.data(), nullptr, nullptr), "the cells");
  for (const auto& s : c.SideSets)
  {
    Check(ex_put_set_param(id, EX_SIDE_SET, s.Id, static_cast<std::int64_t>(s.Elements.size()), 0),
      "a side set");
    Check(ex_put_set(id, EX_SIDE_SET, s.Id, s.Elements.data(), s.Sides.data()), "a side set");
    if (!s.Name.empty())
    {
      Check(ex_put_name(id, EX_SIDE_SET, s.Id, s.Name.c_str()), "a side set's name");
    }
  }
  for (const auto& s : c.NodeSets)
  {
    Check(ex_put_set_param(id, EX_NODE_SET, s.Id, static_cast<std::int64_t>(s.Nodes.size()), 0),
      "a node set");
    Check(ex_put_set(id, EX_NODE_SET, s.Id, s.Nodes.data(), nullptr), "a node set");
    if (!s.Name.empty())
    {
      Check(ex_put_name(id, EX_NODE_SET, s.Id, s.Name.c_str()), "a node set's name");
    }
  }
  Check(ex_close(id), "the file (closing)");
}

/// Two unit hexahedra along x (nodes 1-12): side set "inlet" on x = 0 (element 1, side 4),
/// an unnamed side set 7 on x = 2 (element 2, side 2), node set "floor" on z = 0.
ExodusContent TwoHexahedra()
{
  ExodusContent c;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
      {
        c.X.push_back(i);
        c.Y.push_back(j);
        c.Z.push_back(k);
      }
  // Node (i, j, k) is 1 + i + 3 j + 6 k.
  const auto node = [](int i, int j, int k) { return std::int64_t{ 1 + i + 3 * j + 6 * k }; };
  for (int e = 0; e < 2; ++e)
  {
    for (int k = 0; k < 2; ++k)
    {
      c.Connectivity.insert(c.Connectivity.end(),
        { node(e, 0, k), node(e + 1, 0, k), node(e + 1, 1, k), node(e, 1, k) });
    }
  }
  c.SideSets.push_back({ 3, "inlet", { 1 }, { 4 } });
  c.SideSets.push_back({ 7, "", { 2 }, { 2 } });
  c.NodeSets.push_back({ 5, "floor",
    { node(0, 0, 0), node(1, 0, 0), node(2, 0, 0), node(0, 1, 0), node(1, 1, 0), node(2, 1, 0) } });
  return c;
}

using dgmf_test::Find;
using dgmf_test::NodesOf;

std::string ErrorOf(const fs::path& path)
{
  return dgmf_test::ErrorOf(mf::ReadExodus, path);
}

/// Two quadrilaterals side by side at z = 0 (nodes 1..6), in a file of `dimension` coordinates.
ExodusContent TwoQuadrilaterals(int dimension)
{
  ExodusContent c;
  c.Dimension = dimension;
  c.BlockType = "QUAD4";
  c.NodesPerElement = 4;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
    {
      c.X.push_back(i);
      c.Y.push_back(j);
    }
  c.Z.assign(c.X.size(), 0.0);
  c.Connectivity = { 1, 2, 5, 4, 2, 3, 6, 5 };
  return c;
}
} // namespace

TEST(ExodusFile, ReadsNodesInFileOrderCellsAndSetsAsNamedBoundaries)
{
  const fs::path file = WorkDirectory() / "hexes.exo";
  const ExodusContent c = TwoHexahedra();
  WriteExodus(file, c);
  const mf::NamedMesh mesh = mf::ReadExodus(file.string());
  EXPECT_EQ(mesh.Dimension, 3);
  ASSERT_EQ(mesh.NumberOfNodes(), 12u);
  for (std::size_t i = 0; i < 12; ++i)
  {
    EXPECT_EQ(mesh.Points[3 * i], c.X[i]);
    EXPECT_EQ(mesh.Points[3 * i + 1], c.Y[i]);
    EXPECT_EQ(mesh.Points[3 * i + 2], c.Z[i]);
    EXPECT_EQ(mesh.NodeIds[i], static_cast<std::int64_t>(i + 1)); // no map: 1..N
  }
  ASSERT_EQ(mesh.Volume.Size(), 2u);
  EXPECT_EQ(mesh.Volume.Types[0], mf::Hexahedron);
  for (std::size_t k = 0; k < c.Connectivity.size(); ++k)
  {
    EXPECT_EQ(mesh.Volume.Connectivity[k], c.Connectivity[k] - 1);
  }
  // The side sets' faces, the unnamed one named by its id as ParaView names it; the node set.
  ASSERT_EQ(mesh.Boundaries.size(), 3u);
  const mf::NamedBoundary* inlet = Find(mesh, "inlet");
  const mf::NamedBoundary* outlet = Find(mesh, "sideset_7");
  const mf::NamedBoundary* floor = Find(mesh, "floor");
  ASSERT_TRUE(inlet && outlet && floor);
  ASSERT_EQ(inlet->Faces.Size(), 1u);
  EXPECT_EQ(inlet->Faces.Types[0], mf::Quad);
  for (std::int64_t n : NodesOf(*inlet))
  {
    EXPECT_EQ(mesh.Points[3 * n], 0.0);
  }
  EXPECT_EQ(NodesOf(*inlet).size(), 4u);
  for (std::int64_t n : NodesOf(*outlet))
  {
    EXPECT_EQ(mesh.Points[3 * n], 2.0);
  }
  EXPECT_EQ(NodesOf(*outlet).size(), 4u);
  EXPECT_EQ(floor->Faces.Size(), 6u);
  EXPECT_TRUE(std::all_of(floor->Faces.Types.begin(), floor->Faces.Types.end(),
    [](std::uint8_t t) { return t == mf::Vertex; }));
  for (std::int64_t n : NodesOf(*floor))
  {
    EXPECT_EQ(mesh.Points[3 * n + 2], 0.0);
  }
}

TEST(ExodusFile, NodeIdsAreTheNodeNumberMap)
{
  const fs::path file = WorkDirectory() / "mapped.exo";
  ExodusContent c = TwoHexahedra();
  for (std::size_t i = 0; i < c.X.size(); ++i)
  {
    c.NodeMap.push_back(100 + 3 * static_cast<std::int64_t>(i));
  }
  WriteExodus(file, c);
  const mf::NamedMesh mesh = mf::ReadExodus(file.string());
  EXPECT_EQ(mesh.NodeIds, c.NodeMap);
}

TEST(ExodusFile, ReadsA2DMeshWithEdgeSideSets)
{
  const fs::path file = WorkDirectory() / "quads.exo";
  ExodusContent c = TwoQuadrilaterals(2);
  c.SideSets.push_back({ 1, "left", { 1 }, { 4 } });
  c.SideSets.push_back({ 2, "bottom", { 1, 2 }, { 1, 1 } });
  WriteExodus(file, c);
  const mf::NamedMesh mesh = mf::ReadExodus(file.string());
  EXPECT_EQ(mesh.Dimension, 2);
  EXPECT_EQ(mesh.Volume.Size(), 2u);
  EXPECT_EQ(mesh.Volume.Types[0], mf::Quad);
  const mf::NamedBoundary* bottom = Find(mesh, "bottom");
  ASSERT_TRUE(bottom);
  EXPECT_EQ(bottom->Faces.Size(), 2u);
  EXPECT_EQ(bottom->Faces.Types[0], mf::Line);
  EXPECT_EQ(NodesOf(*bottom), (std::set<std::int64_t>{ 0, 1, 2 }));
  const mf::NamedBoundary* left = Find(mesh, "left");
  ASSERT_TRUE(left);
  EXPECT_EQ(NodesOf(*left), (std::set<std::int64_t>{ 0, 3 }));
}

TEST(ExodusFile, ANodeSetTwinOfASideSetIsOneBoundary)
{
  // meshio and other writers give a boundary as a side set and a node set of the same name.
  const fs::path file = WorkDirectory() / "twins.exo";
  ExodusContent c = TwoHexahedra();
  c.NodeSets.push_back({ 8, "inlet", { 1, 4, 7, 10 } }); // the inlet's nodes
  c.NodeSets.push_back({ 9, "sideset_7", { 1 } });       // another node under a side set's name
  WriteExodus(file, c);
  const mf::NamedMesh mesh = mf::ReadExodus(file.string());
  ASSERT_EQ(mesh.Boundaries.size(), 4u);
  EXPECT_EQ(Find(mesh, "inlet")->Faces.Types[0], mf::Quad);
  ASSERT_TRUE(Find(mesh, "sideset_7 (node set)"));
  EXPECT_EQ(NodesOf(*Find(mesh, "sideset_7 (node set)")), (std::set<std::int64_t>{ 0 }));
}

TEST(ExodusFile, WritesACopyWithOnlyTheCoordinatesChanged)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "source.exo";
  const fs::path target = directory / "moved.exo";
  const ExodusContent c = TwoHexahedra();
  WriteExodus(source, c);
  const mf::NamedMesh before = mf::ReadExodus(source.string());
  std::vector<double> moved(before.Points);
  for (std::size_t k = 0; k < moved.size(); ++k)
  {
    moved[k] = moved[k] * 1.25 + 0.1 * std::sin(static_cast<double>(k));
  }
  mf::WriteExodusWithPoints(source.string(), target.string(), moved.data(), moved.size() / 3);
  const mf::NamedMesh after = mf::ReadExodus(target.string());
  EXPECT_EQ(after.Points, moved); // double coordinates: bit for bit
  EXPECT_EQ(after.NodeIds, before.NodeIds);
  EXPECT_EQ(after.Volume.Connectivity, before.Volume.Connectivity);
  ASSERT_EQ(after.Boundaries.size(), before.Boundaries.size());
  for (std::size_t b = 0; b < after.Boundaries.size(); ++b)
  {
    EXPECT_EQ(after.Boundaries[b].Name, before.Boundaries[b].Name);
    EXPECT_EQ(after.Boundaries[b].Faces.Connectivity, before.Boundaries[b].Faces.Connectivity);
  }
  // The source is untouched, and nothing is left beside the target.
  EXPECT_EQ(mf::ReadExodus(source.string()).Points, before.Points);
  EXPECT_EQ(std::distance(fs::directory_iterator(directory), fs::directory_iterator()), 2);

  // In place (the target is the source).
  mf::WriteExodusWithPoints(source.string(), source.string(), moved.data(), moved.size() / 3);
  EXPECT_EQ(mf::ReadExodus(source.string()).Points, moved);
}

TEST(ExodusFile, FloatCoordinatesStayFloat)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "float.exo";
  ExodusContent c = TwoHexahedra();
  c.WordSize = 4;
  WriteExodus(source, c);
  std::vector<double> moved = mf::ReadExodus(source.string()).Points;
  moved[0] = 0.1; // not a float
  mf::WriteExodusWithPoints(source.string(), source.string(), moved.data(), moved.size() / 3);
  EXPECT_EQ(mf::ReadExodus(source.string()).Points[0], static_cast<double>(0.1f));
  int cpu = 8, io = 0;
  float version = 0;
  const int id = ex_open(source.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(io, 4);
  ex_close(id);
}

TEST(ExodusFile, A2DMeshInA3DFileIsWrittenWithItsZAndOnlyAtZZero)
{
  // Quadrilaterals in a file of three coordinates: the write moves x and y and keeps the file's
  // z (0); a file whose z is not 0 (which the reader refuses) is not written either.
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "flat.exo";
  const fs::path target = directory / "flat_moved.exo";
  ExodusContent c = TwoQuadrilaterals(3);
  WriteExodus(source, c);
  std::vector<double> moved = mf::ReadExodus(source.string()).Points;
  for (std::size_t k = 0; k < moved.size(); ++k)
  {
    moved[k] = k % 3 == 2 ? 7.0 : moved[k] + 0.25; // a z given is not written in 2D
  }
  mf::WriteExodusWithPoints(source.string(), target.string(), moved.data(), moved.size() / 3);
  const mf::NamedMesh written = mf::ReadExodus(target.string());
  ASSERT_EQ(written.Points.size(), moved.size());
  for (std::size_t k = 0; k < moved.size(); ++k)
  {
    EXPECT_EQ(written.Points[k], k % 3 == 2 ? 0.0 : moved[k]) << k;
  }
  c.Z[4] = 0.5;
  WriteExodus(source, c);
  fs::remove(target);
  EXPECT_THROW(
    mf::WriteExodusWithPoints(source.string(), target.string(), moved.data(), moved.size() / 3),
    mf::FileError);
  EXPECT_FALSE(fs::exists(target));
}

TEST(ExodusFile, AWrongPointCountOrANaNWritesNothing)
{
  const fs::path directory = WorkDirectory();
  const fs::path source = directory / "source.exo";
  const fs::path target = directory / "target.exo";
  WriteExodus(source, TwoHexahedra());
  std::vector<double> points = mf::ReadExodus(source.string()).Points;
  EXPECT_THROW(
    mf::WriteExodusWithPoints(source.string(), target.string(), points.data(), 11), mf::FileError);
  points[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(
    mf::WriteExodusWithPoints(source.string(), target.string(), points.data(), 12), mf::FileError);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(std::distance(fs::directory_iterator(directory), fs::directory_iterator()), 1);
}

TEST(ExodusFile, RefusesWhatItCannotRead)
{
  const fs::path directory = WorkDirectory();
  EXPECT_NE(ErrorOf(directory / "missing.exo").find("missing.exo"), std::string::npos);
  {
    std::ofstream text(directory / "text.exo");
    text << "not an exodus file\n";
  }
  EXPECT_NE(ErrorOf(directory / "text.exo").find("text.exo"), std::string::npos);

  // A second-order element type.
  ExodusContent quadratic = TwoHexahedra();
  quadratic.BlockType = "TETRA10";
  quadratic.NodesPerElement = 8; // 2 elements of 8 nodes, declared quadratic tetrahedra
  WriteExodus(directory / "tetra10.exo", quadratic);
  EXPECT_NE(ErrorOf(directory / "tetra10.exo").find("linear types"), std::string::npos);

  // An element on a node that does not exist.
  ExodusContent outside = TwoHexahedra();
  outside.Connectivity[3] = 13;
  WriteExodus(directory / "outside.exo", outside);
  EXPECT_NE(ErrorOf(directory / "outside.exo").find("node 13"), std::string::npos);

  // A node set holding a node that does not exist.
  ExodusContent badSet = TwoHexahedra();
  badSet.NodeSets[0].Nodes[0] = 40;
  WriteExodus(directory / "badset.exo", badSet);
  EXPECT_NE(ErrorOf(directory / "badset.exo").find("floor"), std::string::npos);

  // A truncated file.
  WriteExodus(directory / "whole.exo", TwoHexahedra());
  fs::copy_file(directory / "whole.exo", directory / "truncated.exo");
  fs::resize_file(directory / "truncated.exo", fs::file_size(directory / "whole.exo") / 2);
  const std::string truncated = ErrorOf(directory / "truncated.exo");
  EXPECT_NE(truncated, "");
  // Said as what it most often is (until 2026-11-30 only "an element uses node 0, outside 1..N").
  EXPECT_NE(truncated.find("is the file cut short?"), std::string::npos) << truncated;
}

TEST(ExodusFile, SeededMutantsReadAsMeshesOrFileErrors)
{
  // Bytes flipped, runs overwritten, the file cut (ByteMutations.h): each mutant reads as a valid
  // mesh (ReadExodus validates it) that writes back, or is a FileError; netCDF's allocations
  // driven by a corrupted header and the Exodus library's crashes stay in the reader's child.
  const fs::path directory = WorkDirectory();
  const fs::path valid = directory / "valid.exo";
  WriteExodus(valid, TwoHexahedra());
  const fs::path mutant = directory / "mutant.exo";
  const fs::path written = directory / "written.exo";
  int meshes = 0, errors = 0;
  dgmf_test::ForEachMutant(valid, mutant, 150, 20261124,
    [&](int k)
    {
      try
      {
        const mf::NamedMesh mesh = mf::ReadExodus(mutant.string());
        mf::WriteExodusWithPoints(
          mutant.string(), written.string(), mesh.Points.data(), mesh.NumberOfNodes());
        EXPECT_EQ(mf::ReadExodus(written.string()).Points, mesh.Points) << k;
        ++meshes;
      }
      catch (const mf::FileError&)
      {
        ++errors;
      }
    });
  EXPECT_EQ(meshes + errors, 150);
  EXPECT_GT(errors, 0);
}
