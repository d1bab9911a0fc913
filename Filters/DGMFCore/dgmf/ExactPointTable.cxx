#include "dgmf/ExactPointTable.h"

#include "dgmf/Simd.h"

#include <cstring>
#include <stdexcept>

namespace dgmf
{
namespace
{
std::uint64_t Bits(double value)
{
  value = value == 0.0 ? 0.0 : value; // -0 and +0 are the same point
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

std::uint64_t Hash(const double p[3])
{
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (int c = 0; c < 3; ++c)
  {
    h = (h ^ Bits(p[c])) * 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return h;
}

bool Same(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

constexpr std::int64_t kIdMask = (std::int64_t(1) << 40) - 1;

std::size_t CapacityFor(std::size_t expected)
{
  std::size_t capacity = 16;
  while (capacity < 2 * expected)
  {
    capacity *= 2;
  }
  return capacity;
}
} // namespace

ExactPointTable::ExactPointTable(std::size_t expected)
  : Slots(CapacityFor(expected), -1)
  , Mask(Slots.size() - 1)
{
}

std::int64_t ExactPointTable::FindOrInsert(const double* points, const double p[3], std::int64_t id)
{
  if (id < 0 || id > kIdMask)
  {
    throw std::length_error("ExactPointTable: point ids must be below 2^40");
  }
  if (2 * (this->Count + 1) > this->Slots.size())
  {
    this->Grow(points);
  }
  // A slot holds the point's id and 23 bits of its hash (the tag): most occupied slots are told
  // apart from the tag alone, without reading the kept point's coordinates (a cache miss).
  const std::uint64_t h = Hash(p);
  const std::int64_t tag = static_cast<std::int64_t>(h >> 41);
  for (std::size_t slot = h & this->Mask;; slot = (slot + 1) & this->Mask)
  {
    const std::int64_t value = this->Slots[slot];
    if (value < 0)
    {
      this->Slots[slot] = (tag << 40) | id;
      ++this->Count;
      return id;
    }
    const std::int64_t kept = value & kIdMask;
    if ((value >> 40) == tag && Same(points + 3 * kept, p))
    {
      return kept;
    }
  }
}

void ExactPointTable::Prefetch(const double p[3]) const
{
  simd::Prefetch(&this->Slots[Hash(p) & this->Mask]);
}

void ExactPointTable::Grow(const double* points)
{
  std::vector<std::int64_t> old(2 * this->Slots.size(), -1);
  old.swap(this->Slots);
  this->Mask = this->Slots.size() - 1;
  for (std::int64_t value : old)
  {
    if (value >= 0)
    {
      std::size_t slot = Hash(points + 3 * (value & kIdMask)) & this->Mask;
      while (this->Slots[slot] >= 0)
      {
        slot = (slot + 1) & this->Mask;
      }
      this->Slots[slot] = value;
    }
  }
}

} // namespace dgmf
