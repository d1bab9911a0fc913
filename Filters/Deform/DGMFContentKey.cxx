#include "DGMFContentKey.h"

#include "DGMFSMPTools.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <vector>

namespace dgmf_vtk
{

namespace
{
/// Bytes per block of HashBytes: blocks are hashed on the threads, then combined in order.
constexpr std::size_t HashBlock = std::size_t(1) << 22;

/// The lanes' hash of one block.
std::uint64_t HashBlockBytes(const unsigned char* p, std::size_t bytes, std::uint64_t seed)
{
  std::uint64_t lane[4] = { seed ^ (bytes * 0xff51afd7ed558ccdull), seed + 1, seed + 2, seed + 3 };
  std::size_t k = 0;
  for (; k + 32 <= bytes; k += 32)
  {
    for (int l = 0; l < 4; ++l)
    {
      std::uint64_t word;
      std::memcpy(&word, p + k + 8 * l, 8);
      lane[l] = (lane[l] ^ word) * 0x100000001b3ull;
      lane[l] ^= lane[l] >> 32;
    }
  }
  std::uint64_t h = lane[0];
  for (int l = 1; l < 4; ++l)
  {
    h = (h ^ lane[l]) * 0xff51afd7ed558ccdull;
    h ^= h >> 33;
  }
  for (; k < bytes; ++k)
  {
    h = (h ^ p[k]) * 0x100000001b3ull;
  }
  return h;
}
} // namespace

std::uint64_t HashBytes(const void* data, std::size_t bytes, std::uint64_t seed, bool onThreads)
{
  const auto* p = static_cast<const unsigned char*>(data);
  if (bytes <= HashBlock)
  {
    return HashBlockBytes(p, bytes, seed);
  }
  // Fixed blocks, so the hash does not depend on the threads.
  const std::size_t blocks = (bytes + HashBlock - 1) / HashBlock;
  std::vector<std::uint64_t> hashes(blocks);
  dgmf::ForEachBlock(onThreads ? MakeSMPParallelFor() : dgmf::ParallelFor(dgmf::SerialFor), blocks,
    [&](std::size_t block)
    {
      const std::size_t begin = block * HashBlock;
      hashes[block] = HashBlockBytes(p + begin, std::min(HashBlock, bytes - begin), seed + block);
    });
  std::uint64_t h = seed ^ (bytes * 0xc4ceb9fe1a85ec53ull);
  for (const std::uint64_t blockHash : hashes)
  {
    h = (h ^ blockHash) * 0xff51afd7ed558ccdull;
    h ^= h >> 33;
  }
  return h;
}

std::uint64_t HashArray(vtkDataArray* array, std::uint64_t seed, bool onThreads)
{
  return HashBytes(array->GetVoidPointer(0),
    static_cast<std::size_t>(array->GetNumberOfValues()) *
      static_cast<std::size_t>(array->GetDataTypeSize()),
    seed + static_cast<std::uint64_t>(array->GetDataType()), onThreads);
}

std::uint64_t HashCells(vtkUnstructuredGrid* mesh, bool onThreads)
{
  vtkCellArray* cells = mesh->GetCells();
  std::uint64_t h = HashArray(cells->GetConnectivityArray(), 0, onThreads);
  h = HashArray(cells->GetOffsetsArray(), h, onThreads);
  h = HashArray(mesh->GetCellTypesArray(), h, onThreads);
  return mesh->GetFaces() ? HashArray(mesh->GetFaces(), h, onThreads) : h;
}

bool ContentKey::Matches(vtkObject* object, const std::function<std::uint64_t()>& hash)
{
  if (!this->Valid)
  {
    return false;
  }
  if (this->MatchesObject(object))
  {
    return true;
  }
  if (this->ObjectOnly || hash() != this->Hash)
  {
    return false;
  }
  this->Object = object;
  this->MTime = object->GetMTime();
  this->VerifiedEpoch = DistrustedObjects::Epoch();
  return true;
}

void ContentKey::Set(vtkObject* object, const std::function<std::uint64_t()>& hash)
{
  this->Object = object;
  this->MTime = object->GetMTime();
  this->Hash = hash();
  this->Valid = true;
  this->ObjectOnly = false;
  this->VerifiedEpoch = DistrustedObjects::Epoch();
}

bool ContentKey::MatchesObject(vtkObject* object) const
{
  return this->Valid && this->Object == object && this->MTime == object->GetMTime() &&
    (!DistrustedObjects::Active() || this->VerifiedEpoch == DistrustedObjects::Epoch());
}

namespace
{
std::atomic<int>& DistrustCount()
{
  static std::atomic<int> count{ 0 };
  return count;
}

std::atomic<std::uint64_t>& DistrustEpoch()
{
  static std::atomic<std::uint64_t> epoch{ 0 };
  return epoch;
}
} // namespace

DistrustedObjects::DistrustedObjects(bool active)
  : Counted(active)
{
  if (this->Counted)
  {
    ++DistrustEpoch();
    ++DistrustCount();
  }
}

DistrustedObjects::~DistrustedObjects()
{
  if (this->Counted)
  {
    --DistrustCount();
  }
}

bool DistrustedObjects::Active()
{
  return DistrustCount().load() > 0;
}

std::uint64_t DistrustedObjects::Epoch()
{
  return DistrustEpoch().load();
}

void ContentKey::SetHash(std::uint64_t hash)
{
  this->Hash = hash;
  this->ObjectOnly = false;
}

void ContentKey::SetObjectOnly(vtkObject* object)
{
  this->Object = object;
  this->MTime = object->GetMTime();
  this->Hash = 0;
  this->Valid = true;
  this->ObjectOnly = true;
  this->VerifiedEpoch = DistrustedObjects::Epoch();
}

} // namespace dgmf_vtk
