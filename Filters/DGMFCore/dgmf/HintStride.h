/**
 * @file HintStride.h
 * @brief The index difference between mesh neighbours across layers, for the point location.
 */
#ifndef dgmf_HintStride_h
#define dgmf_HintStride_h

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/**
 * The hint stride of a mesh (DelaunayMapping, LocateNodes) from a sample of its cells, each given
 * by its point ids: the most common difference between the ids of two corners of a cell (the
 * largest one when several are equally common), or 0 when there is no such regularity.
 *
 * Structured and layered meshes number neighbours at a few fixed differences: 1 along a row, the
 * row length across rows, the layer size across layers. The largest of them is the one the
 * previous node's element cannot serve, and across layers (from a body to the far field) is the
 * direction along which the Delaunay graph's elements are long. Unstructured numberings have no
 * common difference: a difference must occur at least once per sampled cell on average (and be at
 * least 2) to be returned.
 */
std::size_t FindHintStride(const std::vector<std::vector<std::int64_t>>& cells);

} // namespace dgmf

#endif
