// The graph's seed grid: a uniform grid over its bounding box with an element per cell, where
// walks start after a jump in the numbering (DelaunayGraph::GetSeedElement).
#include "dgmf/DelaunayGraph.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace dgmf
{
namespace
{
/// Elements per block of the seed grid's parallel pass.
constexpr std::size_t SeedBlock = 4096;
} // namespace

void DelaunayGraph::BuildSeedGrid(const ParallelFor& parallelFor)
{
  // A uniform grid with about one cell per 4 elements over the graph's bounding box.
  const std::size_t elements = this->GetNumberOfElements();
  double lower[3] = { 0, 0, 0 }, upper[3] = { 0, 0, 0 };
  for (std::size_t v = 0; v < this->GetNumberOfVertices(); ++v)
  {
    const double* x = this->GetVertexPosition(static_cast<std::int32_t>(v));
    for (int c = 0; c < this->Dimension; ++c)
    {
      lower[c] = v == 0 || x[c] < lower[c] ? x[c] : lower[c];
      upper[c] = v == 0 || x[c] > upper[c] ? x[c] : upper[c];
    }
  }
  double volume = 1.0;
  for (int c = 0; c < this->Dimension; ++c)
  {
    volume *= std::max(upper[c] - lower[c], 1e-300);
  }
  const double cellsWanted = std::max(1.0, static_cast<double>(elements) / 4.0);
  const double size = std::pow(volume / cellsWanted, 1.0 / this->Dimension);
  this->SeedInverseSize = size > 0.0 && std::isfinite(1.0 / size) ? 1.0 / size : 1.0;
  std::size_t total = 1;
  for (int c = 0; c < 3; ++c)
  {
    this->SeedOrigin[c] = lower[c];
    this->SeedUpper[c] = upper[c];
    this->SeedCells[c] = c < this->Dimension
      ? std::clamp<std::int64_t>(
          static_cast<std::int64_t>((upper[c] - lower[c]) * this->SeedInverseSize) + 1, 1, 1024)
      : 1;
    total *= static_cast<std::size_t>(this->SeedCells[c]);
  }
  // Each cell gets the first element (in the Hilbert order) whose centroid lies in it (the
  // elements' cells found on the threads)...
  this->SeedGrid.assign(total, -1);
  const int n = this->Dimension + 1;
  UninitializedVector<std::size_t> cellOf(elements); // written by the threads
  ForEachIndex(parallelFor, elements, SeedBlock,
    [&](std::size_t e)
    {
      double centroid[3] = { 0, 0, 0 };
      for (int k = 0; k < n; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          centroid[c] += this->Records[e].Corners[k][c] / n;
        }
      }
      cellOf[e] = this->GetSeedCell(centroid);
    });
  for (std::size_t e = 0; e < elements; ++e)
  {
    std::int32_t& cell = this->SeedGrid[cellOf[e]];
    cell = cell < 0 ? static_cast<std::int32_t>(e) : cell;
  }
  // ... and empty cells the element of a filled neighbour, by sweeps along each axis: along every
  // line of cells in the axis' direction, forwards then backwards.
  const std::size_t cells[3] = { static_cast<std::size_t>(this->SeedCells[0]),
    static_cast<std::size_t>(this->SeedCells[1]), static_cast<std::size_t>(this->SeedCells[2]) };
  const std::size_t stride[3] = { 1, cells[0], cells[0] * cells[1] };
  for (int c = 0; c < 3; ++c)
  {
    const int a = (c + 1) % 3, b = (c + 2) % 3; // the two other axes span the lines' starts
    for (std::size_t i = 0; i < cells[a]; ++i)
    {
      for (std::size_t j = 0; j < cells[b]; ++j)
      {
        std::int32_t* line = this->SeedGrid.data() + i * stride[a] + j * stride[b];
        for (std::size_t k = 1; k < cells[c]; ++k)
        {
          std::int32_t& cell = line[k * stride[c]];
          cell = cell < 0 ? line[(k - 1) * stride[c]] : cell;
        }
        for (std::size_t k = cells[c] - 1; k-- > 0;)
        {
          std::int32_t& cell = line[k * stride[c]];
          cell = cell < 0 ? line[(k + 1) * stride[c]] : cell;
        }
      }
    }
  }
  for (std::int32_t& cell : this->SeedGrid)
  {
    cell = cell < 0 ? 0 : cell; // only when there are no elements near at all
  }
}

std::size_t DelaunayGraph::GetSeedCell(const double p[3]) const
{
  std::size_t index = 0, stride = 1;
  for (int c = 0; c < 3; ++c)
  {
    const double x = (p[c] - this->SeedOrigin[c]) * this->SeedInverseSize;
    const std::int64_t i = x > 0.0
      ? std::min<std::int64_t>(static_cast<std::int64_t>(std::min(x, 1e9)), this->SeedCells[c] - 1)
      : 0;
    index += static_cast<std::size_t>(i) * stride;
    stride *= static_cast<std::size_t>(this->SeedCells[c]);
  }
  return index;
}

std::int32_t DelaunayGraph::GetSeedElement(const double p[3]) const
{
  return this->SeedGrid[this->GetSeedCell(p)];
}

} // namespace dgmf
