/**
 * @file MshNodeIndex.h
 * @brief A .msh file's node tags as indices (private to the gmsh module's GmshModel.cxx and to
 * MshReader41.cxx, which number the nodes alike: in increasing tag order).
 */
#ifndef dgmf_meshfile_MshNodeIndex_h
#define dgmf_meshfile_MshNodeIndex_h

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace dgmf
{
namespace meshfile
{

/// Node tag -> 0-based index (a vector when the tags are dense, a hash map otherwise).
class NodeIndex
{
public:
  explicit NodeIndex(const std::vector<std::size_t>& sortedTags)
  {
    const std::size_t maxTag = sortedTags.empty() ? 0 : sortedTags.back();
    if (maxTag <= 4 * sortedTags.size() + 1024)
    {
      this->Dense.assign(maxTag + 1, -1);
      for (std::size_t k = 0; k < sortedTags.size(); ++k)
      {
        this->Dense[sortedTags[k]] = static_cast<std::int64_t>(k);
      }
    }
    else
    {
      for (std::size_t k = 0; k < sortedTags.size(); ++k)
      {
        this->Sparse[sortedTags[k]] = static_cast<std::int64_t>(k);
      }
      this->UseSparse = true;
    }
  }

  /// The index of `tag`, or -1.
  std::int64_t Find(std::size_t tag) const
  {
    if (this->UseSparse)
    {
      const auto it = this->Sparse.find(tag);
      return it == this->Sparse.end() ? -1 : it->second;
    }
    return tag < this->Dense.size() ? this->Dense[tag] : -1;
  }

private:
  bool UseSparse = false;
  std::vector<std::int64_t> Dense;
  std::unordered_map<std::size_t, std::int64_t> Sparse;
};

} // namespace meshfile
} // namespace dgmf

#endif
