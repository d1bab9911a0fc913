// gmsh's library loaded on first use (GmshModule.h).
#include "dgmf/meshfile/GmshModule.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
constexpr const char* kModuleName = "libDGMFGmshFile.so";

/// The directory of the library or program holding this code, or empty.
std::filesystem::path DirectoryOfThisCode()
{
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(&LoadGmshModule), &info) == 0 || !info.dli_fname)
  {
    return std::filesystem::path();
  }
  std::error_code ignored;
  const std::filesystem::path self = std::filesystem::canonical(info.dli_fname, ignored);
  return ignored ? std::filesystem::path() : self.parent_path();
}

/// Where the module is looked for, in order (GmshModule.h).
std::vector<std::string> Candidates()
{
  std::vector<std::string> candidates;
  if (const char* chosen = std::getenv("DGMF_GMSH_MODULE"))
  {
    if (*chosen)
    {
      candidates.emplace_back(chosen);
      return candidates;
    }
  }
  const std::filesystem::path here = DirectoryOfThisCode();
  if (!here.empty())
  {
    candidates.push_back((here / kModuleName).string());
  }
#ifdef DGMF_GMSH_MODULE_BUILD_PATH
  candidates.emplace_back(DGMF_GMSH_MODULE_BUILD_PATH);
#endif
  candidates.emplace_back(kModuleName);
  return candidates;
}

struct Loaded
{
  GmshModule Module{ nullptr, nullptr };
  std::string Failure; // why no module loaded, empty when one did
};

/// The first candidate that opens and has the entry points of this interface's version.
Loaded Load()
{
  Loaded loaded;
  std::string absent;
  for (const std::string& candidate : Candidates())
  {
    const bool byName = candidate.find('/') == std::string::npos;
    if (!byName && !std::filesystem::exists(candidate))
    {
      absent += (absent.empty() ? "" : ", ") + candidate;
      continue;
    }
    // RTLD_LOCAL: gmsh's symbols stay out of the process's global scope.
    void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
    {
      const char* error = ::dlerror();
      loaded.Failure +=
        (loaded.Failure.empty() ? "" : "; ") + std::string(error ? error : candidate);
      continue;
    }
    using VersionFunction = int (*)();
    const auto version =
      reinterpret_cast<VersionFunction>(::dlsym(handle, kGmshModuleVersionSymbol));
    GmshModule module{ reinterpret_cast<decltype(GmshModule::Read)>(
                         ::dlsym(handle, kGmshModuleReadSymbol)),
      reinterpret_cast<decltype(GmshModule::Write)>(::dlsym(handle, kGmshModuleWriteSymbol)) };
    if (!version || version() != kGmshModuleInterfaceVersion || !module.Read || !module.Write)
    {
      loaded.Failure += (loaded.Failure.empty() ? "" : "; ") + candidate +
        " is not a gmsh module of this version of the program";
      ::dlclose(handle);
      continue;
    }
    loaded.Module = module; // kept open for the process's life
    loaded.Failure.clear();
    return loaded;
  }
  if (!absent.empty())
  {
    loaded.Failure += (loaded.Failure.empty() ? "" : "; ") + std::string("no file ") + absent;
  }
  return loaded;
}
} // namespace

const GmshModule& LoadGmshModule(const std::string& file)
{
  static const Loaded loaded = Load();
  if (!loaded.Module.Read)
  {
    throw FileError(file + ": gmsh's library cannot be loaded: " + loaded.Failure);
  }
  return loaded.Module;
}

} // namespace meshfile
} // namespace dgmf
