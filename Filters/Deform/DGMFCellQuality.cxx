#include "DGMFCellQuality.h"

#include "DGMFArrayAllocation.h"

#include "DGMFMeshConversion.h"

#include "dgmf/CellFaces.h"
#include "dgmf/DecomposedSizeSkew.h"

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
#include <limits>
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
} // namespace

dgmf::QualitySummary ComputeCellQuality(vtkUnstructuredGrid* mesh, const double* originalPoints,
  const double* deformedPoints, vtkDoubleArray* sizeSkew, vtkUnsignedCharArray* inverted,
  vtkUnsignedCharArray* inputInvalid, const dgmf::ParallelFor& parallelFor)
{
  const vtkIdType numberOfCells = mesh->GetNumberOfCells();
  sizeSkew->SetNumberOfComponents(1);
  AllocateTuples(sizeSkew, numberOfCells);
  inverted->SetNumberOfComponents(1);
  AllocateTuples(inverted, numberOfCells);
  inputInvalid->SetNumberOfComponents(1);
  AllocateTuples(inputInvalid, numberOfCells);
  double* values = sizeSkew->GetPointer(0);
  unsigned char* flags = inverted->GetPointer(0);
  unsigned char* invalid = inputInvalid->GetPointer(0);
  vtkCellArray* cells = mesh->GetCells();
  const unsigned char* types = mesh->GetCellTypesArray()->GetPointer(0);

  parallelFor(0, static_cast<std::size_t>(numberOfCells), 4096,
    [&](std::size_t begin, std::size_t end)
    {
      vtkNew<vtkIdList> scratch;
      FacedCell faced;
      // Hexahedra go by two (ComputeHexSizeSkewPair, the same bits): `pending` is one waiting
      // for its partner, its corners in the second half of the buffers.
      double original[2][8 * 3];
      double deformed[2][8 * 3];
      std::size_t pending = end;
      for (std::size_t c = begin; c < end; ++c)
      {
        const auto cellId = static_cast<vtkIdType>(c);
        dgmf::CellShape shape;
        const int* order;
        vtkIdType npts;
        const vtkIdType* pts;
        invalid[c] = 0;
        const bool standard = CellShapeOf(types[c], shape, order);
        cells->GetCellAtId(cellId, npts, pts, scratch);
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
            values[c] = quality.SizeSkew;
            flags[c] = quality.Inverted ? 1 : 0;
          }
          else
          {
            values[c] = std::numeric_limits<double>::quiet_NaN();
            flags[c] = 0;
          }
          continue;
        }
        const int corners = dgmf::GetNumberOfCorners(shape);
        const bool hexahedron = shape == dgmf::CellShape::Hexahedron;
        const int slot = hexahedron && pending == end ? 1 : 0;
        for (int k = 0; k < corners; ++k)
        {
          const auto p = static_cast<std::size_t>(pts[order[k]]);
          for (int d = 0; d < 3; ++d)
          {
            original[slot][3 * k + d] = originalPoints[3 * p + d];
            deformed[slot][3 * k + d] = deformedPoints[3 * p + d];
          }
        }
        dgmf::CellQuality quality;
        if (!hexahedron)
        {
          quality = dgmf::ComputeCellSizeSkew(shape, original[0], deformed[0]);
        }
        else if (slot == 1)
        {
          pending = c;
          continue;
        }
        else
        {
          dgmf::CellQuality first;
          dgmf::ComputeHexSizeSkewPair(
            original[1], deformed[1], original[0], deformed[0], first, quality);
          if (first.InputInvalid) // non-convex before the deformation: through its faces
          {
            first = dgmf::JudgeInvalidInputCell(shape, original[1], deformed[1]);
          }
          if (quality.InputInvalid)
          {
            quality = dgmf::JudgeInvalidInputCell(shape, original[0], deformed[0]);
          }
          values[pending] = first.SizeSkew;
          flags[pending] = first.Inverted ? 1 : 0;
          invalid[pending] = first.InputInvalid ? 1 : 0;
          pending = end;
        }
        values[c] = quality.SizeSkew;
        flags[c] = quality.Inverted ? 1 : 0;
        invalid[c] = quality.InputInvalid ? 1 : 0;
      }
      if (pending < end)
      {
        const dgmf::CellQuality last =
          dgmf::ComputeCellSizeSkew(dgmf::CellShape::Hexahedron, original[1], deformed[1]);
        values[pending] = last.SizeSkew;
        flags[pending] = last.Inverted ? 1 : 0;
        invalid[pending] = last.InputInvalid ? 1 : 0;
      }
    });
  // Left out of the summary, though evaluated: ghost cells (counted by their owner), and cells of
  // a lower dimension than the mesh's (the boundary faces a reader gives with the volume, as the
  // OpenFOAM, gmsh and SU2 readers do): the summary is the volume mesh's.
  // The dimension of each cell type present, asked of VTK once per type (it complains about types
  // it does not know).
  std::array<std::int8_t, 256> dimensionOf;
  dimensionOf.fill(-1);
  std::array<bool, 256> seen{};
  std::int8_t meshDimension = 0;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    if (!seen[types[c]])
    {
      seen[types[c]] = true;
      dimensionOf[types[c]] = static_cast<std::int8_t>(vtkCellTypes::GetDimension(types[c]));
      meshDimension = std::max(meshDimension, dimensionOf[types[c]]);
    }
  }
  std::vector<std::uint8_t> skip;
  const unsigned char* ghosts =
    mesh->GetCellGhostArray() ? mesh->GetCellGhostArray()->GetPointer(0) : nullptr;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
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
