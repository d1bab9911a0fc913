/**
 * @file ExactPointTable.h
 * @brief Finds points at exactly the same coordinates: an open-addressing hash table of point ids.
 */
#ifndef dgmf_ExactPointTable_h
#define dgmf_ExactPointTable_h

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/**
 * The distinct points of a point stream, found by their exact coordinates (-0 and +0 alike): the
 * merge of a composite input's blocks at their shared nodes, and the coincident nodes of a mesh.
 * The table keeps only ids (below 2^40) with 23 bits of their hash (8 bytes per slot, at most
 * half full); the coordinates stay in the caller's array of kept points, `points[3 * id]`. One
 * lookup is one probe sequence, so a stream of n points costs O(n) (std::map took 0.5 s for 826,080
 * nodes, this about 0.03 s).
 */
class ExactPointTable
{
public:
  /// A table for about `expected` distinct points (it grows when needed).
  explicit ExactPointTable(std::size_t expected = 0);

  /**
   * The id of the kept point with the coordinates of `p`, looked up in `points` (the kept points'
   * coordinates, id k at points[3 k]); if there is none, `id` is recorded for them and returned
   * (the caller then keeps `p` as point `id`, which must be the next id not yet recorded or any id
   * whose coordinates in `points` are those of `p`).
   */
  std::int64_t FindOrInsert(const double* points, const double p[3], std::int64_t id);

  /// Starts loading the slot where `p` would be looked up (call it a few points ahead).
  void Prefetch(const double p[3]) const;

  /// The number of ids recorded.
  std::size_t Size() const { return this->Count; }

private:
  void Grow(const double* points);
  std::vector<std::int64_t> Slots; // -1: empty
  std::size_t Mask = 0;
  std::size_t Count = 0;
};

} // namespace dgmf

#endif
