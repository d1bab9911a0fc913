/**
 * @file MshText.h
 * @brief Private to the .msh code that reads files without gmsh (MshNodes.cxx, MshModel.cxx,
 * MshReader41.cxx, MshReader22.cxx): a cursor over a file's bytes that reads tokens, lines and
 * binary values, never past the end.
 */
#ifndef dgmf_meshfile_MshText_h
#define dgmf_meshfile_MshText_h

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>

namespace dgmf
{
namespace meshfile
{
namespace msh
{
constexpr bool IsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

inline std::string_view Trim(std::string_view text)
{
  while (!text.empty() && IsBlank(text.front()))
  {
    text.remove_prefix(1);
  }
  while (!text.empty() && IsBlank(text.back()))
  {
    text.remove_suffix(1);
  }
  return text;
}

template <typename T>
inline bool ToInteger(std::string_view token, T& value)
{
  const char* end = token.data() + token.size();
  const std::from_chars_result read = std::from_chars(token.data(), end, value);
  return !token.empty() && read.ec == std::errc() && read.ptr == end;
}

/// A position in the file, read as text (tokens, lines) or as binary values; nothing past its end.
struct Cursor
{
  std::string_view File;
  std::size_t At = 0;

  /// The next whitespace-separated token; empty at the end of the file.
  std::string_view Token()
  {
    while (this->At < this->File.size() && IsBlank(this->File[this->At]))
    {
      ++this->At;
    }
    const std::size_t begin = this->At;
    while (this->At < this->File.size() && !IsBlank(this->File[this->At]))
    {
      ++this->At;
    }
    return this->File.substr(begin, this->At - begin);
  }

  /// The rest of the line (trimmed); the cursor moves past its '\n'.
  std::string_view Line()
  {
    const std::size_t end = this->File.find('\n', this->At);
    const std::size_t stop = end == std::string_view::npos ? this->File.size() : end;
    const std::string_view line = this->File.substr(this->At, stop - this->At);
    this->At = end == std::string_view::npos ? this->File.size() : end + 1;
    return Trim(line);
  }

  template <typename T>
  bool Binary(T& value)
  {
    if (this->File.size() - this->At < sizeof(T))
    {
      return false;
    }
    std::memcpy(&value, this->File.data() + this->At, sizeof(T));
    this->At += sizeof(T);
    return true;
  }

  bool Skip(std::uint64_t bytes)
  {
    if (this->File.size() - this->At < bytes)
    {
      return false;
    }
    this->At += static_cast<std::size_t>(bytes);
    return true;
  }

  /// Where `token` (a view into File) starts.
  std::size_t Offset(std::string_view token) const
  {
    return static_cast<std::size_t>(token.data() - this->File.data());
  }
};

/// Numbers in a file's mode: tokens (ASCII), or binary values of this machine's order (int 4
/// bytes, size_t 8, double 8: the "8" of the format line).
class Values
{
public:
  Values(Cursor& cursor, bool binary)
    : At(cursor)
    , Binary(binary)
  {
  }

  bool Int(int& value)
  {
    if (this->Binary)
    {
      std::int32_t read = 0;
      const bool ok = this->At.Binary(read);
      value = read;
      return ok;
    }
    return ToInteger(this->At.Token(), value);
  }

  bool Size(std::uint64_t& value)
  {
    return this->Binary ? this->At.Binary(value) : ToInteger(this->At.Token(), value);
  }

  bool Real(double& value)
  {
    if (this->Binary)
    {
      return this->At.Binary(value);
    }
    const std::string_view token = this->At.Token();
    const char* end = token.data() + token.size();
    const std::from_chars_result read = std::from_chars(token.data(), end, value);
    return !token.empty() && read.ec == std::errc() && read.ptr == end;
  }

  /// Bytes left in the file.
  std::size_t Left() const { return this->At.File.size() - this->At.At; }

private:
  Cursor& At;
  bool Binary;
};

/// Reads the token "$End<name>".
inline bool EndsSection(Cursor& cursor, std::string_view name)
{
  const std::string_view token = cursor.Token();
  return token.size() == name.size() + 4 && token.substr(0, 4) == "$End" && token.substr(4) == name;
}

/**
 * The name of the section that starts at the cursor (the line "$Name", blank lines before it
 * skipped); the cursor is then after that line. Empty at the end of the file, or when the next
 * line does not start a section (the cursor then at that line).
 */
inline std::string_view NextSection(Cursor& cursor)
{
  while (cursor.At < cursor.File.size())
  {
    const std::size_t start = cursor.At;
    const std::string_view line = cursor.Line();
    if (!line.empty())
    {
      if (line.front() == '$' && line.size() > 1)
      {
        return line.substr(1);
      }
      cursor.At = start; // not a section: the cursor stays at that line
      break;
    }
  }
  return std::string_view();
}

/// Moves the cursor past the line "$End<name>" that ends section `name`; false if there is none.
inline bool SkipSection(Cursor& cursor, std::string_view name)
{
  const std::string end = "\n$End" + std::string(name);
  const std::size_t found = cursor.File.find(end, cursor.At == 0 ? 0 : cursor.At - 1);
  if (found == std::string_view::npos)
  {
    return false;
  }
  cursor.At = found + 1;
  cursor.Line();
  return true;
}

/**
 * Reads the $MeshFormat section at the start of the file; for a binary file, checks that the
 * integer 1 after the version line reads as 1 on this machine. False otherwise (the other byte
 * order, or no such section).
 */
inline bool ReadMeshFormat(Cursor& cursor, bool binary)
{
  if (NextSection(cursor) != "MeshFormat")
  {
    return false;
  }
  if (binary)
  {
    cursor.Line(); // "<version> 1 8"
    std::int32_t one = 0;
    if (!cursor.Binary(one) || one != 1)
    {
      return false;
    }
  }
  return SkipSection(cursor, "MeshFormat");
}

/// Whether only blanks are left after the cursor (no line outside a section).
inline bool OnlyBlanksLeft(const Cursor& cursor)
{
  for (std::size_t at = cursor.At; at < cursor.File.size(); ++at)
  {
    if (!IsBlank(cursor.File[at]))
    {
      return false;
    }
  }
  return true;
}

/// What a reader did with a section (WalkSections).
enum class SectionRead
{
  Parsed,  ///< read to its $End line
  Refused, ///< the file is left to gmsh
  Unknown  ///< not the reader's: skipped to its $End line
};

/**
 * Reads the sections after $MeshFormat to the end of the file: `read(name)` for each (the cursor
 * after the "$name" line); an Unknown section is skipped to its $End line (comments, periodicity,
 * post-processing data). False when a section is Refused or cannot be skipped, or when a line
 * outside any section is left.
 */
template <typename Read>
bool WalkSections(Cursor& cursor, Read read)
{
  for (std::string_view name = NextSection(cursor); !name.empty(); name = NextSection(cursor))
  {
    const SectionRead result = read(name);
    if (result == SectionRead::Refused ||
      (result == SectionRead::Unknown && !SkipSection(cursor, name)))
    {
      return false;
    }
  }
  return OnlyBlanksLeft(cursor);
}

} // namespace msh
} // namespace meshfile
} // namespace dgmf

#endif
