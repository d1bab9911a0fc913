/**
 * @file HugePages.h
 * @brief The advice that large arrays be backed by transparent huge pages: one page fault per
 * 2 MiB of new memory instead of one per 4 KiB, and fewer TLB misses when the array is read out of
 * order. Used by the core, the filter's VTK arrays and the mesh-file readers (a library of its own,
 * DGMFHugePages, so that the readers need not link the core).
 */
#ifndef dgmf_HugePages_h
#define dgmf_HugePages_h

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <type_traits>

namespace dgmf
{

/// Arrays from this size up are advised to be backed by huge pages (AdviseHugePages).
constexpr std::size_t HugePageAdviceBytes = std::size_t(4) << 20;

/**
 * Asks the kernel to back the whole 2 MiB pages inside [begin, begin + bytes) with transparent
 * huge pages (Linux's madvise(MADV_HUGEPAGE)), when `bytes` is at least HugePageAdviceBytes:
 * where the system's policy is "madvise" (Ubuntu's and many distributions' default), new memory
 * is otherwise faulted in 4 KiB pages, and on virtual machines each fault is costly (measured on
 * this project's VM: 1 GiB first touched in 3.0-3.3 s in 4 KiB pages, 0.13-2.3 s advised). Call
 * it on new memory before its first touch. Values are unchanged; a no-op elsewhere, where the
 * policy is "never", when the kernel refuses, and when the environment variable DGMF_HUGE_PAGES
 * is "0" (default: advised). Pages outside the range are never affected.
 */
void AdviseHugePages(void* begin, std::size_t bytes) noexcept;

/// Allocations from this size up are made of whole huge pages (AllocateOnHugePages).
constexpr std::size_t HugePageAllocationBytes = std::size_t(1) << 20;

/**
 * Allocates `bytes` bytes aligned to `alignment` (a power of two), to be freed with std::free;
 * null when they cannot be had. From HugePageAllocationBytes up (and unless DGMF_HUGE_PAGES is
 * "0"), the memory starts on a 2 MiB boundary, is rounded up to whole 2 MiB pages and advised
 * huge pages, so none of it is faulted in 4 KiB pages: a range advised where it lies
 * (AdviseHugePages) still faults the parts of its first and last 2 MiB pages that it covers in
 * 4 KiB pages, 2 MiB on average (512 faults). The cost: at most 2 MiB of memory more than asked
 * for (the rest of the last page, once touched). Smaller allocations, and all outside Linux, are
 * std::malloc's (std::aligned_alloc's beyond its alignment).
 */
void* AllocateOnHugePages(
  std::size_t bytes, std::size_t alignment = alignof(std::max_align_t)) noexcept;

/**
 * Gives `values` (a std::vector of numbers) room for at least `count` elements, its new storage
 * advised huge pages before anything is written into it (std::vector::reserve would copy the
 * elements into the new storage first). Grows geometrically, as std::vector does, so that calls
 * with growing counts cost amortised linear time.
 */
template <typename Vector>
void ReserveOnHugePages(Vector& values, std::size_t count)
{
  static_assert(std::is_trivially_copyable<typename Vector::value_type>::value,
    "for arrays of numbers: the elements are copied into the new storage");
  if (count <= values.capacity())
  {
    return;
  }
  Vector grown;
  grown.reserve(std::max(count, 2 * values.capacity()));
  AdviseHugePages(grown.data(), grown.capacity() * sizeof(typename Vector::value_type));
  grown.insert(grown.end(), values.begin(), values.end());
  values.swap(grown);
}

/// Resizes `values` (a std::vector) to `count` elements, new storage advised huge pages first
/// (ReserveOnHugePages); new elements are value-initialised as by resize().
template <typename Vector>
void ResizeOnHugePages(Vector& values, std::size_t count)
{
  ReserveOnHugePages(values, count);
  values.resize(count);
}

/**
 * Makes `values` (a std::vector of numbers) a copy of [first, last), new storage advised huge
 * pages before the copy writes it (the vector's own assignment would fault it in 4 KiB pages).
 * Storage it already has is reused.
 */
template <typename Vector, typename Iterator>
void AssignOnHugePages(Vector& values, Iterator first, Iterator last)
{
  values.clear();
  ReserveOnHugePages(values, static_cast<std::size_t>(std::distance(first, last)));
  values.assign(first, last);
}

/// Makes `values` (a std::vector of numbers) `count` copies of `value`, new storage advised huge
/// pages before it is written (AssignOnHugePages).
template <typename Vector>
void AssignOnHugePages(Vector& values, std::size_t count, const typename Vector::value_type& value)
{
  values.clear();
  ReserveOnHugePages(values, count);
  values.assign(count, value);
}

} // namespace dgmf

#endif
