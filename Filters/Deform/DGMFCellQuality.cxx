#include "DGMFCellQuality.h"

#include "DGMFArrayAllocation.h"
#include "DGMFTupleAllocation.h"

#include "DGMFMeshConversion.h"

#include "dgmf/CellFaces.h"
#include "dgmf/DecomposedSizeSkew.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/Simd.h"

#include "vtkPoints.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace dgmf_vtk
{
namespace
{
/// The corners of a cell judged through its faces, and its face stream in local corner numbers.
struct FacedCell
{
  std::vector<double> Original, Deformed;
  std::vector<std::int64_t> Faces;

  /// Gathers the corners `ids` (count of them) of the two point arrays.
  void Gather(const vtkIdType* ids, vtkIdType count, const double* original, const double* deformed)
  {
    this->Original.resize(3 * static_cast<std::size_t>(count));
    this->Deformed.resize(3 * static_cast<std::size_t>(count));
    for (vtkIdType k = 0; k < count; ++k)
    {
      const auto p = static_cast<std::size_t>(ids[k]);
      std::copy(original + 3 * p, original + 3 * p + 3, &this->Original[3 * k]);
      std::copy(deformed + 3 * p, deformed + 3 * p + 3, &this->Deformed[3 * k]);
    }
  }

  /// A polyhedron's face stream (VTK's, without the number of faces) in local corner numbers.
  bool SetPolyhedronFaces(
    const vtkIdType* ids, vtkIdType count, vtkIdType faces, const vtkIdType* stream)
  {
    this->Faces.assign(1, faces);
    for (vtkIdType f = 0, at = 0; f < faces; ++f)
    {
      const vtkIdType n = stream[at++];
      this->Faces.push_back(n);
      for (vtkIdType k = 0; k < n; ++k, ++at)
      {
        const vtkIdType* local = std::find(ids, ids + count, stream[at]);
        if (local == ids + count)
        {
          return false;
        }
        this->Faces.push_back(local - ids);
      }
    }
    return faces > 0;
  }

  /// A polygon: one face, its corners in order.
  void SetPolygon(vtkIdType count)
  {
    this->Faces.assign({ 1, count });
    for (vtkIdType k = 0; k < count; ++k)
    {
      this->Faces.push_back(k);
    }
  }

  dgmf::CellQuality Quality() const
  {
    return dgmf::ComputeDecomposedSizeSkew(static_cast<int>(this->Original.size() / 3),
      this->Original.data(), this->Deformed.data(), this->Faces.data());
  }
};
/// How many cells ahead the quality asks for a cell's corners (the first 8 of them).
constexpr std::size_t CornersAhead = 4;

/// The `corners` corners of a cell (ids `pts` in VTK's order, read in the metric's `order`) from
/// `points` (3 doubles each) into `out`.
void GatherCorners(
  int corners, const vtkIdType* pts, const int* order, const double* points, double* out)
{
  for (int k = 0; k < corners; ++k)
  {
    const double* p = points + 3 * static_cast<std::size_t>(pts[order[k]]);
    out[3 * k] = p[0];
    out[3 * k + 1] = p[1];
    out[3 * k + 2] = p[2];
  }
}

/**
 * Hexahedra gathered from a block of cells and evaluated together
 * (dgmf::ComputeHexSizeSkewInGroups, four at a time): their deformed corners, and their original
 * corners only when the reference sizes are to be computed, written straight into the metric's
 * vector layout.
 */
struct HexBatch
{
  static constexpr int Capacity = 64;
  std::size_t Cells[Capacity];
  alignas(64) double Original[Capacity / 4 * dgmf::kHexGroupDoubles];
  alignas(64) double Deformed[Capacity / 4 * dgmf::kHexGroupDoubles];
  double Reference[Capacity];
  dgmf::CellQuality Quality[Capacity];
  int Count = 0;

  /// Adds cell `c` (corner ids `pts` in VTK's order, read in the metric's `order`); true when full.
  bool Add(std::size_t c, const vtkIdType* pts, const int* order, const double* originalPoints,
    const double* deformedPoints, bool withOriginal)
  {
    const auto slot = static_cast<std::size_t>(this->Count);
    for (int k = 0; k < 8; ++k)
    {
      const auto point = 3 * static_cast<std::size_t>(pts[order[k]]);
      dgmf::StoreHexGroupCorner(this->Deformed, slot, k, deformedPoints + point);
      if (withOriginal)
      {
        dgmf::StoreHexGroupCorner(this->Original, slot, k, originalPoints + point);
      }
    }
    this->Cells[this->Count++] = c;
    return this->Count == Capacity;
  }
};
} // namespace

dgmf::QualitySummary ComputeCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDoubleArray* sizeSkew, vtkUnsignedCharArray* inverted,
  vtkUnsignedCharArray* inputInvalid, const HexReferences& references,
  const dgmf::ParallelFor& parallelFor)
{
  const vtkIdType numberOfCells = mesh->GetNumberOfCells();
  // An array kept from the last execution with as many values is written in place (its pages
  // are mapped already: every value is written below). New memory, and the hexahedra's reference
  // sizes when they are to be computed, is faulted in first, in parts on the threads: the
  // kernel's MADV_POPULATE_WRITE costs less than the page faults of the writes would
  // (dgmf::FirstTouch).
  std::vector<dgmf::FirstTouchPart> newMemory;
  for (vtkDataArray* array :
    std::initializer_list<vtkDataArray*>{ sizeSkew, inverted, inputInvalid })
  {
    if (array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != numberOfCells ||
      numberOfCells == 0)
    {
      array->SetNumberOfComponents(1);
      AllocateTuples(array, numberOfCells);
      dgmf::AppendFirstTouchParts(array->GetVoidPointer(0),
        static_cast<std::size_t>(numberOfCells) *
          static_cast<std::size_t>(array->GetDataTypeSize()),
        newMemory);
    }
  }
  if (references.Sizes && !references.Known)
  {
    dgmf::AppendFirstTouchParts(
      references.Sizes, static_cast<std::size_t>(numberOfCells) * sizeof(double), newMemory);
  }
  dgmf::FirstTouchParts(newMemory, parallelFor);
  double* values = sizeSkew->GetPointer(0);
  unsigned char* flags = inverted->GetPointer(0);
  unsigned char* invalid = inputInvalid->GetPointer(0);
  vtkCellArray* cells = mesh->GetCells();
  const unsigned char* types = mesh->GetCellTypesArray()->GetPointer(0);
  // 64-bit cell storage (VTK's default) is read in place, without a call per cell.
  const bool direct =
    sizeof(vtkIdType) == 8 && cells && cells->IsStorage64Bit() && numberOfCells > 0;
  const vtkTypeInt64* directOffsets = direct ? cells->GetOffsetsArray64()->GetPointer(0) : nullptr;
  const auto* directConnectivity = direct
    ? reinterpret_cast<const vtkIdType*>(cells->GetConnectivityArray64()->GetPointer(0))
    : nullptr;
  const auto write = [&](std::size_t c, const dgmf::CellQuality& quality)
  {
    values[c] = quality.SizeSkew;
    flags[c] = quality.Inverted ? 1 : 0;
    invalid[c] = quality.InputInvalid ? 1 : 0;
  };

  // The cell types present, noted on the way (a serial pass over the types would cost a tenth of
  // the metric on a large hexahedral mesh).
  std::array<bool, 256> present{};
  std::mutex presentMutex;

  parallelFor(0, static_cast<std::size_t>(numberOfCells), 4096,
    [&](std::size_t begin, std::size_t end)
    {
      std::array<bool, 256> blockPresent{};
      vtkNew<vtkIdList> scratch;
      FacedCell faced;
      double original[8 * 3];
      double deformed[8 * 3];
      // Hexahedra go by batches: the original corners are read only when their reference sizes
      // are not known.
      // Not value-initialized (make_unique would zero its 27 KB for every block of cells).
      const std::unique_ptr<HexBatch> batch(new HexBatch);
      const bool knownReferences = references.Known && references.Sizes;
      const auto evaluate = [&]()
      {
        HexBatch& b = *batch;
        const auto count = static_cast<std::size_t>(b.Count);
        if (knownReferences)
        {
          for (std::size_t i = 0; i < count; ++i)
          {
            b.Reference[i] = references.Sizes[b.Cells[i]];
          }
        }
        else
        {
          dgmf::ComputeHexReferenceSizesInGroups(count, b.Original, b.Reference);
          if (references.Sizes)
          {
            for (std::size_t i = 0; i < count; ++i)
            {
              references.Sizes[b.Cells[i]] = b.Reference[i];
            }
          }
        }
        dgmf::ComputeHexSizeSkewInGroups(count, b.Reference, b.Deformed, b.Quality);
        for (std::size_t i = 0; i < count; ++i)
        {
          if (b.Quality[i].InputInvalid) // non-convex before the deformation: through its faces
          {
            vtkIdType npts;
            const vtkIdType* pts;
            dgmf::CellShape shape;
            const int* order;
            CellShapeOf(types[b.Cells[i]], shape, order);
            cells->GetCellAtId(static_cast<vtkIdType>(b.Cells[i]), npts, pts, scratch);
            GatherCorners(8, pts, order, originalPoints, original);
            dgmf::LoadHexGroupCell(b.Deformed, i, deformed);
            b.Quality[i] = dgmf::JudgeInvalidInputCell(shape, original, deformed);
          }
          write(b.Cells[i], b.Quality[i]);
        }
        b.Count = 0;
      };
      for (std::size_t c = begin; c < end; ++c)
      {
        const auto cellId = static_cast<vtkIdType>(c);
        dgmf::CellShape shape;
        const int* order;
        vtkIdType npts;
        const vtkIdType* pts;
        blockPresent[types[c]] = true;
        const bool standard = CellShapeOf(types[c], shape, order);
        if (direct)
        {
          npts = static_cast<vtkIdType>(directOffsets[c + 1] - directOffsets[c]);
          pts = directConnectivity + directOffsets[c];
          // The corners of the cell CornersAhead cells on: in an unstructured mesh they lie
          // anywhere, and each would be a wait (the wing-body's quality 0.07 - 0.2 -> 0.05 s).
          if (c + CornersAhead < end)
          {
            const std::size_t next = c + CornersAhead;
            const vtkIdType* ahead = directConnectivity + directOffsets[next];
            const vtkIdType n =
              std::min<vtkIdType>(8, directOffsets[next + 1] - directOffsets[next]);
            const bool original = !(knownReferences && types[next] == VTK_HEXAHEDRON);
            for (vtkIdType k = 0; k < n; ++k)
            {
              dgmf::simd::Prefetch(deformedPoints + 3 * ahead[k]);
              if (original)
              {
                dgmf::simd::Prefetch(originalPoints + 3 * ahead[k]);
              }
            }
          }
        }
        else
        {
          cells->GetCellAtId(cellId, npts, pts, scratch);
        }
        if (!standard || npts < dgmf::GetNumberOfCorners(shape))
        {
          // Polyhedra and polygons through their faces; other cells (quadratic) are not covered.
          vtkIdType faces = 0;
          const vtkIdType* stream = nullptr;
          bool covered = false;
          if (types[c] == VTK_POLYHEDRON)
          {
            mesh->GetFaceStream(cellId, faces, stream);
            covered = faced.SetPolyhedronFaces(pts, npts, faces, stream);
          }
          else if (types[c] == VTK_POLYGON && npts >= 3)
          {
            faced.SetPolygon(npts);
            covered = true;
          }
          if (covered)
          {
            faced.Gather(pts, npts, originalPoints, deformedPoints);
            const dgmf::CellQuality quality = faced.Quality();
            write(c, { quality.SizeSkew, quality.Inverted, false });
          }
          else
          {
            write(c, { std::numeric_limits<double>::quiet_NaN(), false, false });
          }
          continue;
        }
        if (shape == dgmf::CellShape::Hexahedron)
        {
          if (batch->Add(c, pts, order, originalPoints, deformedPoints, !knownReferences))
          {
            evaluate();
          }
          continue;
        }
        const int corners = dgmf::GetNumberOfCorners(shape);
        GatherCorners(corners, pts, order, originalPoints, original);
        GatherCorners(corners, pts, order, deformedPoints, deformed);
        write(c, dgmf::ComputeCellSizeSkew(shape, original, deformed));
      }
      evaluate();
      const std::lock_guard<std::mutex> lock(presentMutex);
      for (int type = 0; type < 256; ++type)
      {
        present[type] = present[type] || blockPresent[type];
      }
    });
  // Left out of the summary, though evaluated: ghost cells (counted by their owner), and cells of
  // a lower dimension than the mesh's (the boundary faces a reader gives with the volume, as the
  // OpenFOAM, gmsh and SU2 readers do): the summary is the volume mesh's.
  // The dimension of each cell type present, asked of VTK once per type (it complains about types
  // it does not know).
  std::array<std::int8_t, 256> dimensionOf;
  dimensionOf.fill(-1);
  std::int8_t meshDimension = 0;
  for (int type = 0; type < 256; ++type)
  {
    if (present[type])
    {
      dimensionOf[type] = static_cast<std::int8_t>(vtkCellTypes::GetDimension(type));
      meshDimension = std::max(meshDimension, dimensionOf[type]);
    }
  }
  bool lowerDimension = false;
  for (int type = 0; type < 256; ++type)
  {
    lowerDimension = lowerDimension || (present[type] && dimensionOf[type] < meshDimension);
  }
  std::vector<std::uint8_t> skip;
  const unsigned char* ghosts =
    mesh->GetCellGhostArray() ? mesh->GetCellGhostArray()->GetPointer(0) : nullptr;
  for (vtkIdType c = 0; (ghosts || lowerDimension) && c < numberOfCells; ++c)
  {
    if ((ghosts && (ghosts[c] & vtkDataSetAttributes::DUPLICATECELL) != 0) ||
      dimensionOf[types[c]] < meshDimension)
    {
      skip.resize(static_cast<std::size_t>(numberOfCells), 0);
      skip[static_cast<std::size_t>(c)] = 1;
    }
  }
  return dgmf::SummarizeQuality(values, flags, static_cast<std::size_t>(numberOfCells),
    skip.empty() ? nullptr : skip.data(), invalid);
}

} // namespace dgmf_vtk
