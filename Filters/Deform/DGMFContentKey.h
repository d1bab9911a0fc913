/**
 * @file DGMFContentKey.h
 * @brief Tells whether an input's content changed between executions: the object and its MTime,
 * and a fast hash of the content when either changed (private to the DGMF::Filters module).
 */
#ifndef DGMFContentKey_h
#define DGMFContentKey_h

#include "vtkObject.h"
#include "vtkType.h"

#include <cstddef>
#include <cstdint>
#include <functional>

class vtkDataArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// HashBytes' seed when none is given.
constexpr std::uint64_t DefaultHashSeed = 0x9e3779b97f4a7c15ull;

/// A fast 64-bit hash of raw memory (not cryptographic: it tells equal content from changed).
/// Four independent lanes of 8-byte words, so the multiplications overlap (200 MB in ~20 ms on
/// one thread), in blocks of 4 MB hashed on the vtkSMPTools threads and combined in order (the
/// same value for any number of threads).
/// `onThreads` false: on the calling thread only (for a caller that is itself one of the
/// threads' tasks: VTK 9.2 runs nested loops on new threads, beside the other tasks). The same
/// value either way.
std::uint64_t HashBytes(
  const void* data, std::size_t bytes, std::uint64_t seed = DefaultHashSeed, bool onThreads = true);

/// HashBytes of an array's values, seeded with its value type.
std::uint64_t HashArray(vtkDataArray* array, std::uint64_t seed = 0, bool onThreads = true);

/// HashArray of a grid's cells: connectivity, offsets, types and polyhedron faces.
std::uint64_t HashCells(vtkUnstructuredGrid* mesh, bool onThreads = true);

/**
 * While one with `active` true lives (on any thread of the process), no ContentKey trusts an
 * object's identity and MTime alone (MatchesObject is false, Matches compares the content's hash)
 * and no composite merge is reused. The filter opens one for an execution whose input was marked
 * Modified() since its last execution: grid->Modified() after the grid's points or cells were
 * changed in place leaves their arrays' own MTimes as they were (the graph built for the old
 * points was reused until 2026-11-30). Costs hashing or work done again, never a wrong match;
 * each activation starts an epoch, and a key verified by its hash (or set) in the current epoch
 * is trusted again for the rest of it, so one execution hashes each array once.
 */
class DistrustedObjects
{
public:
  explicit DistrustedObjects(bool active);
  ~DistrustedObjects();
  DistrustedObjects(const DistrustedObjects&) = delete;
  DistrustedObjects& operator=(const DistrustedObjects&) = delete;
  /// True while any active instance lives.
  static bool Active();
  /// The number of activations so far (the current epoch).
  static std::uint64_t Epoch();

private:
  bool Counted;
};

/**
 * The content of an input object between executions: the object and its MTime, and, when either
 * changed (a reader that reads the same mesh again at each time step, a composite input merged
 * anew), a hash of the content. A reader's new object with the same content then matches.
 */
class ContentKey
{
public:
  /// True when `object` has the content the key was set for; refreshes the object and MTime.
  bool Matches(vtkObject* object, const std::function<std::uint64_t()>& hash);
  /// Remembers `object`'s content (its hash from `hash`).
  void Set(vtkObject* object, const std::function<std::uint64_t()>& hash);
  /// Remembers `object` and its MTime only, for a result cheaper to compute again than to hash:
  /// another object (or this one modified) then never matches.
  void SetObjectOnly(vtkObject* object);
  /// Remembers `object` and its MTime now and its content's hash later (SetHash), for a hash
  /// computed off the critical path: until then the key is a SetObjectOnly key.
  void SetHashLater(vtkObject* object) { this->SetObjectOnly(object); }
  /// The hash of the content of the object given to SetHashLater (computed from that object,
  /// unmodified since).
  void SetHash(std::uint64_t hash);
  /// True when `object` is the object the key was set for, unmodified (what a SetObjectOnly key
  /// can tell; no hash).
  bool MatchesObject(vtkObject* object) const;
  /// Forgets the content: the next Matches is false.
  void Reset() { this->Valid = false; }

private:
  const void* Object = nullptr;
  vtkMTimeType MTime = 0;
  std::uint64_t Hash = 0;
  std::uint64_t VerifiedEpoch = 0; ///< DistrustedObjects::Epoch() when last hashed or set
  bool Valid = false;
  bool ObjectOnly = false; ///< SetObjectOnly: no hash to compare
};

} // namespace dgmf_vtk

#endif
