/**
 * @file LocationStartGrid.h
 * @brief Where the walk of a node numbered without spatial coherence starts: an element found
 * beforehand near it, from a grid refined where the nodes are.
 */
#ifndef dgmf_LocationStartGrid_h
#define dgmf_LocationStartGrid_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/NodeKind.h"
#include "dgmf/ParallelFor.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/**
 * @class LocationStartGrid
 * @brief A start element for the visibility walk of any point, a few elements from it.
 *
 * Each cell of the graph's seed grid (DelaunayGraph::GetSeedGridGeometry) is cut into s^3
 * sub-cells (s^2 in 2D), s chosen from the number of interior nodes in the cell (one node in 8
 * counted) so that a sub-cell holds at most about NodesPerSubCell of them (s = 1 for an empty
 * cell, at most MaximumSide). The centre of every sub-cell (kept within the graph's bounding box)
 * is located once by LocateNodes, in fixed blocks of sub-cells: the cells row by row, the
 * sub-cells of a cell row by row, so most walks start at a neighbouring centre's element. A point's
 * start element is then its sub-cell centre's: a few array reads, and a walk as long as from the
 * centre to the point.
 *
 * The nodes can then be located in their own order, whatever it is: the node arrays are read and
 * written in order, and only the graph and this grid are read at random (DelaunayMapping's path for
 * numberings without spatial coherence). The graph's elements are long slivers from the body to the
 * far field, so the seed grid's own elements (one per cell, from the elements' centroids) are tens
 * of steps from most nodes; the sub-cells' centres follow the nodes' density instead.
 *
 * Everything depends only on the graph and the points: the sub-cells' centres are located in
 * fixed blocks, so the start elements are the same for any number of threads.
 */
class LocationStartGrid
{
public:
  /// Interior nodes per sub-cell wanted.
  static constexpr double NodesPerSubCell = 32.0;
  /// Sub-cells per axis of a seed cell, at most.
  static constexpr int MaximumSide = 64;
  static_assert(MaximumSide <= 255, "a cell's side is kept in 8 bits");

  LocationStartGrid(const DelaunayGraph& graph, const double* points, const NodeKind* kinds,
    std::size_t numberOfNodes, const ParallelFor& parallelFor);

  /// The element of the centre of the sub-cell containing `p` (clamped to the grid).
  std::int32_t GetStartElement(const double p[3]) const
  {
    return this->Elements[this->GetSubCell(p)];
  }

  /// The index in Elements of the sub-cell containing `p`.
  std::size_t GetSubCell(const double p[3]) const
  {
    std::size_t index = 0, stride = 1;
    double local[3] = { 0.0, 0.0, 0.0 };
    for (int c = 0; c < this->Dimension; ++c)
    {
      const double x = (p[c] - this->Geometry.Origin[c]) * this->Geometry.InverseCellSize;
      const double upper = static_cast<double>(this->Geometry.Cells[c]);
      // Written so that NaN lands in cell 0: the walk then decides.
      const double clamped = x > 0.0 ? (x < upper ? x : this->Below[c]) : 0.0;
      const auto i = static_cast<std::size_t>(clamped);
      local[c] = clamped - static_cast<double>(i);
      index += i * stride;
      stride *= static_cast<std::size_t>(this->Geometry.Cells[c]);
    }
    const std::size_t first = this->FirstSubCell[index];
    const auto side = static_cast<std::size_t>(this->Side[index]);
    std::size_t sub = 0;
    stride = 1;
    for (int c = 0; c < this->Dimension; ++c)
    {
      const auto j = static_cast<std::size_t>(local[c] * static_cast<double>(side));
      sub += std::min(j, side - 1) * stride;
      stride *= side;
    }
    return first + sub;
  }

  /**
   * The start element of every interior node i in [begin, end) into starts[i - begin] (-1 for a
   * boundary node): the grid's arrays are asked for ahead, so that the lookups of successive nodes
   * overlap.
   */
  void GetStartElements(const double* points, const NodeKind* kinds, std::size_t begin,
    std::size_t end, std::int32_t* starts) const;

  /// Sub-cells in all, each with a located centre.
  std::size_t GetNumberOfSubCells() const { return this->Elements.size(); }

  /// Memory held, in bytes.
  std::size_t GetMemorySize() const;

private:
  int Dimension;
  DelaunayGraph::SeedGridGeometry Geometry;
  double Below[3]; ///< per axis, the largest grid coordinate below the number of cells
  /// Per seed cell, its first sub-cell in Elements; then the number of sub-cells.
  std::vector<std::uint32_t> FirstSubCell;
  /// Sub-cells per axis of each seed cell.
  std::vector<std::uint8_t> Side;
  /// The element of each sub-cell's centre.
  std::vector<std::int32_t> Elements;
};

} // namespace dgmf

#endif
