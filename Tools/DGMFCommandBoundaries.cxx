#include "DGMFCommandBoundaries.h"

#include "DGMFCommandData.h"
#include "DGMFCommandMessages.h"

#include "DGMFBoundaryNameParts.h"
#include "dgmf/openfoam/CaseDirectory.h"

#include "vtkDGMFDeformFilter.h"

#include <algorithm>
#include <fnmatch.h>
#include <iostream>

namespace dgmf_cli
{
std::string Listed(const std::vector<std::string>& names)
{
  std::string text;
  for (const std::string& name : names)
  {
    text += (text.empty() ? "" : ", ") + name;
  }
  return text.empty() ? "(none)" : text;
}

void PrintBoundaries(const CommandOptions& options, const std::vector<std::string>& fileNames,
  const std::vector<std::string>& families)
{
  const std::vector<std::string>&moving = options.Moving, &fixed = options.Static,
        &slip = options.Slip;
  std::vector<std::string> chosen, others;
  for (const auto* list : { &moving, &fixed, &slip })
  {
    chosen.insert(chosen.end(), list->begin(), list->end());
  }
  const auto inFile = [&fileNames](const std::string& name)
  { return std::find(fileNames.begin(), fileNames.end(), name) != fileNames.end(); };
  // Whether `group` is the family of the file's boundary `name` (and no boundary's own name).
  const auto inFamily = [&](const std::string& group, const std::string& name)
  {
    const auto at = static_cast<std::size_t>(
      std::find(fileNames.begin(), fileNames.end(), name) - fileNames.begin());
    return !group.empty() && at < families.size() && families[at] == group && !inFile(group);
  };
  // Whether an entry reaches the file's name `name` as the filter takes it: the name itself, its
  // family, an OpenFOAM region name ("patch/wing") or a selector ending in it unless a block has
  // that very name, or an alternative or wildcard of it ("flap|slat", "wing_*").
  const auto reaches = [&inFile, &inFamily](const std::string& entry, const std::string& name)
  {
    if (entry == name)
    {
      return true;
    }
    if (inFile(entry))
    {
      return false;
    }
    if (inFamily(entry, name))
    {
      return true;
    }
    const std::size_t slash = entry.rfind('/');
    if (slash != std::string::npos && entry.compare(slash + 1, std::string::npos, name) == 0)
    {
      return true;
    }
    if (entry.find_first_of("|*?") == std::string::npos)
    {
      return false;
    }
    // Each alternative as the filter reads it (DGMFBoundaryNameParts: trimmed, without an
    // OpenFOAM region prefix).
    for (const std::string& given : dgmf_vtk::Alternatives(entry))
    {
      const std::string alternative = dgmf_vtk::NameOf(given);
      if (alternative == name || fnmatch(alternative.c_str(), name.c_str(), 0) == 0 ||
        inFamily(alternative, name))
      {
        return true;
      }
    }
    return false;
  };
  // A name the file does not have is the filter's error, which names it: no listing before it
  // (nor for an alternative of an entry, 'wing|typo').
  for (const std::string& entry : chosen)
  {
    const bool whole = inFile(entry) || entry.find('|') == std::string::npos;
    for (const std::string& part :
      whole ? std::vector<std::string>{ entry } : dgmf_vtk::Alternatives(entry))
    {
      if (std::none_of(fileNames.begin(), fileNames.end(),
            [&](const std::string& name) { return reaches(part, name); }))
      {
        return;
      }
    }
  }
  for (const std::string& name : fileNames)
  {
    if (std::none_of(chosen.begin(), chosen.end(),
          [&](const std::string& entry) { return reaches(entry, name); }))
    {
      others.push_back(name);
    }
  }
  std::cout << "dgmf-deform: boundaries from the file's names: moving " << Listed(moving)
            << "; slip " << Listed(slip) << "; static " << Listed(fixed) << " and the others ("
            << Listed(others) << ")" << std::endl;
}

std::string CyclicSlipProblem(const std::string& input, const CommandOptions& options)
{
  std::vector<dgmf::openfoam::PatchEntry> patches;
  try
  {
    patches = dgmf::openfoam::ReadPatches(dgmf::openfoam::CaseDirectoryOf(input));
  }
  catch (const std::exception&)
  {
    return std::string(); // the reader says what is wrong with the case
  }
  const std::vector<std::string> expanded = ExpandPatchGroups(input, options.Slip);
  for (std::size_t k = 0; k < expanded.size(); ++k)
  {
    for (const std::string& alternative : dgmf_vtk::Alternatives(expanded[k]))
    {
      for (const dgmf::openfoam::PatchEntry& patch : patches)
      {
        if (patch.Type.rfind("cyclic", 0) == 0 &&
          fnmatch(dgmf_vtk::NameOf(alternative).c_str(), patch.Name.c_str(), 0) == 0)
        {
          return "the patch '" + patch.Name + "' (of --slip " + options.Slip[k] + ") is " +
            patch.Type +
            ": a slip boundary's nodes slide within its plane apart from any other plane's, so "
            "the two planes of the cyclic pair would no longer match (checkMesh: \"face area "
            "does not match neighbour\"). Leave cyclic patches static (they are when not named; a "
            "body crossing the pair then shears their faces: openfoam.md).";
        }
      }
    }
  }
  return std::string();
}

void GiveOpenFOAMBoundaries(
  vtkDGMFDeformFilter* filter, const std::string& input, const CommandOptions& options)
{
  filter->RemoveAllMovingBoundaries();
  filter->RemoveAllStaticBoundaries();
  filter->RemoveAllSlipBoundaries();
  // Every name as the user gave it: an expansion a user also typed ('front|back') is not
  // renamed in messages.
  std::vector<std::string> given = options.Moving;
  given.insert(given.end(), options.Static.begin(), options.Static.end());
  given.insert(given.end(), options.Slip.begin(), options.Slip.end());
  const auto add = [&input, &given](const std::vector<std::string>& names, auto addBoundary)
  {
    const std::vector<std::string> expanded = ExpandPatchGroups(input, names);
    for (std::size_t k = 0; k < names.size(); ++k)
    {
      // Messages name a group of several patches as the user did (a group of one is its
      // patch, whose name the messages use for the block as well).
      if (expanded[k] != names[k] && expanded[k].find('|') != std::string::npos &&
        std::find(given.begin(), given.end(), expanded[k]) == given.end())
      {
        ShowInMessagesAs("'" + expanded[k] + "'", "'" + names[k] + "'");
      }
      addBoundary(expanded[k].c_str());
    }
  };
  add(options.Moving, [&filter](const char* name) { filter->AddMovingBoundary(name); });
  add(options.Static, [&filter](const char* name) { filter->AddStaticBoundary(name); });
  add(options.Slip, [&filter](const char* name) { filter->AddSlipBoundary(name); });
}
} // namespace dgmf_cli
