// Hostile SU2 files: each is a FileError naming the file and the line (or what is missing),
// never a crash, a hang or a huge allocation.
#include "SU2TestFiles.h"

#include <vector>

using namespace su2test;

namespace
{
/// `text` with its only occurrence of `from` replaced by `to`.
std::string Replace(std::string text, const std::string& from, const std::string& to)
{
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

struct HostileCase
{
  const char* What;
  std::string Text;
  const char* Error; ///< a part of the expected message (after "<folder>/")
};

std::vector<HostileCase> HostileCases()
{
  const std::string h = Hand2D;
  const std::string huge = "999999999999";
  return {
    { "no NDIME", Replace(h, "NDIME = 2\n", ""), "bad.su2:4: NELEM= comes before NDIME=" },
    { "NDIME 4", Replace(h, "NDIME = 2", "NDIME = 4"), "bad.su2:3: NDIME= must be 2 or 3" },
    { "NZONE 2", "NZONE= 2\n" + h, "bad.su2:1: NZONE= 2: multi-zone files are not supported" },
    { "two zones", h + "IZONE= 2\n" + h, "bad.su2:30: a second IZONE= after the mesh" },
    { "NELEM too big", Replace(h, "NELEM= 3", "NELEM= 4"),
      "bad.su2:10: found 'NPOIN=6' where element 3 of NELEM= 4 should be (fewer lines than "
      "NELEM= 4 says?)" },
    { "NELEM too small", Replace(h, "NELEM= 3", "NELEM= 2"),
      "bad.su2:8: expected a keyword line (NDIME=, NELEM=, NPOIN=, NMARK=), found '5 1 5 4' "
      "(more lines than NELEM= 2 says?)" },
    { "NPOIN too big", Replace(h, "NPOIN=6", "NPOIN=7"),
      "bad.su2:17: found 'NMARK= 3' where point 6 of NPOIN= 7 should be" },
    { "NPOIN too small", Replace(h, "NPOIN=6", "NPOIN=5"), "bad.su2:16: expected a keyword line" },
    { "MARKER_ELEMS too small", Replace(h, "MARKER_ELEMS= 2", "MARKER_ELEMS= 1"),
      "bad.su2:21: marker 1 of NMARK= 3: expected MARKER_TAG= and a non-empty name" },
    { "MARKER_ELEMS too big at the end", Replace(h, "MARKER_ELEMS= 3", "MARKER_ELEMS= 4"),
      "bad.su2: the file ends (after line 29) where element 3 of marker 'upper & left (#2)' "
      "(MARKER_ELEMS= 4) should follow" },
    { "MARKER_ELEMS too small at the end", Replace(h, "MARKER_ELEMS= 3", "MARKER_ELEMS= 2"),
      "bad.su2:29: unexpected line '3 3 0' (more lines than marker 'upper & left (#2)' "
      "(MARKER_ELEMS= 2) says?)" },
    { "NMARK too big", Replace(h, "NMARK= 3", "NMARK= 4"),
      "bad.su2: the file ends (after line 29) where MARKER_TAG= of marker 3 of NMARK= 4" },
    { "NMARK too small", Replace(h, "NMARK= 3", "NMARK= 2"),
      "bad.su2:25: a second MARKER_TAG= after the mesh" },
    { "negative node", Replace(h, "3 2 5", "3 2 -5"),
      "bad.su2:24: marker 'outlet' (MARKER_ELEMS= 1): '-5' is not a node index (0-based)" },
    { "face node out of range", Replace(h, "3 2 5", "3 2 6"),
      "bad.su2:24: node index 6 is outside 0..5 (NPOIN= 6)" },
    { "cell node out of range", Replace(h, "5 1 5 4", "5 1 5 6"),
      "bad.su2:8: node index 6 is outside 0..5" },
    { "NaN", Replace(h, "0 1 3", "nan 1 3"),
      "bad.su2:14: point 3 of NPOIN= 6: 'nan' is not a finite number" },
    { "inf", Replace(h, "0 1 3", "0 -inf 3"), "bad.su2:14: point 3 of NPOIN= 6: '-inf' is not" },
    { "overflow", Replace(h, "0 1 3", "1e999 1 3"), "bad.su2:14: point 3 of NPOIN= 6: '1e999'" },
    { "huge NPOIN", Replace(h, "NPOIN=6", "NPOIN= " + huge),
      "bad.su2:17: found 'NMARK= 3' where point 6 of NPOIN= 999999999999 should be" },
    { "huge NELEM", Replace(h, "NELEM= 3", "NELEM= " + huge), "bad.su2:10: found 'NPOIN=6'" },
    { "huge NMARK", Replace(h, "NMARK= 3", "NMARK= " + huge),
      "bad.su2: the file ends (after line 29) where MARKER_TAG= of marker 3" },
    { "huge MARKER_ELEMS", Replace(h, "MARKER_ELEMS= 3", "MARKER_ELEMS= " + huge),
      "bad.su2: the file ends (after line 29) where element 3 of marker" },
    { "NPOIN beyond 64 bits", Replace(h, "NPOIN=6", "NPOIN= 99999999999999999999"),
      "bad.su2:10: NPOIN= needs a non-negative integer (and optionally a second), found " },
    { "negative NELEM", Replace(h, "NELEM= 3", "NELEM= -3"),
      "bad.su2:5: NELEM= needs a non-negative integer, found '-3'" },
    { "NELEM with garbage", Replace(h, "NELEM= 3", "NELEM= 3x"), "bad.su2:5: NELEM= needs" },
    { "NELEM 0", Replace(h, "NELEM= 3", "NELEM= 0"), "bad.su2:5: NELEM= 0: the mesh has no" },
    { "polygon", Replace(h, "9 0 1 4 3 0", "7 0 1 4 3 0"),
      "bad.su2:6: element of NELEM= 3: '7' is not the VTK type of a 2D element this reader "
      "takes (5, 9)" },
    { "tetra in 2D", Replace(h, "9 0 1 4 3 0", "10 0 1 4 3 0"), "bad.su2:6: element of NELEM" },
    { "line as a 2D cell", Replace(h, "5 1 5 4", "3 1 5"), "bad.su2:8: element of NELEM= 3: '3'" },
    { "triangle as a 2D face", Replace(h, "3 2 5", "5 2 5 4"),
      "bad.su2:24: marker 'outlet' (MARKER_ELEMS= 1): '5' is not the VTK type of a 1D element" },
    { "type 256", Replace(h, "9 0 1 4 3 0", "261 0 1 4 3 0"), "bad.su2:6: element of NELEM" },
    { "too many nodes", Replace(h, "5 1 5 4", "5 1 5 4 0 0"),
      "bad.su2:8: element of NELEM= 3: an element of type 5 needs 3 node indices (and "
      "optionally its index), found 5 values" },
    { "too few nodes", Replace(h, "5 1 5 4", "5 1 5"), "bad.su2:8: element of NELEM= 3: an" },
    { "far too many values", Replace(h, "5 1 5 4", "5 1 5 4 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1"),
      "found more than 11 values" },
    { "no NMARK", h.substr(0, h.find("NMARK")), "bad.su2: no NMARK= section (the file ends" },
    { "no NPOIN", Replace(h, "NPOIN=6", "% NPOIN=6"), "bad.su2:11: expected a keyword line" },
    { "empty", "", "bad.su2: no NDIME= section (the file ends at line 0)" },
    { "comments only", "% NDIME= 2\n%\n", "bad.su2: no NDIME= section (the file ends at line 2)" },
    { "duplicate marker", Replace(h, "MARKER_TAG =outlet", "MARKER_TAG =lower wall  "),
      "bad.su2:22: marker 1 of NMARK= 3: a second marker named 'lower wall'" },
    { "empty marker name", Replace(h, "MARKER_TAG =outlet", "MARKER_TAG =  \t"),
      "bad.su2:22: marker 1 of NMARK= 3: expected MARKER_TAG= and a non-empty name" },
    { "MARKER_TAG outside NMARK", Replace(h, "NMARK= 3", "MARKER_TAG= x"),
      "bad.su2:17: MARKER_TAG= outside the NMARK= section" },
    { "non-numeric coordinate", Replace(h, "1.0 0.0 1", "1.0 abc 1"),
      "bad.su2:12: point 1 of NPOIN= 6: 'abc' is not a finite number" },
    { "coordinate with garbage", Replace(h, "1.0 0.0 1", "1.5abc 0.0 1"), "'1.5abc' is not" },
    { "coordinate with a comma", Replace(h, "1.0 0.0 1", "1,5 0.0 1"), "'1,5' is not" },
    { "plus minus", Replace(h, "1.0 0.0 1", "+-1 0.0 1"), "'+-1' is not a finite number" },
    { "node with garbage", Replace(h, "3 2 5", "3 2x 5"), "bad.su2:24: marker 'outlet'" },
    { "fractional node", Replace(h, "3 2 5", "3 2.0 5"), "'2.0' is not a node index" },
    { "element index garbage", Replace(h, "9 0 1 4 3 0", "9 0 1 4 3 zero"),
      "bad.su2:6: element of NELEM= 3: 'zero' is not an integer element index" },
    { "fractional point index", Replace(h, "1.0 0.0 1", "1.0 0.0 1.5"),
      "bad.su2:12: point 1 of NPOIN= 6: expected 2 coordinates and optionally an integer index" },
    { "3 coordinates in 2D", Replace(h, "1.0 0.0 1", "1.0 0.0 0.5 1"),
      "bad.su2:12: point 1 of NPOIN= 6: expected 2 coordinates" },
    { "control byte", Replace(h, "1.0 0.0 1", std::string("1.0 0\x01.0 1")), "'0?.0' is not" },
    { "NUL byte", Replace(h, "1.0 0.0 1", std::string("1.0 0\0.0 1", 10)), "'0?.0' is not" },
    { "second NPOIN", Replace(h, "NMARK= 3", "NPOIN= 1\n0 0"),
      "bad.su2:17: a second NPOIN= (several zones are not supported)" },
  };
}
} // namespace

TEST(SU2Hostile, EachIsAFileErrorNamingTheFileAndTheLine)
{
  TemporaryFolder folder;
  const std::string file = folder.File("bad.su2");
  for (const HostileCase& hostile : HostileCases())
  {
    WriteText(file, hostile.Text);
    const std::string error = ReadError(file);
    EXPECT_EQ(error.rfind(folder.Path.string() + "/bad.su2", 0), 0u) << hostile.What;
    EXPECT_NE(error.find(hostile.Error), std::string::npos)
      << hostile.What << ": " << error << "\n  expected: " << hostile.Error;
  }
}

TEST(SU2Hostile, NoFileOrAFolder)
{
  TemporaryFolder folder;
  EXPECT_EQ(
    ReadError(folder.File("missing.su2")), folder.File("missing.su2") + ": cannot be opened");
  EXPECT_EQ(
    ReadError(folder.Path.string()), folder.Path.string() + ": is a directory, not an SU2 file");
}

TEST(SU2Hostile, EveryTruncationBeforeTheLastNodeIsAnError)
{
  TemporaryFolder folder;
  const std::string file = folder.File("cut.su2");
  for (const std::string& text : { std::string(Hand2D), std::string(Hand3D), WithCRLF(Hand2D) })
  {
    const std::size_t complete = text.find_last_not_of(" \t\r\n") + 1;
    for (std::size_t size = 0; size <= text.size(); ++size)
    {
      WriteText(file, text.substr(0, size));
      const std::string error = ReadError(file);
      EXPECT_EQ(error.empty(), size >= complete) << "cut after " << size << " bytes: " << error;
    }
  }
}

TEST(SU2Hostile, OddMarkerNamesAreKeptAsWrittenTrimmed)
{
  TemporaryFolder folder;
  const std::string odd = Replace(
    Replace(Hand2D, "MARKER_TAG= lower wall", "MARKER_TAG= \t Wand (\xc3\xbc) #1 = a=b \t\r"),
    "MARKER_TAG =outlet", "MARKER_TAG=%outlet");
  WriteText(folder.File("odd.su2"), odd);
  const mf::NamedMesh mesh = mf::ReadSU2(folder.File("odd.su2"));
  ASSERT_EQ(mesh.Boundaries.size(), 3u);
  EXPECT_EQ(mesh.Boundaries[0].Name, "Wand (\xc3\xbc) #1 = a=b");
  EXPECT_EQ(mesh.Boundaries[1].Name, "%outlet");
}

TEST(SU2Hostile, OtherSectionsAfterTheMeshAreSkipped)
{
  TemporaryFolder folder;
  const std::string ffd = std::string(Hand3D) +
    "% FFD\nFFD_NBOX= 1\nFFD_NLEVEL= 1\nFFD_TAG= box\n" + "FFD_CORNER_POINTS= 2\n0 0 0\n1 1 1\n";
  WriteText(folder.File("ffd.su2"), ffd);
  EXPECT_EQ(mf::ReadSU2(folder.File("ffd.su2")).NumberOfNodes(), 12u);
  WriteText(folder.File("ffd.su2"), ffd + "NDIME= 3\n");
  EXPECT_NE(ReadError(folder.File("ffd.su2")).find("ffd.su2:39: a second NDIME= after the mesh"),
    std::string::npos);
}
