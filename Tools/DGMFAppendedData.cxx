#include "DGMFAppendedData.h"

#include "DGMFCompressorClasses.h"

#include "dgmf/FirstTouch.h"

#include "vtkSMPTools.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <type_traits>

namespace dgmf_cli
{
namespace
{
/// VTK's compressor of the class `name` (null for "" or another one).
vtkSmartPointer<vtkDataCompressor> NewCompressor(const std::string& name)
{
  return WithCompressorClass(name,
    [](auto* vtkClass)
    {
      using Class = std::remove_pointer_t<decltype(vtkClass)>;
      return vtkSmartPointer<vtkDataCompressor>(vtkSmartPointer<Class>::New());
    });
}
} // namespace

AppendedData::AppendedData(
  const std::string& path, std::size_t position, int headerBytes, const std::string& compressorName)
  : Position(position)
  , HeaderBytes(static_cast<std::size_t>(headerBytes))
  , CompressorName(compressorName)
{
  // The file mapped read-only: the kernel's page cache, no copy.
  const int fd = ::open(path.c_str(), O_RDONLY);
  struct stat status;
  if (fd >= 0 && ::fstat(fd, &status) == 0 && status.st_size > 0)
  {
    int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
    flags |= MAP_POPULATE; // the pages mapped at once, not one fault at a time
#endif
    const auto size = static_cast<std::size_t>(status.st_size);
    void* data = ::mmap(nullptr, size, PROT_READ, flags, fd, 0);
    if (data != MAP_FAILED)
    {
      this->File = std::shared_ptr<const void>(
        data, [size](const void* at) { ::munmap(const_cast<void*>(at), size); });
      this->Data = static_cast<const unsigned char*>(data);
      this->Size = size;
    }
  }
  if (fd >= 0)
  {
    ::close(fd);
  }
  if (!this->Data)
  {
    throw NotTaken{ "the file cannot be mapped" };
  }
}

bool AppendedData::CanDecompress(const std::string& compressorName)
{
  return compressorName.empty() || NewCompressor(compressorName);
}

std::uint64_t AppendedData::Word(std::size_t at) const
{
  this->Check(at, this->HeaderBytes);
  if (this->HeaderBytes == 4)
  {
    std::uint32_t value;
    std::memcpy(&value, this->Data + at, sizeof value);
    return value;
  }
  std::uint64_t value;
  std::memcpy(&value, this->Data + at, sizeof value);
  return value;
}

void AppendedData::Check(std::size_t at, std::size_t bytes) const
{
  if (at > this->Size || bytes > this->Size - at)
  {
    throw NotTaken{ "an array that runs past the end of the file" };
  }
}

AppendedData::CompressedBlocks AppendedData::Queue(
  std::size_t offset, unsigned char* target, std::size_t bytes)
{
  CompressedBlocks compressedBlocks;
  const std::size_t header = this->HeaderBytes;
  if (offset > this->Size)
  {
    throw NotTaken{ "an array that runs past the end of the file" };
  }
  const std::size_t at = this->Position + offset;
  if (this->CompressorName.empty())
  {
    if (this->Word(at) != bytes)
    {
      throw NotTaken{ "an array whose size is not the one the header gives" };
    }
    this->Check(at + header, bytes);
    this->Jobs.push_back({ this->Data + at + header, bytes, target, bytes });
    return compressedBlocks;
  }
  const std::uint64_t blocks = this->Word(at);
  const std::uint64_t blockSize = this->Word(at + header);
  const std::uint64_t lastSize = this->Word(at + 2 * header);
  if (blocks > this->Size / header || (blocks > 0 && blockSize == 0) || lastSize > blockSize)
  {
    throw NotTaken{ "an array whose blocks are not what the header says" };
  }
  // Each block's size taken from what is left of the array: the sizes must add up to it.
  std::size_t left = bytes;
  std::size_t source = at + (3 + static_cast<std::size_t>(blocks)) * header;
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    const std::uint64_t compressed = this->Word(at + (3 + b) * header);
    const std::uint64_t size = b + 1 < blocks || lastSize == 0 ? blockSize : lastSize;
    if (size > left || compressed > this->Size)
    {
      throw NotTaken{ "an array whose size is not the one the header gives" };
    }
    this->Check(source, static_cast<std::size_t>(compressed));
    this->Jobs.push_back({ this->Data + source, static_cast<std::size_t>(compressed), target,
      static_cast<std::size_t>(size) });
    compressedBlocks.Blocks.emplace_back(this->Data + source, static_cast<std::size_t>(compressed));
    source += static_cast<std::size_t>(compressed);
    target += size;
    left -= static_cast<std::size_t>(size);
  }
  if (left != 0)
  {
    throw NotTaken{ "an array whose size is not the one the header gives" };
  }
  compressedBlocks.BlockSize = static_cast<std::size_t>(blockSize);
  return compressedBlocks;
}

void AppendedData::Run()
{
  std::atomic<bool> failed(false);
  const std::vector<Job>& jobs = this->Jobs;
  vtkSMPTools::For(0, static_cast<vtkIdType>(jobs.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkSmartPointer<vtkDataCompressor> compressor = NewCompressor(this->CompressorName);
      for (vtkIdType j = begin; j < end && !failed.load(std::memory_order_relaxed); ++j)
      {
        const Job& job = jobs[static_cast<std::size_t>(j)];
        // The block's new pages faulted in by one call first: cheaper than a page fault each
        // (dgmf::FirstTouch).
        dgmf::FirstTouch(job.Target, job.TargetBytes);
        if (!compressor)
        {
          std::memcpy(job.Target, job.Source, job.TargetBytes);
        }
        else if (compressor->Uncompress(job.Source, job.SourceBytes, job.Target, job.TargetBytes) !=
          job.TargetBytes)
        {
          failed = true;
        }
      }
    });
  this->Jobs.clear();
  if (failed)
  {
    throw NotTaken{ "a block that does not decompress to its size" };
  }
}

} // namespace dgmf_cli
