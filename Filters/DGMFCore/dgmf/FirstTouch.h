/**
 * @file FirstTouch.h
 * @brief New memory made resident ahead of its use: the first touch of a large array costs page
 * faults (the kernel zeroing each page), which can run on another thread while the graph is
 * built, huge pages advised first (HugePages.h); and a vector that does not zero what it
 * allocates.
 */
#ifndef dgmf_FirstTouch_h
#define dgmf_FirstTouch_h

#include "dgmf/HugePages.h"
#include "dgmf/ParallelFor.h"

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace dgmf
{

/**
 * Faults in the pages of [begin, begin + bytes) for writing (huge pages are advised by the
 * allocation or by AppendFirstTouchParts, not here): with Linux's madvise(MADV_POPULATE_WRITE)
 * (5.14 and later), one call for the range, else one store per page. The range's values are
 * unspecified afterwards (zero on fresh memory): for arrays whose every value is written later.
 * Much cheaper than zeroing the array after the kernel did (std::vector's value-initialisation,
 * memset). While the call runs it holds the address space's lock for reading: another thread that
 * grows its heap meanwhile waits (measured: CGAL's insertion in a new process, 0.15 s at 8.26M
 * nodes, whatever the size of the calls; DelaunayGraph reserves CGAL's storage first for that
 * reason).
 */
void FirstTouch(void* begin, std::size_t bytes);

/// The size of the parts in which large arrays are first touched by several threads: small
/// enough for two threads to share the end of the work evenly, large enough to cost one call each.
constexpr std::size_t FirstTouchPartBytes = std::size_t(8) << 20;

/// A part of a range of memory to first touch.
struct FirstTouchPart
{
  void* Begin;
  std::size_t Bytes;
};

/// Appends [begin, begin + bytes) to `parts`, cut into parts of at most FirstTouchPartBytes, and
/// advises the whole range huge pages (AdviseHugePages).
void AppendFirstTouchParts(void* begin, std::size_t bytes, std::vector<FirstTouchPart>& parts);

/// First touches every part of `parts` (FirstTouch), the parts shared by the threads of
/// `parallelFor`.
void FirstTouchParts(const std::vector<FirstTouchPart>& parts, const ParallelFor& parallelFor);

/**
 * An allocator whose default construction leaves trivial values uninitialised: a
 * std::vector<T, DefaultInitAllocator<T>> resized to n elements neither writes nor touches them
 * (FirstTouch can then fault the pages in parts, on the threads). Values given explicitly are
 * constructed as usual. Large allocations are made of whole huge pages (AllocateOnHugePages).
 */
template <typename T>
struct DefaultInitAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept
  {
  }
  T* allocate(std::size_t n)
  {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T))
    {
      throw std::bad_array_new_length();
    }
    void* memory = AllocateOnHugePages(n * sizeof(T), alignof(T));
    if (!memory)
    {
      throw std::bad_alloc();
    }
    return static_cast<T*>(memory);
  }
  void deallocate(T* memory, std::size_t) noexcept { std::free(memory); }
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A vector whose resize() does not write its new trivial elements.
template <typename T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace dgmf

#endif
