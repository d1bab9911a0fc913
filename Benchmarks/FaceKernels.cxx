// The core's passes over the faces of a hexahedral mesh alone, without VTK: the face matching
// (FindInternalFaces), the faces' parity (FacesPairUp) and the non-orthogonality of a new motion
// (ComputeNonOrthogonality), on a jittered N x N x N block of hexahedra numbered row by row.
// Best of several runs; for before/after measurements of these passes (Documentation/speed.md),
// quieter than the whole benchmark.
//
//   dgmf-face-kernels [--cells-per-axis N (160)] [--threads T (2)] [--repeats R (7)]
//                     [--shuffled-points 0|1 (0)]
// --shuffled-points 1 numbers the points at random, as an unstructured mesh's may be: each
// cell's corners then lie anywhere in memory.
#include "dgmf/CellFaces.h"
#include "dgmf/FaceMatching.h"
#include "dgmf/FaceParity.h"
#include "dgmf/NonOrthogonality.h"
#include "dgmf/ParallelFor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
/// Hexahedra whose corners follow one another in one array: one run of one shape.
class HexBlock : public dgmf::FaceCells
{
public:
  std::vector<std::int64_t> Corners; ///< 8 point ids per cell, VTK's order

  std::size_t GetNumberOfCells() const override { return this->Corners.size() / 8; }
  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override
  {
    const std::int64_t* local = dgmf::GetShapeFaceStream(dgmf::CellShape::Hexahedron);
    stream.assign(local, local + dgmf::FaceStreamLength(local));
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        stream[at + 1 + k] = this->Corners[8 * cell + local[at + 1 + k]];
      }
    }
  }
  const std::int64_t* GetCornerRun(std::size_t cell, std::size_t maxCells, const void*& ids,
    std::size_t& count, int& cornersPerCell) const override
  {
    ids = this->Corners.data() + 8 * cell;
    count = maxCells;
    cornersPerCell = 8;
    return dgmf::GetShapeFaceStream(dgmf::CellShape::Hexahedron);
  }
};

/// A ParallelFor over `threads` std::threads, each taking an equal part of the range.
dgmf::ParallelFor ThreadsFor(int threads)
{
  return [threads](std::size_t begin, std::size_t end, std::size_t, const dgmf::RangeFunction& body)
  {
    const std::size_t parts = static_cast<std::size_t>(std::max(1, threads));
    const std::size_t size = (end - begin + parts - 1) / parts;
    std::vector<std::thread> others;
    for (std::size_t p = 1; p < parts; ++p)
    {
      const std::size_t first = std::min(end, begin + p * size);
      const std::size_t last = std::min(end, first + size);
      if (first < last)
      {
        others.emplace_back([&body, first, last]() { body(first, last); });
      }
    }
    if (begin < std::min(end, begin + size))
    {
      body(begin, std::min(end, begin + size));
    }
    for (std::thread& other : others)
    {
      other.join();
    }
  };
}

/// The best wall-clock seconds of `repeats` calls of `run`.
double Best(int repeats, const std::function<void()>& run)
{
  double best = 1e300;
  for (int r = 0; r < repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    best = std::min(
      best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}
} // namespace

int main(int argc, char* argv[])
{
  int n = 160, threads = 2, repeats = 7, shuffled = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (i + 1 >= argc ||
      (option != "--cells-per-axis" && option != "--threads" && option != "--repeats" &&
        option != "--shuffled-points"))
    {
      std::fprintf(stderr,
        "usage: dgmf-face-kernels [--cells-per-axis N] [--threads T] [--repeats R] "
        "[--shuffled-points 0|1]\n");
      return 1;
    }
    const int value = std::atoi(argv[++i]);
    int& target = option == "--cells-per-axis" ? n
      : option == "--threads"                  ? threads
      : option == "--repeats"                  ? repeats
                                               : shuffled;
    target = &target == &shuffled ? value : std::max(1, value);
  }
  const std::int64_t p = n + 1;
  const auto id = [p](std::int64_t i, std::int64_t j, std::int64_t k)
  { return i + p * (j + p * k); };
  HexBlock cells;
  cells.Corners.reserve(8 * static_cast<std::size_t>(n) * n * n);
  for (std::int64_t k = 0; k < n; ++k)
  {
    for (std::int64_t j = 0; j < n; ++j)
    {
      for (std::int64_t i = 0; i < n; ++i)
      {
        for (const std::int64_t corner :
          { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
            id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) })
        {
          cells.Corners.push_back(corner);
        }
      }
    }
  }
  // The points jittered by a tenth of a cell, then moved by another twentieth (the new motion).
  const auto points = static_cast<std::size_t>(p * p * p);
  std::vector<double> original(3 * points), moved(3 * points);
  for (std::size_t q = 0; q < points; ++q)
  {
    const std::size_t index[3] = { q % static_cast<std::size_t>(p),
      q / static_cast<std::size_t>(p) % static_cast<std::size_t>(p),
      q / static_cast<std::size_t>(p * p) };
    for (int c = 0; c < 3; ++c)
    {
      original[3 * q + c] =
        static_cast<double>(index[c]) + 0.1 * std::sin(static_cast<double>(q) + c);
      moved[3 * q + c] =
        original[3 * q + c] + 0.05 * std::cos(0.3 * static_cast<double>(q) * (c + 1));
    }
  }
  if (shuffled)
  {
    // Point q becomes newOf[q]: the cells keep their order, their corners are scattered.
    std::vector<std::int64_t> newOf(points);
    std::iota(newOf.begin(), newOf.end(), std::int64_t{ 0 });
    std::shuffle(newOf.begin(), newOf.end(), std::mt19937_64(7));
    for (std::int64_t& corner : cells.Corners)
    {
      corner = newOf[static_cast<std::size_t>(corner)];
    }
    std::vector<double> from = original, to = moved;
    for (std::size_t q = 0; q < points; ++q)
    {
      const auto at = static_cast<std::size_t>(newOf[q]);
      std::copy_n(from.data() + 3 * q, 3, original.data() + 3 * at);
      std::copy_n(to.data() + 3 * q, 3, moved.data() + 3 * at);
    }
  }
  const dgmf::ParallelFor parallelFor = ThreadsFor(threads);
  dgmf::InternalFaces faces;
  const double matching =
    Best(repeats, [&]() { faces = dgmf::FindInternalFaces(cells, points, parallelFor); });
  bool closed = true;
  const double parity =
    Best(repeats, [&]() { closed = dgmf::FacesPairUp(cells, points, parallelFor); });
  const dgmf::InputOrientation orientation =
    dgmf::OrientCells(cells, faces, original.data(), parallelFor);
  double maximum = 0.0;
  const double nonOrthogonality = Best(repeats,
    [&]()
    {
      maximum =
        dgmf::ComputeNonOrthogonality(cells, faces, orientation, moved.data(), parallelFor).Maximum;
    });
  std::printf("%zu hexahedra%s, %zu internal faces, %d thread(s), best of %d:\n",
    cells.GetNumberOfCells(), shuffled ? " (points shuffled)" : "", faces.Size(), threads, repeats);
  std::printf("  FindInternalFaces %.3f s\n  FacesPairUp %.3f s (%s)\n", matching, parity,
    closed ? "closed" : "open: no patches");
  std::printf("  ComputeNonOrthogonality (a new motion) %.3f s (maximum %.4f degrees)\n",
    nonOrthogonality, maximum);
  return 0;
}
