#include "DGMFMeshConversion.h"

#include "DGMFArrayAllocation.h"
#include "DGMFSMPTools.h"

#include "dgmf/HintStride.h"
#include "dgmf/ResultNames.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

namespace dgmf_vtk
{
namespace
{
/// Cells per block of the scans of the cell types on the threads.
constexpr std::size_t CellTypeBlock = std::size_t(1) << 18;
} // namespace

const double* PointsAsDouble(vtkPoints* points, std::vector<double>& copy)
{
  if (!points)
  {
    copy.clear(); // a data set without points (an empty block of a composite input)
    return copy.data();
  }
  auto* doubles = vtkDoubleArray::SafeDownCast(points->GetData());
  if (doubles && doubles->GetNumberOfComponents() == 3)
  {
    return doubles->GetPointer(0);
  }
  const vtkIdType n = points->GetNumberOfPoints();
  copy.resize(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, copy.data() + 3 * i);
  }
  return copy.data();
}

bool CellShapeOf(int vtkCellType, dgmf::CellShape& shape, const int*& order)
{
  static const int identity[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  static const int pixel[4] = { 0, 1, 3, 2 };
  static const int voxel[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  order = identity;
  switch (vtkCellType)
  {
    case VTK_TRIANGLE:
      shape = dgmf::CellShape::Triangle;
      return true;
    case VTK_QUAD:
      shape = dgmf::CellShape::Quad;
      return true;
    case VTK_PIXEL:
      shape = dgmf::CellShape::Quad;
      order = pixel;
      return true;
    case VTK_TETRA:
      shape = dgmf::CellShape::Tetra;
      return true;
    case VTK_HEXAHEDRON:
      shape = dgmf::CellShape::Hexahedron;
      return true;
    case VTK_VOXEL:
      shape = dgmf::CellShape::Hexahedron;
      order = voxel;
      return true;
    case VTK_WEDGE:
      shape = dgmf::CellShape::Wedge;
      return true;
    case VTK_PYRAMID:
      shape = dgmf::CellShape::Pyramid;
      return true;
    default:
      return false;
  }
}

vtkSmartPointer<vtkUnstructuredGrid> AsUnstructuredGrid(vtkPointSet* points)
{
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(points))
  {
    return grid;
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points->GetPoints());
  // InsertNextCell grows VTK arrays, and VTK aborts when that fails: check the memory first.
  EnsureAvailableMemory(2 * static_cast<std::size_t>(points->GetNumberOfCells()) * 8 * 10);
  grid->Allocate(points->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < points->GetNumberOfCells(); ++c)
  {
    points->GetCellPoints(c, ids);
    grid->InsertNextCell(points->GetCellType(c), ids);
  }
  return grid;
}

std::array<bool, 256> CellTypesPresent(vtkUnstructuredGrid* mesh)
{
  vtkUnsignedCharArray* types = mesh->GetCellTypesArray();
  const auto n = static_cast<std::size_t>(types ? types->GetNumberOfValues() : 0);
  const unsigned char* values = n > 0 ? types->GetPointer(0) : nullptr;
  const std::size_t blocks = (n + CellTypeBlock - 1) / CellTypeBlock;
  std::vector<std::array<bool, 256>> perBlock(blocks);
  dgmf::ForEachBlock(MakeSMPParallelFor(), blocks,
    [&](std::size_t block)
    {
      std::array<bool, 256> present{};
      const std::size_t end = std::min(n, (block + 1) * CellTypeBlock);
      for (std::size_t c = block * CellTypeBlock; c < end;)
      {
        // A run of one type (as a rule, all the cells of a mesh), skipped 8 bytes at a time.
        const unsigned char type = values[c];
        present[type] = true;
        const std::uint64_t eight = 0x0101010101010101ull * type;
        std::uint64_t word;
        while (c + 8 <= end && (std::memcpy(&word, values + c, 8), word == eight))
        {
          c += 8;
        }
        while (c < end && values[c] == type)
        {
          ++c;
        }
      }
      perBlock[block] = present;
    });
  std::array<bool, 256> present{};
  for (const std::array<bool, 256>& block : perBlock)
  {
    for (int type = 0; type < 256; ++type)
    {
      present[type] = present[type] || block[type];
    }
  }
  return present;
}

bool IsPolygonType(int vtkCellType)
{
  return vtkCellType == VTK_TRIANGLE || vtkCellType == VTK_QUAD || vtkCellType == VTK_PIXEL ||
    vtkCellType == VTK_POLYGON;
}

std::array<bool, 256> CellTypesOf(vtkPointSet* block)
{
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(block))
  {
    return CellTypesPresent(grid);
  }
  std::array<bool, 256> present{};
  vtkNew<vtkCellTypes> types;
  block->GetCellTypes(types);
  for (vtkIdType k = 0; k < types->GetNumberOfTypes(); ++k)
  {
    present[types->GetCellType(k)] = true;
  }
  return present;
}

int CellDimensionOf(const std::array<bool, 256>& types, bool& polygonsOnly)
{
  int dimension = 0;
  polygonsOnly = true;
  for (int type = 0; type < 256; ++type)
  {
    if (types[type] && type != VTK_EMPTY_CELL)
    {
      dimension = std::max(dimension, vtkCellTypes::GetDimension(static_cast<unsigned char>(type)));
      polygonsOnly = polygonsOnly && IsPolygonType(type);
    }
  }
  return dimension;
}

vtkIdType CellsWithPatches(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches)
{
  return mesh->GetNumberOfCells() + (patches ? patches->GetNumberOfCells() : 0);
}

std::vector<vtkIdType> CellsOfTypes(vtkUnstructuredGrid* mesh, const std::array<bool, 256>& wanted)
{
  if (std::none_of(wanted.begin(), wanted.end(), [](bool type) { return type; }))
  {
    return {};
  }
  vtkUnsignedCharArray* types = mesh->GetCellTypesArray();
  const auto n = static_cast<std::size_t>(types ? types->GetNumberOfValues() : 0);
  const unsigned char* values = n > 0 ? types->GetPointer(0) : nullptr;
  const std::size_t blocks = (n + CellTypeBlock - 1) / CellTypeBlock;
  std::vector<std::vector<vtkIdType>> perBlock(blocks);
  dgmf::ForEachBlock(MakeSMPParallelFor(), blocks,
    [&](std::size_t block)
    {
      for (std::size_t c = block * CellTypeBlock; c < std::min(n, (block + 1) * CellTypeBlock); ++c)
      {
        if (wanted[values[c]])
        {
          perBlock[block].push_back(static_cast<vtkIdType>(c));
        }
      }
    });
  std::vector<vtkIdType> cells;
  for (const std::vector<vtkIdType>& block : perBlock)
  {
    cells.insert(cells.end(), block.begin(), block.end());
  }
  return cells;
}

dgmf::CellMesh ToCellMesh(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches)
{
  dgmf::CellMesh cells;
  cells.NumberOfPoints = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  cells.Offsets.push_back(0);
  vtkNew<vtkIdList> ids;
  for (vtkUnstructuredGrid* grid : { mesh, patches })
  {
    for (vtkIdType c = 0; grid && c < grid->GetNumberOfCells(); ++c)
    {
      grid->GetCellPoints(c, ids);
      dgmf::CellShape shape = dgmf::CellShape::Triangle;
      const int* order = nullptr;
      const bool covered = CellShapeOf(grid->GetCellType(c), shape, order);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        cells.Connectivity.push_back(ids->GetId(covered && k < 8 ? order[k] : k));
      }
      cells.Offsets.push_back(static_cast<std::int64_t>(cells.Connectivity.size()));
      cells.Shapes.push_back(shape);
      cells.Covered.push_back(covered ? 1 : 0);
    }
  }
  return cells;
}

int DetectDimension(vtkUnstructuredGrid* mesh, const double* xyz, std::size_t n)
{
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const int type = mesh->GetCellType(c);
    if (type != VTK_EMPTY_CELL && vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 3)
    {
      return 3;
    }
  }
  // Non-finite coordinates are left to the core's check (which names them). The z of a plane
  // z = constant may carry round-off (a 2D mesh turned into it by a transform, single-precision
  // points): a spread of PlanarZTolerance of the x-y extent is allowed.
  double low[3], high[3];
  std::fill(low, low + 3, std::numeric_limits<double>::infinity());
  std::fill(high, high + 3, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double x = xyz[3 * i + static_cast<std::size_t>(c)];
      if (std::isfinite(x))
      {
        low[c] = std::min(low[c], x);
        high[c] = std::max(high[c], x);
      }
    }
  }
  if (high[2] > low[2] &&
    high[2] - low[2] > PlanarZTolerance * std::hypot(high[0] - low[0], high[1] - low[1]))
  {
    return -1;
  }
  return 2;
}

namespace
{
/// The cell types present in a mesh that are of its largest cell dimension, and whether it has
/// cells of other types (another dimension, or empty cells).
struct LargestDimensionTypes
{
  std::array<bool, 256> Types{};
  bool Others = false;
};

LargestDimensionTypes TypesOfLargestDimension(vtkUnstructuredGrid* mesh)
{
  const std::array<bool, 256> present = CellTypesPresent(mesh);
  bool polygons = false;
  const int largest = CellDimensionOf(present, polygons);
  LargestDimensionTypes types;
  for (int type = 0; type < 256; ++type)
  {
    types.Types[type] = present[type] && type != VTK_EMPTY_CELL &&
      vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == largest;
    types.Others = types.Others || (present[type] && !types.Types[type]);
  }
  return types;
}
} // namespace

vtkIdType CountBadCellsOutsideTheGuard(
  vtkUnstructuredGrid* mesh, vtkDataArray* sizeSkew, double threshold)
{
  if (!sizeSkew || sizeSkew->GetNumberOfTuples() != mesh->GetNumberOfCells())
  {
    return 0;
  }
  // The types of the mesh's dimension that the guard does not see (no CellShapeOf).
  std::array<bool, 256> unguarded = TypesOfLargestDimension(mesh).Types;
  bool any = false;
  for (int type = 0; type < 256; ++type)
  {
    dgmf::CellShape shape;
    const int* order = nullptr;
    unguarded[type] = unguarded[type] && !CellShapeOf(type, shape, order);
    any = any || unguarded[type];
  }
  vtkIdType count = 0;
  for (vtkIdType c = 0; any && c < mesh->GetNumberOfCells(); ++c)
  {
    count += unguarded[mesh->GetCellType(c)] && sizeSkew->GetTuple1(c) < threshold ? 1 : 0;
  }
  return count;
}

std::string CountUnguardedCellsAsUnrepaired(vtkUnstructuredGrid* output, double threshold)
{
  vtkDataArray* unrepaired = output->GetFieldData()->GetArray(dgmf::names::UnrepairedCellCount);
  if (!unrepaired || unrepaired->GetNumberOfTuples() < 1)
  {
    return "";
  }
  const vtkIdType outside = CountBadCellsOutsideTheGuard(
    output, output->GetCellData()->GetArray(dgmf::names::SizeSkew), threshold);
  unrepaired->SetTuple1(0, unrepaired->GetTuple1(0) + static_cast<double>(outside));
  return outside == 0 ? ""
                      : std::to_string(outside) +
      " polyhedra or polygons have a SizeSkew below the Repair Threshold: the quality guard "
      "does not move their nodes (counted in UnrepairedCellCount).";
}

vtkIdType CountCellsOfLargestDimension(vtkUnstructuredGrid* mesh)
{
  const LargestDimensionTypes largest = TypesOfLargestDimension(mesh);
  const std::array<bool, 256>& counted = largest.Types;
  // Any type of another dimension, empty cells included: count the cells one by one.
  if (!largest.Others)
  {
    return mesh->GetNumberOfCells();
  }
  vtkIdType count = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    count += counted[mesh->GetCellType(c)] ? 1 : 0;
  }
  return count;
}

std::size_t HintStrideOf(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches)
{
  const vtkIdType meshCells = mesh->GetNumberOfCells();
  const vtkIdType cells = CellsWithPatches(mesh, patches);
  const vtkIdType samples = std::min<vtkIdType>(cells, 4096);
  std::vector<std::vector<std::int64_t>> sampled;
  sampled.reserve(static_cast<std::size_t>(samples));
  for (vtkIdType s = 0; s < samples; ++s)
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    const vtkIdType c = s * cells / samples;
    if (c < meshCells)
    {
      mesh->GetCellPoints(c, count, ids);
    }
    else
    {
      patches->GetCellPoints(c - meshCells, count, ids);
    }
    sampled.emplace_back(ids, ids + count);
  }
  return dgmf::FindHintStride(sampled);
}

} // namespace dgmf_vtk
