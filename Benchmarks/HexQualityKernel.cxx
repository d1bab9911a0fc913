// The hexahedra's size-skew kernel in cache (speed.md, "The corners in the vectors' layout"):
// 65,536 jittered unit cubes, one thread, the best of 200 runs of each of the core's four batch
// functions, in nanoseconds per hexahedron. The mean's digits show that both layouts give the
// same values.
//   dgmf-hex-quality-kernel
#include "dgmf/SizeSkewQuality.h"

#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

int main()
{
  constexpr std::size_t count = 65536;
  constexpr double cube[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  std::vector<double> corners(count * 24), groups(count / 4 * dgmf::kHexGroupDoubles);
  std::vector<const double*> pointers(count);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (std::size_t c = 0; c < count; ++c)
  {
    for (int k = 0; k < 8; ++k)
    {
      for (int d = 0; d < 3; ++d)
      {
        const double value = cube[k][d] + jitter(random);
        corners[c * 24 + 3 * k + d] = value;
        groups[c / 4 * dgmf::kHexGroupDoubles + dgmf::HexGroupIndex(k, d, c % 4)] = value;
      }
    }
    pointers[c] = &corners[c * 24];
  }
  std::vector<double> references(count);
  std::vector<dgmf::CellQuality> quality(count);
  const auto best = [](auto run)
  {
    double fastest = 1e9;
    for (int r = 0; r < 200; ++r)
    {
      const auto start = std::chrono::steady_clock::now();
      run();
      fastest = std::min(
        fastest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return fastest / count * 1e9;
  };
  const auto mean = [&]()
  {
    double sum = 0.0;
    for (const dgmf::CellQuality& q : quality)
    {
      sum += q.SizeSkew;
    }
    return sum / count;
  };
  const double pointerReference =
    best([&]() { dgmf::ComputeHexReferenceSizes(count, pointers.data(), references.data()); });
  const double pointerDeformed = best(
    [&]() { dgmf::ComputeHexSizeSkew(count, references.data(), pointers.data(), quality.data()); });
  const double pointerMean = mean();
  const double groupReference = best(
    [&]() { dgmf::ComputeHexReferenceSizesInGroups(count, groups.data(), references.data()); });
  const double groupDeformed = best([&]()
    { dgmf::ComputeHexSizeSkewInGroups(count, references.data(), groups.data(), quality.data()); });
  std::printf("by pointers: reference half %.1f ns, deformed half %.1f ns per hexahedron (mean "
              "%.17g)\nin groups:   reference half %.1f ns, deformed half %.1f ns per hexahedron "
              "(mean %.17g)\n",
    pointerReference, pointerDeformed, pointerMean, groupReference, groupDeformed, mean());
  return 0;
}
