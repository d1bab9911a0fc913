#include "DGMFCommandOptions.h"

#include "vtkDGMFDeformFilter.h"

#include "dgmf/openfoam/CaseDirectory.h"

#include "dgmf/MotionLaw.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace dgmf_cli
{
namespace
{
/// A number as a user writes one: no leading space, no hexadecimal ("0x10" is not 16 degrees).
bool Plain(const std::string& text)
{
  return !text.empty() && !std::isspace(static_cast<unsigned char>(text[0])) &&
    text.find_first_of("xX") == std::string::npos;
}

/// Reads `count` finite numbers after argv[i]; advances i.
bool ReadDoubles(int argc, char* argv[], int& i, int count, double* values)
{
  if (i + count >= argc)
  {
    return false;
  }
  for (int k = 0; k < count; ++k)
  {
    char* end = nullptr;
    values[k] = std::strtod(argv[++i], &end);
    if (!end || *end != '\0' || end == argv[i] || !std::isfinite(values[k]) || !Plain(argv[i]))
    {
      return false;
    }
  }
  return true;
}

/// Reads one integer in [minimum, maximum] after argv[i] ("1.5" and "2x" are refused).
bool ReadInteger(int argc, char* argv[], int& i, long minimum, long maximum, int& value)
{
  if (i + 1 >= argc)
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long read = std::strtol(argv[++i], &end, 10);
  if (!end || *end != '\0' || end == argv[i] || errno != 0 || read < minimum || read > maximum)
  {
    return false;
  }
  value = static_cast<int>(read);
  return true;
}

/// Gives `filter` the boundary `name` in the role ('m' moving, 's' static, 'l' slip) and notes it
/// in the options' list of that role.
void AddBoundary(
  char role, const std::string& name, CommandOptions& options, vtkDGMFDeformFilter* filter)
{
  role == 'm'     ? filter->AddMovingBoundary(name.c_str())
    : role == 's' ? filter->AddStaticBoundary(name.c_str())
                  : filter->AddSlipBoundary(name.c_str());
  (role == 'm' ? options.Moving : role == 's' ? options.Static : options.Slip).push_back(name);
}

/// The comma-separated names of `list`.
std::vector<std::string> SplitNames(const std::string& list)
{
  std::vector<std::string> names;
  std::stringstream stream(list);
  std::string name;
  while (std::getline(stream, name, ','))
  {
    if (!name.empty())
    {
      names.push_back(name);
    }
  }
  return names;
}
/// A law: `harmonic` or `ramp` and four numbers (with `pitch`, harmonic and the four numbers).
bool ReadLaw(int argc, char* argv[], int& i, bool pitch, int& kind, double parameters[4])
{
  int at = i;
  if (!pitch)
  {
    if (at + 1 >= argc)
    {
      return false;
    }
    const std::string name = argv[at + 1];
    if (name != "harmonic" && name != "ramp")
    {
      return false;
    }
    kind = name == "harmonic" ? vtkDGMFDeformFilter::HARMONIC : vtkDGMFDeformFilter::RAMP;
    ++at;
  }
  else
  {
    kind = vtkDGMFDeformFilter::HARMONIC;
  }
  if (!ReadDoubles(argc, argv, at, 4, parameters))
  {
    return false;
  }
  i = at;
  return true;
}

/// START:END:COUNT into `times`, COUNT equally spaced times (COUNT 1 to 1000000; END >= START;
/// END > START when COUNT > 1, else the frames would share one time; COUNT 1 gives START alone).
/// Returns why not ("" when read).
std::string ReadTimes(const char* text, std::vector<double>& times)
{
  const std::string form = "give START:END:COUNT, such as 0:1:21";
  std::stringstream stream(text);
  std::string start, end, count;
  std::string rest;
  if (!std::getline(stream, start, ':') || !std::getline(stream, end, ':') ||
    !std::getline(stream, count, ':') || std::getline(stream, rest) || stream.peek() != EOF ||
    std::count(text, text + std::strlen(text), ':') != 2 || !Plain(start) || !Plain(end) ||
    !Plain(count))
  {
    return form; // (also "0:1:2:junk")
  }
  try
  {
    std::size_t used = 0;
    const double a = std::stod(start, &used);
    bool whole = used == start.size();
    const double b = std::stod(end, &used);
    whole = whole && used == end.size();
    const long n = std::stol(count, &used);
    whole = whole && used == count.size();
    if (!whole || !std::isfinite(a) || !std::isfinite(b))
    {
      return form + " (finite numbers, COUNT a whole number)";
    }
    if (n < 1 || n > 1000000)
    {
      return "COUNT must be 1 to 1000000 frames";
    }
    if (b < a || (n > 1 && !(b > a)))
    {
      return n > 1 ? "END must be above START for several frames" : "END must not be below START";
    }
    // (b - a) k must be finite too: the times are a + (b - a) k / (n - 1), here and in the filter.
    if (!std::isfinite((b - a) * static_cast<double>(n - 1)))
    {
      return "the times are too far apart to be computed";
    }
    times.clear();
    for (long k = 0; k < n; ++k)
    {
      times.push_back(
        n == 1 ? a : a + (b - a) * static_cast<double>(k) / static_cast<double>(n - 1));
    }
    return std::string();
  }
  catch (const std::exception&)
  {
    return form + " (numbers in range)";
  }
}
} // namespace

int ParseCommandLine(int argc, char* argv[], vtkDGMFDeformFilter* filter, CommandOptions& options)
{
  if (argc < 3)
  {
    std::cerr << Usage();
    return ExitUsage;
  }
  // The two files may come anywhere among the options (INPUT OUTPUT [options], [options] INPUT
  // OUTPUT, INPUT [options] OUTPUT): an argument that is neither an option nor an option's value
  // is a file, the first the input, the second the output.
  // A value that is an option itself ("--moving --no-write") is missing: a bad value.
  const auto hasValue = [&](int i)
  { return i + 1 < argc && std::strncmp(argv[i + 1], "--", 2) != 0; };
  std::vector<std::string> files;
  // The option that gave the rotation law and the one that gave the translation law: a second
  // would replace the first without a word.
  std::string rotationLaw, translationLaw;
  for (int i = 1; i < argc; ++i)
  {
    if (argv[i][0] != '-')
    {
      files.emplace_back(argv[i]);
      continue;
    }
    if (std::strcmp(argv[i], "--") == 0) // the end of the options: files named "-..." follow
    {
      files.insert(files.end(), argv + i + 1, argv + argc);
      break;
    }
    const std::string option = argv[i];
    double v[3];
    double law[4];
    int k = 0;
    if (option == "--rotate" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationAngles(v);
    }
    else if (option == "--center" && i + 1 < argc &&
      (std::strcmp(argv[i + 1], "body") == 0 || std::strcmp(argv[i + 1], "moving") == 0))
    {
      // BODY_CENTROID, "Body Centroid" in ParaView; "moving" is the name it had until 2026-11-30.
      filter->SetRotationCenterMode(vtkDGMFDeformFilter::BODY_CENTROID);
      ++i;
    }
    else if (option == "--center" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationCenter(v);
    }
    else if ((option == "--moving" || option == "--static" || option == "--slip") && hasValue(i))
    {
      options.NameValues.emplace_back(option == "--moving" ? 'm'
          : option == "--static"                           ? 's'
                                                           : 'l',
        argv[i + 1]);
      for (const std::string& name : SplitNames(argv[++i]))
      {
        AddBoundary(options.NameValues.back().first, name, options, filter);
        options.ByName = true;
      }
    }
    else if (option == "--time" && hasValue(i))
    {
      // A time directory's name, or constant: "latestTime" and the like were refused only after
      // the case was read, with exit 1 (until 2026-11-30).
      options.Time = argv[++i];
      if (!dgmf::openfoam::IsTimeName(options.Time))
      {
        std::cerr << "dgmf-deform: bad option or value: --time " << options.Time
                  << ": a time directory's name (0, 0.5, 100) or constant\n";
        return ExitUsage;
      }
    }
    else if (option == "--decompose-polyhedra")
    {
      options.DecomposePolyhedra = true;
    }
    else if (option == "--one-cell-thick" && i + 1 < argc &&
      (std::strcmp(argv[i + 1], "detect") == 0 || std::strcmp(argv[i + 1], "on") == 0 ||
        std::strcmp(argv[i + 1], "off") == 0))
    {
      const std::string mode = argv[++i];
      filter->SetOneCellThickMode(mode == "on" ? vtkDGMFDeformFilter::ON
          : mode == "off"                      ? vtkDGMFDeformFilter::OFF
                                               : vtkDGMFDeformFilter::DETECT);
    }
    else if (option == "--translate" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetTranslation(v);
    }
    else if (option == "--axis" && ReadDoubles(argc, argv, i, 3, v))
    {
      filter->SetRotationAxis(v);
    }
    else if (option == "--angle" && ReadDoubles(argc, argv, i, 1, v))
    {
      filter->SetRotationAngle(v[0]);
    }
    else if ((option == "--rotation-law" || option == "--translation-law" || option == "--pitch") &&
      ReadLaw(argc, argv, i, option == "--pitch", k, law))
    {
      std::string& given = option == "--translation-law" ? translationLaw : rotationLaw;
      if (!given.empty())
      {
        std::cerr << "dgmf-deform: " << given << " and " << option << " both give the "
                  << (option == "--translation-law" ? "translation" : "rotation")
                  << " law: give one\n";
        return ExitUsage;
      }
      given = option;
      // Bad parameters (a ramp ending before it starts, a negative frequency) are a bad value,
      // said now (exit 2), not at the first frame (exit 1).
      dgmf::MotionLaw checked;
      checked.Kind = static_cast<dgmf::MotionLawKind>(k);
      std::copy_n(law, 4, checked.Parameters);
      try
      {
        checked.Check(option == "--translation-law" ? "the translation law" : "the rotation law");
      }
      catch (const std::invalid_argument& e)
      {
        std::cerr << "dgmf-deform: bad option or value: " << option << ": " << e.what() << "\n";
        return ExitUsage;
      }
      option == "--translation-law" ? filter->SetTranslationLaw(k) : filter->SetRotationLaw(k);
      option == "--translation-law" ? filter->SetTranslationLawParameters(law)
                                    : filter->SetRotationLawParameters(law);
      options.Series = true;
    }
    else if (option == "--trajectory" && hasValue(i))
    {
      options.Trajectory = argv[++i];
      options.Series = true;
    }
    else if (option == "--times" && i + 1 < argc)
    {
      const std::string why = ReadTimes(argv[++i], options.Times);
      if (!why.empty())
      {
        std::cerr << "dgmf-deform: bad option or value: --times " << argv[i] << ": " << why << "\n";
        return ExitUsage;
      }
      filter->SetTimeRange(options.Times.front(), options.Times.back());
      filter->SetNumberOfTimeSteps(static_cast<int>(options.Times.size()));
    }
    else if (option == "--method" && i + 1 < argc &&
      vtkDGMFDeformFilter::GetMethodFromName(argv[i + 1]) >= 0)
    {
      filter->SetMethod(vtkDGMFDeformFilter::GetMethodFromName(argv[++i]));
    }
    else if (option == "--mode" && ReadInteger(argc, argv, i, 1, 2, k))
    {
      filter->SetDeformationMode(k);
    }
    else if (option == "--damping" && ReadInteger(argc, argv, i, 1, 7, k))
    {
      filter->SetDampingFunction(k);
    }
    else if (option == "--r0s" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 1)
    {
      filter->SetStaticBoundaryR0(v[0]);
    }
    else if (option == "--sub-steps" &&
      ReadInteger(argc, argv, i, filter->GetSubStepsMinValue(), filter->GetSubStepsMaxValue(), k))
    {
      // The filter's own range: a larger value was clamped without a word until 2026-11-30.
      filter->SetSubSteps(k);
    }
    else if (option == "--repair" && ReadDoubles(argc, argv, i, 1, v) && v[0] >= 0 && v[0] <= 1)
    {
      filter->SetRepairThreshold(v[0]);
    }
    else if (option == "--repair-layers" &&
      ReadInteger(
        argc, argv, i, filter->GetRepairLayersMinValue(), filter->GetRepairLayersMaxValue(), k))
    {
      filter->SetRepairLayers(k);
    }
    else if (option == "--repair-passes" &&
      ReadInteger(
        argc, argv, i, filter->GetRepairPassesMinValue(), filter->GetRepairPassesMaxValue(), k))
    {
      filter->SetRepairPasses(k);
    }
    else if (option == "--threads" && ReadInteger(argc, argv, i, 0, 4096, k))
    {
      filter->SetNumberOfThreads(k);
    }
    else if (option == "--marker" && hasValue(i))
    {
      options.Marker = argv[++i];
      options.MarkerGiven = true;
    }
    else if (option == "--body-id" && hasValue(i))
    {
      filter->SetBodyIdArrayName(argv[++i]);
      options.BodyIdGiven = true;
    }
    else if (option == "--displacement" && hasValue(i))
    {
      options.Displacement = argv[++i];
      options.DisplacementGiven = true;
    }
    else if (option == "--non-orthogonality")
    {
      filter->ComputeNonOrthogonalityOn();
    }
    else if (option == "--no-write")
    {
      options.NoWrite = true;
    }
    else if (option == "--vtu-mode" && i + 1 < argc &&
      (std::strcmp(argv[i + 1], "binary") == 0 || std::strcmp(argv[i + 1], "appended") == 0))
    {
      options.VTUAppended = std::strcmp(argv[++i], "appended") == 0;
    }
    else if (option == "--compression" && i + 1 < argc &&
      (std::strcmp(argv[i + 1], "lz4") == 0 || std::strcmp(argv[i + 1], "zlib") == 0 ||
        std::strcmp(argv[i + 1], "lzma") == 0 || std::strcmp(argv[i + 1], "none") == 0))
    {
      options.Compression = argv[++i];
    }
    else if (option == "--progress")
    {
      options.ProgressDelay = 0.0;
    }
    else if (option == "--fail-on-inverted")
    {
      options.FailOnInverted = true;
    }
    else if (option == "--no-quality")
    {
      filter->ComputeQualityOff();
    }
    else
    {
      // The reason alone: the whole usage after it buried it (until 2026-11-30).
      std::cerr << "dgmf-deform: bad option or value: " << option
                << " (dgmf-deform --help lists the options and their values)\n";
      return ExitUsage;
    }
  }
  if (files.size() != 2)
  {
    std::cerr << "dgmf-deform: " << (files.size() < 2 ? "missing" : "too many") << " files: "
              << "expected INPUT and OUTPUT, got " << files.size();
    for (const std::string& file : files)
    {
      std::cerr << " '" << file << "'";
    }
    std::cerr << "\n" << Usage();
    return ExitUsage;
  }
  options.Input = files[0];
  options.Output = files[1];

  if (!options.Times.empty() && !options.Series)
  {
    std::cerr << "dgmf-deform: --times needs a motion in time (--rotation-law, --pitch, "
                 "--translation-law or --trajectory)\n";
    return ExitUsage;
  }
  if (!options.Trajectory.empty() && !(rotationLaw + translationLaw).empty())
  {
    // The table's rows give the motion of their bodies; the laws move the others only.
    std::cerr << "dgmf-deform: warning: "
              << (rotationLaw.empty()         ? translationLaw
                     : translationLaw.empty() ? rotationLaw
                                              : rotationLaw + " and " + translationLaw)
              << (rotationLaw.empty() || translationLaw.empty() ? " moves" : " move")
              << " only the bodies the trajectory table has no rows for (none, when it moves "
                 "every body)\n";
  }
  if (options.Series && options.Time != "constant")
  {
    std::cerr << "dgmf-deform: --time names the one time directory of a single deformation; a "
                 "series writes one per time of --times\n";
    return ExitUsage;
  }
  if (options.FailOnInverted && !filter->GetComputeQuality())
  {
    std::cerr << "dgmf-deform: --fail-on-inverted needs the quality metric (drop --no-quality)\n";
    return ExitUsage;
  }
  return ExitSuccess;
}
namespace
{
/**
 * The names of a value as the file has them: split at its commas, but for runs of its comma-
 * separated parts that are, joined again, one of `fileNames` ("farfield,Flap, inner": farfield and
 * "Flap, inner"; the longest run first).
 */
std::vector<std::string> NamesOfValue(
  const std::string& value, const std::vector<std::string>& fileNames)
{
  std::vector<std::string> parts;
  std::stringstream stream(value);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    parts.push_back(part);
  }
  std::vector<std::string> names;
  for (std::size_t first = 0; first < parts.size();)
  {
    std::size_t last = first; // the run first..last joined, if the file has it
    std::string joined = parts[first];
    std::string longest;
    for (std::size_t k = first; k < parts.size(); ++k)
    {
      joined = k == first ? parts[first] : joined + "," + parts[k];
      if (k > first && std::find(fileNames.begin(), fileNames.end(), joined) != fileNames.end())
      {
        last = k;
        longest = joined;
      }
    }
    const std::string name = last > first ? longest : parts[first];
    if (!name.empty())
    {
      names.push_back(name);
    }
    first = last + 1;
  }
  return names;
}
} // namespace

void KeepWholeNames(
  CommandOptions& options, const std::vector<std::string>& fileNames, vtkDGMFDeformFilter* filter)
{
  std::vector<std::vector<std::string>> names;
  bool changed = false;
  for (const auto& value : options.NameValues)
  {
    names.push_back(NamesOfValue(value.second, fileNames));
    changed = changed || names.back() != SplitNames(value.second);
  }
  if (!changed)
  {
    return;
  }
  options.Moving.clear();
  options.Static.clear();
  options.Slip.clear();
  filter->RemoveAllMovingBoundaries();
  filter->RemoveAllStaticBoundaries();
  filter->RemoveAllSlipBoundaries();
  for (std::size_t v = 0; v < options.NameValues.size(); ++v)
  {
    for (const std::string& name : names[v])
    {
      AddBoundary(options.NameValues[v].first, name, options, filter);
    }
  }
}

} // namespace dgmf_cli
