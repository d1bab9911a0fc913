// gmsh's library loaded on first use (GmshModule.h).
#include "dgmf/meshfile/GmshModule.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace
{
constexpr const char* kModuleName = "libDGMFGmshFile.so";

/// The directory of the library or program holding this code, or empty. Asked with a function of
/// this file's own (an exported one may resolve to another library's copy).
std::filesystem::path DirectoryOfThisCode()
{
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(&DirectoryOfThisCode), &info) == 0 ||
    !info.dli_fname || !*info.dli_fname)
  {
    return std::filesystem::path();
  }
  std::error_code error;
  // A program's own code gives argv[0], which may be a bare name found through PATH.
  const std::filesystem::path self = std::strchr(info.dli_fname, '/')
    ? std::filesystem::canonical(info.dli_fname, error)
    : std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : self.parent_path();
}

/// True when `directory` is inside `root` (both canonical).
bool IsInside(const std::filesystem::path& directory, const std::filesystem::path& root)
{
  auto d = directory.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++d)
  {
    if (d == directory.end() || *d != *r)
    {
      return false;
    }
  }
  return true;
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
#if defined(DGMF_GMSH_MODULE_BUILD_PATH) && defined(DGMF_BUILD_DIRECTORY)
  // The build tree's module, for the build tree's programs only: an installed copy never falls
  // back to a build tree.
  std::error_code error;
  const std::filesystem::path build = std::filesystem::canonical(DGMF_BUILD_DIRECTORY, error);
  if (!here.empty() && !error && IsInside(here, build))
  {
    candidates.emplace_back(DGMF_GMSH_MODULE_BUILD_PATH);
  }
#endif
  candidates.emplace_back(kModuleName);
  return candidates;
}

/// The module `handle`'s entry points, or a reason why it is not this build's module.
std::optional<GmshModule> EntryPoints(void* handle, const std::string& candidate, std::string& why)
{
  using IdentityFunction = const char* (*)();
  const auto identity =
    reinterpret_cast<IdentityFunction>(::dlsym(handle, kGmshModuleIdentitySymbol));
  if (!identity)
  {
    why =
      candidate + " has no " + kGmshModuleIdentitySymbol + ": not a gmsh module of this program";
    return std::nullopt;
  }
  if (std::strcmp(identity(), kGmshModuleIdentity) != 0)
  {
    why = candidate + " is the gmsh module of another build (" + identity() + ", this one " +
      kGmshModuleIdentity + ")";
    return std::nullopt;
  }
  const GmshModule module{ reinterpret_cast<decltype(GmshModule::Read)>(
                             ::dlsym(handle, kGmshModuleReadSymbol)),
    reinterpret_cast<decltype(GmshModule::Write)>(::dlsym(handle, kGmshModuleWriteSymbol)) };
  if (!module.Read || !module.Write)
  {
    why = candidate + " lacks " + (module.Read ? kGmshModuleWriteSymbol : kGmshModuleReadSymbol);
    return std::nullopt;
  }
  return module;
}

/// The first candidate that opens and is this build's module; else `failure` says why none.
std::optional<GmshModule> Load(std::string& failure)
{
  std::string absent;
  for (const std::string& candidate : Candidates())
  {
    std::error_code error;
    const bool byName = candidate.find('/') == std::string::npos;
    if (!byName && !std::filesystem::exists(candidate, error))
    {
      absent += (absent.empty() ? "" : ", ") + candidate;
      continue;
    }
    // RTLD_LOCAL: gmsh's symbols stay out of the process's global scope.
    void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    std::string why;
    if (!handle)
    {
      const char* message = ::dlerror();
      why = message ? message : candidate + ": cannot be opened";
    }
    else if (std::optional<GmshModule> module = EntryPoints(handle, candidate, why))
    {
      return module; // kept open for the process's life
    }
    else
    {
      ::dlclose(handle);
    }
    failure += (failure.empty() ? "" : "; ") + why;
  }
  if (!absent.empty())
  {
    failure += (failure.empty() ? "" : "; ") + std::string("no file ") + absent;
  }
  return std::nullopt;
}
} // namespace

GmshModule LoadGmshModule(const std::string& file)
{
  // Only a success is kept: a failure (a missing libgmsh, a wrong DGMF_GMSH_MODULE) is tried
  // again on the next file, so that a long session recovers once it is fixed.
  static std::mutex mutex;
  static std::optional<GmshModule> loaded;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!loaded)
  {
    std::string failure;
    loaded = Load(failure);
    if (!loaded)
    {
      throw FileError(file + ": gmsh's library cannot be loaded: " + failure);
    }
  }
  return *loaded;
}

} // namespace meshfile
} // namespace dgmf
