/**
 * @file TwoThreadFor.h
 * @brief A ParallelFor for the core tests that really runs two threads.
 */
#ifndef dgmf_test_TwoThreadFor_h
#define dgmf_test_TwoThreadFor_h

#include "dgmf/ParallelFor.h"

#include <thread>

namespace dgmf_test
{

/// A ParallelFor that really uses two std::threads, splitting the range in two.
inline void TwoThreadFor(
  std::size_t begin, std::size_t end, std::size_t, const dgmf::RangeFunction& body)
{
  const std::size_t middle = begin + (end - begin) / 2;
  std::thread other(
    [&]()
    {
      if (begin < middle)
      {
        body(begin, middle);
      }
    });
  if (middle < end)
  {
    body(middle, end);
  }
  other.join();
}

} // namespace dgmf_test

#endif
