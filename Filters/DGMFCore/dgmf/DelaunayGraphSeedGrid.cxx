// The graph's seed grid: a uniform grid over its bounding box with an element per cell, where
// walks start after a jump in the numbering (DelaunayGraph::GetSeedElement).
#include "dgmf/DelaunayGraph.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dgmf
{

void DelaunayGraph::BuildSeedGrid()
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
    this->SeedCells[c] = c < this->Dimension
      ? std::clamp<std::int64_t>(
          static_cast<std::int64_t>((upper[c] - lower[c]) * this->SeedInverseSize) + 1, 1, 1024)
      : 1;
    total *= static_cast<std::size_t>(this->SeedCells[c]);
  }
  // Each cell gets the first element (in the Hilbert order) whose centroid lies in it...
  this->SeedGrid.assign(total, -1);
  const int n = this->Dimension + 1;
  for (std::size_t e = 0; e < elements; ++e)
  {
    double centroid[3] = { 0, 0, 0 };
    for (int k = 0; k < n; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        centroid[c] += this->Records[e].Corners[k][c] / n;
      }
    }
    std::int32_t& cell = this->SeedGrid[this->GetSeedCell(centroid)];
    cell = cell < 0 ? static_cast<std::int32_t>(e) : cell;
  }
  // ... and empty cells the element of a filled neighbour, by sweeps along each axis.
  const std::int64_t stride[3] = { 1, this->SeedCells[0], this->SeedCells[0] * this->SeedCells[1] };
  for (int c = 0; c < 3; ++c)
  {
    for (std::size_t i = 0; i < total; ++i)
    {
      const std::int64_t along = (static_cast<std::int64_t>(i) / stride[c]) % this->SeedCells[c];
      if (this->SeedGrid[i] < 0 && along > 0)
      {
        this->SeedGrid[i] = this->SeedGrid[i - stride[c]];
      }
    }
    for (std::size_t i = total; i-- > 0;)
    {
      const std::int64_t along = (static_cast<std::int64_t>(i) / stride[c]) % this->SeedCells[c];
      if (this->SeedGrid[i] < 0 && along + 1 < this->SeedCells[c])
      {
        this->SeedGrid[i] = this->SeedGrid[i + stride[c]];
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
