#include "dgmf/meshfile/SU2File.h"

#include "dgmf/HugePages.h"
#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/MappedFile.h"
#include "dgmf/meshfile/SU2Text.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <set>
#include <string_view>
#include <system_error>

namespace dgmf
{
namespace meshfile
{
namespace fs = std::filesystem;

namespace
{
using namespace su2;

/// Everything the reader and the writer need from a parsed file.
struct ParsedFile
{
  NamedMesh Mesh;
  std::vector<std::size_t> PointLineBegins; ///< where each point's line starts in the text
};

/**
 * Parses the sections of one SU2 zone. The sections NDIME first, then NELEM, NPOIN and NMARK in
 * any order; other keywords before them are skipped.
 */
class SU2Parser
{
public:
  SU2Parser(const std::string& path, std::string_view text)
    : Path(path)
    , Reader(path, text)
  {
  }

  ParsedFile Parse();

private:
  void ParseKeywordLine(const TextLine& line, const Keyword& keyword);
  std::int64_t ParseCount(const TextLine& line, const Keyword& keyword, bool allowSecond);
  TextLine NextDataLine(const char* item, std::int64_t k, const std::string& section);
  void ParseCellLine(const TextLine& line, int dimension, const std::string& section, Cells& cells,
    std::vector<std::size_t>& lines);
  void ParseElements(const TextLine& line, const Keyword& keyword);
  void ParsePoints(const TextLine& line, const Keyword& keyword);
  void ParseMarkers(const TextLine& line, const Keyword& keyword);
  void CheckRest();
  void CheckNodeIndices(const Cells& cells, const std::vector<std::size_t>& lines);
  bool Complete() const { return this->HasElements && this->HasPoints && this->HasMarkers; }

  const std::string& Path;
  LineReader Reader;
  ParsedFile Result;
  int Dimension = 0;
  bool HasElements = false;
  bool HasPoints = false;
  bool HasMarkers = false;
  std::string LastSection; ///< for the hint on a line that no section expects
  /// The line of each volume cell and of each face of each marker, for the node-index check
  /// once NPOIN is known.
  std::vector<std::size_t> VolumeLines;
  std::vector<std::vector<std::size_t>> FaceLines;
};

ParsedFile SU2Parser::Parse()
{
  TextLine line;
  while (!this->Complete() && this->Reader.Next(line))
  {
    Keyword keyword;
    if (!SplitKeyword(line.Text, keyword))
    {
      this->Reader.Fail(line.Number,
        "expected a keyword line (NDIME=, NELEM=, NPOIN=, NMARK=), found " + Excerpt(line.Text) +
          (this->LastSection.empty() ? std::string()
                                     : " (more lines than " + this->LastSection + " says?)"));
    }
    this->ParseKeywordLine(line, keyword);
  }
  const std::pair<const char*, bool> sections[] = { { "NDIME", this->Dimension != 0 },
    { "NELEM", this->HasElements }, { "NPOIN", this->HasPoints }, { "NMARK", this->HasMarkers } };
  for (const auto& section : sections)
  {
    if (!section.second)
    {
      throw FileError(this->Path + ": no " + section.first + "= section (the file ends at line " +
        std::to_string(this->Reader.LastLineNumber()) + ")");
    }
  }
  this->CheckRest();
  NamedMesh& mesh = this->Result.Mesh;
  this->CheckNodeIndices(mesh.Volume, this->VolumeLines);
  for (std::size_t b = 0; b < mesh.Boundaries.size(); ++b)
  {
    this->CheckNodeIndices(mesh.Boundaries[b].Faces, this->FaceLines[b]);
  }
  ValidateNamedMesh(this->Result.Mesh, this->Path);
  return std::move(this->Result);
}

void SU2Parser::ParseKeywordLine(const TextLine& line, const Keyword& keyword)
{
  const std::string key(keyword.Key);
  const bool needsDimension = key == "NELEM" || key == "NPOIN" || key == "NMARK";
  if (needsDimension && this->Dimension == 0)
  {
    this->Reader.Fail(line.Number, key + "= comes before NDIME=");
  }
  const bool again = (key == "NELEM" && this->HasElements) || (key == "NPOIN" && this->HasPoints) ||
    (key == "NMARK" && this->HasMarkers);
  if (again || (key == "NDIME" && this->Dimension != 0))
  {
    this->Reader.Fail(line.Number, "a second " + key + "= (several zones are not supported)");
  }
  if (key == "NDIME")
  {
    const std::int64_t dimension = this->ParseCount(line, keyword, false);
    if (dimension != 2 && dimension != 3)
    {
      this->Reader.Fail(line.Number, "NDIME= must be 2 or 3");
    }
    this->Dimension = static_cast<int>(dimension);
    this->Result.Mesh.Dimension = this->Dimension;
  }
  else if (key == "NZONE" || key == "IZONE")
  {
    const std::int64_t zones = this->ParseCount(line, keyword, false);
    if (zones != 1)
    {
      this->Reader.Fail(
        line.Number, key + "= " + std::to_string(zones) + ": multi-zone files are not supported");
    }
  }
  else if (key == "NELEM")
  {
    this->ParseElements(line, keyword);
  }
  else if (key == "NPOIN")
  {
    this->ParsePoints(line, keyword);
  }
  else if (key == "NMARK")
  {
    this->ParseMarkers(line, keyword);
  }
  else if (key == "MARKER_TAG" || key == "MARKER_ELEMS")
  {
    this->Reader.Fail(line.Number, key + "= outside the NMARK= section (more markers than NMARK?)");
  }
  // Other keywords (before the four sections) are not ours: skipped.
}

std::int64_t SU2Parser::ParseCount(const TextLine& line, const Keyword& keyword, bool allowSecond)
{
  const std::string key(keyword.Key);
  const Tokens tokens = Split(keyword.Value);
  std::int64_t value = 0, second = 0;
  const bool counts = tokens.Count == 1 || (allowSecond && tokens.Count == 2);
  if (!counts || tokens.Overflow || !ToNumber(tokens.Items[0], value) || value < 0 ||
    (tokens.Count == 2 && (!ToNumber(tokens.Items[1], second) || second < 0)))
  {
    this->Reader.Fail(line.Number,
      key + "= needs a non-negative integer" + (allowSecond ? " (and optionally a second)" : "") +
        ", found " + Excerpt(keyword.Value));
  }
  return value;
}

/**
 * The line of data item `k` ("element", "point") of `section` ("NPOIN= 6"): an error at the end
 * of the file, or on a keyword line (the section's count is larger than its lines).
 */
TextLine SU2Parser::NextDataLine(const char* item, std::int64_t k, const std::string& section)
{
  TextLine line;
  Keyword keyword;
  const bool found = this->Reader.Next(line);
  if (!found || (line.Text.find('=') != std::string_view::npos && SplitKeyword(line.Text, keyword)))
  {
    const std::string what = item + (" " + std::to_string(k)) + " of " + section;
    if (!found)
    {
      this->Reader.FailAtEnd(what);
    }
    this->Reader.Fail(line.Number,
      "found " + Excerpt(Trim(line.Text)) + " where " + what + " should be (fewer lines than " +
        section + " says?)");
  }
  return line;
}

void SU2Parser::ParseCellLine(const TextLine& line, int dimension, const std::string& section,
  Cells& cells, std::vector<std::size_t>& lines)
{
  const Tokens tokens = Split(line.Text);
  std::int64_t type = 0;
  if (!ToNumber(tokens.Items[0], type) || type < 0 || type > 255 ||
    DimensionOfCellType(static_cast<std::uint8_t>(type)) != dimension)
  {
    this->Reader.Fail(line.Number,
      section + ": " + Excerpt(tokens.Items[0]) + " is not the VTK type of a " +
        std::to_string(dimension) + "D element this reader takes" +
        (dimension == 1      ? " (3)"
            : dimension == 2 ? " (5, 9)"
                             : " (10, 12, 13, 14)"));
  }
  const std::size_t nodes = NodesOfCellType(static_cast<std::uint8_t>(type));
  if (tokens.Overflow || tokens.Count < 1 + nodes || tokens.Count > 2 + nodes)
  {
    this->Reader.Fail(line.Number,
      section + ": an element of type " + std::to_string(type) + " needs " + std::to_string(nodes) +
        " node indices (and optionally its index), found " +
        (tokens.Overflow ? std::string("more than ") : std::string()) +
        std::to_string(tokens.Count - 1) + " values");
  }
  std::array<std::int64_t, 8> node{};
  for (std::size_t k = 1; k < tokens.Count; ++k)
  {
    std::int64_t value = 0;
    if (!ToNumber(tokens.Items[k], value) || (k <= nodes && value < 0))
    {
      this->Reader.Fail(line.Number,
        section + ": " + Excerpt(tokens.Items[k]) + " is not " +
          (k <= nodes ? "a node index (0-based)" : "an integer element index"));
    }
    if (k <= nodes)
    {
      node[k - 1] = value;
    }
  }
  cells.Add(static_cast<std::uint8_t>(type), node.data(), nodes);
  lines.push_back(line.Number);
}

void SU2Parser::ParseElements(const TextLine& line, const Keyword& keyword)
{
  const std::int64_t count = this->ParseCount(line, keyword, false);
  if (count == 0)
  {
    this->Reader.Fail(line.Number, "NELEM= 0: the mesh has no elements");
  }
  const std::string section = "NELEM= " + std::to_string(count);
  const std::size_t reserved =
    std::min(static_cast<std::size_t>(count), this->Reader.MaxRemainingLines());
  // Room for hexahedra (8 nodes, the most an SU2 element has): memory never written is never
  // faulted in, so the room that tetrahedra leave costs address space only. No more node indices
  // than the rest of the file can hold (two bytes each at least), whatever NELEM says.
  this->Result.Mesh.Volume.Reserve(
    reserved, std::min(8 * reserved, this->Reader.MaxRemainingLines()));
  ReserveOnHugePages(this->VolumeLines, reserved);
  const std::string where = "element of " + section;
  for (std::int64_t k = 0; k < count; ++k)
  {
    const TextLine element = this->NextDataLine("element", k, section);
    this->ParseCellLine(
      element, this->Dimension, where, this->Result.Mesh.Volume, this->VolumeLines);
  }
  this->HasElements = true;
  this->LastSection = section;
}

void SU2Parser::ParsePoints(const TextLine& line, const Keyword& keyword)
{
  const std::int64_t count = this->ParseCount(line, keyword, true);
  const std::string section = "NPOIN= " + std::to_string(count);
  const std::size_t reserved =
    std::min(static_cast<std::size_t>(count), this->Reader.MaxRemainingLines());
  NamedMesh& mesh = this->Result.Mesh;
  ReserveOnHugePages(mesh.Points, 3 * reserved);
  ReserveOnHugePages(this->Result.PointLineBegins, reserved);
  const std::size_t coordinates = static_cast<std::size_t>(this->Dimension);
  for (std::int64_t k = 0; k < count; ++k)
  {
    auto what = [k, &section]() { return "point " + std::to_string(k) + " of " + section; };
    const TextLine point = this->NextDataLine("point", k, section);
    const Tokens tokens = Split(point.Text);
    std::int64_t index = 0;
    if (tokens.Overflow || tokens.Count < coordinates || tokens.Count > coordinates + 1 ||
      (tokens.Count == coordinates + 1 && !ToNumber(tokens.Items[coordinates], index)))
    {
      this->Reader.Fail(point.Number,
        what() + ": expected " + std::to_string(coordinates) +
          " coordinates and optionally an integer index, found " + Excerpt(point.Text));
    }
    double xyz[3] = { 0.0, 0.0, 0.0 };
    for (std::size_t c = 0; c < coordinates; ++c)
    {
      if (!ToNumber(tokens.Items[c], xyz[c]))
      {
        this->Reader.Fail(
          point.Number, what() + ": " + Excerpt(tokens.Items[c]) + " is not a finite number");
      }
    }
    mesh.Points.insert(mesh.Points.end(), xyz, xyz + 3);
    this->Result.PointLineBegins.push_back(point.Begin);
  }
  mesh.NodeIds.resize(static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < mesh.NodeIds.size(); ++k)
  {
    mesh.NodeIds[k] = static_cast<std::int64_t>(k);
  }
  this->HasPoints = true;
  this->LastSection = section;
}

void SU2Parser::ParseMarkers(const TextLine& line, const Keyword& keyword)
{
  const std::int64_t count = this->ParseCount(line, keyword, false);
  std::vector<NamedBoundary>& boundaries = this->Result.Mesh.Boundaries;
  boundaries.reserve(std::min(static_cast<std::size_t>(count), this->Reader.MaxRemainingLines()));
  std::set<std::string> names;
  for (std::int64_t m = 0; m < count; ++m)
  {
    const std::string what = "marker " + std::to_string(m) + " of NMARK= " + std::to_string(count);
    const TextLine tagLine = this->Reader.Require("MARKER_TAG= of " + what);
    Keyword tag;
    if (!SplitKeyword(tagLine.Text, tag) || tag.Key != "MARKER_TAG" || tag.Value.empty())
    {
      this->Reader.Fail(tagLine.Number,
        what + ": expected MARKER_TAG= and a non-empty name, found " + Excerpt(tagLine.Text));
    }
    const std::string name(tag.Value);
    if (!names.insert(name).second)
    {
      this->Reader.Fail(tagLine.Number, what + ": a second marker named " + Excerpt(name));
    }
    const TextLine elemsLine = this->Reader.Require("MARKER_ELEMS= of " + what);
    Keyword elems;
    if (!SplitKeyword(elemsLine.Text, elems) || elems.Key != "MARKER_ELEMS")
    {
      this->Reader.Fail(elemsLine.Number,
        what + " (" + Excerpt(name) + "): expected MARKER_ELEMS=, found " +
          Excerpt(elemsLine.Text));
    }
    const std::int64_t faces = this->ParseCount(elemsLine, elems, false);
    boundaries.emplace_back();
    boundaries.back().Name = name;
    this->FaceLines.emplace_back();
    const std::string section =
      "marker " + Excerpt(name) + " (MARKER_ELEMS= " + std::to_string(faces) + ")";
    for (std::int64_t k = 0; k < faces; ++k)
    {
      const TextLine face = this->NextDataLine("element", k, section);
      this->ParseCellLine(
        face, this->Dimension - 1, section, boundaries.back().Faces, this->FaceLines.back());
    }
    this->LastSection = section;
  }
  this->HasMarkers = true;
}

/**
 * After the four sections: comments, blank lines and other keyword sections (FFD boxes) may
 * follow; a data line right after the last section, or a second zone's section, is an error.
 */
void SU2Parser::CheckRest()
{
  TextLine line;
  bool inOtherSection = false;
  while (this->Reader.Next(line))
  {
    Keyword keyword;
    if (!SplitKeyword(line.Text, keyword))
    {
      if (!inOtherSection)
      {
        this->Reader.Fail(line.Number,
          "unexpected line " + Excerpt(line.Text) + " (more lines than " + this->LastSection +
            " says?)");
      }
      continue;
    }
    const std::string key(keyword.Key);
    if (key == "NDIME" || key == "NELEM" || key == "NPOIN" || key == "NMARK" || key == "NZONE" ||
      key == "IZONE" || key == "MARKER_TAG" || key == "MARKER_ELEMS")
    {
      this->Reader.Fail(line.Number,
        "a second " + key + "= after the mesh (multi-zone files are not supported, or more " +
          "markers than NMARK= says)");
    }
    inOtherSection = true;
  }
}

void SU2Parser::CheckNodeIndices(const Cells& cells, const std::vector<std::size_t>& lines)
{
  const std::size_t nodes = this->Result.Mesh.NumberOfNodes();
  for (std::size_t c = 0; c < cells.Size(); ++c)
  {
    for (std::int64_t k = cells.Offsets[c]; k < cells.Offsets[c + 1]; ++k)
    {
      const std::int64_t node = cells.Connectivity[static_cast<std::size_t>(k)];
      if (node < 0 || static_cast<std::size_t>(node) >= nodes)
      {
        this->Reader.Fail(lines[c],
          "node index " + std::to_string(node) + " is outside 0.." +
            std::to_string(nodes == 0 ? 0 : nodes - 1) + " (NPOIN= " + std::to_string(nodes) + ")");
      }
    }
  }
}

/// Refuses a directory by name (before its bytes are asked for).
void RefuseDirectory(const std::string& path)
{
  std::error_code error;
  if (fs::is_directory(path, error))
  {
    throw FileError(path + ": is a directory, not an SU2 file");
  }
}

/// Writes `value` with 17 significant digits (reads back as the same double; no locale) into
/// `buffer` (32 characters at least); returns its length.
std::size_t FormatCoordinate(char* buffer, double value)
{
  const std::to_chars_result written =
    std::to_chars(buffer, buffer + 32, value, std::chars_format::general, 17);
  return static_cast<std::size_t>(written.ptr - buffer);
}

/**
 * What the writer needs of the last file the reader parsed, with its bytes' size and hash: the
 * command and ParaView write back the file they read, and the writer, given the same bytes, skips
 * a second parse (0.2 s of 0.5 s for a 62 MB file). A file whose bytes differ is parsed again.
 */
struct LastParsed
{
  std::size_t Size = 0;
  std::size_t Hash = 0;
  int Dimension = 0;
  std::vector<std::size_t> PointLineBegins;
};

std::mutex LastParsedMutex;
LastParsed TheLastParsed; ///< guarded by LastParsedMutex

std::size_t HashOf(std::string_view text)
{
  return std::hash<std::string_view>()(text);
}

/// The dimension and point lines of `text` (from the last read when it had these bytes).
LastParsed PointsOf(const std::string& path, std::string_view text)
{
  const std::size_t hash = HashOf(text);
  {
    const std::lock_guard<std::mutex> lock(LastParsedMutex);
    if (TheLastParsed.Size == text.size() && TheLastParsed.Hash == hash &&
      !TheLastParsed.PointLineBegins.empty())
    {
      return TheLastParsed;
    }
  }
  ParsedFile parsed = SU2Parser(path, text).Parse();
  return { text.size(), hash, parsed.Mesh.Dimension, std::move(parsed.PointLineBegins) };
}
} // namespace

NamedMesh ReadSU2(const std::string& path)
{
  RefuseDirectory(path);
  const MappedFile file(path);
  const std::string_view text = file.Bytes();
  ParsedFile parsed = SU2Parser(path, text).Parse();
  const std::size_t hash = HashOf(text);
  const std::lock_guard<std::mutex> lock(LastParsedMutex);
  TheLastParsed = { text.size(), hash, parsed.Mesh.Dimension, std::move(parsed.PointLineBegins) };
  return std::move(parsed.Mesh);
}

void WriteSU2WithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count)
{
  RefuseDirectory(source);
  const MappedFile file(source);
  const std::string_view text = file.Bytes();
  const LastParsed parsed = PointsOf(source, text);
  const std::size_t expected = parsed.PointLineBegins.size();
  if (count != expected || points == nullptr)
  {
    throw FileError(target + ": " + std::to_string(count) + " points given for " + source +
      ", whose NPOIN= is " + std::to_string(expected) + "; nothing written");
  }
  const std::size_t dimension = static_cast<std::size_t>(parsed.Dimension);
  for (std::size_t k = 0; k < count; ++k)
  {
    for (std::size_t c = 0; c < dimension; ++c)
    {
      if (!std::isfinite(points[3 * k + c]))
      {
        throw FileError(target + ": point " + std::to_string(k) +
          " has a non-finite coordinate; nothing written");
      }
    }
  }
  // Written in pieces (the text between the coordinates as it is), never whole in memory.
  const fs::path path(target);
  WriteFileAtomically(target,
    (path.parent_path() / ("." + path.filename().string() + ".dgmf-writing")).string(),
    [&](BufferedOutput& out)
    {
      std::size_t copied = 0;
      char number[32];
      for (std::size_t k = 0; k < count; ++k)
      {
        const std::size_t begin = parsed.PointLineBegins[k];
        const std::size_t end = std::min(text.find('\n', begin), text.size());
        const Tokens tokens = Split(text.substr(begin, end - begin));
        for (std::size_t c = 0; c < dimension; ++c)
        {
          const std::size_t at = static_cast<std::size_t>(tokens.Items[c].data() - text.data());
          out.Append(text.data() + copied, at - copied);
          out.Append(number, FormatCoordinate(number, points[3 * k + c]));
          copied = at + tokens.Items[c].size();
        }
      }
      out.Append(text.data() + copied, text.size() - copied);
    });
}

} // namespace meshfile
} // namespace dgmf
