#include "DGMFLookAheadCompressor.h"

#include "DGMFCompressorClasses.h"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace dgmf_cli
{
namespace
{

/**
 * VTK's compressor `Base`, compressing ahead on worker threads while VTK's writer writes. No
 * vtkTypeMacro: the class name stays Base's, which the writer records in the file for its readers.
 *
 * The blocks of the array VTK is writing are queued in order, a window of them ahead of the block
 * VTK asks for; the workers take them from the queue and compress them while the caller's thread
 * writes the blocks before. Only the caller's thread changes the queue's ends; every block is
 * compressed by Base itself, so the bytes are Base's.
 */
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

  void SetWorkers(int threads, std::size_t windowBytes)
  {
    this->Workers = std::max(1, threads);
    this->WindowBytes = windowBytes;
  }

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
    this->StopWorkers(); // no worker reads the ranges' memory after this
    this->Ranges.clear();
    this->Compressed.clear();
    this->Spare.clear(); // the buffers' memory back after each write
  }

  std::size_t GetBlocksHandedAsRead() const override { return this->HandedAsRead; }

  std::size_t GetCacheHits() const override { return this->Hits; }
  std::size_t GetCacheMisses() const override { return this->Misses; }

protected:
  LookAhead() = default;
  ~LookAhead() override { this->StopWorkers(); }

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
    std::shared_ptr<Block> block = this->Take(data, size);
    if (!block)
    {
      return this->Base::CompressBuffer(data, size, compressed, space);
    }
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->BlockDone.wait(lock, [&block]() { return block->Done; });
    }
    if (!block->Ready || block->Bytes.size() > space)
    {
      return this->Base::CompressBuffer(data, size, compressed, space); // as VTK would
    }
    std::copy(block->Bytes.begin(), block->Bytes.end(), compressed);
    const std::size_t length = block->Bytes.size();
    this->Recycle(std::move(block->Bytes));
    return length;
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
  /// A block queued ahead: its values, and once Done its compressed bytes.
  struct Block
  {
    const unsigned char* Data = nullptr;
    std::size_t Size = 0; ///< uncompressed size
    std::vector<unsigned char> Bytes;
    bool Done = false;  ///< a worker has finished it (under Mutex)
    bool Ready = false; ///< compressed (a failure is left to the caller's thread, as VTK would)
  };

  /**
   * The queued block for the `size` bytes at `data`, null when they lie in no registered range.
   * A block that is not the next one queued (VTK has moved to another array) drops the queue and
   * starts a new one there. Keeps a window of blocks queued after it.
   */
  std::shared_ptr<Block> Take(const unsigned char* data, std::size_t size)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    if (this->Ahead.empty() || this->Ahead.front()->Data != data ||
      this->Ahead.front()->Size != size)
    {
      ++this->Misses;
      this->Ahead.clear();
      this->Queue.clear(); // blocks a worker holds are finished and dropped
      const auto at = reinterpret_cast<std::uintptr_t>(data);
      const Range* inside = nullptr;
      for (const Range& range : this->Ranges)
      {
        if (size > 0 && at >= reinterpret_cast<std::uintptr_t>(range.Begin) &&
          at + size <= reinterpret_cast<std::uintptr_t>(range.End))
        {
          inside = &range;
        }
      }
      if (!inside)
      {
        return nullptr;
      }
      this->Next = data;
      this->End = inside->End;
      this->Size = size;
      this->StartWorkers();
      if (this->Threads.empty())
      {
        return nullptr;
      }
      this->Refill(true);
    }
    else
    {
      ++this->Hits;
    }
    std::shared_ptr<Block> block = std::move(this->Ahead.front());
    this->Ahead.pop_front();
    this->Refill(false);
    return block;
  }

  /// The blocks queued ahead at most: the window's bytes in blocks of the current size.
  std::size_t WindowBlocks() const
  {
    return std::max<std::size_t>(1, this->WindowBytes / this->Size);
  }

  /// Queues blocks up to the window (when half of it is left, or `now`), and wakes the workers.
  void Refill(bool now)
  {
    const std::size_t window = this->WindowBlocks();
    if (this->Next == this->End || (!now && 2 * this->Ahead.size() > window))
    {
      return;
    }
    while (this->Ahead.size() < window && this->Next != this->End)
    {
      auto block = std::make_shared<Block>();
      block->Data = this->Next;
      block->Size =
        std::min<std::size_t>(this->Size, static_cast<std::size_t>(this->End - this->Next));
      this->Next += block->Size;
      this->Ahead.push_back(block);
      this->Queue.push_back(std::move(block));
    }
    this->WorkQueued.notify_all();
  }

  /// Starts the workers if they are not running (under Mutex).
  void StartWorkers()
  {
    if (!this->Threads.empty())
    {
      return;
    }
    this->Stopping = false;
    try
    {
      for (int k = 0; k < this->Workers; ++k)
      {
        this->Threads.emplace_back([this]() { this->Work(); });
      }
    }
    catch (...) // no thread to be had: the blocks the others cannot take are compressed on the spot
    {
    }
  }

  /// Drops the queue, lets the workers finish the blocks they hold, and joins them.
  void StopWorkers()
  {
    {
      const std::lock_guard<std::mutex> lock(this->Mutex);
      this->Stopping = true;
      this->Queue.clear();
      this->Ahead.clear();
      this->WorkQueued.notify_all();
    }
    for (std::thread& thread : this->Threads)
    {
      thread.join();
    }
    this->Threads.clear();
  }

  /// Keeps a block's buffer for the next block a worker compresses (under Mutex): a new buffer
  /// of a block's size is new memory, faulted in page by page. At most one per block in flight.
  void Recycle(std::vector<unsigned char>&& bytes)
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    if (this->Spare.size() < this->WindowBlocks() + static_cast<std::size_t>(this->Workers))
    {
      this->Spare.push_back(std::move(bytes));
    }
  }

  /// A worker: compresses the queued blocks in order until stopped.
  void Work()
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    for (;;)
    {
      this->WorkQueued.wait(lock, [this]() { return this->Stopping || !this->Queue.empty(); });
      if (this->Stopping)
      {
        return;
      }
      std::shared_ptr<Block> block = std::move(this->Queue.front());
      this->Queue.pop_front();
      if (!this->Spare.empty())
      {
        block->Bytes = std::move(this->Spare.back());
        this->Spare.pop_back();
      }
      lock.unlock();
      try
      {
        block->Bytes.resize(this->GetMaximumCompressionSpace(block->Size));
        const size_t length = this->Base::CompressBuffer(
          block->Data, block->Size, block->Bytes.data(), block->Bytes.size());
        block->Bytes.resize(length);
        block->Ready = length > 0;
      }
      catch (...)
      {
        block->Ready = false; // compressed again on the caller's thread
      }
      lock.lock();
      block->Done = true;
      this->BlockDone.notify_all();
    }
  }

  int Workers = 1;
  std::size_t WindowBytes = std::size_t(8) << 20;
  std::vector<Range> Ranges;
  std::vector<CompressedRange> Compressed;
  std::size_t HandedAsRead = 0;
  std::size_t Hits = 0;
  std::size_t Misses = 0;

  // The queue, under Mutex: the blocks ahead in order (Ahead), those no worker has taken
  // (Queue), where the next block starts, the range's end and the block size.
  std::mutex Mutex;
  std::condition_variable WorkQueued, BlockDone;
  std::deque<std::shared_ptr<Block>> Ahead, Queue;
  std::vector<std::vector<unsigned char>> Spare; ///< buffers of blocks handed out (Recycle)
  const unsigned char* Next = nullptr;
  const unsigned char* End = nullptr;
  std::size_t Size = 1;
  bool Stopping = false;
  std::vector<std::thread> Threads;
};

template <class Base>
vtkSmartPointer<vtkDataCompressor> Make(int threads, std::size_t windowBytes)
{
  vtkSmartPointer<LookAhead<Base>> compressor =
    vtkSmartPointer<LookAhead<Base>>::Take(LookAhead<Base>::New());
  compressor->SetWorkers(threads, windowBytes);
  return compressor;
}

} // namespace

vtkSmartPointer<vtkDataCompressor> NewLookAheadCompressor(
  const std::string& className, int threads, std::size_t windowBytes)
{
  return WithCompressorClass(className,
    [threads, windowBytes](auto* vtkClass)
    { return Make<std::remove_pointer_t<decltype(vtkClass)>>(threads, windowBytes); });
}

} // namespace dgmf_cli
