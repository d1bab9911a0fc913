#include "dgmf/openfoam/PointsFile.h"

#include "dgmf/openfoam/FoamFileText.h"

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <system_error>

namespace dgmf
{
namespace openfoam
{
namespace fs = std::filesystem;

namespace
{
[[noreturn]] void Fail(const fs::path& file, const std::string& what)
{
  throw std::runtime_error("OpenFOAM points file " + file.string() + ": " + what);
}

/// Parses the ASCII list of `count` vectors "(x y z)" from `at` (just after the list's '(').
std::size_t ParseAsciiPoints(
  const fs::path& file, const std::string& text, std::size_t at, std::vector<double>& points)
{
  const char* end = text.data() + text.size();
  for (std::size_t k = 0; k < points.size(); k += 3)
  {
    at = SkipSpaceAndComments(text, at);
    if (at >= text.size() || text[at] != '(')
    {
      Fail(file, "point " + std::to_string(k / 3) + " does not start with '('");
    }
    ++at;
    for (int c = 0; c < 3; ++c)
    {
      at = SkipSpaceAndComments(text, at);
      const char* first = text.data() + at;
      if (first < end && *first == '+')
      {
        ++first; // from_chars does not take a leading '+'
      }
      const std::from_chars_result read = std::from_chars(first, end, points[k + c]);
      if (read.ec != std::errc())
      {
        Fail(file, "point " + std::to_string(k / 3) + " has an unreadable coordinate");
      }
      at = static_cast<std::size_t>(read.ptr - text.data());
    }
    at = SkipSpaceAndComments(text, at);
    if (at >= text.size() || text[at] != ')')
    {
      Fail(file, "point " + std::to_string(k / 3) + " does not have 3 coordinates");
    }
    ++at;
  }
  return at;
}

/// Reverses the bytes of each `width`-byte value of `data` (a big-endian file on this machine).
void SwapBytes(char* data, std::size_t bytes, std::size_t width)
{
  for (std::size_t k = 0; k + width <= bytes; k += width)
  {
    for (std::size_t a = 0, b = width - 1; a < b; ++a, --b)
    {
      std::swap(data[k + a], data[k + b]);
    }
  }
}

bool LittleEndianMachine()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Appends the shortest text that reads back as `value`.
void AppendNumber(std::string& out, double value)
{
  char buffer[32];
  const std::to_chars_result written = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, written.ptr);
}

/// Writes `bytes` to `file`, through gzip when `compressed`.
void WriteAll(const fs::path& file, const std::string& bytes, bool compressed)
{
  gzFile out = gzopen(file.string().c_str(), compressed ? "wb6" : "wbT"); // T: no compression
  if (!out)
  {
    Fail(file, "cannot be created");
  }
  std::size_t done = 0;
  bool ok = true;
  while (ok && done < bytes.size())
  {
    const unsigned chunk =
      static_cast<unsigned>(std::min<std::size_t>(bytes.size() - done, 1u << 30));
    ok = gzwrite(out, bytes.data() + done, chunk) == static_cast<int>(chunk);
    done += chunk;
  }
  if (gzclose(out) != Z_OK || !ok)
  {
    std::error_code ignored;
    fs::remove(file, ignored);
    Fail(file, "could not be written completely (disk full?)");
  }
}
} // namespace

fs::path FindPointsFile(const fs::path& polyMesh)
{
  std::error_code error;
  for (const char* name : { "points", "points.gz" })
  {
    if (fs::is_regular_file(polyMesh / name, error))
    {
      return polyMesh / name;
    }
  }
  return fs::path();
}

PointsFile ReadPointsFile(const fs::path& file)
{
  const std::string text = ReadFoamText(file);
  const FoamHeader header = ParseFoamHeader(text);
  if (!header.Found)
  {
    Fail(file, "no FoamFile header");
  }
  PointsFile result;
  result.Compressed = file.extension() == ".gz";
  const std::string format = header.Get("format");
  if (format == "binary")
  {
    result.BodyFormat = Format::Binary;
  }
  else if (format != "ascii")
  {
    Fail(file, "unknown format '" + format + "'");
  }
  std::size_t at = SkipSpaceAndComments(text, header.End);
  result.Preamble = text.substr(0, at);
  std::size_t count = 0;
  const std::from_chars_result read =
    std::from_chars(text.data() + at, text.data() + text.size(), count);
  if (read.ec != std::errc())
  {
    Fail(file, "no point count after the header");
  }
  at = SkipSpaceAndComments(text, static_cast<std::size_t>(read.ptr - text.data()));
  if (at >= text.size() || text[at] != '(')
  {
    Fail(file, "the list of " + std::to_string(count) + " points does not start with '('");
  }
  ++at;
  result.Points.resize(3 * count);
  if (result.BodyFormat == Format::Ascii)
  {
    at = ParseAsciiPoints(file, text, at, result.Points);
    at = SkipSpaceAndComments(text, at);
  }
  else
  {
    const ArchInfo arch = ParseArch(header.Get("arch"));
    if (arch.ScalarBytes != 8 && arch.ScalarBytes != 4)
    {
      Fail(file, "binary scalars of " + std::to_string(arch.ScalarBytes) + " bytes");
    }
    const std::size_t bytes = 3 * count * arch.ScalarBytes;
    if (text.size() - at < bytes + 1)
    {
      Fail(file, "the binary list is shorter than " + std::to_string(count) + " points");
    }
    std::string raw = text.substr(at, bytes);
    if (arch.LittleEndian != LittleEndianMachine())
    {
      SwapBytes(&raw[0], raw.size(), arch.ScalarBytes);
    }
    for (std::size_t k = 0; k < 3 * count; ++k)
    {
      if (arch.ScalarBytes == 8)
      {
        std::memcpy(&result.Points[k], raw.data() + 8 * k, 8);
      }
      else
      {
        float value = 0.0f;
        std::memcpy(&value, raw.data() + 4 * k, 4);
        result.Points[k] = value;
      }
    }
    at += bytes;
  }
  if (at >= text.size() || text[at] != ')')
  {
    Fail(file, "the list of " + std::to_string(count) + " points does not end with ')'");
  }
  result.Epilogue = text.substr(at + 1);
  return result;
}

fs::path WritePointsFile(const fs::path& polyMesh, const PointsFile& like, const double* xyz,
  std::size_t numberOfPoints, const std::string& location)
{
  std::string body = SetHeaderEntry(like.Preamble, "location", "\"" + location + "\"");
  const std::size_t values = 3 * numberOfPoints;
  body += std::to_string(numberOfPoints);
  if (like.BodyFormat == Format::Ascii)
  {
    body.reserve(body.size() + 24 * values + 16);
    body += "\n(\n";
    for (std::size_t k = 0; k < values; k += 3)
    {
      body += '(';
      AppendNumber(body, xyz[k]);
      body += ' ';
      AppendNumber(body, xyz[k + 1]);
      body += ' ';
      AppendNumber(body, xyz[k + 2]);
      body += ")\n";
    }
    body += ')';
  }
  else
  {
    const ArchInfo arch = ParseArch(FoamHeaderEntry(like.Preamble, "arch"));
    const std::size_t start = body.size() + 2;
    body += "\n(";
    body.resize(start + values * arch.ScalarBytes);
    for (std::size_t k = 0; k < values; ++k)
    {
      if (arch.ScalarBytes == 8)
      {
        std::memcpy(&body[start + 8 * k], xyz + k, 8);
      }
      else
      {
        const float value = static_cast<float>(xyz[k]);
        std::memcpy(&body[start + 4 * k], &value, 4);
      }
    }
    if (arch.LittleEndian != LittleEndianMachine())
    {
      SwapBytes(&body[start], values * arch.ScalarBytes, arch.ScalarBytes);
    }
    body += ')';
  }
  body += like.Epilogue;

  std::error_code error;
  fs::create_directories(polyMesh, error);
  const char* name = like.Compressed ? "points.gz" : "points";
  const char* other = like.Compressed ? "points" : "points.gz";
  const fs::path target = polyMesh / name;
  const fs::path temporary = polyMesh / (std::string(".") + name + ".dgmf-writing");
  WriteAll(temporary, body, like.Compressed);
  fs::rename(temporary, target, error);
  if (error)
  {
    fs::remove(temporary, error);
    Fail(target, "cannot be replaced: " + error.message());
  }
  fs::remove(polyMesh / other, error); // it would shadow the new file, or be shadowed by it
  return target;
}

} // namespace openfoam
} // namespace dgmf
