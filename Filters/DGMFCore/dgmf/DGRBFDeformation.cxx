#include "dgmf/DGRBFDeformation.h"

#include "dgmf/Wendland.h"

#include "dgmf/DGMDeformation.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dgmf
{
namespace
{

inline double Distance(const double* a, const double* b)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// Per element: the support radius, then for each vertex a_k (3 values) and b_k.
template <int N>
void FitElement(const DelaunayGraph& graph, std::int32_t e,
  const std::vector<double>& vertexDisplacement, double supportRadius, double* coefficients)
{
  const std::int32_t* v = graph.GetElement(e);
  double longest = 0.0;
  for (int j = 0; j < N; ++j)
  {
    for (int k = j + 1; k < N; ++k)
    {
      longest =
        std::max(longest, Distance(graph.GetVertexPosition(v[j]), graph.GetVertexPosition(v[k])));
    }
  }
  const double R = supportRadius > 0.0 ? std::max(supportRadius, longest) : 2.0 * longest;
  Eigen::Matrix<double, N, N> phi;
  Eigen::Matrix<double, N, 4> rhs;
  for (int j = 0; j < N; ++j)
  {
    for (int k = 0; k < N; ++k)
    {
      phi(j, k) =
        WendlandC2(Distance(graph.GetVertexPosition(v[j]), graph.GetVertexPosition(v[k])) / R);
    }
    const double* d = vertexDisplacement.data() + 3 * static_cast<std::size_t>(v[j]);
    rhs(j, 0) = d[0];
    rhs(j, 1) = d[1];
    rhs(j, 2) = d[2];
    rhs(j, 3) = 1.0;
  }
  // Wendland C2 is positive definite in up to three dimensions: Cholesky.
  const Eigen::Matrix<double, N, 4> solution = phi.llt().solve(rhs);
  coefficients[0] = R;
  for (int k = 0; k < N; ++k)
  {
    for (int c = 0; c < 4; ++c)
    {
      coefficients[1 + 4 * k + c] = solution(k, c);
    }
  }
}
} // namespace

void DeformDGRBF(const DelaunayMapping& mapping, const BoundaryMotion& boundary,
  double supportRadius, const double* points, double* deformed, const ParallelFor& parallelFor)
{
  const std::vector<double> vertexDisplacement = GatherVertexDisplacement(mapping, boundary);
  const DelaunayGraph& graph = mapping.GetGraph();
  const int n = graph.GetVerticesPerElement();
  const std::size_t stride = 1 + 4 * static_cast<std::size_t>(n);
  const std::size_t elements = graph.GetNumberOfElements();

  // Fit every element (fixed-size solves).
  std::vector<double> coefficients(elements * stride);
  parallelFor(0, elements, 1024,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        double* c = coefficients.data() + e * stride;
        if (n == 3)
        {
          FitElement<3>(graph, static_cast<std::int32_t>(e), vertexDisplacement, supportRadius, c);
        }
        else
        {
          FitElement<4>(graph, static_cast<std::int32_t>(e), vertexDisplacement, supportRadius, c);
        }
      }
    });

  // Evaluate at every interior node.
  mapping.ForEachNode(parallelFor,
    [&](std::size_t i)
    {
      const double* x = points + 3 * i;
      double d[3] = { 0.0, 0.0, 0.0 };
      if (!mapping.IsBoundaryNode(i))
      {
        const std::int32_t e = mapping.GetElementOfNode(i);
        const std::int32_t* v = graph.GetElement(e);
        const double* c = coefficients.data() + static_cast<std::size_t>(e) * stride;
        const double R = c[0];
        double p[3] = { x[0], x[1], mapping.GetDimension() == 3 ? x[2] : 0.0 };
        double denominator = 0.0;
        for (int k = 0; k < n; ++k)
        {
          const double phi = WendlandC2(Distance(p, graph.GetVertexPosition(v[k])) / R);
          const double* ck = c + 1 + 4 * k;
          d[0] += ck[0] * phi;
          d[1] += ck[1] * phi;
          d[2] += ck[2] * phi;
          denominator += ck[3] * phi;
        }
        if (denominator > 1e-12)
        {
          for (int k = 0; k < 3; ++k)
          {
            d[k] /= denominator;
          }
        }
        else
        {
          // Degenerate local fit (not seen in practice): fall back to DGM's barycentric mapping.
          const double* w = mapping.GetWeights(i);
          d[0] = d[1] = d[2] = 0.0;
          for (int k = 0; k < n; ++k)
          {
            const double* dk = vertexDisplacement.data() + 3 * static_cast<std::size_t>(v[k]);
            for (int c = 0; c < 3; ++c)
            {
              d[c] += w[k] * dk[c];
            }
          }
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        deformed[3 * i + k] = x[k] + d[k];
      }
    });
  ApplyBoundaryMotion(boundary, points, deformed);
}

} // namespace dgmf
