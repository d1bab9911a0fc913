#include "dgmf/meshfile/LibraryIsolation.h"

#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/NamedMesh.h"

#include <fcntl.h>
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

/// The child's answer starts with its kind ('O' done, 'E' FileError, 'X' other failure) and the
/// body's length in bytes (8, native order: the same program on both ends).
constexpr std::size_t AnswerHeaderBytes = 1 + sizeof(std::uint64_t);

/// The bytes read from the child at most per call, and the pipe's capacity asked for: a 62 MB
/// answer went through the default 64 KiB pipe at about 0.65 GB/s, a switch between the two
/// processes every 64 KiB.
constexpr std::size_t PipeBytes = std::size_t(1) << 20;

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
  char kind = 'O';
  std::string body;
  try
  {
    body = work();
  }
  catch (const FileError& e)
  {
    kind = 'E';
    body = e.what();
  }
  catch (const std::exception& e)
  {
    kind = 'X';
    body = e.what();
  }
  catch (...)
  {
    kind = 'X';
    body = "unknown exception";
  }
  // The answer's header (AnswerHeaderBytes: the kind, then the body's length), then the body as
  // it is: the caller reads it straight into a string of that length.
  const std::uint64_t length = body.size();
  std::string header(1, kind);
  header.append(reinterpret_cast<const char*>(&length), sizeof(length));
  WriteAll(fd, header);
  WriteAll(fd, body);
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
#ifdef F_SETPIPE_SZ
  ::fcntl(fds[0], F_SETPIPE_SZ, static_cast<int>(PipeBytes)); // the default where refused
#endif
  char header[AnswerHeaderBytes];
  std::size_t headerRead = 0;
  std::string body;
  std::size_t bodyRead = 0;
  bool tooLong = false; // bytes past the announced length, or a length beyond any answer
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  char excess[4096];
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
    // The header first, then the body in place, then anything more into `excess` (an error).
    char* into = excess;
    std::size_t room = sizeof(excess);
    if (headerRead < AnswerHeaderBytes)
    {
      into = header + headerRead;
      room = AnswerHeaderBytes - headerRead;
    }
    else if (bodyRead < body.size())
    {
      into = body.data() + bodyRead;
      room = std::min(body.size() - bodyRead, PipeBytes);
    }
    const ssize_t got = ::read(fds[0], into, room);
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      break; // the child closed the pipe: done or dead
    }
    const auto count = static_cast<std::size_t>(got);
    if (headerRead < AnswerHeaderBytes)
    {
      headerRead += count;
      if (headerRead == AnswerHeaderBytes)
      {
        std::uint64_t length = 0;
        std::memcpy(&length, header + 1, sizeof(length));
        try
        {
          body.resize(static_cast<std::size_t>(length));
        }
        catch (const std::exception&) // a length no answer can have (std::length_error, bad_alloc)
        {
          tooLong = true;
          break;
        }
      }
    }
    else if (bodyRead < body.size())
    {
      bodyRead += count;
    }
    else
    {
      tooLong = true;
      break;
    }
  }
  ::close(fds[0]);
  if (timedOut || tooLong)
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
  if (WIFSIGNALED(status) && !tooLong) // (killed above when its answer was too long)
  {
    throw FileError(file + ": " + library + " crashed on it (signal " +
      std::to_string(WTERMSIG(status)) + ": " + ::strsignal(WTERMSIG(status)) + ")");
  }
  if (headerRead < AnswerHeaderBytes)
  {
    throw FileError(file + ": " + library + "'s process ended without an answer");
  }
  if (tooLong || bodyRead < body.size())
  {
    throw FileError(file + ": " + library + "'s process gave a broken answer (" +
      std::to_string(bodyRead) + " bytes of " + std::to_string(body.size()) +
      (tooLong ? ", or more than it announced)" : ")"));
  }
  if (header[0] == 'E')
  {
    throw FileError(body);
  }
  if (header[0] != 'O')
  {
    throw FileError(file + ": " + body);
  }
  return body;
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

/// The bytes Put appends for `values`.
template <typename T>
std::size_t BytesOf(const std::vector<T>& values)
{
  return sizeof(std::uint64_t) + values.size() * sizeof(T);
}

std::size_t BytesOfCells(const Cells& cells)
{
  return BytesOf(cells.Types) + BytesOf(cells.Offsets) + BytesOf(cells.Connectivity);
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
  // Its exact size first: no copy as it grows (a volume of 1.3M tetrahedra is 60 MB).
  const std::size_t number = sizeof(std::uint64_t) + sizeof(std::int64_t); // a count, a value
  std::size_t bytes =
    number + BytesOf(mesh.Points) + BytesOf(mesh.NodeIds) + BytesOfCells(mesh.Volume) + number;
  for (const NamedBoundary& boundary : mesh.Boundaries)
  {
    bytes += sizeof(std::uint64_t) + boundary.Name.size() + BytesOfCells(boundary.Faces);
  }
  out.reserve(bytes);
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
