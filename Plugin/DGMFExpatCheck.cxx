/**
 * @file DGMFExpatCheck.cxx
 * @brief The expat inspection and the warning text of DGMFExpatCheck.h.
 */
#include "DGMFExpatCheck.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>

#include <sstream>

namespace dgmf_plugin
{
namespace
{

/** The file of the loaded object that holds `address`; empty if none. */
std::string ObjectFile(const void* address, const void** base)
{
  Dl_info info{};
  if (!address || dladdr(address, &info) == 0 || !info.dli_fname)
  {
    return std::string();
  }
  if (base)
  {
    *base = info.dli_fbase;
  }
  return info.dli_fname;
}

/** `path` made absolute and normalised when it exists, else as given. */
std::string Normalised(const std::string& path)
{
  char resolved[PATH_MAX];
  return realpath(path.c_str(), resolved) ? std::string(resolved) : path;
}

/** The folder of `file` (everything before the last '/'), "." if it has none. */
std::string Folder(const std::string& file)
{
  const auto slash = file.rfind('/');
  return slash == std::string::npos ? std::string(".") : file.substr(0, slash);
}

} // namespace

ExpatState InspectExpat()
{
  ExpatState state;
  state.DefersReparse = dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled") != nullptr;
  const void* parserBase = nullptr;
  state.ParserLibrary =
    Normalised(ObjectFile(dlsym(RTLD_DEFAULT, "XML_ParserCreate"), &parserBase));
  const void* markerBase = nullptr;
  const bool marked =
    !ObjectFile(dlsym(RTLD_DEFAULT, "dgmf_expat_fix_loaded"), &markerBase).empty();
  state.WorkAroundServes = marked && parserBase && markerBase == parserBase;
  return state;
}

bool NeedsWorkAround(const ExpatState& state)
{
  return state.DefersReparse && !state.ParserLibrary.empty() && !state.WorkAroundServes;
}

std::string ProgramName()
{
  char exe[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
  if (length <= 0)
  {
    return std::string();
  }
  exe[length] = '\0';
  const std::string file(exe);
  const std::string name = file.substr(file.rfind('/') + 1);
  // Debian's pvpython and pvbatch are pvpython3.11 and pvbatch3.11.
  for (const char* program : { "pvpython", "pvbatch", "paraview" })
  {
    if (name.rfind(program, 0) == 0)
    {
      return program;
    }
  }
  return name;
}

WorkAroundPaths FindWorkAround(
  const std::string& pluginFile, const std::string& pluginToLib, const std::string& pluginToBin)
{
  const std::string pluginFolder = Folder(Normalised(pluginFile));
  WorkAroundPaths paths;
  paths.Library = Normalised(pluginFolder + "/" + pluginToLib + "/libdgmf_expat_fix.so");
  paths.Launchers = Normalised(pluginFolder + "/" + pluginToBin);
  paths.Program = ProgramName();
  return paths;
}

std::string WarningText(const ExpatState& state, const WorkAroundPaths& paths)
{
  const std::string& p = paths.Program;
  const std::string program =
    p == "pvpython" || p == "pvbatch" || p == "paraview" ? p : std::string("pvpython");
  const std::string launcher = paths.Launchers + "/dgmf-" + program;
  std::ostringstream text;
  text << "DGMF: this process's libexpat (" << state.ParserLibrary
       << ") defers re-parsing (Debian 12's 2.5.0-1+deb12u2 and later) and the DGMF expat "
          "work-around is not loaded: VTK 9.2's XML reading fails, appended-mode .vtu files read "
          "back empty, and under MPI RedistributeDataSet silently drops data. Quit and start "
       << program << " with the work-around:\n  " << launcher
       << " ARGUMENTS\nor\n  LD_PRELOAD=" << paths.Library << " " << program
       << " ARGUMENTS\nUnder MPI: mpiexec -np N " << paths.Launchers
       << "/dgmf-pvbatch ARGUMENTS. Without a display: xvfb-run -a -s \"-screen 0 "
          "1280x1024x24 -noreset\" "
       << launcher << " ARGUMENTS (the preload after xvfb-run, never before it).";
  return text.str();
}

} // namespace dgmf_plugin
