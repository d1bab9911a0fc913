#include "DGMFLookAheadCompressor.h"

#include "DGMFCompressorClasses.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

namespace dgmf_cli
{
namespace
{

/// VTK's compressor `Base`, compressing ahead. No vtkTypeMacro: the class name stays Base's,
/// which the writer records in the file for its readers.
template <class Base>
class LookAhead final
  : public Base
  , public LookAheadCompressor
{
public:
  static LookAhead* New()
  {
    auto* compressor = new LookAhead;
    compressor->InitializeObjectBase();
    return compressor;
  }

  void SetLookAhead(int blocks) { this->Blocks = std::max(1, blocks); }

  void RegisterRange(const void* begin, std::size_t bytes) override
  {
    const auto* first = static_cast<const unsigned char*>(begin);
    if (first != nullptr && bytes > 0)
    {
      this->Ranges.push_back({ first, first + bytes });
    }
  }

  void RegisterCompressed(const void* begin, std::size_t bytes, std::size_t blockSize,
    const std::vector<std::pair<const unsigned char*, std::size_t>>& blocks) override
  {
    const auto* first = static_cast<const unsigned char*>(begin);
    if (first != nullptr && bytes > 0 && blockSize > 0 &&
      blocks.size() == (bytes + blockSize - 1) / blockSize)
    {
      this->Compressed.push_back({ { first, first + bytes }, blockSize, blocks });
    }
  }

  void ClearRanges() override
  {
    this->Ranges.clear();
    this->Compressed.clear();
    this->Cache.clear();
  }

  std::size_t GetBlocksHandedAsRead() const override { return this->HandedAsRead; }

  std::size_t GetCacheHits() const override { return this->Hits; }
  std::size_t GetCacheMisses() const override { return this->Misses; }

protected:
  LookAhead() = default;
  ~LookAhead() override = default;

  size_t CompressBuffer(
    unsigned char const* data, size_t size, unsigned char* compressed, size_t space) override
  {
    // Addresses compared as integers (pointers into different arrays do not compare in C++).
    const auto at = reinterpret_cast<std::uintptr_t>(data);
    for (const CompressedRange& range : this->Compressed)
    {
      const auto begin = reinterpret_cast<std::uintptr_t>(range.Values.Begin);
      const auto end = reinterpret_cast<std::uintptr_t>(range.Values.End);
      if (at < begin || at >= end || (at - begin) % range.BlockSize != 0)
      {
        continue;
      }
      const std::size_t k = (at - begin) / range.BlockSize;
      const std::size_t expected = std::min<std::size_t>(range.BlockSize, end - at);
      const auto& block = range.Blocks[k];
      if (size == expected && block.second <= space)
      {
        std::copy(block.first, block.first + block.second, compressed);
        ++this->HandedAsRead;
        return block.second;
      }
    }
    const auto cached = this->Cache.find(data);
    if (cached != this->Cache.end() && cached->second.Size == size &&
      cached->second.Bytes.size() <= space)
    {
      const std::vector<unsigned char>& bytes = cached->second.Bytes;
      std::copy(bytes.begin(), bytes.end(), compressed);
      const size_t length = bytes.size();
      this->Cache.erase(cached);
      ++this->Hits;
      return length;
    }
    ++this->Misses;
    this->Cache.clear(); // VTK has moved on: what is left ahead will not be asked for
    for (const Range& range : this->Ranges)
    {
      if (size > 0 && at >= reinterpret_cast<std::uintptr_t>(range.Begin) &&
        at + size <= reinterpret_cast<std::uintptr_t>(range.End))
      {
        return this->CompressAhead(range, data, size, compressed, space);
      }
    }
    return this->Base::CompressBuffer(data, size, compressed, space);
  }

private:
  struct Range
  {
    const unsigned char* Begin;
    const unsigned char* End;
  };
  /// Values already compressed, in blocks of BlockSize bytes (RegisterCompressed).
  struct CompressedRange
  {
    Range Values;
    std::size_t BlockSize;
    std::vector<std::pair<const unsigned char*, std::size_t>> Blocks;
  };
  struct Block
  {
    std::size_t Size = 0; ///< uncompressed size
    std::vector<unsigned char> Bytes;
    bool Ready = false; ///< compressed (a failure is left to the caller's thread, as VTK would)
  };

  /// Compresses the block at `data` and up to Blocks - 1 blocks after it in `range`, in parallel;
  /// returns the first as CompressBuffer does and keeps the others.
  size_t CompressAhead(const Range& range, unsigned char const* data, size_t size,
    unsigned char* compressed, size_t space)
  {
    const std::size_t left = static_cast<std::size_t>(range.End - data);
    const std::size_t count =
      std::min<std::size_t>(static_cast<std::size_t>(this->Blocks), (left + size - 1) / size);
    std::vector<Block> blocks(count);
    vtkSMPTools::For(0, static_cast<vtkIdType>(count), 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          Block& block = blocks[static_cast<std::size_t>(k)];
          const unsigned char* start = data + static_cast<std::size_t>(k) * size;
          block.Size = std::min<std::size_t>(size, static_cast<std::size_t>(range.End - start));
          try
          {
            block.Bytes.resize(this->GetMaximumCompressionSpace(block.Size));
            const size_t length =
              this->Base::CompressBuffer(start, block.Size, block.Bytes.data(), block.Bytes.size());
            block.Bytes.resize(length);
            block.Ready = length > 0;
          }
          catch (...)
          {
            block.Ready = false; // compressed again on the caller's thread when asked for
          }
        }
      });
    for (std::size_t k = 1; k < count; ++k)
    {
      if (blocks[k].Ready)
      {
        this->Cache[data + k * size] = std::move(blocks[k]);
      }
    }
    if (!blocks[0].Ready || blocks[0].Bytes.size() > space)
    {
      return this->Base::CompressBuffer(data, size, compressed, space);
    }
    std::copy(blocks[0].Bytes.begin(), blocks[0].Bytes.end(), compressed);
    return blocks[0].Bytes.size();
  }

  int Blocks = 1;
  std::vector<Range> Ranges;
  std::vector<CompressedRange> Compressed;
  std::map<const unsigned char*, Block> Cache;
  std::size_t HandedAsRead = 0;
  std::size_t Hits = 0;
  std::size_t Misses = 0;
};

template <class Base>
vtkSmartPointer<vtkDataCompressor> Make(int lookAhead)
{
  vtkSmartPointer<LookAhead<Base>> compressor =
    vtkSmartPointer<LookAhead<Base>>::Take(LookAhead<Base>::New());
  compressor->SetLookAhead(lookAhead);
  return compressor;
}

} // namespace

vtkSmartPointer<vtkDataCompressor> NewLookAheadCompressor(
  const std::string& className, int lookAhead)
{
  return WithCompressorClass(className,
    [lookAhead](auto* vtkClass)
    { return Make<std::remove_pointer_t<decltype(vtkClass)>>(lookAhead); });
}

} // namespace dgmf_cli
