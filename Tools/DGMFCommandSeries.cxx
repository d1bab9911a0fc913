#include "DGMFCommandSeries.h"

#include "vtkDelimitedTextReader.h"
#include "vtkNew.h"
#include "vtkTable.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace dgmf_cli
{
namespace
{
const std::regex Conversion("%0?[0-9]*d");

/// `text` as the value of an XML attribute in double quotes (a file named "wing&flap.vtu").
std::string XMLAttribute(const std::string& text)
{
  std::string escaped;
  for (const char c : text)
  {
    switch (c)
    {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}
} // namespace

std::string FramePath(const std::string& output, std::size_t index, std::size_t count)
{
  std::smatch match;
  if (output.find('%') != std::string::npos)
  {
    // One conversion, in the file's name (a folder per frame would need each folder made, and
    // the collection would have no folder of its own), at most 20 digits wide.
    if (!std::regex_search(output, match, Conversion) ||
      output.find('%', static_cast<std::size_t>(match.position(0)) + 1) != std::string::npos ||
      output.find('/', static_cast<std::size_t>(match.position(0))) != std::string::npos ||
      match.length(0) > 5) // "%020d" at most: a longer width would be cut, or wrap around
    {
      return "";
    }
    char number[64];
    const int written =
      std::snprintf(number, sizeof number, match.str(0).c_str(), static_cast<int>(index));
    if (written < 0 || written >= static_cast<int>(sizeof number) ||
      std::atoi(match.str(0).c_str() + 1) > 20)
    {
      return "";
    }
    return match.prefix().str() + number + match.suffix().str();
  }
  std::size_t digits = 4;
  for (std::size_t last = count > 0 ? count - 1 : 0; last >= 10000; last /= 10)
  {
    ++digits;
  }
  const std::filesystem::path path(output);
  std::ostringstream name;
  name << path.stem().string() << "_" << std::setw(static_cast<int>(digits)) << std::setfill('0')
       << index << path.extension().string();
  return (path.parent_path() / name.str()).string();
}

std::string CollectionPath(const std::string& output)
{
  std::string base = std::regex_replace(output, Conversion, "");
  std::filesystem::path path(base);
  std::string stem = path.stem().string();
  while (!stem.empty() && (stem.back() == '_' || stem.back() == '-' || stem.back() == '.'))
  {
    stem.pop_back();
  }
  return (path.parent_path() / ((stem.empty() ? "series" : stem) + ".pvd")).string();
}

bool WriteCollection(
  const std::string& path, const std::vector<std::pair<double, std::string>>& frames)
{
  // Written beside and renamed into place: a series stopped while it rewrites the collection
  // keeps the last one whole.
  const std::string temporary = path + ".dgmf-writing";
  std::ofstream file(temporary);
  file << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const auto& frame : frames)
  {
    const std::string relative = std::filesystem::path(frame.second)
                                   .lexically_relative(folder.empty() ? "." : folder)
                                   .string();
    file << "    <DataSet timestep=\"" << std::setprecision(17) << frame.first
         << "\" part=\"0\" file=\"" << XMLAttribute(relative) << "\"/>\n";
  }
  file << "  </Collection>\n</VTKFile>\n";
  file.close();
  std::error_code error;
  if (!file || (std::filesystem::rename(temporary, path, error), error))
  {
    std::filesystem::remove(temporary, error);
    return false;
  }
  return true;
}

std::vector<std::string> OpenFOAMTimeNames(const std::vector<double>& times)
{
  std::vector<std::string> names(times.size());
  for (int digits = 6; digits <= 17; ++digits)
  {
    for (std::size_t k = 0; k < times.size(); ++k)
    {
      char name[64];
      std::snprintf(name, sizeof name, "%.*g", digits, times[k]);
      names[k] = name;
    }
    std::vector<std::string> sorted = names;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
    {
      break;
    }
  }
  return names;
}

vtkSmartPointer<vtkTable> ReadTrajectoryCSV(const std::string& path)
{
  if (!std::filesystem::is_regular_file(path))
  {
    std::cerr << "dgmf-deform: error: the trajectory table " << path << " is not a file\n";
    return nullptr;
  }
  // Every row whole: VTK's reader makes a short row's missing values, and an empty value, 0 (or
  // shorter columns), which would move a body silently (a table still being written, say).
  {
    std::ifstream text(path);
    std::string line;
    std::size_t fields = 0;
    for (std::size_t number = 1; std::getline(text, line); ++number)
    {
      if (!line.empty() && line.back() == '\r')
      {
        line.pop_back();
      }
      if (line.find_first_not_of(" \t") == std::string::npos)
      {
        continue; // blank lines are skipped, as VTK's reader does
      }
      std::vector<std::string> values;
      std::stringstream row(line);
      for (std::string value; std::getline(row, value, ',');)
      {
        values.push_back(value);
      }
      if (line.back() == ',')
      {
        values.emplace_back();
      }
      if (fields == 0)
      {
        // The header: a column named twice would be one column in VTK's table (the last).
        std::vector<std::string> names;
        for (const std::string& value : values)
        {
          std::string name = value.substr(value.find_first_not_of(" \t") == std::string::npos
              ? value.size()
              : value.find_first_not_of(" \t"));
          name = name.substr(0, name.find_last_not_of(" \t") + 1);
          std::transform(name.begin(), name.end(), name.begin(),
            [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
          if (std::find(names.begin(), names.end(), name) != names.end())
          {
            std::cerr << "dgmf-deform: error: the trajectory table " << path
                      << " names the column '" << value << "' twice: name each column once\n";
            return nullptr;
          }
          names.push_back(name);
        }
      }
      fields = fields == 0 ? values.size() : fields;
      const bool blank = std::any_of(values.begin(), values.end(),
        [](const std::string& value)
        { return value.find_first_not_of(" \t") == std::string::npos; });
      if (values.size() != fields || blank)
      {
        std::cerr << "dgmf-deform: error: the trajectory table " << path << ", line " << number
                  << ": " << values.size() << " values" << (blank ? ", one of them empty" : "")
                  << ", where the header has " << fields
                  << " (a row cut short, or a table still being written?)\n";
        return nullptr;
      }
    }
  }
  vtkNew<vtkDelimitedTextReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetHaveHeaders(true);
  reader->SetDetectNumericColumns(true);
  reader->SetFieldDelimiterCharacters(",");
  reader->Update();
  vtkSmartPointer<vtkTable> table = reader->GetOutput();
  if (!table || table->GetNumberOfRows() == 0)
  {
    std::cerr << "dgmf-deform: error: the trajectory table " << path << " has no rows\n";
    return nullptr;
  }
  return table;
}

} // namespace dgmf_cli
