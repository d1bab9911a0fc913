/**
 * @file HugePageArena.h
 * @brief Small blocks carved out of large chunks made of whole huge pages, for containers that
 * allocate many blocks of growing sizes. CGAL's `Compact_container` (the cells and vertices of a
 * Delaunay triangulation) allocates blocks of 14, 30, 46, ... elements: at 260,000 cells, about
 * 180 blocks of up to 230 KB, each below the size that AllocateOnHugePages backs with huge pages,
 * so each was faulted in 4 KiB pages (about 4,700 faults before the insertion could start).
 */
#ifndef dgmf_HugePageArena_h
#define dgmf_HugePageArena_h

#include <cstddef>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>

namespace dgmf
{

/**
 * Allocates `bytes` bytes aligned to alignof(std::max_align_t) from the process's arena, to be
 * returned with DeallocateToHugePageArena. The arena hands out blocks one after the other from
 * its current chunk. A new chunk, when a block does not fit, comes from AllocateOnHugePages (whole
 * huge pages from 1 MiB up) and is as large as the blocks in use (at least 2 MiB, at most 8 MiB,
 * or the block's size when larger), so the chunks grow with the demand. Thread-safe (one
 * mutex). Throws std::bad_alloc when the memory cannot be had.
 */
void* AllocateFromHugePageArena(std::size_t bytes);

/**
 * Returns a block of AllocateFromHugePageArena (null: nothing). A chunk goes back to the system
 * when its last block is returned: the arena keeps no memory that no block uses. Thread-safe.
 */
void DeallocateToHugePageArena(void* block) noexcept;

/// The bytes of the chunks the arena holds now (for tests and memory reports).
std::size_t HugePageArenaBytes() noexcept;

/**
 * A stateless allocator over the arena (all instances are equal). CGAL's containers take their
 * allocator from `std::allocator` of the element type, so the graph's cell and vertex types
 * (DelaunayGraphCgal.h) specialise `std::allocator` with this allocator's functions.
 */
template <typename T>
class HugePageArenaAllocator
{
public:
  using value_type = T;
  using size_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using propagate_on_container_move_assignment = std::true_type;
  using is_always_equal = std::true_type;

  HugePageArenaAllocator() noexcept = default;
  template <typename U>
  HugePageArenaAllocator(const HugePageArenaAllocator<U>&) noexcept
  {
  }

  T* allocate(std::size_t count)
  {
    static_assert(alignof(T) <= alignof(std::max_align_t), "the arena's alignment");
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(T))
    {
      throw std::bad_array_new_length();
    }
    return static_cast<T*>(AllocateFromHugePageArena(count * sizeof(T)));
  }

  void deallocate(T* block, std::size_t) noexcept { DeallocateToHugePageArena(block); }

  // What std::allocator has besides, which libstdc++'s allocator_traits of a std::allocator
  // specialisation calls directly.
  std::size_t max_size() const noexcept
  {
    return std::numeric_limits<std::size_t>::max() / 2 / sizeof(T);
  }
  template <typename U, typename... Arguments>
  void construct(U* at, Arguments&&... arguments)
  {
    ::new (static_cast<void*>(at)) U(std::forward<Arguments>(arguments)...);
  }
  template <typename U>
  void destroy(U* at) noexcept
  {
    at->~U();
  }

  template <typename U>
  bool operator==(const HugePageArenaAllocator<U>&) const noexcept
  {
    return true;
  }
  template <typename U>
  bool operator!=(const HugePageArenaAllocator<U>&) const noexcept
  {
    return false;
  }
};

} // namespace dgmf

#endif
