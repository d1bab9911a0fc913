#include "dgmf/HugePageArena.h"

#include "dgmf/HugePages.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <mutex>

namespace dgmf
{
namespace
{
constexpr std::size_t Alignment = alignof(std::max_align_t);
// From the first chunk on whole huge pages: the first mebibyte of a large triangulation's storage
// would otherwise be faulted in 4 KiB pages (256 faults); a small one shares the 2 MiB chunk.
constexpr std::size_t MinimumChunkBytes = std::size_t(2) << 20;
constexpr std::size_t MaximumChunkBytes = std::size_t(8) << 20;
/// Chunks are rounded to whole huge pages (AllocateOnHugePages makes them that large anyway).
constexpr std::size_t HugePage = std::size_t(2) << 20;

/// The head of a chunk: its size, the bytes handed out from its start, its blocks in use.
struct alignas(std::max_align_t) Chunk
{
  std::size_t Bytes;
  std::size_t Used;
  std::size_t Blocks;
};

/// The head of a block: its chunk and its size (head included).
struct alignas(std::max_align_t) BlockHead
{
  Chunk* Owner;
  std::size_t Bytes;
};

struct Arena
{
  std::mutex Lock;
  Chunk* Current = nullptr;
  std::size_t ChunkBytes = 0;
  std::size_t BlockBytes = 0;
};

/// The process's arena, never destroyed (blocks may be returned by static destructors).
Arena& TheArena()
{
  static Arena* arena = new Arena;
  return *arena;
}

void FreeChunk(Arena& arena, Chunk* chunk)
{
  arena.ChunkBytes -= chunk->Bytes;
  if (arena.Current == chunk)
  {
    arena.Current = nullptr;
  }
  std::free(chunk);
}
} // namespace

void* AllocateFromHugePageArena(std::size_t bytes)
{
  if (bytes > SIZE_MAX - sizeof(Chunk) - sizeof(BlockHead) - Alignment - HugePage)
  {
    throw std::bad_alloc();
  }
  const std::size_t need =
    sizeof(BlockHead) + (std::max<std::size_t>(bytes, 1) + Alignment - 1) / Alignment * Alignment;
  Arena& arena = TheArena();
  std::lock_guard<std::mutex> guard(arena.Lock);
  Chunk* chunk = arena.Current;
  if (!chunk || chunk->Bytes - chunk->Used < need)
  {
    std::size_t size = std::max(sizeof(Chunk) + need,
      std::min(MaximumChunkBytes, std::max(MinimumChunkBytes, arena.BlockBytes)));
    size = (size + HugePage - 1) / HugePage * HugePage;
    void* memory = AllocateOnHugePages(size);
    if (!memory)
    {
      throw std::bad_alloc();
    }
    Chunk* fresh = new (memory) Chunk{ size, sizeof(Chunk), 0 };
    arena.ChunkBytes += size;
    // The chunk that was current keeps its blocks (an empty chunk is freed at once), its rest
    // unused until they are all returned.
    arena.Current = chunk = fresh;
  }
  char* at = reinterpret_cast<char*>(chunk) + chunk->Used;
  chunk->Used += need;
  ++chunk->Blocks;
  arena.BlockBytes += need;
  return new (at) BlockHead{ chunk, need } + 1;
}

void DeallocateToHugePageArena(void* block) noexcept
{
  if (!block)
  {
    return;
  }
  const BlockHead* head = static_cast<const BlockHead*>(block) - 1;
  Arena& arena = TheArena();
  std::lock_guard<std::mutex> guard(arena.Lock);
  Chunk* chunk = head->Owner;
  arena.BlockBytes -= head->Bytes;
  if (--chunk->Blocks == 0)
  {
    FreeChunk(arena, chunk);
  }
}

std::size_t HugePageArenaBytes() noexcept
{
  Arena& arena = TheArena();
  std::lock_guard<std::mutex> guard(arena.Lock);
  return arena.ChunkBytes;
}

} // namespace dgmf
