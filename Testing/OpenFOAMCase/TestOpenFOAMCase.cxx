// Tests of the VTK-free OpenFOAM case library (dgmf::openfoam): points files in every form
// OpenFOAM writes, headers, and deformed points written into a case. Real OpenFOAM reading what
// this library writes is tested in Testing/OpenFOAM (checkMesh, simpleFoam).
#include "dgmf/openfoam/CaseDirectory.h"
#include "dgmf/openfoam/FoamFileText.h"
#include "dgmf/openfoam/PointsFile.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;
namespace of = dgmf::openfoam;

namespace
{
const char* const Banner =
  "/*--------------------------------*- C++ -*----------------------------------*\\\n"
  "| =========                 |                                                 |\n"
  "\\*---------------------------------------------------------------------------*/\n";

std::string Header(const char* format, const char* extra = "")
{
  return std::string(Banner) + "FoamFile\n{\n    version     2.0;\n    format      " + format +
    ";\n" + extra +
    "    class       vectorField;\n    location    \"constant/polyMesh\";\n"
    "    object      points;\n}\n"
    "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n\n";
}

const std::vector<double> Sample = { -1.2, -2.2, 0.1, 0.1 + 0.2, 1e-300, -0.0, 3.0, 4.5, 1.0 / 3 };

std::string AsciiPoints(const std::vector<double>& xyz)
{
  std::ostringstream body;
  body.precision(17);
  body << Header("ascii") << xyz.size() / 3 << "\n(\n";
  for (std::size_t k = 0; k < xyz.size(); k += 3)
  {
    body << "(" << xyz[k] << " " << xyz[k + 1] << " " << xyz[k + 2] << ")\n";
  }
  body
    << ")\n\n\n// ************************************************************************* //\n";
  return body.str();
}

std::string BinaryPoints(const std::vector<double>& xyz, bool bigEndian, bool floats)
{
  std::string arch = std::string("    arch        \"") + (bigEndian ? "MSB" : "LSB") +
    ";label=32;scalar=" + (floats ? "32" : "64") + "\";\n";
  std::string body = Header("binary", arch.c_str()) + std::to_string(xyz.size() / 3) + "\n(";
  for (double value : xyz)
  {
    char bytes[8];
    std::size_t width = floats ? 4 : 8;
    if (floats)
    {
      const float f = static_cast<float>(value);
      std::memcpy(bytes, &f, 4);
    }
    else
    {
      std::memcpy(bytes, &value, 8);
    }
    if (bigEndian)
    {
      for (std::size_t a = 0, b = width - 1; a < b; ++a, --b)
      {
        std::swap(bytes[a], bytes[b]);
      }
    }
    body.append(bytes, width);
  }
  return body +
    ")\n\n\n// ************************************************************************* //\n";
}

void WriteText(const fs::path& file, const std::string& text, bool gzip = false)
{
  fs::create_directories(file.parent_path());
  if (gzip)
  {
    gzFile out = gzopen(file.string().c_str(), "wb");
    gzwrite(out, text.data(), static_cast<unsigned>(text.size()));
    gzclose(out);
    return;
  }
  std::ofstream(file.string(), std::ios::binary) << text;
}

std::string ReadText(const fs::path& file)
{
  std::ifstream in(file.string(), std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A fresh directory for one test.
fs::path Scratch(const std::string& name)
{
  const fs::path directory = fs::temp_directory_path() / ("dgmf-openfoam-test-" + name);
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

/// A minimal case: system/controlDict, constant/polyMesh/{points, boundary}, 0/, 1/, 2/.
fs::path MakeCase(const fs::path& directory, const std::string& points, bool gzip = false)
{
  WriteText(directory / "system" / "controlDict", Header("ascii") + "startTime 0;\n");
  WriteText(directory / "constant" / "polyMesh" / (gzip ? "points.gz" : "points"), points, gzip);
  WriteText(directory / "constant" / "polyMesh" / "boundary",
    Header("ascii") +
      "3\n(\n    wing\n    {\n        type wall;\n        inGroups List<word> 2(wall body);\n"
      "        nFaces 2;\n    }\n"
      "    symFront { type symmetryPlane; inGroups 1(symmetryPlane); }\n    front\n    {\n"
      "        type empty;\n    }\n)\n");
  WriteText(directory / "0" / "U", "fields to start from");
  WriteText(directory / "1" / "U", "a result");
  WriteText(directory / "processor0" / "x", "a decomposed piece");
  return directory;
}

void ExpectSameBits(const std::vector<double>& a, const std::vector<double>& b)
{
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}
} // namespace

TEST(PointsFile, ReadsAsciiBinaryBothEndiansSinglePrecisionAndGzip)
{
  const fs::path dir = Scratch("read");
  WriteText(dir / "ascii", AsciiPoints(Sample));
  WriteText(dir / "lsb", BinaryPoints(Sample, false, false));
  WriteText(dir / "msb", BinaryPoints(Sample, true, false));
  WriteText(dir / "f32", BinaryPoints(Sample, false, true));
  WriteText(dir / "ascii.gz", AsciiPoints(Sample), true);
  WriteText(dir / "lsb.gz", BinaryPoints(Sample, false, false), true);
  for (const char* name : { "ascii", "lsb", "msb", "ascii.gz", "lsb.gz" })
  {
    SCOPED_TRACE(name);
    const of::PointsFile file = of::ReadPointsFile(dir / name);
    EXPECT_EQ(file.NumberOfPoints(), 3u);
    ExpectSameBits(file.Points, Sample);
    EXPECT_EQ(file.Compressed, std::string(name).find(".gz") != std::string::npos);
    EXPECT_EQ(file.BodyFormat,
      std::string(name).rfind("ascii", 0) == 0 ? of::Format::Ascii : of::Format::Binary);
  }
  const of::PointsFile single = of::ReadPointsFile(dir / "f32");
  for (std::size_t k = 0; k < Sample.size(); ++k)
  {
    EXPECT_EQ(single.Points[k], static_cast<double>(static_cast<float>(Sample[k])));
  }
}

TEST(PointsFile, WritesEveryFormItReadsAndReadsBackTheSameBits)
{
  const fs::path dir = Scratch("write");
  const std::vector<double> moved = { 1.0 / 7, -2.5e-17, 0.1, 1e300, -0.0, 3.0, 4.5, 2.0, -1.0 };
  const std::vector<std::pair<std::string, std::string>> forms = { { "ascii", AsciiPoints(Sample) },
    { "lsb", BinaryPoints(Sample, false, false) }, { "msb", BinaryPoints(Sample, true, false) } };
  for (const auto& form : forms)
  {
    for (bool gzip : { false, true })
    {
      SCOPED_TRACE(form.first + (gzip ? ".gz" : ""));
      const fs::path source = dir / (form.first + (gzip ? "-gz" : "")) / "in";
      WriteText(source / (gzip ? "points.gz" : "points"), form.second, gzip);
      const of::PointsFile like = of::ReadPointsFile(of::FindPointsFile(source));
      const fs::path out = dir / (form.first + (gzip ? "-gz" : "")) / "out";
      const fs::path written = of::WritePointsFile(out, like, moved.data(), 3, "1/polyMesh");
      EXPECT_EQ(written.filename(), gzip ? "points.gz" : "points");
      const of::PointsFile back = of::ReadPointsFile(written);
      ExpectSameBits(back.Points, moved);
      EXPECT_EQ(back.BodyFormat, like.BodyFormat);
      EXPECT_EQ(back.Compressed, gzip);
      EXPECT_EQ(of::FoamHeaderEntry(back.Preamble, "location"), "1/polyMesh");
      EXPECT_EQ(
        of::FoamHeaderEntry(back.Preamble, "arch"), of::FoamHeaderEntry(like.Preamble, "arch"));
      EXPECT_EQ(back.Epilogue, like.Epilogue);
      for (const fs::directory_entry& entry : fs::directory_iterator(out))
      {
        EXPECT_EQ(entry.path(), written) << "a temporary file was left behind";
      }
    }
  }
}

TEST(PointsFile, AsciiNumbersAreTheShortestThatReadBackExactly)
{
  const fs::path dir = Scratch("shortest");
  WriteText(dir / "in" / "points", AsciiPoints(Sample));
  const of::PointsFile like = of::ReadPointsFile(dir / "in" / "points");
  const std::vector<double> xyz = { -1.2, -2.2, 0.1 };
  const std::string text = ReadText(of::WritePointsFile(dir / "out", like, xyz.data(), 1, "x"));
  EXPECT_NE(text.find("\n1\n(\n(-1.2 -2.2 0.1)\n)"), std::string::npos) << text;
}

TEST(PointsFile, TheOtherVariantIsRemovedSoItCannotShadowTheNewFile)
{
  const fs::path dir = Scratch("variants");
  WriteText(dir / "points", AsciiPoints(Sample));
  WriteText(dir / "points.gz", AsciiPoints(Sample), true);
  EXPECT_EQ(of::FindPointsFile(dir), dir / "points"); // OpenFOAM reads the uncompressed one
  of::PointsFile gz = of::ReadPointsFile(dir / "points.gz");
  of::WritePointsFile(dir, gz, Sample.data(), 3, "constant/polyMesh");
  EXPECT_FALSE(fs::exists(dir / "points"));
  EXPECT_EQ(of::FindPointsFile(dir), dir / "points.gz");
}

TEST(PointsFile, DamagedFilesGiveTheirNameAndTheProblem)
{
  const fs::path dir = Scratch("damaged");
  const std::string good = AsciiPoints(Sample);
  const std::vector<std::pair<std::string, std::string>> cases = {
    { "noheader", "3\n(\n(0 0 0)\n)\n" },
    { "short", good.substr(0, good.find("(3 4.5")) },
    { "twocoordinates", Header("ascii") + "1\n(\n(1 2)\n)\n" },
    { "badnumber", Header("ascii") + "1\n(\n(1 x 2)\n)\n" },
    { "binaryshort", BinaryPoints(Sample, false, false).substr(0, 400) },
    { "format", Header("hdf5") + "1\n(\n(1 2 3)\n)\n" },
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.first);
    WriteText(dir / c.first, c.second);
    try
    {
      of::ReadPointsFile(dir / c.first);
      ADD_FAILURE() << "no error";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find(c.first), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(of::ReadPointsFile(dir / "missing"), std::runtime_error);
}

TEST(FoamFileText, HeaderEntriesAreReadAndSetWithoutTouchingTheRest)
{
  const std::string text = Header("binary", "    arch        \"LSB;label=32;scalar=64\";\n");
  EXPECT_EQ(of::FoamHeaderEntry(text, "format"), "binary");
  EXPECT_EQ(of::FoamHeaderEntry(text, "location"), "constant/polyMesh");
  EXPECT_EQ(of::FoamHeaderEntry(text, "note"), "");
  const std::string moved = of::SetHeaderEntry(text, "location", "\"2.5/polyMesh\"");
  EXPECT_EQ(of::FoamHeaderEntry(moved, "location"), "2.5/polyMesh");
  EXPECT_EQ(moved.size() + std::string("constant").size(), text.size() + std::string("2.5").size());
  EXPECT_EQ(of::FoamHeaderEntry(moved, "arch"), "LSB;label=32;scalar=64");
  EXPECT_EQ(of::SetHeaderEntry(moved, "arch", "\"MSB;label=32;scalar=32\"").size(), moved.size());
  const std::string added = of::SetHeaderEntry(moved, "note", "\"moved\"");
  EXPECT_EQ(of::FoamHeaderEntry(added, "note"), "moved");
  EXPECT_EQ(of::FoamHeaderEntry(added, "object"), "points");
  const of::ArchInfo big = of::ParseArch("MSB;label=64;scalar=32");
  EXPECT_FALSE(big.LittleEndian);
  EXPECT_EQ(big.LabelBytes, 8u);
  EXPECT_EQ(big.ScalarBytes, 4u);
  const of::ArchInfo none = of::ParseArch("");
  EXPECT_TRUE(none.LittleEndian);
  EXPECT_EQ(none.ScalarBytes, 8u);

  // A brace inside a quoted entry or a comment does not close the header (OpenFOAM reads such
  // files; until 2026-11-30 the points after it were "no point count after the header").
  const std::string braces =
    Header("ascii", "    note        \"a } brace\";\n    // a } comment\n    /* and } this */\n");
  EXPECT_EQ(of::FoamHeaderEntry(braces, "note"), "a } brace");
  EXPECT_EQ(of::FoamHeaderEntry(braces, "class"), "vectorField"); // after the comments
  EXPECT_EQ(of::FoamHeaderEntry(braces, "object"), "points");
}

TEST(CaseDirectory, NamesTimesAndPatches)
{
  const fs::path dir = MakeCase(Scratch("names"), AsciiPoints(Sample));
  EXPECT_TRUE(of::IsCase(dir));
  EXPECT_FALSE(of::IsCase(dir / "constant"));
  EXPECT_EQ(of::CaseDirectoryOf(dir / "case.foam"), dir);
  EXPECT_EQ(of::CaseDirectoryOf(dir / "system" / "controlDict"), dir);
  EXPECT_EQ(of::CaseDirectoryOf(dir), dir);
  for (const char* good : { "constant", "0", "1", "0.05", "1e-3" })
  {
    EXPECT_TRUE(of::IsTimeName(good)) << good;
  }
  for (const char* bad : { "", "system", "../1", "-1", "1/polyMesh", "nan", "inf" })
  {
    EXPECT_FALSE(of::IsTimeName(bad)) << bad;
  }
  // The writer's check of other meshes reads the case's directory names with the same TimeValue.
  double value = -1.0;
  EXPECT_TRUE(of::TimeValue("2e-4", value));
  EXPECT_EQ(value, 0.0002);
  for (const char* notATime : { "constant", "processor0", "0x10", " 1", "1 ", "inf", "nan", "" })
  {
    EXPECT_FALSE(of::TimeValue(notATime, value)) << notATime;
  }
  EXPECT_EQ(of::ReadPatchNames(dir), (std::vector<std::string>{ "wing", "symFront", "front" }));
  const std::vector<of::PatchEntry> patches = of::ReadPatches(dir);
  ASSERT_EQ(patches.size(), 3u);
  EXPECT_EQ(patches[0].Groups, (std::vector<std::string>{ "wall", "body" }));
  EXPECT_EQ(patches[1].Groups, (std::vector<std::string>{ "symmetryPlane" }));
  EXPECT_TRUE(patches[2].Groups.empty());
  EXPECT_EQ(patches[0].Type, "wall");
  EXPECT_EQ(patches[1].Type, "symmetryPlane");
  EXPECT_EQ(patches[2].Type, "empty");
}

TEST(CaseDirectory, UnmovedPointsKeepTheirBitsAndTheReadersRoundingDoesNotReachTheCase)
{
  const fs::path source = MakeCase(Scratch("deformed-src"), AsciiPoints(Sample));
  // The mesh as VTK's OpenFOAM reader gives it (single precision), and its deformation: the
  // first point moves by (0.5, 0, 0), the others do not move.
  std::vector<double> reference(Sample.size()), deformed(Sample.size());
  for (std::size_t k = 0; k < Sample.size(); ++k)
  {
    reference[k] = static_cast<float>(Sample[k]);
  }
  deformed = reference;
  deformed[0] += 0.5;
  const fs::path target = Scratch("deformed-out") / "new";
  const fs::path written =
    of::WriteDeformedPoints(source, target, "constant", reference.data(), deformed.data(), 3);
  EXPECT_EQ(written, target / "constant" / "polyMesh" / "points");
  std::vector<double> expected = Sample;
  expected[0] = Sample[0] + (deformed[0] - reference[0]);
  ExpectSameBits(of::ReadPointsFile(written).Points, expected);
  EXPECT_EQ(std::abs(expected[0] - (Sample[0] + 0.5)) < 1e-15, true);
  // The new case is a copy: system, constant, the first time; not later times or pieces.
  EXPECT_TRUE(of::IsCase(target));
  EXPECT_TRUE(fs::exists(target / "constant" / "polyMesh" / "boundary"));
  EXPECT_TRUE(fs::exists(target / "0" / "U"));
  EXPECT_FALSE(fs::exists(target / "1"));
  EXPECT_FALSE(fs::exists(target / "processor0"));
  // The source case is unchanged.
  EXPECT_EQ(ReadText(source / "constant" / "polyMesh" / "points"), AsciiPoints(Sample));
  // Written again into the case made before, at a time: the faces stay in constant.
  const fs::path timed =
    of::WriteDeformedPoints(source, target, "2", reference.data(), deformed.data(), 3);
  EXPECT_EQ(timed, target / "2" / "polyMesh" / "points");
  EXPECT_EQ(of::FoamHeaderEntry(ReadText(timed), "location"), "2/polyMesh");
}

TEST(CaseDirectory, PointsAlreadyAtTheTimeWrittenAreSaidToBeReplaced)
{
  // A mesh a solver moved sits in the source case's first time (0/polyMesh/points): a new output
  // case gets it with the copy, and writing time 0 replaces it. Until 2026-11-30 only a case that
  // existed before the write was checked, and this replacement went unsaid.
  const fs::path source = MakeCase(Scratch("replaced-src"), AsciiPoints(Sample));
  fs::create_directories(source / "0" / "polyMesh");
  fs::copy_file(source / "constant" / "polyMesh" / "points", source / "0" / "polyMesh" / "points");
  const fs::path target = Scratch("replaced-out") / "new";
  bool replaced = true;
  of::WriteDeformedPoints(source, target, "constant", Sample.data(), Sample.data(), 3, &replaced);
  EXPECT_FALSE(replaced); // constant's points are the mesh itself, not a time's
  of::WriteDeformedPoints(source, target, "1", Sample.data(), Sample.data(), 3, &replaced);
  EXPECT_FALSE(replaced); // a new time
  of::WriteDeformedPoints(source, target, "1", Sample.data(), Sample.data(), 3, &replaced);
  EXPECT_TRUE(replaced); // the same time again
  const fs::path copied = Scratch("replaced-copy") / "new";
  of::WriteDeformedPoints(source, copied, "0", Sample.data(), Sample.data(), 3, &replaced);
  EXPECT_TRUE(replaced); // brought along by the copy
}

TEST(CaseDirectory, ExtraPointsAfterTheCasesAreNotWritten)
{
  // The reader appends one point per polyhedron when it decomposes polyhedra.
  const fs::path source = MakeCase(Scratch("extra"), AsciiPoints(Sample));
  std::vector<double> points = Sample;
  points.insert(points.end(), { 9.0, 9.0, 9.0 });
  const fs::path written = of::WriteDeformedPoints(
    source, Scratch("extra-out") / "c", "constant", points.data(), points.data(), 4);
  ExpectSameBits(of::ReadPointsFile(written).Points, Sample);
}

TEST(CaseDirectory, ACopyOfAReadOnlyCaseCanTakeThePoints)
{
  // A read-only source (a tutorial tree, a colleague's case): the copy's directories and files
  // are its owner's to write (fs::copy kept the source's modes: as a user, the copy's own
  // constant/polyMesh could not be written, and the half copy blocked a second try).
  const fs::path source = MakeCase(Scratch("readonly"), AsciiPoints(Sample));
  const auto writable = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(source))
  {
    fs::permissions(entry.path(), writable, fs::perm_options::remove);
  }
  const fs::path target = Scratch("readonly-copy") / "case";
  of::CopyCase(source, target);
  std::size_t entries = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(target))
  {
    EXPECT_NE(entry.status().permissions() & fs::perms::owner_write, fs::perms::none)
      << entry.path();
    ++entries;
  }
  EXPECT_GE(entries, 6u); // system, controlDict, constant, polyMesh, points, boundary, 0, ...
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(source))
  {
    fs::permissions(entry.path(), fs::perms::owner_write, fs::perm_options::add);
  }
}

TEST(CaseDirectory, WrongInputsWriteNothingAndSayWhy)
{
  const fs::path source = MakeCase(Scratch("wrong"), AsciiPoints(Sample));
  const std::string before = ReadText(source / "constant" / "polyMesh" / "points");
  std::vector<double> good = Sample, shifted = Sample, nan = Sample;
  shifted[4] += 1e-3;
  nan[2] = std::nan("");
  const fs::path out = Scratch("wrong-out") / "c";
  const auto message = [&](const fs::path& target, const std::string& time, const double* ref,
                         const double* def, std::size_t n)
  {
    try
    {
      of::WriteDeformedPoints(source, target, time, ref, def, n);
    }
    catch (const std::runtime_error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(out, "constant", good.data(), good.data(), 2).find("has 3"), std::string::npos);
  EXPECT_NE(
    message(out, "constant", shifted.data(), good.data(), 3).find("point 1"), std::string::npos);
  EXPECT_NE(
    message(out, "constant", good.data(), nan.data(), 3).find("not finite"), std::string::npos);
  EXPECT_NE(message(out, "../x", good.data(), good.data(), 3).find("time"), std::string::npos);
  EXPECT_FALSE(fs::exists(out)) << "nothing is written when the input is wrong";
  // A directory that holds something else is not overwritten.
  WriteText(out / "notes.txt", "mine");
  EXPECT_NE(message(out, "constant", good.data(), good.data(), 3).find("not an OpenFOAM case"),
    std::string::npos);
  EXPECT_FALSE(fs::exists(out / "constant"));
  // A new directory inside the case: until 2026-11-30 the case was copied into itself until the
  // names got too long, leaving the nested copies.
  for (const fs::path& inside : { source / "deformed", source / "constant" / "x" / "y" })
  {
    EXPECT_NE(message(inside, "constant", good.data(), good.data(), 3).find("is inside the case"),
      std::string::npos)
      << inside;
  }
  EXPECT_FALSE(fs::exists(source / "deformed"));
  EXPECT_FALSE(fs::exists(source / "constant" / "x"));
  EXPECT_EQ(ReadText(source / "constant" / "polyMesh" / "points"), before);
}

TEST(CaseDirectory, InPlaceOnPurposeAndInTheCasesOwnFormat)
{
  const fs::path source =
    MakeCase(Scratch("inplace"), BinaryPoints(Sample, false, false), /*gzip=*/true);
  std::vector<double> deformed = Sample;
  deformed[8] = 7.0;
  const fs::path written =
    of::WriteDeformedPoints(source, source, "1", Sample.data(), deformed.data(), 3);
  EXPECT_EQ(written, source / "1" / "polyMesh" / "points.gz");
  const of::PointsFile back = of::ReadPointsFile(written);
  EXPECT_EQ(back.BodyFormat, of::Format::Binary);
  ExpectSameBits(back.Points, deformed);
  ExpectSameBits(of::ReadPointsFile(source / "constant" / "polyMesh" / "points.gz").Points, Sample);
}

TEST(FoamFileText, TopLevelEntriesAreFoundPastSubDictionariesAndDirectives)
{
  // A controlDict's startFrom and startTime: after the header, directives and comments; entries
  // of the same keyword inside a sub-dictionary do not count.
  const std::string text = "FoamFile\n{\n    version 2.0;\n    object controlDict;\n}\n"
                           "#include \"settings\"\n"
                           "functions\n{\n    probe { startTime 7; type probes; }\n}\n"
                           "// startFrom firstTime;\n"
                           "application simpleFoam;\n"
                           "startFrom   startTime; /* not latestTime */\n"
                           "startTime   0.25;\n";
  EXPECT_EQ(of::FoamTopLevelEntry(text, "startFrom"), "startTime");
  EXPECT_EQ(of::FoamTopLevelEntry(text, "startTime"), "0.25");
  EXPECT_EQ(of::FoamTopLevelEntry(text, "type"), "");
  EXPECT_EQ(of::FoamTopLevelEntry(text, "endTime"), "");
  // Given twice, the last counts (as foamDictionary says).
  EXPECT_EQ(of::FoamTopLevelEntry(text + "startFrom latestTime;\n", "startFrom"), "latestTime");
}

TEST(CaseDirectory, TheSolversStartTimeFollowsStartFrom)
{
  const fs::path source = MakeCase(Scratch("start-from"), AsciiPoints(Sample));
  fs::create_directories(source / "100");
  const auto controlDict = [&](const std::string& entries)
  {
    std::ofstream(source / "system" / "controlDict")
      << "FoamFile\n{\n    version 2.0;\n    object controlDict;\n}\n"
      << entries;
  };
  double start = -1.0;
  controlDict("startFrom latestTime;\nstartTime 0;\n");
  ASSERT_TRUE(of::SolverStartTime(source, { 0.5, 1.0 }, false, start));
  EXPECT_EQ(start, 100.0); // the case's time 100, after the frames written
  controlDict("startFrom firstTime;\n");
  ASSERT_TRUE(of::SolverStartTime(source, { 0.5, 1.0 }, false, start));
  EXPECT_EQ(start, 0.0); // the case's 0
  controlDict("startFrom startTime;\nstartTime 0.75;\n");
  ASSERT_TRUE(of::SolverStartTime(source, { 0.5, 1.0 }, false, start));
  EXPECT_EQ(start, 0.75);
  // The source of a new case: its copy has the first time only (0), not 100.
  controlDict("startFrom latestTime;\nstartTime 0;\n");
  ASSERT_TRUE(of::SolverStartTime(source, { 0.5, 1.0 }, true, start));
  EXPECT_EQ(start, 1.0);
  controlDict("startFrom somewhere;\n");
  EXPECT_FALSE(of::SolverStartTime(source, { 0.5 }, false, start));
}
