/**
 * @file FoamFileText.h
 * @brief The text of an OpenFOAM file: read (gzip or not), comments skipped, and its
 * `FoamFile { ... }` header: the entries read and one entry replaced, leaving the rest of the text
 * as it is (VTK-free; namespace dgmf::openfoam).
 */
#ifndef dgmf_openfoam_FoamFileText_h
#define dgmf_openfoam_FoamFileText_h

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

namespace dgmf
{
namespace openfoam
{

/**
 * The whole of `file`, decompressed if it is gzip (a `.gz` file); plain files are read as they
 * are. Throws std::runtime_error naming the file when it cannot be read.
 */
std::string ReadFoamText(const std::filesystem::path& file);

/// The offset of the first character from `at` that is neither white space nor in a comment.
std::size_t SkipSpaceAndComments(const std::string& text, std::size_t at);

/// The header of an OpenFOAM file.
struct FoamHeader
{
  bool Found = false;                        ///< the text has a FoamFile dictionary
  std::size_t End = 0;                       ///< the offset just after its closing brace
  std::map<std::string, std::string> Values; ///< keyword -> value, quotes removed

  /// The value of `keyword`, or "" when it is absent.
  std::string Get(const std::string& keyword) const;
};

/// The header of `text` (the start of an OpenFOAM file).
FoamHeader ParseFoamHeader(const std::string& text);

/// The value of `keyword` in the header of `text`, or "".
std::string FoamHeaderEntry(const std::string& text, const std::string& keyword);

/**
 * The value of the top-level entry `keyword` of `text` after its header ("startFrom startTime;"
 * in a controlDict: "startTime"; the last one when the keyword comes twice, as OpenFOAM reads
 * it), or "" when absent; sub-dictionaries ("functions { ... }") are skipped, not searched.
 */
std::string FoamTopLevelEntry(const std::string& text, const std::string& keyword);

/**
 * `text` with the header entry `keyword` set to `value` (written as given: quote it if needed).
 * An entry that is absent is added at the end of the header. `text` without a header is returned
 * unchanged.
 */
std::string SetHeaderEntry(
  const std::string& text, const std::string& keyword, const std::string& value);

/// A binary file's `arch` entry ("LSB;label=32;scalar=64").
struct ArchInfo
{
  bool LittleEndian = true;
  std::size_t LabelBytes = 4;
  std::size_t ScalarBytes = 8;
};

/// Parses an `arch` value; what it does not say keeps OpenFOAM's defaults (LSB, 32, 64).
ArchInfo ParseArch(const std::string& arch);

} // namespace openfoam
} // namespace dgmf

#endif
