#include "dgmf/IDWDeformation.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace dgmf
{
namespace
{
/// Nodes per block (fixed, so results do not depend on the ParallelFor).
constexpr std::size_t BlockSize = 1024;
/// Bound on each of the two weight terms in the fast path. With A_i <= 1 (the weights are divided
/// by the largest one) a sum over any realistic number of nodes stays far below DBL_MAX.
constexpr double LargestTerm = 1e200;
/// Below this total weight, the fast path may have lost the weights to underflow.
constexpr double SmallestSum = 1e-200;
/// A node with (d / Ldef)^2 <= 1e-300 (d <= 1e-150 Ldef) coincides with the boundary node.
constexpr double CoincidentSquared = 1e-300;

/// The boundary nodes as contiguous arrays, and the constants of the weight function.
struct Sources
{
  std::size_t Count = 0;
  bool ThreeD = true;
  std::vector<double> X, Y, Z;   ///< positions (Z = 0 in 2D)
  std::vector<double> A;         ///< A_i divided by the largest A_i
  std::vector<double> S[3];      ///< displacement - Reference (S[2] = 0 in 2D)
  const double* Exact = nullptr; ///< the given displacements, 3 per node
  double Reference[3] = { 0.0, 0.0, 0.0 };
  double L = 1.0; ///< Ldef
  double LSquared = 1.0;
  double InverseL = 1.0;
  double ExponentA = 3.0;
  double ExponentB = 5.0;
  double Alpha = 5.0;
  double AlphaPowerB = 3125.0; ///< alpha^b, for the default exponents
  double SafeSquared = 0.0;    ///< below this d^2 the fast path could overflow
};

/// Boundary nodes are processed in tiles of this many, with Eigen arrays (SIMD sqrt and division).
constexpr Eigen::Index Tile = 256;
using TileArray = Eigen::Array<double, Eigen::Dynamic, 1, 0, Tile, 1>;
using ConstMap = Eigen::Map<const Eigen::ArrayXd>;

/// Writes Reference + sum / sw, or returns false if the total weight is unusable.
bool Finish(const Sources& s, double sw, const double sum[3], double out[3])
{
  if (!(sw >= SmallestSum) || !std::isfinite(sw))
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    out[c] = s.Reference[c] + sum[c] / sw;
  }
  return true;
}

/**
 * Fast path for the default exponents a = 3, b = 5: with q = L^2 / d^2,
 * w_i = A_i q sqrt(q) (1 + alpha^5 q) (one division and one square root per pair, no pow),
 * vectorised over tiles of boundary nodes. Returns false when the slow path must be used: a node
 * closer than the safe distance (possible overflow, or a coincident node), or a total weight lost
 * to underflow.
 */
template <int Dimension>
bool SumDefault(const Sources& s, const double p[3], double out[3])
{
  double sw = 0.0;
  double sum[3] = { 0.0, 0.0, 0.0 };
  const auto count = static_cast<Eigen::Index>(s.Count);
  for (Eigen::Index start = 0; start < count; start += Tile)
  {
    const Eigen::Index length = std::min(Tile, count - start);
    TileArray d2 = (ConstMap(s.X.data() + start, length) - p[0]).square() +
      (ConstMap(s.Y.data() + start, length) - p[1]).square();
    if (Dimension == 3)
    {
      d2 += (ConstMap(s.Z.data() + start, length) - p[2]).square();
    }
    if (!(d2.minCoeff() >= s.SafeSquared))
    {
      return false;
    }
    const TileArray q = s.LSquared / d2;
    const TileArray w =
      ConstMap(s.A.data() + start, length) * q * q.sqrt() * (1.0 + s.AlphaPowerB * q);
    sw += w.sum();
    for (int c = 0; c < Dimension; ++c)
    {
      sum[c] += (w * ConstMap(s.S[c].data() + start, length)).sum();
    }
  }
  return Finish(s, sw, sum, out);
}

/// Fast path for other exponents: w_i = A_i [ (L/d)^a + (alpha L/d)^b ] with std::pow.
bool SumGeneral(const Sources& s, const double p[3], double out[3])
{
  double sw = 0.0;
  double sum[3] = { 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < s.Count; ++i)
  {
    const double dx = p[0] - s.X[i];
    const double dy = p[1] - s.Y[i];
    const double dz = p[2] - s.Z[i];
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 >= s.SafeSquared))
    {
      return false;
    }
    const double t = s.L / std::sqrt(d2);
    const double w = s.A[i] * (std::pow(t, s.ExponentA) + std::pow(s.Alpha * t, s.ExponentB));
    sw += w;
    for (int c = 0; c < 3; ++c)
    {
      sum[c] += w * s.S[c][i];
    }
  }
  return Finish(s, sw, sum, out);
}

/**
 * Slow path, overflow- and underflow-safe. Distances are taken relative to Ldef, q_i = d_i / L.
 * A node with q_i^2 <= 1e-300 gets that boundary node's displacement exactly. Otherwise, with
 * q_m the smallest q_i among nodes with A_i > 0, tau = 1/q_m and u_i = q_m / q_i in (0, 1],
 * w_i = A_i [ tau^a u_i^a + (alpha tau)^b u_i^b ]; every w_i is divided by
 * exp(max(a ln tau, b ln(alpha tau))), so that both coefficients are <= 1 and one equals 1.
 */
void SumSafe(const Sources& s, const double p[3], double out[3])
{
  std::size_t nearest = 0;
  double nearestQ2 = std::numeric_limits<double>::infinity();
  double weightedQ2 = std::numeric_limits<double>::infinity();
  const auto scaledSquared = [&](std::size_t i)
  {
    const double ex = (p[0] - s.X[i]) * s.InverseL;
    const double ey = (p[1] - s.Y[i]) * s.InverseL;
    const double ez = (p[2] - s.Z[i]) * s.InverseL;
    return ex * ex + ey * ey + ez * ez;
  };
  for (std::size_t i = 0; i < s.Count; ++i)
  {
    const double q2 = scaledSquared(i);
    if (q2 < nearestQ2)
    {
      nearestQ2 = q2;
      nearest = i;
    }
    if (s.A[i] > 0.0)
    {
      weightedQ2 = std::min(weightedQ2, q2);
    }
  }
  const auto copyNearest = [&]()
  {
    for (int c = 0; c < 3; ++c)
    {
      out[c] = c < 2 || s.ThreeD ? s.Exact[3 * nearest + c] : 0.0;
    }
  };
  if (nearestQ2 <= CoincidentSquared || !std::isfinite(weightedQ2))
  {
    copyNearest();
    return;
  }
  const double qm = std::sqrt(weightedQ2);
  const double la = s.ExponentA * -std::log(qm);
  const double lb =
    s.Alpha > 0.0 ? s.ExponentB * std::log(s.Alpha / qm) : -std::numeric_limits<double>::infinity();
  const double lmax = std::max(la, lb);
  const double ca = std::exp(la - lmax);
  const double cb = std::exp(lb - lmax);
  double sw = 0.0, sum[3] = { 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < s.Count; ++i)
  {
    if (!(s.A[i] > 0.0))
    {
      continue;
    }
    const double u = qm / std::sqrt(scaledSquared(i));
    const double w = s.A[i] * (ca * std::pow(u, s.ExponentA) + cb * std::pow(u, s.ExponentB));
    sw += w;
    for (int c = 0; c < 3; ++c)
    {
      sum[c] += w * s.S[c][i];
    }
  }
  if (!(sw > 0.0))
  {
    copyNearest();
    return;
  }
  for (int c = 0; c < 3; ++c)
  {
    out[c] = s.Reference[c] + sum[c] / sw;
  }
}

void CheckParameters(const BoundaryMotion& boundary, const IDWParameters& parameters)
{
  const std::size_t n = boundary.Size();
  if (boundary.Dimension != 2 && boundary.Dimension != 3)
  {
    throw std::invalid_argument("IDW: the dimension must be 2 or 3");
  }
  if (n == 0)
  {
    throw std::invalid_argument("IDW: there are no boundary nodes to interpolate from");
  }
  if (boundary.Positions.size() != 3 * n || boundary.Displacements.size() != 3 * n)
  {
    throw std::invalid_argument("IDW: boundary positions and displacements need 3 values per node");
  }
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    if (!std::isfinite(boundary.Positions[i]) || !std::isfinite(boundary.Displacements[i]))
    {
      throw std::invalid_argument("IDW: boundary node " + std::to_string(i / 3) +
        " has a non-finite position or displacement");
    }
  }
  if (!boundary.Weights.empty())
  {
    if (boundary.Weights.size() != n)
    {
      throw std::invalid_argument("IDW: there must be one weight A_i per boundary node (or none)");
    }
    bool positive = false;
    for (double a : boundary.Weights)
    {
      if (!std::isfinite(a) || a < 0.0)
      {
        throw std::invalid_argument("IDW: the weights A_i must be finite and >= 0");
      }
      positive = positive || a > 0.0;
    }
    if (!positive)
    {
      throw std::invalid_argument("IDW: at least one weight A_i must be positive");
    }
  }
  if (!(parameters.ExponentA > 0.0) || !(parameters.ExponentB > 0.0) ||
    !std::isfinite(parameters.ExponentA) || !std::isfinite(parameters.ExponentB))
  {
    throw std::invalid_argument("IDW: the exponents a and b must be finite and positive");
  }
  if (!(parameters.Alpha >= 0.0) || !std::isfinite(parameters.Alpha))
  {
    throw std::invalid_argument("IDW: IDWAlpha must be finite and >= 0");
  }
  if (!(parameters.ReferenceLength >= 0.0) || !std::isfinite(parameters.ReferenceLength))
  {
    throw std::invalid_argument("IDW: IDWReferenceLength must be finite and >= 0 (0: automatic)");
  }
}
} // namespace

double DeformIDW(const BoundaryMotion& boundary, const IDWParameters& parameters,
  const double* points, std::size_t numberOfNodes, double* deformed, const ParallelFor& parallelFor)
{
  CheckParameters(boundary, parameters);
  const std::size_t n = boundary.Size();
  const int dim = boundary.Dimension;

  Sources s;
  s.Count = n;
  s.ThreeD = dim == 3;
  s.Exact = boundary.Displacements.data();
  s.ExponentA = parameters.ExponentA;
  s.ExponentB = parameters.ExponentB;
  s.Alpha = parameters.Alpha;
  s.AlphaPowerB = std::pow(parameters.Alpha, parameters.ExponentB);
  s.X.resize(n);
  s.Y.resize(n);
  s.Z.assign(n, 0.0);
  s.A.assign(n, 1.0);
  for (int c = 0; c < 3; ++c)
  {
    s.S[c].assign(n, 0.0);
  }

  double centroid[3] = { 0.0, 0.0, 0.0 };
  double lower[3], upper[3];
  for (int c = 0; c < 3; ++c)
  {
    lower[c] = std::numeric_limits<double>::max();
    upper[c] = -std::numeric_limits<double>::max();
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* x = boundary.Positions.data() + 3 * i;
    const double* d = boundary.Displacements.data() + 3 * i;
    s.X[i] = x[0];
    s.Y[i] = x[1];
    s.Z[i] = dim == 3 ? x[2] : 0.0;
    for (int c = 0; c < dim; ++c)
    {
      centroid[c] += x[c];
      lower[c] = std::min(lower[c], d[c]);
      upper[c] = std::max(upper[c], d[c]);
    }
  }
  // Reference: the midrange of the displacements, exact when all are equal (a translation).
  for (int c = 0; c < dim; ++c)
  {
    centroid[c] /= static_cast<double>(n);
    s.Reference[c] = 0.5 * lower[c] + 0.5 * upper[c];
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < dim; ++c)
    {
      s.S[c][i] = boundary.Displacements[3 * i + c] - s.Reference[c];
    }
  }
  if (!boundary.Weights.empty())
  {
    const double largest = *std::max_element(boundary.Weights.begin(), boundary.Weights.end());
    for (std::size_t i = 0; i < n; ++i)
    {
      s.A[i] = boundary.Weights[i] / largest;
    }
  }

  double L = parameters.ReferenceLength;
  if (L == 0.0)
  {
    double largest2 = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double r[3] = { s.X[i] - centroid[0], s.Y[i] - centroid[1], s.Z[i] - centroid[2] };
      largest2 = std::max(largest2, r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    }
    L = std::sqrt(largest2);
    if (!(L > 0.0))
    {
      L = 1.0; // a single boundary position: any Ldef gives the same result
    }
  }
  s.L = L;
  s.LSquared = L * L;
  s.InverseL = 1.0 / L;
  const double safe = L *
    std::max(std::pow(LargestTerm, -1.0 / s.ExponentA),
      s.Alpha * std::pow(LargestTerm, -1.0 / s.ExponentB));
  s.SafeSquared = std::max(safe * safe, std::numeric_limits<double>::min());
  const bool defaultExponents = s.ExponentA == 3.0 && s.ExponentB == 5.0;

  ForEachIndex(parallelFor, numberOfNodes, BlockSize,
    [&](std::size_t i)
    {
      const double x[3] = { points[3 * i], points[3 * i + 1], points[3 * i + 2] };
      const double p[3] = { x[0], x[1], dim == 3 ? x[2] : 0.0 };
      double d[3];
      const bool done = !defaultExponents ? SumGeneral(s, p, d)
        : dim == 3                        ? SumDefault<3>(s, p, d)
                                          : SumDefault<2>(s, p, d);
      if (!done)
      {
        SumSafe(s, p, d);
      }
      deformed[3 * i] = x[0] + d[0];
      deformed[3 * i + 1] = x[1] + d[1];
      deformed[3 * i + 2] = x[2] + (dim == 3 ? d[2] : 0.0);
    });
  return L;
}

} // namespace dgmf
