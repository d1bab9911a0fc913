#include "dgmf/HintStride.h"

#include <algorithm>
#include <unordered_map>

namespace dgmf
{

std::size_t FindHintStride(const std::vector<std::vector<std::int64_t>>& cells)
{
  std::unordered_map<std::int64_t, std::size_t> counts;
  for (const std::vector<std::int64_t>& cell : cells)
  {
    // Corner pairs of the first 8 corners (a hexahedron's 28 pairs include its 12 edges).
    const std::size_t corners = std::min<std::size_t>(cell.size(), 8);
    for (std::size_t a = 0; a < corners; ++a)
    {
      for (std::size_t b = a + 1; b < corners; ++b)
      {
        const std::int64_t difference = cell[a] > cell[b] ? cell[a] - cell[b] : cell[b] - cell[a];
        if (difference >= 2)
        {
          ++counts[difference];
        }
      }
    }
  }
  std::int64_t best = 0;
  std::size_t bestCount = 0;
  for (const auto& entry : counts)
  {
    if (entry.second > bestCount || (entry.second == bestCount && entry.first > best))
    {
      best = entry.first;
      bestCount = entry.second;
    }
  }
  return bestCount >= cells.size() && !cells.empty() ? static_cast<std::size_t>(best) : 0;
}

} // namespace dgmf
