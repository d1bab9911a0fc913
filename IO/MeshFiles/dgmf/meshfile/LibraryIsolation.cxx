#include "dgmf/meshfile/LibraryIsolation.h"

#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/NamedMesh.h"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace dgmf
{
namespace meshfile
{

namespace
{
void WriteAll(int fd, const std::string& bytes)
{
  std::size_t done = 0;
  while (done < bytes.size())
  {
    const ssize_t written = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      return;
    }
    done += static_cast<std::size_t>(written);
  }
}

/// Limits this process's address space to what it has now plus `budget` bytes.
void LimitAddressSpace(std::size_t budget)
{
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  const auto now = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE));
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0)
  {
    const rlim_t wanted = now + static_cast<rlim_t>(budget);
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
    ::setrlimit(RLIMIT_AS, &limit);
  }
}

[[noreturn]] void ChildMain(
  int fd, std::size_t memoryBudget, const std::function<std::string()>& work)
{
#if !defined(__SANITIZE_ADDRESS__)
  // (AddressSanitizer maps its own memory as it goes: no limit under it.)
  if (memoryBudget > 0)
  {
    LimitAddressSpace(memoryBudget);
  }
#else
  (void)memoryBudget;
#endif
  std::string answer;
  try
  {
    answer = "O" + work();
  }
  catch (const FileError& e)
  {
    answer = std::string("E") + e.what();
  }
  catch (const std::exception& e)
  {
    answer = std::string("X") + e.what();
  }
  catch (...)
  {
    answer = "Xunknown exception";
  }
  WriteAll(fd, answer);
  ::close(fd);
  ::_exit(0);
}
} // namespace

double TimeAllowed(const std::string& path)
{
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  return 120.0 + (error ? 0.0 : 10.0 * static_cast<double>(bytes) / (1 << 20));
}

namespace
{
/// The address space a reader's child may add: 1 GiB plus 64 times the file's size.
std::size_t MemoryBudget(const std::string& path)
{
  std::error_code error;
  const auto bytes = static_cast<std::size_t>(std::filesystem::file_size(path, error));
  return (std::size_t{ 1 } << 30) + 64 * (error ? 0 : bytes);
}
} // namespace

NamedMesh ReadMeshIsolated(
  const std::string& path, const std::string& library, const std::function<NamedMesh()>& read)
{
  return MeshFromBytes(RunIsolated(
    path, library, TimeAllowed(path), MemoryBudget(path), [&]() { return MeshToBytes(read()); }));
}

void WriteIsolated(const std::string& source, const std::string& target, const std::string& library,
  const std::function<void()>& write)
{
  try
  {
    RunIsolated(source, library, TimeAllowed(source), MemoryBudget(source),
      [&]()
      {
        write();
        return std::string();
      });
  }
  catch (const FileError&)
  {
    std::error_code error;
    std::filesystem::remove(TemporaryBeside(target), error);
    throw;
  }
}

std::string RunIsolated(const std::string& file, const std::string& library, double seconds,
  std::size_t memoryBudget, const std::function<std::string()>& work)
{
  int fds[2];
  if (::pipe(fds) != 0)
  {
    throw FileError(file + ": cannot create a pipe for " + library + ": " + std::strerror(errno));
  }
  const pid_t child = ::fork();
  if (child < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    throw FileError(file + ": cannot start a process for " + library + ": " + std::strerror(errno));
  }
  if (child == 0)
  {
    ::close(fds[0]);
    ChildMain(fds[1], memoryBudget, work);
  }
  ::close(fds[1]);
  std::string answer;
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  char buffer[1 << 16];
  for (;;)
  {
    const double left =
      std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0)
    {
      timedOut = true;
      break;
    }
    pollfd p{ fds[0], POLLIN, 0 };
    const int ready = ::poll(&p, 1, static_cast<int>(std::min(left * 1000.0, 1000.0)) + 1);
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    if (ready == 0)
    {
      continue;
    }
    const ssize_t got = ::read(fds[0], buffer, sizeof(buffer));
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      break; // the child closed the pipe: done or dead
    }
    answer.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(fds[0]);
  if (timedOut)
  {
    ::kill(child, SIGKILL);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (timedOut)
  {
    throw FileError(
      file + ": " + library + " did not finish within " + std::to_string(seconds) + " s (stopped)");
  }
  if (WIFSIGNALED(status))
  {
    throw FileError(file + ": " + library + " crashed on it (signal " +
      std::to_string(WTERMSIG(status)) + ": " + ::strsignal(WTERMSIG(status)) + ")");
  }
  if (answer.empty())
  {
    throw FileError(file + ": " + library + "'s process ended without an answer");
  }
  if (answer[0] == 'E')
  {
    throw FileError(answer.substr(1));
  }
  if (answer[0] != 'O')
  {
    throw FileError(file + ": " + answer.substr(1));
  }
  return answer.substr(1);
}

namespace
{
/// Appends the bytes of `values` after their count.
template <typename T>
void Put(std::string& out, const std::vector<T>& values)
{
  const std::uint64_t count = values.size();
  out.append(reinterpret_cast<const char*>(&count), sizeof(count));
  if (!values.empty())
  {
    out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
}

template <typename T>
void Get(const std::string& in, std::size_t& at, std::vector<T>& values)
{
  std::uint64_t count = 0;
  if (in.size() - at < sizeof(count))
  {
    throw FileError("short answer from a reader's process");
  }
  std::memcpy(&count, in.data() + at, sizeof(count));
  at += sizeof(count);
  if ((in.size() - at) / sizeof(T) < count)
  {
    throw FileError("short answer from a reader's process");
  }
  values.resize(count);
  if (count > 0) // an empty vector's data() may be null, which memcpy does not take
  {
    std::memcpy(values.data(), in.data() + at, count * sizeof(T));
  }
  at += count * sizeof(T);
}

void PutCells(std::string& out, const Cells& cells)
{
  Put(out, cells.Types);
  Put(out, cells.Offsets);
  Put(out, cells.Connectivity);
}

void GetCells(const std::string& in, std::size_t& at, Cells& cells)
{
  Get(in, at, cells.Types);
  Get(in, at, cells.Offsets);
  Get(in, at, cells.Connectivity);
}

} // namespace

std::string MeshToBytes(const NamedMesh& mesh)
{
  std::string out;
  Put(out, std::vector<std::int64_t>{ mesh.Dimension });
  Put(out, mesh.Points);
  Put(out, mesh.NodeIds);
  PutCells(out, mesh.Volume);
  Put(out, std::vector<std::int64_t>{ static_cast<std::int64_t>(mesh.Boundaries.size()) });
  for (const NamedBoundary& boundary : mesh.Boundaries)
  {
    Put(out, std::vector<char>(boundary.Name.begin(), boundary.Name.end()));
    PutCells(out, boundary.Faces);
  }
  return out;
}

NamedMesh MeshFromBytes(const std::string& in)
{
  NamedMesh mesh;
  std::size_t at = 0;
  std::vector<std::int64_t> number;
  Get(in, at, number);
  mesh.Dimension = number.empty() ? 0 : static_cast<int>(number[0]);
  Get(in, at, mesh.Points);
  Get(in, at, mesh.NodeIds);
  GetCells(in, at, mesh.Volume);
  Get(in, at, number);
  mesh.Boundaries.resize(number.empty() ? 0 : static_cast<std::size_t>(number[0]));
  for (NamedBoundary& boundary : mesh.Boundaries)
  {
    std::vector<char> name;
    Get(in, at, name);
    boundary.Name.assign(name.begin(), name.end());
    GetCells(in, at, boundary.Faces);
  }
  return mesh;
}

} // namespace meshfile
} // namespace dgmf
