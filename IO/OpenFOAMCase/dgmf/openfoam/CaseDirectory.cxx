#include "dgmf/openfoam/CaseDirectory.h"

#include "dgmf/openfoam/FoamFileText.h"
#include "dgmf/openfoam/PointsFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace dgmf
{
namespace openfoam
{
namespace fs = std::filesystem;

namespace
{
/// The times of the case's time directories, in no order.
std::vector<double> TimesOf(const fs::path& caseDirectory)
{
  std::vector<double> times;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(caseDirectory, error))
  {
    double value = 0.0;
    std::error_code notDirectory;
    if (entry.is_directory(notDirectory) && TimeValue(entry.path().filename().string(), value))
    {
      times.push_back(value);
    }
  }
  return times;
}

bool IsEmptyDirectory(const fs::path& directory)
{
  std::error_code error;
  return fs::is_directory(directory, error) && fs::is_empty(directory, error);
}

/// The name to show for `path` in messages.
std::string Quoted(const fs::path& path)
{
  return "'" + path.string() + "'";
}
} // namespace

bool TimeValue(const std::string& name, double& value)
{
  if (name.empty())
  {
    return false;
  }
  const char* end = name.data() + name.size();
  const std::from_chars_result read = std::from_chars(name.data(), end, value);
  return read.ec == std::errc() && read.ptr == end && std::isfinite(value);
}

bool IsCase(const fs::path& directory)
{
  std::error_code error;
  return fs::is_regular_file(directory / "system" / "controlDict", error);
}

fs::path CaseDirectoryOf(const fs::path& path)
{
  const std::string extension = path.extension().string();
  if (extension == ".foam" || extension == ".OpenFOAM")
  {
    return path.parent_path().empty() ? fs::path(".") : path.parent_path();
  }
  if (path.filename() == "controlDict" && path.parent_path().filename() == "system")
  {
    return path.parent_path().parent_path();
  }
  return path;
}

bool IsTimeName(const std::string& time)
{
  double value = 0.0;
  return time == "constant" || (TimeValue(time, value) && value >= 0.0);
}

fs::path PolyMeshDirectory(const fs::path& caseDirectory, const std::string& time)
{
  return caseDirectory / time / "polyMesh";
}

std::vector<PatchEntry> ReadPatches(const fs::path& caseDirectory)
{
  const fs::path polyMesh = PolyMeshDirectory(caseDirectory, "constant");
  std::error_code error;
  const fs::path file =
    fs::exists(polyMesh / "boundary", error) ? polyMesh / "boundary" : polyMesh / "boundary.gz";
  const std::string text = ReadFoamText(file);
  const FoamHeader header = ParseFoamHeader(text);
  std::size_t at = SkipSpaceAndComments(text, header.Found ? header.End : 0);
  while (at < text.size() && text[at] != '(') // the count
  {
    ++at;
  }
  std::vector<PatchEntry> patches;
  ++at;
  while ((at = SkipSpaceAndComments(text, at)) < text.size() && text[at] != ')')
  {
    const std::size_t nameEnd = text.find_first_of(" \t\r\n{", at);
    if (nameEnd == std::string::npos)
    {
      break;
    }
    PatchEntry patch;
    patch.Name = text.substr(at, nameEnd - at);
    const std::size_t close = text.find('}', nameEnd);
    if (close == std::string::npos)
    {
      break;
    }
    // inGroups List<word> 2(wall motorBikeGroup); (or "inGroups 1(wall);")
    const std::size_t groups = text.find("inGroups", nameEnd);
    const std::size_t open = groups < close ? text.find('(', groups) : std::string::npos;
    const std::size_t shut = open < close ? text.find(')', open) : std::string::npos;
    if (shut < close)
    {
      std::istringstream words(text.substr(open + 1, shut - open - 1));
      for (std::string word; words >> word;)
      {
        patch.Groups.push_back(word);
      }
    }
    // type cyclic;
    std::string body = text.substr(nameEnd, close - nameEnd);
    std::replace(body.begin(), body.end(), '{', ' '); // "{type cyclic;"
    std::istringstream entries(body);
    for (std::string word; entries >> word;)
    {
      if (word == "type" && entries >> patch.Type)
      {
        patch.Type = patch.Type.substr(0, patch.Type.find(';'));
        break;
      }
    }
    patches.push_back(std::move(patch));
    at = close + 1;
  }
  return patches;
}

std::vector<std::string> ReadPatchNames(const fs::path& caseDirectory)
{
  std::vector<std::string> names;
  for (const PatchEntry& patch : ReadPatches(caseDirectory))
  {
    names.push_back(patch.Name);
  }
  return names;
}

bool IsInside(const fs::path& directory, const fs::path& path)
{
  std::error_code directoryError, pathError;
  const fs::path outer = fs::weakly_canonical(directory, directoryError);
  const fs::path inner = fs::weakly_canonical(path, pathError);
  if (directoryError || pathError || outer.empty())
  {
    return false;
  }
  const auto [end, rest] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
  return end == outer.end() && rest != inner.end() && !rest->empty();
}

std::string CopyTargetProblem(const fs::path& source, const fs::path& target)
{
  // A target inside the case would be copied into itself, again and again (until 2026-11-30 a
  // 0.4 MB case grew to 190 MB of nested copies before the names got too long).
  if (IsInside(source, target))
  {
    return Quoted(target) + " is inside the case " + Quoted(source) +
      ", which would be copied into it: give a directory outside the case";
  }
  std::error_code error;
  if (fs::exists(target, error) && !IsEmptyDirectory(target))
  {
    return Quoted(target) +
      " already holds files and is not an OpenFOAM case: give a new directory";
  }
  return std::string();
}

bool FirstTimeOf(const fs::path& caseDirectory, double& first)
{
  const std::vector<double> times = TimesOf(caseDirectory);
  if (times.empty())
  {
    return false;
  }
  first = *std::min_element(times.begin(), times.end());
  return true;
}

bool SolverStartTime(
  const fs::path& caseDirectory, const std::vector<double>& written, bool copied, double& start)
{
  std::string text;
  try
  {
    text = ReadFoamText(caseDirectory / "system" / "controlDict");
  }
  catch (const std::exception&)
  {
    return false;
  }
  const std::string from = FoamTopLevelEntry(text, "startFrom");
  if (from == "startTime")
  {
    return TimeValue(FoamTopLevelEntry(text, "startTime"), start);
  }
  if (from != "firstTime" && from != "latestTime")
  {
    return false;
  }
  std::vector<double> times = TimesOf(caseDirectory);
  if (copied && !times.empty()) // a copy has the first time directory only
  {
    times.assign(1, *std::min_element(times.begin(), times.end()));
  }
  times.insert(times.end(), written.begin(), written.end());
  if (times.empty())
  {
    return false;
  }
  start = from == "firstTime" ? *std::min_element(times.begin(), times.end())
                              : *std::max_element(times.begin(), times.end());
  return true;
}

namespace
{
/**
 * Copies the directory tree `from` into the new directory `to`: directories made with the
 * default permissions and files given their owner's write permission, so that the copy of a
 * read-only case (a tutorial tree, a colleague's case) can take the deformed points (fs::copy
 * kept the source's modes: the copy's own constant/polyMesh could not be written). Symbolic
 * links are copied as links.
 */
void CopyTree(const fs::path& from, const fs::path& to)
{
  fs::create_directory(to);
  for (const fs::directory_entry& entry : fs::directory_iterator(from))
  {
    const fs::path target = to / entry.path().filename();
    if (entry.is_symlink())
    {
      fs::copy_symlink(entry.path(), target);
    }
    else if (entry.is_directory())
    {
      CopyTree(entry.path(), target);
    }
    else
    {
      fs::copy_file(entry.path(), target);
      fs::permissions(target, fs::perms::owner_write, fs::perm_options::add);
    }
  }
}
} // namespace

void CopyCase(const fs::path& source, const fs::path& target)
{
  if (!IsCase(source))
  {
    throw std::runtime_error(Quoted(source) + " is not an OpenFOAM case (no system/controlDict)");
  }
  const std::string problem = CopyTargetProblem(source, target);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  std::error_code error;
  // The first time directory holds the fields a solver starts from; later ones are results.
  double first = HUGE_VAL;
  FirstTimeOf(source, first);
  const bool created = !fs::exists(target, error);
  fs::create_directories(target, error);
  if (error)
  {
    throw std::runtime_error(Quoted(target) + " cannot be created: " + error.message());
  }
  fs::path copying;
  try
  {
    for (const fs::directory_entry& entry : fs::directory_iterator(source))
    {
      const std::string name = entry.path().filename().string();
      double value = 0.0;
      const bool laterTime = entry.is_directory() && TimeValue(name, value) && value != first;
      if (laterTime || name.rfind("processor", 0) == 0 || name == "postProcessing")
      {
        continue;
      }
      copying = entry.path();
      if (entry.is_directory() && !entry.is_symlink())
      {
        CopyTree(entry.path(), target / name);
      }
      else
      {
        fs::copy(entry.path(), target / name, fs::copy_options::copy_symlinks);
        if (!entry.is_symlink())
        {
          fs::permissions(target / name, fs::perms::owner_write, fs::perm_options::add);
        }
      }
    }
  }
  catch (const fs::filesystem_error& e)
  {
    // Nothing half-copied is left: the target was empty or new (CopyTargetProblem), and a
    // second try would refuse a directory holding files.
    std::error_code ignored;
    for (const fs::directory_entry& entry : fs::directory_iterator(target, ignored))
    {
      fs::remove_all(entry.path(), ignored);
    }
    if (created)
    {
      fs::remove(target, ignored);
    }
    throw std::runtime_error("cannot copy " + Quoted(copying) + " to " +
      Quoted(target / copying.filename()) + ": " + e.code().message());
  }
}

fs::path WriteDeformedPoints(const fs::path& source, const fs::path& target,
  const std::string& time, const double* reference, const double* deformed,
  std::size_t numberOfPoints, bool* replaced)
{
  if (!IsTimeName(time))
  {
    throw std::runtime_error("the time directory must be 'constant' or a time such as 1 or 0.5 "
                             "(got '" +
      time + "')");
  }
  const fs::path sourceFile = FindPointsFile(PolyMeshDirectory(source, "constant"));
  if (sourceFile.empty())
  {
    throw std::runtime_error(Quoted(source) +
      " is not an OpenFOAM case with a mesh: no constant/polyMesh/points or points.gz");
  }
  const PointsFile original = ReadPointsFile(sourceFile);
  const std::size_t n = original.NumberOfPoints();
  if (numberOfPoints < n)
  {
    throw std::runtime_error("the mesh has " + std::to_string(numberOfPoints) +
      " points, but the case " + Quoted(source) + " has " + std::to_string(n) +
      ": is it the mesh read from this case (its internalMesh)?");
  }

  // The reference must be the case's points, up to the reader's rounding to single precision.
  double largest = 0.0;
  for (std::size_t k = 0; k < 3 * n; ++k)
  {
    largest = std::max(largest, std::abs(original.Points[k]));
  }
  const double tolerance = 1e-6 * std::max(largest, 1e-300);
  std::vector<double> points(original.Points);
  for (std::size_t k = 0; k < 3 * n; ++k)
  {
    const double p = original.Points[k];
    if (!(std::abs(reference[k] - p) <= tolerance))
    {
      throw std::runtime_error("point " + std::to_string(k / 3) + " of the undeformed mesh (" +
        std::to_string(reference[k]) + " in coordinate " + std::to_string(k % 3) +
        ") is not the case's (" + std::to_string(p) + " in " + sourceFile.string() +
        "): give the case the mesh was read from, with its mesh at the time it was read");
    }
    const double motion = deformed[k] - reference[k];
    points[k] = motion == 0.0 ? p : p + motion; // an unmoved point keeps its bits (and -0)
    if (!std::isfinite(points[k]))
    {
      throw std::runtime_error(
        "deformed point " + std::to_string(k / 3) + " is not finite: nothing was written");
    }
  }

  fs::path out = target;
  std::error_code error;
  if (!fs::equivalent(source, target, error))
  {
    if (IsCase(target))
    {
      const fs::path existing = FindPointsFile(PolyMeshDirectory(target, "constant"));
      if (!existing.empty() && ReadPointsFile(existing).NumberOfPoints() != n)
      {
        throw std::runtime_error(Quoted(target) + " is an OpenFOAM case with another mesh");
      }
    }
    else
    {
      CopyCase(source, target);
    }
  }
  if (replaced)
  {
    *replaced = time != "constant" && !FindPointsFile(PolyMeshDirectory(out, time)).empty();
  }
  return WritePointsFile(
    PolyMeshDirectory(out, time), original, points.data(), n, time + "/polyMesh");
}

} // namespace openfoam
} // namespace dgmf
