#include "dgmf/meshfile/FileReplacement.h"

#include "dgmf/meshfile/MappedFile.h"
#include "dgmf/meshfile/NamedMesh.h"

#include <filesystem>
#include <fstream>
#include <system_error>

namespace dgmf
{
namespace meshfile
{
namespace fs = std::filesystem;

std::string ReadFileBytes(const std::string& path)
{
  return std::string(MappedFile(path).Bytes());
}

void WriteFileAtomically(const std::string& target, const std::string& temporary,
  const std::function<void(BufferedOutput&)>& write)
{
  std::error_code error;
  {
    BufferedOutput out(temporary);
    try
    {
      write(out);
      out.Flush();
      out.File.close();
    }
    catch (...)
    {
      out.File.close();
      fs::remove(temporary, error);
      throw;
    }
    if (!out.File)
    {
      fs::remove(temporary, error);
      throw FileError(target + ": cannot write " + temporary + " (disk full?)");
    }
  }
  fs::rename(temporary, target, error);
  if (error)
  {
    const std::string message = error.message();
    fs::remove(temporary, error);
    throw FileError(target + ": cannot be replaced: " + message);
  }
}

void WriteFileAtomically(
  const std::string& target, const std::string& temporary, const std::string& bytes)
{
  WriteFileAtomically(
    target, temporary, [&](BufferedOutput& out) { out.Append(bytes.data(), bytes.size()); });
}

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
