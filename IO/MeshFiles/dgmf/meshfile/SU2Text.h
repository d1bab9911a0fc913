/**
 * @file SU2Text.h
 * @brief The text layer of the SU2 reader (private to SU2File.cxx): lines with their numbers,
 * tokens, numbers read whole, keywords; and the excerpts error messages quote.
 */
#ifndef dgmf_meshfile_SU2Text_h
#define dgmf_meshfile_SU2Text_h

#include "dgmf/meshfile/NamedMesh.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

namespace dgmf
{
namespace meshfile
{
namespace su2
{
/// One line of the file: its text without the line end, its number (from 1), where it starts.
struct TextLine
{
  std::string_view Text;
  std::size_t Number = 0;
  std::size_t Begin = 0;
};

/// The whitespace-separated tokens of a line (at most Capacity; Overflow says there were more).
struct Tokens
{
  static constexpr std::size_t Capacity = 12;
  std::array<std::string_view, Capacity> Items;
  std::size_t Count = 0;
  bool Overflow = false;
};

/// Whether `c` separates tokens: ' ', '\t', '\r' (before the '\n' included), '\v', '\f'.
/// (string_view's find_first_of on a set of them calls memchr on the set for each character: a
/// sixth of a large file's read went there.)
constexpr bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

inline std::string_view Trim(std::string_view text)
{
  std::size_t first = 0, last = text.size();
  while (first < last && IsSpace(text[first]))
  {
    ++first;
  }
  while (last > first && IsSpace(text[last - 1]))
  {
    --last;
  }
  return text.substr(first, last - first);
}

inline Tokens Split(std::string_view text)
{
  Tokens tokens;
  const std::size_t size = text.size();
  std::size_t begin = 0;
  for (;;)
  {
    while (begin < size && IsSpace(text[begin]))
    {
      ++begin;
    }
    if (begin == size)
    {
      break;
    }
    if (tokens.Count == Tokens::Capacity)
    {
      tokens.Overflow = true;
      break;
    }
    std::size_t end = begin;
    while (end < size && !IsSpace(text[end]))
    {
      ++end;
    }
    tokens.Items[tokens.Count++] = text.substr(begin, end - begin);
    begin = end;
  }
  return tokens;
}

/// The first characters of `text` for a message, with unprintable bytes shown as '?'.
inline std::string Excerpt(std::string_view text)
{
  std::string shown(text.substr(0, 40));
  for (char& c : shown)
  {
    c = (c < 32 || c > 126) ? '?' : c;
  }
  return "'" + shown + (text.size() > 40 ? "...'" : "'");
}

/**
 * True if all of `token` is a number of type T (for doubles: finite). A leading '+' is taken
 * (from_chars does not take one), but not "+-" or "++".
 */
template <typename T>
inline bool ToNumber(std::string_view token, T& value)
{
  if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-')
  {
    token.remove_prefix(1);
  }
  const char* end = token.data() + token.size();
  const std::from_chars_result read = std::from_chars(token.data(), end, value);
  return !token.empty() && read.ec == std::errc() && read.ptr == end && std::isfinite(value);
}

/**
 * Gives the lines of a file one by one, without blank lines and comments (lines whose first
 * non-blank character is '%'), and makes the errors that name the file and the line.
 */
class LineReader
{
public:
  LineReader(const std::string& path, std::string_view text)
    : Path(path)
    , Text(text)
  {
  }

  /// The next line with content; false at the end of the file.
  bool Next(TextLine& line)
  {
    while (this->At < this->Text.size())
    {
      const std::size_t begin = this->At;
      std::size_t end = this->Text.find('\n', begin);
      end = end == std::string::npos ? this->Text.size() : end;
      this->At = end + 1;
      ++this->Number;
      const std::string_view text(this->Text.data() + begin, end - begin);
      const std::string_view content = Trim(text);
      if (!content.empty() && content.front() != '%')
      {
        line.Text = text.back() == '\r' ? text.substr(0, text.size() - 1) : text;
        line.Number = this->Number;
        line.Begin = begin;
        return true;
      }
    }
    return false;
  }

  /// How many more lines the rest of the file could hold at most (a bound for reserve()).
  std::size_t MaxRemainingLines() const
  {
    return this->At >= this->Text.size() ? 0 : (this->Text.size() - this->At) / 2 + 1;
  }

  std::size_t LastLineNumber() const { return this->Number; }

  [[noreturn]] void Fail(std::size_t line, const std::string& what) const
  {
    throw FileError(this->Path + ":" + std::to_string(line) + ": " + what);
  }

  /// The error for a file that ends where `expected` should follow.
  [[noreturn]] void FailAtEnd(const std::string& expected) const
  {
    throw FileError(this->Path + ": the file ends (after line " + std::to_string(this->Number) +
      ") where " + expected + " should follow");
  }

  /// The next line with content, or the error for a file that ends where `expected` should be.
  TextLine Require(const std::string& expected)
  {
    TextLine line;
    if (!this->Next(line))
    {
      this->FailAtEnd(expected);
    }
    return line;
  }

private:
  const std::string& Path;
  std::string_view Text;
  std::size_t At = 0;
  std::size_t Number = 0;
};

/// A "KEY= value" line: KEY is upper-case letters, digits and '_'.
struct Keyword
{
  std::string_view Key;
  std::string_view Value;
};

inline bool SplitKeyword(std::string_view text, Keyword& keyword)
{
  const std::size_t equal = text.find('=');
  if (equal == std::string_view::npos)
  {
    return false;
  }
  keyword.Key = Trim(text.substr(0, equal));
  keyword.Value = Trim(text.substr(equal + 1));
  return !keyword.Key.empty() &&
    std::all_of(keyword.Key.begin(), keyword.Key.end(),
      [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; });
}
} // namespace su2
} // namespace meshfile
} // namespace dgmf

#endif
