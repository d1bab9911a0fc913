#include "dgmf/meshfile/MappedFile.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace dgmf
{
namespace meshfile
{

MappedFile::MappedFile(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
  {
    throw FileError(path + ": cannot be opened");
  }
  struct stat status
  {
  };
  if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0)
  {
    void* bytes =
      ::mmap(nullptr, static_cast<std::size_t>(status.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (bytes != MAP_FAILED)
    {
      this->Data = static_cast<const char*>(bytes);
      this->Size = static_cast<std::size_t>(status.st_size);
      this->Mapped = true;
    }
  }
  if (!this->Mapped)
  {
    // Read from the descriptor already open (a named pipe could not be opened twice).
    char chunk[1 << 16];
    for (;;)
    {
      const ssize_t got = ::read(fd, chunk, sizeof(chunk));
      if (got < 0 && errno == EINTR)
      {
        continue;
      }
      if (got < 0)
      {
        ::close(fd);
        throw FileError(path + ": cannot be read");
      }
      if (got == 0)
      {
        break;
      }
      this->Owned.append(chunk, static_cast<std::size_t>(got));
    }
    this->Data = this->Owned.data();
    this->Size = this->Owned.size();
  }
  ::close(fd); // (a mapping outlives its descriptor)
}

MappedFile::~MappedFile()
{
  if (this->Mapped)
  {
    ::munmap(const_cast<char*>(this->Data), this->Size);
  }
}

} // namespace meshfile
} // namespace dgmf
