#include "dgmf/openfoam/FoamFileText.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace dgmf
{
namespace openfoam
{
namespace
{
bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/// Where the FoamFile dictionary's '{' and '}' are, or npos.
void FindHeader(const std::string& text, std::size_t& open, std::size_t& close)
{
  open = close = std::string::npos;
  std::size_t at = 0;
  while ((at = text.find("FoamFile", at)) != std::string::npos)
  {
    // A keyword, not a word inside a comment line or another word.
    const bool wordStart = at == 0 || std::isspace(static_cast<unsigned char>(text[at - 1]));
    const std::size_t brace = text.find_first_not_of(" \t\r\n", at + 8);
    if (wordStart && brace != std::string::npos && text[brace] == '{')
    {
      // Its closing brace: not one inside a quoted entry or a comment (OpenFOAM reads those).
      open = brace;
      bool quoted = false;
      for (std::size_t k = brace + 1; k < text.size(); ++k)
      {
        if (text[k] == '"')
        {
          quoted = !quoted;
        }
        else if (quoted)
        {
          continue;
        }
        else if (text.compare(k, 2, "//") == 0)
        {
          k = std::min(text.find('\n', k), text.size()); // to the line's end
        }
        else if (text.compare(k, 2, "/*") == 0)
        {
          const std::size_t end = text.find("*/", k + 2);
          k = end == std::string::npos ? text.size() : end + 1;
        }
        else if (text[k] == '}')
        {
          close = k;
          return;
        }
      }
      return;
    }
    at += 8;
  }
}

/// The first ';' from `at` that is not inside double quotes (arch "LSB;label=32;scalar=64";).
std::size_t FindEntryEnd(const std::string& text, std::size_t at)
{
  bool quoted = false;
  for (; at < text.size(); ++at)
  {
    if (text[at] == '"')
    {
      quoted = !quoted;
    }
    else if (text[at] == ';' && !quoted)
    {
      return at;
    }
  }
  return std::string::npos;
}

/// The entries "keyword value;" between `begin` and `end`.
std::map<std::string, std::string> ParseEntries(
  const std::string& text, std::size_t begin, std::size_t end)
{
  std::map<std::string, std::string> values;
  std::size_t at = begin;
  while (at < end)
  {
    const std::size_t semicolon = FindEntryEnd(text, at);
    if (semicolon == std::string::npos || semicolon > end)
    {
      break;
    }
    std::string entry = text.substr(at, semicolon - at);
    // Skip the comments inside the entry: block comments, then comment lines.
    std::size_t comment;
    while ((comment = entry.find("/*")) != std::string::npos)
    {
      const std::size_t blockEnd = entry.find("*/", comment + 2);
      entry.erase(
        comment, blockEnd == std::string::npos ? std::string::npos : blockEnd + 2 - comment);
    }
    while ((comment = entry.find("//")) != std::string::npos)
    {
      const std::size_t lineEnd = entry.find('\n', comment);
      entry.erase(comment, lineEnd == std::string::npos ? std::string::npos : lineEnd - comment);
    }
    const std::size_t keyStart = entry.find_first_not_of(" \t\r\n");
    if (keyStart != std::string::npos)
    {
      const std::size_t keyEnd = entry.find_first_of(" \t\r\n", keyStart);
      const std::string keyword = entry.substr(keyStart, keyEnd - keyStart);
      std::string value;
      if (keyEnd != std::string::npos)
      {
        const std::size_t valueStart = entry.find_first_not_of(" \t\r\n", keyEnd);
        const std::size_t valueEnd = entry.find_last_not_of(" \t\r\n");
        if (valueStart != std::string::npos)
        {
          value = entry.substr(valueStart, valueEnd + 1 - valueStart);
        }
      }
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
      {
        value = value.substr(1, value.size() - 2);
      }
      values[keyword] = value;
    }
    at = semicolon + 1;
  }
  return values;
}
} // namespace

std::string ReadFoamText(const std::filesystem::path& file)
{
  gzFile in = gzopen(file.string().c_str(), "rb");
  if (!in)
  {
    throw std::runtime_error(file.string() + " cannot be opened");
  }
  std::unique_ptr<gzFile_s, int (*)(gzFile)> closer(in, gzclose);
  std::string text;
  char buffer[1 << 16];
  int count = 0;
  while ((count = gzread(in, buffer, sizeof(buffer))) > 0)
  {
    text.append(buffer, static_cast<std::size_t>(count));
  }
  if (count < 0)
  {
    throw std::runtime_error(file.string() + " cannot be read (a damaged gzip stream?)");
  }
  return text;
}

std::size_t SkipSpaceAndComments(const std::string& text, std::size_t at)
{
  while (at < text.size())
  {
    if (IsSpace(text[at]))
    {
      ++at;
    }
    else if (text.compare(at, 2, "//") == 0)
    {
      at = text.find('\n', at);
      at = at == std::string::npos ? text.size() : at + 1;
    }
    else if (text.compare(at, 2, "/*") == 0)
    {
      at = text.find("*/", at + 2);
      at = at == std::string::npos ? text.size() : at + 2;
    }
    else
    {
      break;
    }
  }
  return at;
}

std::string FoamHeader::Get(const std::string& keyword) const
{
  const auto found = this->Values.find(keyword);
  return found == this->Values.end() ? std::string() : found->second;
}

FoamHeader ParseFoamHeader(const std::string& text)
{
  FoamHeader header;
  std::size_t open = 0, close = 0;
  FindHeader(text, open, close);
  if (open == std::string::npos || close == std::string::npos)
  {
    return header;
  }
  header.Found = true;
  header.End = close + 1;
  header.Values = ParseEntries(text, open + 1, close);
  return header;
}

std::string FoamHeaderEntry(const std::string& text, const std::string& keyword)
{
  return ParseFoamHeader(text).Get(keyword);
}

std::string FoamTopLevelEntry(const std::string& text, const std::string& keyword)
{
  const FoamHeader header = ParseFoamHeader(text);
  std::size_t at = header.Found ? header.End : 0;
  std::string found;
  while ((at = SkipSpaceAndComments(text, at)) < text.size())
  {
    const std::size_t wordEnd = text.find_first_of(" \t\r\n{;", at);
    if (wordEnd == std::string::npos)
    {
      break;
    }
    const std::string word = text.substr(at, wordEnd - at);
    if (!word.empty() && word[0] == '#') // a directive (#include "..."): one line
    {
      at = text.find('\n', at);
      at = at == std::string::npos ? text.size() : at + 1;
      continue;
    }
    const std::size_t next = SkipSpaceAndComments(text, wordEnd);
    if (next < text.size() && text[next] == '{') // a sub-dictionary: skipped whole
    {
      int depth = 0;
      for (at = next; at < text.size(); ++at)
      {
        depth += text[at] == '{' ? 1 : text[at] == '}' ? -1 : 0;
        if (depth == 0)
        {
          break;
        }
      }
      ++at;
      continue;
    }
    const std::size_t semicolon = FindEntryEnd(text, wordEnd);
    if (semicolon == std::string::npos)
    {
      break;
    }
    if (word == keyword) // the last entry of a keyword is the one OpenFOAM takes
    {
      const std::size_t valueStart = SkipSpaceAndComments(text, wordEnd);
      found = text.substr(valueStart, semicolon - valueStart);
      found.erase(found.find_last_not_of(" \t\r\n") + 1);
    }
    at = semicolon + 1;
  }
  return found;
}

std::string SetHeaderEntry(
  const std::string& text, const std::string& keyword, const std::string& value)
{
  std::size_t open = 0, close = 0;
  FindHeader(text, open, close);
  if (open == std::string::npos || close == std::string::npos)
  {
    return text;
  }
  // An existing entry: a line whose first word is the keyword.
  std::size_t at = open + 1;
  while (at < close)
  {
    const std::size_t lineEnd = std::min(text.find('\n', at), close);
    const std::size_t wordStart = text.find_first_not_of(" \t", at);
    if (wordStart < lineEnd && text.compare(wordStart, keyword.size(), keyword) == 0 &&
      wordStart + keyword.size() < lineEnd &&
      std::isspace(static_cast<unsigned char>(text[wordStart + keyword.size()])))
    {
      const std::size_t valueStart = text.find_first_not_of(" \t", wordStart + keyword.size());
      const std::size_t semicolon = FindEntryEnd(text, valueStart);
      if (semicolon != std::string::npos && semicolon < close)
      {
        return text.substr(0, valueStart) + value + text.substr(semicolon);
      }
    }
    at = lineEnd + 1;
  }
  // A new entry, before the closing brace, aligned as OpenFOAM writes them.
  std::string padded = keyword;
  padded.resize(std::max<std::size_t>(keyword.size() + 1, 12), ' ');
  return text.substr(0, close) + "    " + padded + value + ";\n" + text.substr(close);
}

ArchInfo ParseArch(const std::string& arch)
{
  ArchInfo info;
  if (arch.find("MSB") != std::string::npos)
  {
    info.LittleEndian = false;
  }
  const auto size = [&arch](const char* key, std::size_t fallback)
  {
    const std::size_t at = arch.find(key);
    if (at == std::string::npos)
    {
      return fallback;
    }
    const int bits = std::atoi(arch.c_str() + at + std::string(key).size());
    return bits > 0 ? static_cast<std::size_t>(bits) / 8 : fallback;
  };
  info.LabelBytes = size("label=", 4);
  info.ScalarBytes = size("scalar=", 8);
  return info;
}

} // namespace openfoam
} // namespace dgmf
