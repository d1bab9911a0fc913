// A mesh as bytes (MeshBytes.h): the answer of a library's child process.
#include "dgmf/meshfile/MeshBytes.h"

#include "dgmf/HugePages.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace dgmf
{
namespace meshfile
{

namespace
{
/// Every array of a mesh's bytes starts at a multiple of this from the start.
constexpr std::size_t kAlignment = 8;

constexpr std::size_t Padded(std::size_t bytes)
{
  return (bytes + kAlignment - 1) / kAlignment * kAlignment;
}

/// The bytes Put writes for `count` values of T: the count, the values, padding.
template <typename T>
constexpr std::size_t BytesOf(std::size_t count)
{
  return sizeof(std::uint64_t) + Padded(count * sizeof(T));
}

/// Writes `count` values after their count at `out`, and pads them; moves `out` past them.
template <typename T>
void Put(char*& out, const T* values, std::size_t count)
{
  static_assert(alignof(T) <= kAlignment, "a mesh array's values must fit the alignment");
  const std::uint64_t number = count;
  std::memcpy(out, &number, sizeof(number));
  out += sizeof(number);
  if (count > 0) // an empty vector's data() may be null, which memcpy does not take
  {
    std::memcpy(out, values, count * sizeof(T));
  }
  std::memset(out + count * sizeof(T), 0, Padded(count * sizeof(T)) - count * sizeof(T));
  out += Padded(count * sizeof(T));
}

template <typename T>
void Put(char*& out, const std::vector<T>& values)
{
  Put(out, values.data(), values.size());
}

/// Reads what Put wrote at `at` into `values`, copied once (no zero-filling first).
template <typename T>
void Get(const char* in, std::size_t size, std::size_t& at, std::vector<T>& values)
{
  std::uint64_t count = 0;
  if (size - at < sizeof(count))
  {
    throw FileError("short answer from a reader's process");
  }
  std::memcpy(&count, in + at, sizeof(count));
  at += sizeof(count);
  if ((size - at) / sizeof(T) < count || size - at < Padded(count * sizeof(T)))
  {
    throw FileError("short answer from a reader's process");
  }
  // `in` is aligned and `at` a multiple of kAlignment: the values are T's in place.
  const T* first = reinterpret_cast<const T*>(in + at);
  AssignOnHugePages(values, first, first + count);
  at += Padded(count * sizeof(T));
}

std::size_t BytesOfCells(const Cells& cells)
{
  return BytesOf<std::uint8_t>(cells.Types.size()) + BytesOf<std::int64_t>(cells.Offsets.size()) +
    BytesOf<std::int64_t>(cells.Connectivity.size());
}

void PutCells(char*& out, const Cells& cells)
{
  Put(out, cells.Types);
  Put(out, cells.Offsets);
  Put(out, cells.Connectivity);
}

void GetCells(const char* in, std::size_t size, std::size_t& at, Cells& cells)
{
  Get(in, size, at, cells.Types);
  Get(in, size, at, cells.Offsets);
  Get(in, size, at, cells.Connectivity);
}

} // namespace

std::size_t MeshBytes(const NamedMesh& mesh)
{
  const std::size_t number = BytesOf<std::int64_t>(1);
  std::size_t bytes = number + BytesOf<double>(mesh.Points.size()) +
    BytesOf<std::int64_t>(mesh.NodeIds.size()) + BytesOfCells(mesh.Volume) + number;
  for (const NamedBoundary& boundary : mesh.Boundaries)
  {
    bytes += BytesOf<char>(boundary.Name.size()) + BytesOf<char>(boundary.Family.size()) +
      BytesOfCells(boundary.Faces);
  }
  return bytes;
}

void MeshToBytes(const NamedMesh& mesh, char* out)
{
  const std::int64_t dimension = mesh.Dimension;
  Put(out, &dimension, 1);
  Put(out, mesh.Points);
  Put(out, mesh.NodeIds);
  PutCells(out, mesh.Volume);
  const auto boundaries = static_cast<std::int64_t>(mesh.Boundaries.size());
  Put(out, &boundaries, 1);
  for (const NamedBoundary& boundary : mesh.Boundaries)
  {
    Put(out, boundary.Name.data(), boundary.Name.size());
    Put(out, boundary.Family.data(), boundary.Family.size());
    PutCells(out, boundary.Faces);
  }
}

std::string MeshToBytes(const NamedMesh& mesh)
{
  std::string out(MeshBytes(mesh), '\0');
  MeshToBytes(mesh, out.data());
  return out;
}

NamedMesh MeshFromBytes(const char* in, std::size_t size)
{
  if (reinterpret_cast<std::uintptr_t>(in) % kAlignment != 0)
  {
    // Bytes not 8-byte aligned (a short string's own buffer in some standard libraries): read
    // from an aligned copy.
    std::vector<std::uint64_t> aligned((size + kAlignment - 1) / kAlignment);
    if (size > 0)
    {
      std::memcpy(aligned.data(), in, size);
    }
    return MeshFromBytes(reinterpret_cast<const char*>(aligned.data()), size);
  }
  NamedMesh mesh;
  std::size_t at = 0;
  std::vector<std::int64_t> number;
  Get(in, size, at, number);
  mesh.Dimension = number.empty() ? 0 : static_cast<int>(number[0]);
  Get(in, size, at, mesh.Points);
  Get(in, size, at, mesh.NodeIds);
  GetCells(in, size, at, mesh.Volume);
  Get(in, size, at, number);
  const std::size_t boundaries = number.empty() ? 0 : static_cast<std::size_t>(number[0]);
  if (boundaries > size / (5 * sizeof(std::uint64_t)))
  {
    throw FileError("short answer from a reader's process"); // (each takes at least 5 counts)
  }
  mesh.Boundaries.resize(boundaries);
  for (NamedBoundary& boundary : mesh.Boundaries)
  {
    std::vector<char> name;
    Get(in, size, at, name);
    boundary.Name.assign(name.begin(), name.end());
    Get(in, size, at, name);
    boundary.Family.assign(name.begin(), name.end());
    GetCells(in, size, at, boundary.Faces);
  }
  return mesh;
}

NamedMesh MeshFromBytes(const std::string& bytes)
{
  return MeshFromBytes(bytes.data(), bytes.size());
}

} // namespace meshfile
} // namespace dgmf
