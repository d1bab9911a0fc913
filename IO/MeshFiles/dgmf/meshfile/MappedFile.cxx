#include "dgmf/meshfile/MappedFile.h"

#include "dgmf/meshfile/NamedMesh.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cerrno>

namespace dgmf
{
namespace meshfile
{

namespace
{
/// Closes a descriptor when it goes (an exception while reading included).
struct OpenFile
{
  int Fd;
  explicit OpenFile(int fd)
    : Fd(fd)
  {
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  ~OpenFile()
  {
    if (this->Fd >= 0)
    {
      ::close(this->Fd);
    }
  }
};

/// True for the local file systems a mapping is trusted on: a read error there is a failing
/// disk. Network and FUSE file systems (NFS, SMB, Lustre, GPFS, sshfs...) are read instead, so
/// that their I/O errors are errors, not SIGBUS.
bool IsLocalFileSystem(int fd)
{
  struct statfs system
  {
  };
  if (::fstatfs(fd, &system) != 0)
  {
    return false;
  }
  switch (static_cast<unsigned long>(system.f_type))
  {
    case 0xEF53UL:     // ext2, ext3, ext4
    case 0x58465342UL: // xfs
    case 0x9123683EUL: // btrfs
    case 0x01021994UL: // tmpfs
    case 0x858458F6UL: // ramfs
    case 0x794C7630UL: // overlayfs (containers)
    case 0xF2F52010UL: // f2fs
    case 0x2FC12FC1UL: // zfs
      return true;
    default:
      return false;
  }
}
} // namespace

MappedFile::MappedFile(const std::string& path)
{
  const OpenFile file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.Fd < 0)
  {
    throw FileError(path + ": cannot be opened");
  }
  struct stat status
  {
  };
  if (::fstat(file.Fd, &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0 &&
    IsLocalFileSystem(file.Fd))
  {
    void* bytes =
      ::mmap(nullptr, static_cast<std::size_t>(status.st_size), PROT_READ, MAP_PRIVATE, file.Fd, 0);
    if (bytes != MAP_FAILED)
    {
      this->Data = static_cast<const char*>(bytes);
      this->Size = static_cast<std::size_t>(status.st_size);
      this->Mapped = true;
      return; // (a mapping outlives its descriptor)
    }
  }
  // Read from the descriptor already open (a named pipe could not be opened twice).
  if (S_ISREG(status.st_mode) && status.st_size > 0)
  {
    this->Owned.reserve(static_cast<std::size_t>(status.st_size));
  }
  char chunk[1 << 16];
  for (;;)
  {
    const ssize_t got = ::read(file.Fd, chunk, sizeof(chunk));
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got < 0)
    {
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

MappedFile::~MappedFile()
{
  if (this->Mapped)
  {
    ::munmap(const_cast<char*>(this->Data), this->Size);
  }
}

} // namespace meshfile
} // namespace dgmf
