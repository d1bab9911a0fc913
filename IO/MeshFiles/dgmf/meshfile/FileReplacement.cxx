#include "dgmf/meshfile/FileReplacement.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <filesystem>
#include <system_error>

namespace dgmf
{
namespace meshfile
{
namespace fs = std::filesystem;

std::string TemporaryBeside(const std::string& target)
{
  const fs::path path(target);
  return (
    path.parent_path() / ("." + path.stem().string() + ".dgmf-writing" + path.extension().string()))
    .string();
}

void WriteModifiedCopy(const std::string& source, const std::string& target,
  const std::function<void(const std::string& temporary)>& modify)
{
  const fs::path path(target);
  const fs::path temporary = TemporaryBeside(target);
  std::error_code error;
  if (!fs::copy_file(source, temporary, fs::copy_options::overwrite_existing, error))
  {
    fs::remove(temporary, error);
    throw FileError("cannot copy " + source + " to " + temporary.string() + ": " +
      (error ? error.message() : std::string("copy failed")));
  }
  try
  {
    modify(temporary.string());
  }
  catch (...)
  {
    fs::remove(temporary, error);
    throw;
  }
  fs::rename(temporary, path, error);
  if (error)
  {
    const std::string reason = error.message();
    fs::remove(temporary, error);
    throw FileError("cannot rename " + temporary.string() + " to " + target + ": " + reason);
  }
}

} // namespace meshfile
} // namespace dgmf
