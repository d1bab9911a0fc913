#include "DGMFBoundaryNodes.h"

#include <cmath>

namespace dgmf_vtk
{

std::vector<std::uint8_t> FlagBoundaryNodes(const BoundaryFacets& facets, vtkIdType numberOfPoints)
{
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(numberOfPoints), 0);
  for (vtkIdType id : facets.Ids)
  {
    if (id >= 0 && id < numberOfPoints)
    {
      flags[static_cast<std::size_t>(id)] = 1;
    }
  }
  if (!facets.Canonical.empty())
  {
    for (std::size_t i = 0; i < flags.size(); ++i)
    {
      flags[i] = flags[static_cast<std::size_t>(facets.Canonical[i])];
    }
  }
  return flags;
}

std::vector<double> ComputeBoundaryNodeWeights(
  const BoundaryFacets& facets, const double* points, vtkIdType numberOfPoints, int dimension)
{
  std::vector<double> weights(static_cast<std::size_t>(numberOfPoints), 0.0);
  for (std::size_t f = 0; f < facets.Size(); ++f)
  {
    const vtkIdType* ids = facets.Ids.data() + facets.Offsets[f];
    const vtkIdType count = facets.Offsets[f + 1] - facets.Offsets[f];
    double measure = 0.0;
    if (dimension == 2)
    {
      const double* a = points + 3 * ids[0];
      const double* b = points + 3 * ids[1];
      measure = std::hypot(b[0] - a[0], b[1] - a[1]);
    }
    else
    {
      // Polygon area from its Newell normal.
      double normal[3] = { 0.0, 0.0, 0.0 };
      for (vtkIdType k = 0; k < count; ++k)
      {
        const double* p = points + 3 * ids[k];
        const double* q = points + 3 * ids[(k + 1) % count];
        normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
        normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
        normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
      }
      measure =
        0.5 * std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      weights[static_cast<std::size_t>(ids[k])] += measure / static_cast<double>(count);
    }
  }
  if (!facets.Canonical.empty())
  {
    for (std::size_t i = 0; i < weights.size(); ++i)
    {
      weights[i] = weights[static_cast<std::size_t>(facets.Canonical[i])];
    }
  }
  return weights;
}

} // namespace dgmf_vtk
