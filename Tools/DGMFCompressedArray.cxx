#include "DGMFCompressedArray.h"

#include "vtkAbstractArray.h"
#include "vtkWeakPointer.h"

#include <map>
#include <mutex>

namespace dgmf_cli
{
namespace
{
/// An array's blocks, with the array (alive or not) and its modification time when remembered.
struct Entry
{
  vtkWeakPointer<vtkAbstractArray> Array;
  vtkMTimeType Time = 0;
  CompressedArray Blocks;
};

std::mutex EntriesMutex;
std::map<const vtkAbstractArray*, Entry>& Entries()
{
  static std::map<const vtkAbstractArray*, Entry> entries;
  return entries;
}
} // namespace

void CompressedArray::Remember(vtkAbstractArray* array, CompressedArray blocks)
{
  const std::lock_guard<std::mutex> lock(EntriesMutex);
  auto& entries = Entries();
  for (auto at = entries.begin(); at != entries.end();)
  {
    at = at->second.Array ? std::next(at) : entries.erase(at);
  }
  Entry& entry = entries[array];
  entry.Array = array;
  entry.Time = array->GetMTime();
  entry.Blocks = std::move(blocks);
}

const CompressedArray* CompressedArray::Of(vtkAbstractArray* array)
{
  const std::lock_guard<std::mutex> lock(EntriesMutex);
  const auto at = Entries().find(array);
  // The same address may be a new array after the remembered one died: the weak pointer tells.
  return at != Entries().end() && at->second.Array == array && at->second.Time == array->GetMTime()
    ? &at->second.Blocks
    : nullptr;
}

} // namespace dgmf_cli
