#include "dgmf/meshfile/GmshSession.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <gmsh.h>

#include <cstdlib>

namespace dgmf
{
namespace meshfile
{
namespace fs = std::filesystem;

namespace
{
std::mutex& GmshMutex()
{
  static std::mutex mutex;
  return mutex;
}

/// Index of the first logged message not yet checked for errors (the logger is the session's).
std::size_t& CheckedMessages()
{
  static std::size_t checked = 0;
  return checked;
}

/// The name of the link to the file in the session's private directory (Merge).
constexpr const char* kLinkName = "mesh.msh";

} // namespace

GmshSession::GmshSession(const std::string& file)
  : Lock(GmshMutex())
  , File(file)
{
  static bool initialized = false;
  try
  {
    if (!initialized)
    {
      // Another part of the process may have initialized gmsh already: gmsh then only warns.
      gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
      gmsh::option::setNumber("General.Terminal", 0);
      initialized = true;
    }
    this->SetOption("General.Terminal", 0);
    this->SetOption("General.AbortOnError", 0);
    gmsh::logger::start();
    std::vector<std::string> log;
    gmsh::logger::get(log);
    CheckedMessages() = log.size();
    this->AddModel("dgmf-meshfile");
  }
  catch (const std::string& message)
  {
    this->Fail("gmsh could not be set up: " + message);
  }
  catch (const std::exception& e)
  {
    this->Fail(std::string("gmsh could not be set up: ") + e.what());
  }
  catch (...)
  {
    this->Fail("gmsh could not be set up");
  }
}

GmshSession::~GmshSession()
{
  try
  {
    for (const std::string& model : this->Models)
    {
      gmsh::model::setCurrent(model);
      gmsh::model::remove();
    }
    gmsh::logger::stop();
    for (auto it = this->SavedOptions.rbegin(); it != this->SavedOptions.rend(); ++it)
    {
      gmsh::option::setNumber(it->first, it->second);
    }
  }
  catch (...)
  {
  }
  if (!this->LinkDirectory.empty())
  {
    std::error_code ignored;
    fs::remove_all(this->LinkDirectory, ignored);
  }
}

void GmshSession::SetOption(const std::string& name, double value)
{
  double old = 0.0;
  gmsh::option::getNumber(name, old);
  this->SavedOptions.emplace_back(name, old);
  gmsh::option::setNumber(name, value);
}

void GmshSession::AddModel(const std::string& name)
{
  gmsh::model::add(name);
  this->Models.push_back(name);
}

void GmshSession::Fail(const std::string& what) const
{
  throw FileError(this->File + ": " + what);
}

void GmshSession::ThrowOnGmshError(const std::string& what)
{
  std::vector<std::string> log;
  gmsh::logger::get(log);
  // gmsh reads the file through a link (Merge): its messages name the user's file instead.
  const std::string link =
    this->LinkDirectory.empty() ? std::string() : (this->LinkDirectory / kLinkName).string();
  std::string errors;
  for (std::size_t k = CheckedMessages(); k < log.size(); ++k)
  {
    std::string message = log[k];
    if (message.rfind("Error", 0) != 0)
    {
      continue;
    }
    if (message.rfind("Error: ", 0) == 0)
    {
      message.erase(0, 7);
    }
    for (std::size_t at; !link.empty() && (at = message.find(link)) != std::string::npos;)
    {
      message.replace(at, link.size(), this->File);
    }
    errors += (errors.empty() ? "" : "; ") + message;
  }
  CheckedMessages() = log.size();
  if (!errors.empty())
  {
    this->Fail(what + ": " + errors);
  }
}

void GmshSession::Merge(const std::string& path)
{
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  std::string pattern = (fs::temp_directory_path(error) / "dgmf-gmsh-XXXXXX").string();
  if (error || !::mkdtemp(&pattern[0]))
  {
    this->Fail("no private temporary directory for gmsh to read the file through");
  }
  this->LinkDirectory = pattern;
  const fs::path link = this->LinkDirectory / kLinkName;
  fs::create_symlink(absolute, link, error);
  if (error)
  {
    this->Fail("cannot link the file for gmsh: " + error.message());
  }
  try
  {
    gmsh::merge(link.string());
  }
  catch (...)
  {
    // AbortOnError is 0: gmsh reports through the logger. Anything thrown anyway is reported
    // below with the logged errors.
    gmsh::logger::write("gmsh threw while reading", "error");
  }
  this->ThrowOnGmshError("gmsh cannot read it");
}

} // namespace meshfile
} // namespace dgmf
