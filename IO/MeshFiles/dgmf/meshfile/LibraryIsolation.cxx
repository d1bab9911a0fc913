#include "dgmf/meshfile/LibraryIsolation.h"

#include "dgmf/meshfile/FileReplacement.h"
#include "dgmf/meshfile/MeshBytes.h"
#include "dgmf/meshfile/NamedMesh.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>
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

#if !defined(__SANITIZE_ADDRESS__) // (AddressSanitizer maps its own memory as it goes: no limit)
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
#endif

/// The child's answer room: the memory file, grown to the size asked for and mapped.
char* TakeRoom(int memory, std::size_t bytes, std::size_t& taken)
{
  if (taken != 0 || bytes == 0)
  {
    if (taken != 0)
    {
      throw std::logic_error("a child's answer room is asked for twice");
    }
    return nullptr;
  }
  if (::ftruncate(memory, static_cast<off_t>(bytes)) != 0)
  {
    throw std::runtime_error(
      "no memory for an answer of " + std::to_string(bytes) + " bytes: " + std::strerror(errno));
  }
  void* room = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, memory, 0);
  if (room == MAP_FAILED)
  {
    throw std::runtime_error(
      "no memory for an answer of " + std::to_string(bytes) + " bytes: " + std::strerror(errno));
  }
  taken = bytes;
  return static_cast<char*>(room);
}

[[noreturn]] void ChildMain(
  int fd, int memory, std::size_t memoryBudget, const std::function<void(const AnswerRoom&)>& work)
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
  std::string message; // the error's; an answer is in the memory file
  std::size_t taken = 0;
  try
  {
    work([&](std::size_t bytes) { return TakeRoom(memory, bytes, taken); });
  }
  catch (const FileError& e)
  {
    kind = 'E';
    message = e.what();
  }
  catch (const std::exception& e)
  {
    kind = 'X';
    message = e.what();
  }
  catch (...)
  {
    kind = 'X';
    message = "unknown exception";
  }
  // The header (AnswerHeaderBytes: the kind, then a length: the answer's bytes in the memory
  // file, or the message's that follows it in the pipe).
  const std::uint64_t length = kind == 'O' ? taken : message.size();
  std::string header(1, kind);
  header.append(reinterpret_cast<const char*>(&length), sizeof(length));
  WriteAll(fd, header + message);
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
  // The child writes the mesh's bytes straight into the shared answer; the caller reads them
  // from the mapping into its mesh: one copy each way, none through a pipe.
  const IsolatedAnswer answer =
    RunIsolatedInPlace(path, library, TimeAllowed(path), MemoryBudget(path),
      [&](const AnswerRoom& room)
      {
        const NamedMesh mesh = read();
        MeshToBytes(mesh, room(MeshBytes(mesh)));
      });
  return MeshFromBytes(answer.Data(), answer.Size());
}

void WriteIsolated(const std::string& source, const std::string& target, const std::string& library,
  const std::function<void()>& write)
{
  try
  {
    RunIsolatedInPlace(source, library, TimeAllowed(source), MemoryBudget(source),
      [&](const AnswerRoom&) { write(); });
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
  const IsolatedAnswer answer = RunIsolatedInPlace(file, library, seconds, memoryBudget,
    [&](const AnswerRoom& room)
    {
      const std::string bytes = work();
      if (!bytes.empty())
      {
        std::memcpy(room(bytes.size()), bytes.data(), bytes.size());
      }
    });
  return std::string(answer.Data(), answer.Size());
}

IsolatedAnswer::IsolatedAnswer(const char* data, std::size_t size)
  : Bytes(data)
  , Length(size)
{
}

IsolatedAnswer::IsolatedAnswer(IsolatedAnswer&& other) noexcept
  : Bytes(std::exchange(other.Bytes, nullptr))
  , Length(std::exchange(other.Length, 0))
{
}

IsolatedAnswer& IsolatedAnswer::operator=(IsolatedAnswer&& other) noexcept
{
  if (this != &other)
  {
    IsolatedAnswer gone(std::move(*this));
    this->Bytes = std::exchange(other.Bytes, nullptr);
    this->Length = std::exchange(other.Length, 0);
  }
  return *this;
}

IsolatedAnswer::~IsolatedAnswer()
{
  if (this->Bytes != nullptr)
  {
    ::munmap(const_cast<char*>(this->Bytes), this->Length);
  }
}

namespace
{
/// Closes a descriptor when it goes.
struct Descriptor
{
  int Fd = -1;
  explicit Descriptor(int fd)
    : Fd(fd)
  {
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() { this->Close(); }
  void Close()
  {
    if (this->Fd >= 0)
    {
      ::close(this->Fd);
      this->Fd = -1;
    }
  }
};
} // namespace

IsolatedAnswer RunIsolatedInPlace(const std::string& file, const std::string& library,
  double seconds, std::size_t memoryBudget, const std::function<void(const AnswerRoom&)>& work)
{
  const Descriptor memory(::memfd_create("dgmf-answer", MFD_CLOEXEC));
  if (memory.Fd < 0)
  {
    throw FileError(
      file + ": cannot make room for " + library + "'s answer: " + std::strerror(errno));
  }
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
    ChildMain(fds[1], memory.Fd, memoryBudget, work);
  }
  ::close(fds[1]);
  Descriptor pipe(fds[0]);
  // The header, then an error's message (an answer's bytes are in the memory file).
  char header[AnswerHeaderBytes];
  std::size_t headerRead = 0;
  std::uint64_t length = 0;
  std::string message;
  std::size_t messageRead = 0;
  bool tooLong = false; // bytes past the announced length, or a length beyond any message
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
    pollfd p{ pipe.Fd, POLLIN, 0 };
    const int ready = ::poll(&p, 1, static_cast<int>(std::min(left * 1000.0, 1000.0)) + 1);
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    if (ready == 0)
    {
      continue;
    }
    char* into = excess;
    std::size_t room = sizeof(excess);
    if (headerRead < AnswerHeaderBytes)
    {
      into = header + headerRead;
      room = AnswerHeaderBytes - headerRead;
    }
    else if (messageRead < message.size())
    {
      into = message.data() + messageRead;
      room = message.size() - messageRead;
    }
    const ssize_t got = ::read(pipe.Fd, into, room);
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
        std::memcpy(&length, header + 1, sizeof(length));
        if (header[0] != 'O')
        {
          try
          {
            message.resize(static_cast<std::size_t>(length));
          }
          catch (const std::exception&) // a length no message can have
          {
            tooLong = true;
            break;
          }
        }
      }
    }
    else if (messageRead < message.size())
    {
      messageRead += count;
    }
    else
    {
      tooLong = true;
      break;
    }
  }
  pipe.Close();
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
  if (tooLong || messageRead < message.size())
  {
    throw FileError(file + ": " + library + "'s process gave a broken answer (" +
      std::to_string(messageRead) + " bytes of " + std::to_string(message.size()) +
      (tooLong ? ", or more than it announced)" : ")"));
  }
  if (header[0] == 'E')
  {
    throw FileError(message);
  }
  if (header[0] != 'O')
  {
    throw FileError(file + ": " + message);
  }
  return MapIsolatedAnswer(memory.Fd, length, file, library);
}

IsolatedAnswer MapIsolatedAnswer(
  int memory, std::uint64_t length, const std::string& file, const std::string& library)
{
  struct stat status
  {
  };
  if (::fstat(memory, &status) != 0 || status.st_size < 0 ||
    static_cast<std::uint64_t>(status.st_size) < length)
  {
    throw FileError(file + ": " + library + "'s process gave a broken answer (" +
      std::to_string(status.st_size) + " bytes of " + std::to_string(length) + ")");
  }
  if (length == 0)
  {
    return IsolatedAnswer();
  }
  void* bytes = ::mmap(nullptr, static_cast<std::size_t>(length), PROT_READ, MAP_SHARED, memory, 0);
  if (bytes == MAP_FAILED)
  {
    throw FileError(file + ": cannot map " + library + "'s answer of " + std::to_string(length) +
      " bytes: " + std::strerror(errno));
  }
  return IsolatedAnswer(static_cast<const char*>(bytes), static_cast<std::size_t>(length));
}

} // namespace meshfile
} // namespace dgmf
