/**
 * @file GmshSession.h
 * @brief Private to the gmsh module (GmshModel.cxx, GmshModule.h): one serialized use of gmsh's
 * library (initialized once per process, silent, errors collected instead of thrown).
 */
#ifndef dgmf_meshfile_GmshSession_h
#define dgmf_meshfile_GmshSession_h

#include "dgmf/meshfile/MshHeader.h"

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace dgmf
{
namespace meshfile
{

/**
 * One use of gmsh's library, under a process-wide lock (gmsh's state is global). The first
 * session initializes gmsh (without the user's configuration files); every session sets
 * General.Terminal = 0 (silent) and General.AbortOnError = 0 (gmsh 4.8 leaks the open file and,
 * in gmsh::open, its "busy" lock when an error is thrown through its readers), collects gmsh's
 * messages with gmsh::logger, works in a model of its own (removed at the end) and restores the
 * options it changed.
 */
class GmshSession
{
public:
  /// `file` names the file in every error message.
  explicit GmshSession(const std::string& file);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /**
   * Merges the checked .msh file `path` into the session's (empty) model, through a link named
   * mesh.msh in a private directory: gmsh then picks its reader by the header alone and merges no
   * `path`.opt option file. Throws FileError with gmsh's messages when gmsh reports an error.
   */
  void Merge(const std::string& path);

  /// Sets a numerical gmsh option for this session (the old value comes back at the end).
  void SetOption(const std::string& name, double value);

  /// Adds a model of the session's own and makes it current (removed at the end).
  void AddModel(const std::string& name);

  /// Throws FileError("<file>: <what>: <gmsh's errors>") when gmsh logged an error since the last
  /// check.
  void ThrowOnGmshError(const std::string& what);

  /// Throws FileError("<file>: <what>").
  [[noreturn]] void Fail(const std::string& what) const;

private:
  std::unique_lock<std::mutex> Lock;
  std::string File;
  std::vector<std::string> Models;
  std::vector<std::pair<std::string, double>> SavedOptions;
  std::filesystem::path LinkDirectory;
};

} // namespace meshfile
} // namespace dgmf

#endif
