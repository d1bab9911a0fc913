#include "WholeCommand.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <unistd.h> // sync
#include <vector>

namespace dgmf_bench
{
namespace
{
double Number(const std::string& text, const std::string& pattern)
{
  std::smatch match;
  if (!std::regex_search(text, match, std::regex(pattern)))
  {
    throw std::runtime_error("dgmf-deform printed no '" + pattern + "': " + text);
  }
  return std::stod(match[1].str());
}
} // namespace

namespace
{
/// One run of the command on `input`, into `output` (removed first, then the file system synced).
CommandTimes RunCommand(const std::string& command, const std::string& input,
  const std::string& output, const std::string& log, int threads)
{
  // No output of an earlier run to replace (deleting 600 MB of cached file made the write 0.3 s
  // longer; a user writing to a new name does not pay that), and the input on disk before the
  // clock starts (else the kernel writes it back while the command runs, and the command's own
  // write waits on that: 0.3 to 1 s at 8M nodes).
  std::error_code ignored;
  std::filesystem::remove(output, ignored);
  ::sync();
  const std::string line = "'" + command + "' '" + input + "' '" + output +
    "' --marker BoundaryMarker --rotate 5 10 15 --translate 0.1 0 0 --threads " +
    std::to_string(threads) + " > '" + log + "' 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(line.c_str());
  CommandTimes times;
  times.Wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ifstream file(log);
  std::stringstream text;
  text << file.rdbuf();
  if (status != 0)
  {
    throw std::runtime_error("dgmf-deform failed: " + text.str());
  }
  const std::string printed = text.str();
  times.Filter = Number(printed, "cells, ([0-9.e+-]+) s");
  times.Read = Number(printed, "read ([0-9.e+-]+) s");
  times.Write = Number(printed, "written ([0-9.e+-]+) s");
  return times;
}
} // namespace

CommandTimes TimeWholeCommand(vtkUnstructuredGrid* mesh, const std::string& command,
  const std::string& directory, int threads, int repeats)
{
  const std::string input = directory + "/mesh.vtu";
  const std::string output = directory + "/deformed.vtu";
  const std::string log = directory + "/command.log";
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(input.c_str());
  writer->SetDataModeToAppended();
  writer->SetEncodeAppendedData(0);
  writer->SetCompressorTypeToLZ4();
  if (!writer->Write())
  {
    throw std::runtime_error("could not write " + input);
  }
  std::vector<CommandTimes> runs;
  for (int run = 0; run < std::max(repeats, 1); ++run)
  {
    runs.push_back(RunCommand(command, input, output, log, threads));
  }
  std::sort(runs.begin(), runs.end(),
    [](const CommandTimes& a, const CommandTimes& b) { return a.Wall < b.Wall; });
  return runs[runs.size() / 2];
}

} // namespace dgmf_bench
