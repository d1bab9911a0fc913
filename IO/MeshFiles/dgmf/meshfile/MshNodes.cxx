// A .msh file's node coordinates replaced in its own bytes (MshNodes.h). The $Nodes layouts:
// gmsh's reference manual, "MSH file format" (version 4.1) and "Legacy formats" (version 2.2).
#include "dgmf/meshfile/MshNodes.h"
#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/MshText.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
using namespace msh;

/**
 * The position just after the "$Nodes" line, going from section to section from the file's
 * start: each other section is skipped to its "$End<name>" line, so a line "$Nodes" inside
 * another section (a comment, binary data) is not taken for it. npos when there is none, or when
 * a line between sections does not start a section.
 */
std::size_t NodesSectionStart(std::string_view file)
{
  Cursor cursor{ file };
  for (std::string_view name = NextSection(cursor); !name.empty(); name = NextSection(cursor))
  {
    if (name == "Nodes")
    {
      return cursor.At;
    }
    if (!SkipSection(cursor, name))
    {
      break;
    }
  }
  return std::string_view::npos;
}

/// Where each node's coordinates start in the file (the x token, or the x double), by tag.
struct NodeRecords
{
  std::vector<std::uint64_t> Tags;
  std::vector<std::size_t> At;

  void Reserve(std::uint64_t count, std::size_t fileSize)
  {
    // A count the file cannot hold (each node takes 8 bytes at least) reserves no more than it can.
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(count, fileSize / 8));
    this->Tags.reserve(n);
    this->At.reserve(n);
  }
};

/// Three coordinate tokens at the cursor; records where the first starts.
bool AsciiCoordinates(Cursor& cursor, std::uint64_t tag, NodeRecords& records)
{
  const std::string_view x = cursor.Token();
  if (x.empty() || cursor.Token().empty() || cursor.Token().empty())
  {
    return false;
  }
  records.Tags.push_back(tag);
  records.At.push_back(cursor.Offset(x));
  return true;
}

bool ParseAscii22(Cursor& cursor, NodeRecords& records)
{
  std::uint64_t count = 0;
  if (!ToInteger(cursor.Token(), count))
  {
    return false;
  }
  records.Reserve(count, cursor.File.size());
  for (std::uint64_t k = 0; k < count; ++k)
  {
    std::uint64_t tag = 0;
    if (!ToInteger(cursor.Token(), tag) || !AsciiCoordinates(cursor, tag, records))
    {
      return false;
    }
  }
  return EndsSection(cursor, "Nodes");
}

bool ParseAscii41(Cursor& cursor, NodeRecords& records)
{
  std::uint64_t blocks = 0, count = 0, minimum = 0, maximum = 0;
  if (!ToInteger(cursor.Token(), blocks) || !ToInteger(cursor.Token(), count) ||
    !ToInteger(cursor.Token(), minimum) || !ToInteger(cursor.Token(), maximum))
  {
    return false;
  }
  records.Reserve(count, cursor.File.size());
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    long long dimension = 0, entity = 0;
    int parametric = 0;
    std::uint64_t inBlock = 0;
    if (!ToInteger(cursor.Token(), dimension) || !ToInteger(cursor.Token(), entity) ||
      !ToInteger(cursor.Token(), parametric) || parametric != 0 ||
      !ToInteger(cursor.Token(), inBlock) || inBlock > count - records.Tags.size() ||
      inBlock > (cursor.File.size() - cursor.At) / 8) // a tag and three numbers: 8 bytes at least
    {
      return false;
    }
    std::vector<std::uint64_t> tags(static_cast<std::size_t>(inBlock));
    for (std::uint64_t& tag : tags)
    {
      if (!ToInteger(cursor.Token(), tag))
      {
        return false;
      }
    }
    for (const std::uint64_t tag : tags)
    {
      if (!AsciiCoordinates(cursor, tag, records))
      {
        return false;
      }
    }
  }
  return records.Tags.size() == count && EndsSection(cursor, "Nodes");
}

bool ParseBinary22(Cursor& cursor, NodeRecords& records)
{
  std::uint64_t count = 0;
  if (!ToInteger(cursor.Line(), count))
  {
    return false;
  }
  constexpr std::uint64_t recordBytes = sizeof(std::int32_t) + 3 * sizeof(double);
  if (count > (cursor.File.size() - cursor.At) / recordBytes)
  {
    return false;
  }
  records.Reserve(count, cursor.File.size());
  for (std::uint64_t k = 0; k < count; ++k)
  {
    std::int32_t tag = 0;
    cursor.Binary(tag);
    if (tag <= 0)
    {
      return false;
    }
    records.Tags.push_back(static_cast<std::uint64_t>(tag));
    records.At.push_back(cursor.At);
    cursor.Skip(3 * sizeof(double));
  }
  return EndsSection(cursor, "Nodes");
}

bool ParseBinary41(Cursor& cursor, NodeRecords& records)
{
  std::uint64_t blocks = 0, count = 0, minimum = 0, maximum = 0;
  if (!cursor.Binary(blocks) || !cursor.Binary(count) || !cursor.Binary(minimum) ||
    !cursor.Binary(maximum))
  {
    return false;
  }
  records.Reserve(count, cursor.File.size());
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    std::int32_t dimension = 0, entity = 0, parametric = 0;
    std::uint64_t inBlock = 0;
    if (!cursor.Binary(dimension) || !cursor.Binary(entity) || !cursor.Binary(parametric) ||
      parametric != 0 || !cursor.Binary(inBlock) || inBlock > count - records.Tags.size() ||
      inBlock > (cursor.File.size() - cursor.At) / (4 * sizeof(double)))
    {
      return false;
    }
    const std::size_t tagsAt = cursor.At;
    const std::size_t coordinatesAt = tagsAt + static_cast<std::size_t>(inBlock) * 8;
    if (!cursor.Skip(inBlock * 8) || !cursor.Skip(inBlock * 3 * sizeof(double)))
    {
      return false;
    }
    for (std::size_t k = 0; k < inBlock; ++k)
    {
      std::uint64_t tag = 0;
      std::memcpy(&tag, cursor.File.data() + tagsAt + 8 * k, sizeof(tag));
      records.Tags.push_back(tag);
      records.At.push_back(coordinatesAt + k * 3 * sizeof(double));
    }
  }
  return records.Tags.size() == count && EndsSection(cursor, "Nodes");
}

/// Whether a binary file's "1" after its format line is in this machine's byte order.
bool NativeByteOrder(std::string_view file)
{
  Cursor cursor{ file };
  cursor.Line(); // $MeshFormat
  cursor.Line(); // version, type, size
  std::int32_t one = 0;
  return cursor.Binary(one) && one == 1;
}

/// For each record (file order), the rank of its tag among all tags; false if a tag repeats.
bool RanksOfTags(const std::vector<std::uint64_t>& tags, std::vector<std::size_t>& rank)
{
  rank.resize(tags.size());
  if (std::is_sorted(tags.begin(), tags.end()))
  {
    std::iota(rank.begin(), rank.end(), std::size_t(0));
    return std::adjacent_find(tags.begin(), tags.end()) == tags.end();
  }
  std::vector<std::size_t> order(tags.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(
    order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    if (k > 0 && tags[order[k]] == tags[order[k - 1]])
    {
      return false;
    }
    rank[order[k]] = k;
  }
  return true;
}

/// A record that keeps its coordinates (a node no point is: Replacement::Rank).
constexpr std::size_t KeptNode = static_cast<std::size_t>(-1);

/// Where a file's coordinates are, and the point each node takes.
struct Replacement
{
  NodeRecords Records;
  std::vector<std::size_t> Rank; ///< per record, the index of its point, or KeptNode
};

/**
 * Points given by tag (`tags`, increasing, `count`): each record's point, or KeptNode for a node
 * no point is; false when a tag is not a node. `plan.Rank` holds the ranks of all the file's tags.
 */
bool MatchTags(const std::int64_t* tags, std::size_t count, Replacement& plan)
{
  std::vector<std::uint64_t> sorted(plan.Rank.size());
  for (std::size_t r = 0; r < plan.Rank.size(); ++r)
  {
    sorted[plan.Rank[r]] = plan.Records.Tags[r];
  }
  std::vector<std::size_t> pointOfRank(sorted.size(), KeptNode);
  std::size_t j = 0;
  for (std::size_t k = 0; k < sorted.size() && j < count; ++k)
  {
    if (tags[j] >= 0 && static_cast<std::uint64_t>(tags[j]) == sorted[k])
    {
      pointOfRank[k] = j++;
    }
  }
  if (j != count)
  {
    return false;
  }
  for (std::size_t& rank : plan.Rank)
  {
    rank = pointOfRank[rank];
  }
  return true;
}

/// The replacement of `count` nodes' coordinates in `file`, or with `tags` of those nodes among
/// more; false if this cannot rewrite it.
bool PlanReplacement(std::string_view file, const MshFormat& format, std::size_t count,
  Replacement& plan, const std::int64_t* tags = nullptr)
{
  const bool v22 = std::fabs(format.Version - 2.2) < 1e-9;
  const bool v41 = std::fabs(format.Version - 4.1) < 1e-9;
  if ((!v22 && !v41) || (format.Binary && !NativeByteOrder(file)))
  {
    return false;
  }
  const std::size_t start = NodesSectionStart(file);
  if (start == std::string_view::npos)
  {
    return false;
  }
  Cursor cursor{ file, start };
  const bool parsed = format.Binary
    ? (v22 ? ParseBinary22(cursor, plan.Records) : ParseBinary41(cursor, plan.Records))
    : (v22 ? ParseAscii22(cursor, plan.Records) : ParseAscii41(cursor, plan.Records));
  // (The layouts above give the records in file order, which the ASCII rewrite relies on.)
  const bool counted = tags ? plan.Records.Tags.size() >= count : plan.Records.Tags.size() == count;
  return parsed && counted && RanksOfTags(plan.Records.Tags, plan.Rank) &&
    std::is_sorted(plan.Records.At.begin(), plan.Records.At.end()) &&
    (!tags || MatchTags(tags, count, plan));
}

/// A binary file appended to `append(data, size)` in pieces: its bytes as they are, each node's
/// three doubles from `points` (the records are in file order).
template <typename Append>
void WriteBinary(
  std::string_view file, const Replacement& plan, const double* points, Append append)
{
  std::size_t copied = 0;
  for (std::size_t r = 0; r < plan.Rank.size(); ++r)
  {
    if (plan.Rank[r] == KeptNode)
    {
      continue; // its bytes go with the next piece
    }
    const std::size_t at = plan.Records.At[r];
    append(file.data() + copied, at - copied);
    append(reinterpret_cast<const char*>(points + 3 * plan.Rank[r]), 3 * sizeof(double));
    copied = at + 3 * sizeof(double);
  }
  append(file.data() + copied, file.size() - copied);
}

/**
 * An ASCII file appended to `append(data, size)` in pieces: the text between the coordinates as
 * it is, each coordinate written anew as the shortest decimal that reads back as the same double.
 */
template <typename Append>
void WriteAscii(std::string_view file, const Replacement& plan, const double* points, Append append)
{
  std::size_t copied = 0;
  char number[32];
  for (std::size_t r = 0; r < plan.Rank.size(); ++r)
  {
    if (plan.Rank[r] == KeptNode)
    {
      continue; // its text goes with the next piece
    }
    Cursor at{ file, plan.Records.At[r] };
    for (int c = 0; c < 3; ++c)
    {
      const std::string_view token = at.Token();
      append(file.data() + copied, at.Offset(token) - copied);
      const std::to_chars_result written = std::to_chars(
        number, number + sizeof(number), points[3 * plan.Rank[r] + static_cast<std::size_t>(c)]);
      append(number, static_cast<std::size_t>(written.ptr - number));
      copied = at.Offset(token) + token.size();
    }
  }
  append(file.data() + copied, file.size() - copied);
}

/// The file of `plan` appended to `append` in pieces (WriteBinary or WriteAscii).
template <typename Append>
void WriteMoved(std::string_view file, const MshFormat& format, const Replacement& plan,
  const double* points, Append append)
{
  if (format.Binary)
  {
    WriteBinary(file, plan, points, append);
  }
  else
  {
    WriteAscii(file, plan, points, append);
  }
}
} // namespace

bool ReplaceMshNodeCoordinates(
  std::string& bytes, const MshFormat& format, const double* points, std::size_t count)
{
  Replacement plan;
  if (!PlanReplacement(bytes, format, count, plan))
  {
    return false;
  }
  // The writer's pieces into a string (the same code as the file's).
  std::string moved;
  moved.reserve(bytes.size() + (format.Binary ? 0 : 16 * count));
  WriteMoved(bytes, format, plan, points,
    [&moved](const char* data, std::size_t size) { moved.append(data, size); });
  bytes.swap(moved);
  return true;
}

bool WriteMshWithMovedNodes(std::string_view file, const MshFormat& format, const double* points,
  std::size_t count, const std::string& target, const std::string& temporary)
{
  return WriteMshWithMovedNodesByTag(file, format, points, nullptr, count, target, temporary);
}

bool WriteMshWithMovedNodesByTag(std::string_view file, const MshFormat& format,
  const double* points, const std::int64_t* tags, std::size_t count, const std::string& target,
  const std::string& temporary)
{
  Replacement plan;
  if (!PlanReplacement(file, format, count, plan, tags))
  {
    return false;
  }
  WriteFileAtomically(target, temporary,
    [&](BufferedOutput& out)
    {
      WriteMoved(file, format, plan, points,
        [&out](const char* data, std::size_t size) { out.Append(data, size); });
    });
  return true;
}

} // namespace meshfile
} // namespace dgmf
