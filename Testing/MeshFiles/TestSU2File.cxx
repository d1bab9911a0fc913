// The SU2 reader and writer (SU2File.h): hand-made files field by field, meshes made by gmsh
// checked against their geometry, write-back, and hostile files.
#include "su2/SU2TestFiles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

using namespace su2test;

namespace
{
using Ids = std::vector<std::int64_t>;
using Types = std::vector<std::uint8_t>;

std::string DataFile(const std::string& name)
{
  return std::string(DGMF_SU2_TEST_DATA) + "/" + name;
}

/// The lines of `text` (split at '\n', the line ends kept out).
std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
  {
    lines.push_back(line);
  }
  return lines;
}

double Cross2(const double* p, const double* a, const double* b)
{
  return (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]);
}

/// The unordered node pairs (2D) or sorted node triples (3D) of a cell's faces.
std::vector<Ids> SortedFaces(const mf::Cells& cells)
{
  std::vector<Ids> faces;
  for (std::size_t c = 0; c < cells.Size(); ++c)
  {
    Ids face(cells.Connectivity.begin() + cells.Offsets[c],
      cells.Connectivity.begin() + cells.Offsets[c + 1]);
    std::sort(face.begin(), face.end());
    faces.push_back(face);
  }
  return faces;
}

/// The faces used by exactly one volume cell: edges of triangles, or triangles of tetrahedra.
std::set<Ids> OpenFaces(const mf::NamedMesh& mesh)
{
  std::map<Ids, int> uses;
  const mf::Cells& v = mesh.Volume;
  for (std::size_t c = 0; c < v.Size(); ++c)
  {
    const std::int64_t* n = v.Connectivity.data() + v.Offsets[c];
    const int size = static_cast<int>(v.Offsets[c + 1] - v.Offsets[c]);
    for (int skip = 0; skip < size; ++skip) // the face opposite node `skip` (simplices only)
    {
      Ids face;
      for (int k = 0; k < size; ++k)
      {
        if (k != skip && (size == 3 || size == 4))
        {
          face.push_back(n[k]);
        }
      }
      std::sort(face.begin(), face.end());
      ++uses[face];
    }
  }
  std::set<Ids> open;
  for (const auto& face : uses)
  {
    if (face.second == 1)
    {
      open.insert(face.first);
    }
  }
  return open;
}

std::set<Ids> MarkedFaces(const mf::NamedMesh& mesh)
{
  std::set<Ids> marked;
  for (const mf::NamedBoundary& boundary : mesh.Boundaries)
  {
    for (const Ids& face : SortedFaces(boundary.Faces))
    {
      EXPECT_TRUE(marked.insert(face).second) << "a face in two markers";
    }
  }
  return marked;
}
} // namespace

TEST(SU2Read, Hand2DFieldByField)
{
  TemporaryFolder folder;
  WriteText(folder.File("hand2d.su2"), Hand2D);
  const mf::NamedMesh mesh = mf::ReadSU2(folder.File("hand2d.su2"));
  EXPECT_EQ(mesh.Dimension, 2);
  EXPECT_EQ(
    mesh.Points, std::vector<double>({ 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0 }));
  EXPECT_EQ(mesh.NodeIds, Ids({ 0, 1, 2, 3, 4, 5 }));
  EXPECT_EQ(mesh.Volume.Types, Types({ mf::Quad, mf::Triangle, mf::Triangle }));
  EXPECT_EQ(mesh.Volume.Offsets, Ids({ 0, 4, 7, 10 }));
  EXPECT_EQ(mesh.Volume.Connectivity, Ids({ 0, 1, 4, 3, 1, 2, 5, 1, 5, 4 }));
  ASSERT_EQ(mesh.Boundaries.size(), 3u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "lower wall");
  EXPECT_EQ(mesh.Boundaries[1].Name, "outlet");
  EXPECT_EQ(mesh.Boundaries[2].Name, "upper & left (#2)");
  EXPECT_EQ(mesh.Boundaries[0].Faces.Connectivity, Ids({ 0, 1, 1, 2 }));
  EXPECT_EQ(mesh.Boundaries[1].Faces.Connectivity, Ids({ 2, 5 }));
  EXPECT_EQ(mesh.Boundaries[2].Faces.Connectivity, Ids({ 5, 4, 4, 3, 3, 0 }));
  EXPECT_EQ(mesh.Boundaries[2].Faces.Types, Types(3, mf::Line));
  EXPECT_EQ(mesh.Boundaries[2].Faces.Offsets, Ids({ 0, 2, 4, 6 }));
}

TEST(SU2Read, Hand3DFieldByField)
{
  TemporaryFolder folder;
  WriteText(folder.File("hand3d.su2"), Hand3D);
  const mf::NamedMesh mesh = mf::ReadSU2(folder.File("hand3d.su2"));
  EXPECT_EQ(mesh.Dimension, 3);
  ASSERT_EQ(mesh.NumberOfNodes(), 12u);
  EXPECT_EQ(std::vector<double>(mesh.Points.begin() + 24, mesh.Points.begin() + 30),
    std::vector<double>({ 0.5, 0.5, 1.5, 2, 0, 0 }));
  EXPECT_EQ(mesh.NodeIds, Ids({ 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 }));
  EXPECT_EQ(mesh.Volume.Types, Types({ mf::Hexahedron, mf::Pyramid, mf::Wedge, mf::Tetra }));
  EXPECT_EQ(mesh.Volume.Offsets, Ids({ 0, 8, 13, 19, 23 }));
  EXPECT_EQ(mesh.Volume.Connectivity,
    Ids({ 0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 7, 8, 1, 9, 2, 5, 10, 6, 9, 11, 2, 10 }));
  ASSERT_EQ(mesh.Boundaries.size(), 2u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "bottom");
  EXPECT_EQ(mesh.Boundaries[0].Faces.Types, Types({ mf::Quad, mf::Triangle, mf::Triangle }));
  EXPECT_EQ(mesh.Boundaries[0].Faces.Connectivity, Ids({ 0, 3, 2, 1, 1, 2, 9, 9, 2, 11 }));
  EXPECT_EQ(mesh.Boundaries[1].Name, "apex");
  EXPECT_EQ(mesh.Boundaries[1].Faces.Offsets, Ids({ 0, 3, 6, 9, 12 }));
  EXPECT_EQ(mesh.Boundaries[1].Faces.Connectivity.back(), 8);
}

TEST(SU2Read, CRLFLineEndsReadTheSame)
{
  TemporaryFolder folder;
  for (const char* text : { Hand2D, Hand3D })
  {
    WriteText(folder.File("lf.su2"), text);
    WriteText(folder.File("crlf.su2"), WithCRLF(text));
    const mf::NamedMesh lf = mf::ReadSU2(folder.File("lf.su2"));
    const mf::NamedMesh crlf = mf::ReadSU2(folder.File("crlf.su2"));
    EXPECT_EQ(lf.Points, crlf.Points);
    EXPECT_EQ(lf.Volume.Connectivity, crlf.Volume.Connectivity);
    ASSERT_EQ(lf.Boundaries.size(), crlf.Boundaries.size());
    for (std::size_t b = 0; b < lf.Boundaries.size(); ++b)
    {
      EXPECT_EQ(lf.Boundaries[b].Name, crlf.Boundaries[b].Name);
      EXPECT_EQ(lf.Boundaries[b].Faces.Connectivity, crlf.Boundaries[b].Faces.Connectivity);
    }
  }
}

/// gmsh's circle in a square: the triangles cover the square less the circle's polygon, the
/// markers are exactly the mesh's open edges, the far field is 40 long.
TEST(SU2Read, GmshCircleInSquareMatchesItsGeometry)
{
  const mf::NamedMesh mesh = mf::ReadSU2(DataFile("circle_in_square.su2"));
  ASSERT_EQ(mesh.Dimension, 2);
  EXPECT_EQ(mesh.NumberOfNodes(), 313u);
  EXPECT_EQ(mesh.Volume.Size(), 562u);
  ASSERT_EQ(mesh.Boundaries.size(), 2u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "farfield");
  EXPECT_EQ(mesh.Boundaries[1].Name, "circle");
  const double* p = mesh.Points.data();
  double area = 0.0;
  for (std::size_t c = 0; c < mesh.Volume.Size(); ++c)
  {
    const std::int64_t* n = mesh.Volume.Connectivity.data() + 3 * c;
    area += std::abs(Cross2(p + 3 * n[0], p + 3 * n[1], p + 3 * n[2])) / 2;
  }
  double hole = 0.0, farfield = 0.0;
  const mf::Cells& circle = mesh.Boundaries[1].Faces;
  for (std::size_t e = 0; e < circle.Size(); ++e)
  {
    const double origin[3] = { 0, 0, 0 };
    const double* a = p + 3 * circle.Connectivity[2 * e];
    const double* b = p + 3 * circle.Connectivity[2 * e + 1];
    hole += Cross2(origin, a, b) / 2;
    EXPECT_NEAR(std::hypot(a[0], a[1]), 1.0, 1e-12);
  }
  const mf::Cells& square = mesh.Boundaries[0].Faces;
  for (std::size_t e = 0; e < square.Size(); ++e)
  {
    const double* a = p + 3 * square.Connectivity[2 * e];
    const double* b = p + 3 * square.Connectivity[2 * e + 1];
    farfield += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  EXPECT_NEAR(area, 100.0 - std::abs(hole), 1e-9);
  EXPECT_LT(std::abs(hole), M_PI);
  EXPECT_NEAR(farfield, 40.0, 1e-9);
  EXPECT_EQ(OpenFaces(mesh), MarkedFaces(mesh));
  for (std::size_t k = 0; k < mesh.NumberOfNodes(); ++k)
  {
    EXPECT_EQ(mesh.Points[3 * k + 2], 0.0);
  }
}

/// gmsh's tetrahedra in the box [0,2]x[0,1]x[0,1]: volume 2, marker areas 1, 1 and 6, the
/// markers exactly the open faces, inlet at x = 0.
TEST(SU2Read, GmshBoxMatchesItsGeometry)
{
  const mf::NamedMesh mesh = mf::ReadSU2(DataFile("box.su2"));
  ASSERT_EQ(mesh.Dimension, 3);
  EXPECT_EQ(mesh.NumberOfNodes(), 107u);
  const double* p = mesh.Points.data();
  double volume = 0.0;
  for (std::size_t c = 0; c < mesh.Volume.Size(); ++c)
  {
    ASSERT_EQ(mesh.Volume.Types[c], mf::Tetra);
    const std::int64_t* n = mesh.Volume.Connectivity.data() + 4 * c;
    const double *a = p + 3 * n[0], *b = p + 3 * n[1], *d = p + 3 * n[2], *e = p + 3 * n[3];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
    const double w[3] = { e[0] - a[0], e[1] - a[1], e[2] - a[2] };
    volume += std::abs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                u[2] * (v[0] * w[1] - v[1] * w[0])) /
      6;
  }
  EXPECT_NEAR(volume, 2.0, 1e-12);
  const std::pair<const char*, double> expected[] = { { "inlet", 1 }, { "outlet", 1 },
    { "walls", 8 } };
  ASSERT_EQ(mesh.Boundaries.size(), 3u);
  for (std::size_t b = 0; b < 3; ++b)
  {
    EXPECT_EQ(mesh.Boundaries[b].Name, expected[b].first);
    const mf::Cells& faces = mesh.Boundaries[b].Faces;
    double area = 0.0;
    for (std::size_t f = 0; f < faces.Size(); ++f)
    {
      const std::int64_t* n = faces.Connectivity.data() + 3 * f;
      const double *a = p + 3 * n[0], *c = p + 3 * n[1], *d = p + 3 * n[2];
      const double u[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      const double v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      area += std::hypot(
                u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) /
        2;
      if (b == 0)
      {
        EXPECT_EQ(a[0], 0.0);
      }
    }
    EXPECT_NEAR(area, expected[b].second, 1e-12) << expected[b].first;
  }
  EXPECT_EQ(OpenFaces(mesh), MarkedFaces(mesh));
}

namespace
{
/// The points of `mesh` moved so that printing them must be exact: thirds, tiny and huge
/// magnitudes, a subnormal, a negative zero; z set to 7 (ignored in 2D).
std::vector<double> Moved(const mf::NamedMesh& mesh)
{
  std::vector<double> points = mesh.Points;
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    points[k] = points[k] / 3.0 + 1e-7 * static_cast<double>(k) + M_PI;
  }
  points[0] = -0.0;
  points[1] = 4.9406564584124654e-324;
  points[3] = 1.7976931348623157e308;
  points[4] = -2.2250738585072014e-308;
  points[6] = 0.1;
  if (mesh.Dimension == 2)
  {
    for (std::size_t k = 2; k < points.size(); k += 3)
    {
      points[k] = 7.0;
    }
  }
  return points;
}

/// What reading the written file must give for the z of each 2D node: 0.
std::vector<double> AsRead(std::vector<double> points, int dimension)
{
  for (std::size_t k = 2; dimension == 2 && k < points.size(); k += 3)
  {
    points[k] = 0.0;
  }
  return points;
}

/// `line` cut into its whitespace runs (even places) and its tokens (odd places).
std::vector<std::string> SpacesAndTokens(const std::string& line)
{
  std::vector<std::string> parts(1);
  for (char c : line)
  {
    const bool space = c == ' ' || c == '\t' || c == '\r';
    if (space != (parts.size() % 2 == 1))
    {
      parts.emplace_back();
    }
    parts.back() += c;
  }
  return parts;
}

/**
 * Checks that `written` is `source` with only the coordinates of the point lines changed: the
 * other lines, and the spaces, the index and the line end of each point line, are the same.
 */
void ExpectOnlyCoordinatesChanged(
  const std::string& source, const std::string& written, std::size_t dimension)
{
  const std::vector<std::string> before = Lines(source), after = Lines(written);
  ASSERT_EQ(before.size(), after.size());
  EXPECT_EQ(source.back(), written.back());
  std::size_t first = 0, count = 0, changed = 0;
  for (std::size_t k = 0; k < before.size(); ++k)
  {
    if (before[k].rfind("NPOIN", 0) == 0)
    {
      first = k + 1;
      count = std::stoul(before[k].substr(before[k].find('=') + 1));
    }
    if (count == 0 || k < first || k >= first + count)
    {
      EXPECT_EQ(before[k], after[k]) << "line " << k + 1;
      continue;
    }
    changed += before[k] != after[k];
    const std::vector<std::string> a = SpacesAndTokens(before[k]), b = SpacesAndTokens(after[k]);
    ASSERT_EQ(a.size(), b.size()) << "line " << k + 1;
    for (std::size_t part = 0; part < a.size(); ++part)
    {
      if (part % 2 == 0 || part > 2 * dimension)
      {
        EXPECT_EQ(a[part], b[part]) << "line " << k + 1 << ", part " << part;
      }
    }
  }
  EXPECT_GT(changed, count / 2);
}
} // namespace

TEST(SU2Write, OnlyTheCoordinatesChangeAndTheyReadBackExactly)
{
  TemporaryFolder folder;
  const std::string sources[] = { DataFile("circle_in_square.su2"), DataFile("box.su2"),
    folder.File("hand2d_crlf.su2"), folder.File("hand3d.su2") };
  WriteText(sources[2], WithCRLF(Hand2D));
  WriteText(sources[3], Hand3D);
  for (const std::string& source : sources)
  {
    const mf::NamedMesh mesh = mf::ReadSU2(source);
    const std::vector<double> points = Moved(mesh);
    const std::string target = folder.File("moved.su2");
    mf::WriteSU2WithPoints(source, target, points.data(), mesh.NumberOfNodes());
    ExpectOnlyCoordinatesChanged(ReadText(source), ReadText(target), mesh.Dimension);
    const mf::NamedMesh back = mf::ReadSU2(target);
    EXPECT_TRUE(SameBits(back.Points, AsRead(points, mesh.Dimension))) << source;
    EXPECT_EQ(back.Volume.Connectivity, mesh.Volume.Connectivity);
    EXPECT_EQ(back.Boundaries.size(), mesh.Boundaries.size());
  }
}

TEST(SU2Write, TheIndexOfAPointLineIsKept)
{
  TemporaryFolder folder;
  WriteText(folder.File("hand2d.su2"), Hand2D);
  const mf::NamedMesh mesh = mf::ReadSU2(folder.File("hand2d.su2"));
  std::vector<double> points(mesh.Points.size(), 0.0);
  points[3 * 5] = 0.1;
  mf::WriteSU2WithPoints(
    folder.File("hand2d.su2"), folder.File("out.su2"), points.data(), mesh.NumberOfNodes());
  const std::vector<std::string> lines = Lines(ReadText(folder.File("out.su2")));
  EXPECT_EQ(lines[10], "0 0 0");
  EXPECT_EQ(lines[11], "0 0 1");
  EXPECT_EQ(lines[12], "0 0");
  EXPECT_EQ(lines[14], "0   0\t4");
  EXPECT_EQ(lines[15], "0.10000000000000001 0 5");
}

TEST(SU2Write, TargetMayBeTheSource)
{
  TemporaryFolder folder;
  const std::string file = folder.File("box.su2");
  fs::copy_file(DataFile("box.su2"), file);
  const mf::NamedMesh mesh = mf::ReadSU2(file);
  const std::vector<double> points = Moved(mesh);
  mf::WriteSU2WithPoints(file, file, points.data(), mesh.NumberOfNodes());
  ExpectOnlyCoordinatesChanged(ReadText(DataFile("box.su2")), ReadText(file), 3);
  EXPECT_TRUE(SameBits(mf::ReadSU2(file).Points, points));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.Path), fs::directory_iterator()), 1)
    << "the temporary file is left behind";
}

TEST(SU2Write, RefusedWritesLeaveTheTargetAlone)
{
  TemporaryFolder folder;
  const std::string source = folder.File("hand3d.su2"), target = folder.File("target.su2");
  WriteText(source, Hand3D);
  WriteText(target, "old");
  const mf::NamedMesh mesh = mf::ReadSU2(source);
  std::vector<double> points = mesh.Points;
  EXPECT_THROW(mf::WriteSU2WithPoints(source, target, points.data(), 11), mf::FileError);
  EXPECT_THROW(mf::WriteSU2WithPoints(source, target, nullptr, 12), mf::FileError);
  for (double bad : { std::nan(""), std::numeric_limits<double>::infinity() })
  {
    points[3 * 4 + 2] = bad;
    EXPECT_THROW(mf::WriteSU2WithPoints(source, target, points.data(), 12), mf::FileError);
  }
  WriteText(folder.File("broken.su2"), std::string(Hand3D).substr(0, 100));
  EXPECT_THROW(mf::WriteSU2WithPoints(folder.File("broken.su2"), target, mesh.Points.data(), 12),
    mf::FileError);
  EXPECT_EQ(ReadText(target), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.Path), fs::directory_iterator()), 3);
  EXPECT_THROW(
    mf::WriteSU2WithPoints(source, folder.File("no/such/folder/x.su2"), mesh.Points.data(), 12),
    mf::FileError);
  try
  {
    points[3 * 4 + 2] = std::nan("");
    mf::WriteSU2WithPoints(source, target, points.data(), 12);
  }
  catch (const mf::FileError& e)
  {
    EXPECT_NE(std::string(e.what()).find("target.su2: point 4 has a non-finite coordinate"),
      std::string::npos)
      << e.what();
  }
}

TEST(SU2Write, TheReadsPointLinesServeOnlyTheSameBytes)
{
  // The writer reuses the point lines of the file the reader parsed last when given the same
  // bytes. A file of the same size whose point lines moved (a blank taken from before NPOIN= and
  // put after the points) must be parsed again: written as from a fresh process.
  TemporaryFolder folder;
  const std::string original = Hand2D;
  std::string shifted = original;
  shifted.erase(shifted.find("NELEM= 3") + 6, 1); // "NELEM=3"
  shifted.insert(shifted.find("NMARK= 3"), " ");
  ASSERT_EQ(shifted.size(), original.size());
  WriteText(folder.File("a.su2"), original);
  WriteText(folder.File("b.su2"), shifted);
  const mf::NamedMesh mesh = mf::ReadSU2(folder.File("a.su2"));
  const std::vector<double> points = Moved(mesh);
  mf::WriteSU2WithPoints(
    folder.File("b.su2"), folder.File("from_cache.su2"), points.data(), mesh.NumberOfNodes());
  mf::ReadSU2(DataFile("box.su2")); // another file read last: b.su2 is parsed by the writer
  mf::WriteSU2WithPoints(
    folder.File("b.su2"), folder.File("fresh.su2"), points.data(), mesh.NumberOfNodes());
  EXPECT_EQ(ReadText(folder.File("from_cache.su2")), ReadText(folder.File("fresh.su2")));
  ExpectOnlyCoordinatesChanged(shifted, ReadText(folder.File("fresh.su2")), 2);
  // And the file read last, written back: the same bytes as after another read.
  mf::ReadSU2(folder.File("a.su2"));
  mf::WriteSU2WithPoints(
    folder.File("a.su2"), folder.File("a_cached.su2"), points.data(), mesh.NumberOfNodes());
  mf::ReadSU2(DataFile("box.su2"));
  mf::WriteSU2WithPoints(
    folder.File("a.su2"), folder.File("a_fresh.su2"), points.data(), mesh.NumberOfNodes());
  EXPECT_EQ(ReadText(folder.File("a_cached.su2")), ReadText(folder.File("a_fresh.su2")));
}
