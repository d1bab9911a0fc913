#include "DGMFBoundaryDetection.h"

#include "DGMFArrayAllocation.h"
#include "DGMFFaceCells.h"
#include "DGMFFacetCounting.h"
#include "DGMFMeshConversion.h"
#include "DGMFSMPTools.h"

#include "dgmf/CellFaces.h"
#include "dgmf/CoincidentPoints.h"
#include "dgmf/FaceMatching.h"
#include "dgmf/FaceParity.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkGenericCell.h"
#include "vtkGeometryFilter.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace dgmf_vtk
{
namespace
{
/// The boundary faces from vtkGeometryFilter: any cell type, several times slower than matching.
void FindBoundaryFacesByGeometryFilter(vtkUnstructuredGrid* mesh, BoundaryFacets& facets)
{
  // The geometry filter works on a structure-only copy, so no array of the input goes through it.
  vtkNew<vtkUnstructuredGrid> structure;
  structure->CopyStructure(mesh);
  // CopyStructure keeps the ghost arrays: drop them, so that ghost cells count as cells.
  structure->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  structure->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputData(structure);
  surface->PassThroughPointIdsOn();
  surface->PassThroughCellIdsOn();
  surface->MergingOff();
  surface->Update();
  vtkPolyData* boundary = surface->GetOutput();
  vtkDataArray* ids = boundary->GetPointData()->GetArray(surface->GetOriginalPointIdsName());
  vtkDataArray* cellIds = boundary->GetCellData()->GetArray(surface->GetOriginalCellIdsName());
  // The filter may pass every point through unchanged (it did with a mesh that had ghost cells),
  // and then it writes no original-id array: the ids are the input's.
  if (!ids && boundary->GetNumberOfPoints() != mesh->GetNumberOfPoints())
  {
    return;
  }
  // Without its ghost array, the copy counts ghost cells as cells: a face between a cell
  // and a ghost cell (a partition interface) is inside. Faces of ghost cells themselves (the outer
  // side of the ghost layer) are not the mesh's boundary: they are left out.
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  std::vector<vtkIdType> original;
  auto faces = vtk::TakeSmartPointer(boundary->GetPolys()->NewIterator());
  for (faces->GoToFirstCell(); !faces->IsDoneWithTraversal(); faces->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    faces->GetCurrentCell(npts, pts);
    if (ghosts && cellIds)
    {
      // Cell data of a polydata is indexed over verts, lines, then polys.
      const vtkIdType index =
        boundary->GetNumberOfVerts() + boundary->GetNumberOfLines() + faces->GetCurrentCellId();
      if (IsGhostCell(ghosts, static_cast<vtkIdType>(cellIds->GetTuple1(index))))
      {
        continue;
      }
    }
    original.resize(static_cast<std::size_t>(npts));
    for (vtkIdType k = 0; k < npts; ++k)
    {
      original[k] = ids ? static_cast<vtkIdType>(ids->GetTuple1(pts[k])) : pts[k];
    }
    AddFacet(facets, original.data(), npts);
  }
}

/// Whether `types` (CellTypesPresent) has 2D cells, and whether they are all polygons.
void Find2DTypes(const std::array<bool, 256>& types, bool& any, bool& polygonsOnly)
{
  any = false;
  polygonsOnly = true;
  for (int type = 0; type < 256; ++type)
  {
    if (types[type] && type != VTK_EMPTY_CELL &&
      vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 2)
    {
      any = true;
      polygonsOnly = polygonsOnly && IsPolygonType(type);
    }
  }
}

/**
 * Adds the faces of `cells` that no other cell has (dgmf::FindBoundaryFaces, on the vtkSMPTools
 * threads), in the order of their cells and faces, except those of `mesh`'s ghost cells.
 */
void AddFacesOfOneCell(
  const dgmf::FaceCells& cells, vtkUnstructuredGrid* mesh, BoundaryFacets& facets)
{
  const dgmf::BoundaryFaces faces = dgmf::FindBoundaryFaces(
    cells, static_cast<std::size_t>(mesh->GetNumberOfPoints()), MakeSMPParallelFor());
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  std::vector<std::int64_t> stream;
  std::vector<vtkIdType> ids;
  for (std::size_t f = 0; f < faces.Size(); ++f)
  {
    if (IsGhostCell(ghosts, faces.Cell[f]))
    {
      continue;
    }
    cells.GetFaces(static_cast<std::size_t>(faces.Cell[f]), stream);
    std::int64_t count = 0;
    const std::int64_t* face = dgmf::FaceOfStream(stream.data(), faces.Face[f], count);
    ids.assign(face, face + count);
    AddFacet(facets, ids.data(), static_cast<vtkIdType>(count));
  }
}

/// The polygons of `mesh` as boundary facets, as they are (vtkGeometryFilter passes 2D cells
/// through), but ghost cells; point ids through `canonical` when it is not empty.
void AddPolygons(
  vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& canonical, BoundaryFacets& facets)
{
  vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray();
  std::vector<vtkIdType> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const int type = mesh->GetCellType(c);
    if (!IsPolygonType(type) || IsGhostCell(ghosts, c))
    {
      continue;
    }
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    mesh->GetCellPoints(c, npts, pts);
    ids.assign(pts, pts + npts);
    if (type == VTK_PIXEL && npts == 4)
    {
      std::swap(ids[2], ids[3]);
    }
    for (vtkIdType& id : ids)
    {
      id = canonical.empty() ? id : canonical[static_cast<std::size_t>(id)];
    }
    AddFacet(facets, ids.data(), npts);
  }
}

/**
 * The boundary faces by the core's face matching (the faces of one 3D cell), plus the grid's 2D
 * cells, as vtkGeometryFilter gives them: the faces of ghost cells left out, point ids replaced by
 * `canonical` ones when given.
 */
void FindBoundaryFacesByMatching(vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& canonical,
  bool has2DCells, BoundaryFacets& facets)
{
  AddFacesOfOneCell(VTKFaceCells(mesh, &canonical), mesh, facets);
  if (has2DCells)
  {
    AddPolygons(mesh, canonical, facets);
  }
}

/**
 * The faces of a grid's 3D cells (VTKFaceCells), and each of its polygons as one face; then each
 * polygon of `patches` (on the same points; may be null) as one face, numbered after the grid's
 * cells.
 */
class FacesAndPolygons : public dgmf::FaceCells
{
public:
  FacesAndPolygons(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches)
    : Mesh(mesh)
    , Patches(patches)
    , Faces(mesh)
    , MeshCells(static_cast<std::size_t>(mesh->GetNumberOfCells()))
  {
  }
  std::size_t GetNumberOfCells() const override
  {
    return static_cast<std::size_t>(CellsWithPatches(this->Mesh, this->Patches));
  }
  const std::int64_t* GetCornerFaces(
    std::size_t cell, std::vector<std::int64_t>& corners) const override
  {
    // Polygons: none (not a 3D shape).
    return cell < this->MeshCells ? this->Faces.GetCornerFaces(cell, corners) : nullptr;
  }
  const std::int64_t* GetCornerRun(std::size_t cell, std::size_t maxCells, const void*& ids,
    std::size_t& count, int& cornersPerCell) const override
  {
    return cell < this->MeshCells
      ? this->Faces.GetCornerRun(
          cell, std::min(maxCells, this->MeshCells - cell), ids, count, cornersPerCell)
      : nullptr;
  }
  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override
  {
    const bool ofMesh = cell < this->MeshCells;
    vtkUnstructuredGrid* grid = ofMesh ? this->Mesh : this->Patches;
    const auto id = static_cast<vtkIdType>(ofMesh ? cell : cell - this->MeshCells);
    if (!IsPolygonType(grid->GetCellType(id)))
    {
      if (ofMesh)
      {
        this->Faces.GetFaces(cell, stream);
      }
      else
      {
        stream.assign(1, 0); // a patch's empty cell: no face
      }
      return;
    }
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    thread_local vtkNew<vtkIdList> scratch; // called for every cell, on every thread
    grid->GetCells()->GetCellAtId(id, npts, pts, scratch);
    stream.assign({ 1, static_cast<std::int64_t>(npts) }); // the order of the points is no matter
    stream.insert(stream.end(), pts, pts + npts);
  }

private:
  vtkUnstructuredGrid* Mesh;
  vtkUnstructuredGrid* Patches;
  VTKFaceCells Faces;
  std::size_t MeshCells;
};

/**
 * The edges of a grid's polygons (triangles, quads, pixels, polygons) as the core's face matching
 * reads faces: each edge a 2-point face, in VTK's edge order and point order for the cell type
 * (vtkCell::GetEdge); other cells have none. Point ids through `canonical` when it is not empty.
 */
class PolygonEdgeCells : public dgmf::FaceCells
{
public:
  PolygonEdgeCells(vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& canonical)
    : Mesh(mesh)
    , Canonical(canonical)
  {
  }
  std::size_t GetNumberOfCells() const override
  {
    return static_cast<std::size_t>(this->Mesh->GetNumberOfCells());
  }
  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override
  {
    stream.assign(1, 0);
    const auto id = static_cast<vtkIdType>(cell);
    const int type = this->Mesh->GetCellType(id);
    if (!IsPolygonType(type))
    {
      return;
    }
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    thread_local vtkNew<vtkIdList> scratch; // called for every cell, on every thread
    this->Mesh->GetCells()->GetCellAtId(id, npts, pts, scratch);
    static const int pixelEdges[4][2] = { { 0, 1 }, { 1, 3 }, { 2, 3 }, { 0, 2 } };
    const auto point = [&](vtkIdType k)
    {
      const vtkIdType p = pts[k];
      return static_cast<std::int64_t>(
        this->Canonical.empty() ? p : this->Canonical[static_cast<std::size_t>(p)]);
    };
    stream[0] = npts;
    for (vtkIdType e = 0; e < npts; ++e)
    {
      const bool pixel = type == VTK_PIXEL && npts == 4;
      stream.push_back(2);
      stream.push_back(point(pixel ? pixelEdges[e][0] : e));
      stream.push_back(point(pixel ? pixelEdges[e][1] : (e + 1) % npts));
    }
  }

private:
  vtkUnstructuredGrid* Mesh;
  const std::vector<vtkIdType>& Canonical;
};

/**
 * The boundary edges of a 2D mesh of polygons by the core's face matching (edges of one polygon),
 * in the order of their cells and of VTK's edges, as FindBoundaryEdges gives them; ghost cells'
 * edges left out.
 */
void FindBoundaryEdgesByMatching(
  vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& canonical, BoundaryFacets& facets)
{
  AddFacesOfOneCell(PolygonEdgeCells(mesh, canonical), mesh, facets);
}

/**
 * The facets sorted by their point ids (lexicographically). vtkGeometryFilter's threads emit the
 * faces in an order that changes from run to run: sorted, the facets (and the sums over them, such
 * as IDW's boundary areas) are the same, bit for bit, with any number of threads. Facets with the
 * same ids are interchangeable.
 */
BoundaryFacets SortedFacets(const BoundaryFacets& facets)
{
  std::vector<std::size_t> order(facets.Size());
  for (std::size_t f = 0; f < order.size(); ++f)
  {
    order[f] = f;
  }
  const auto begin = [&](std::size_t f) { return facets.Ids.begin() + facets.Offsets[f]; };
  std::sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b)
    { return std::lexicographical_compare(begin(a), begin(a + 1), begin(b), begin(b + 1)); });
  BoundaryFacets sorted;
  sorted.Canonical = facets.Canonical;
  sorted.Ids.reserve(facets.Ids.size());
  sorted.Offsets.reserve(facets.Offsets.size());
  for (std::size_t f : order)
  {
    sorted.Ids.insert(sorted.Ids.end(), begin(f), begin(f + 1));
    sorted.Offsets.push_back(static_cast<vtkIdType>(sorted.Ids.size()));
  }
  return sorted;
}

/// The first point at each point's exact position, or an empty vector when no two points coincide.
std::vector<vtkIdType> CanonicalPointIds(vtkUnstructuredGrid* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<double> copy;
  const double* xyz = PointsAsDouble(mesh->GetPoints(), copy);
  const dgmf::UninitializedVector<std::int64_t> first =
    dgmf::FirstCoincidentPoints(xyz, static_cast<std::size_t>(n), MakeSMPParallelFor());
  for (std::size_t i = 0; i < first.size(); ++i)
  {
    if (first[i] != static_cast<std::int64_t>(i))
    {
      return std::vector<vtkIdType>(first.begin(), first.end());
    }
  }
  return std::vector<vtkIdType>();
}

/// The mesh's cells on the canonical points (same points, same cell ghost array).
vtkSmartPointer<vtkUnstructuredGrid> RenumberedCopy(
  vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& canonical)
{
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->SetPoints(mesh->GetPoints());
  // InsertNextCell grows VTK arrays, and VTK aborts when that fails: check the memory first.
  EnsureAvailableMemory(2 * static_cast<std::size_t>(mesh->GetNumberOfCells()) * 8 * 10);
  copy->Allocate(mesh->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    if (mesh->GetCellType(c) == VTK_POLYHEDRON)
    {
      vtkNew<vtkIdList> stream;
      mesh->GetFaceStream(c, stream);
      for (vtkIdType k = 1; k < stream->GetNumberOfIds();)
      {
        const vtkIdType count = stream->GetId(k++);
        for (vtkIdType m = 0; m < count; ++m, ++k)
        {
          stream->SetId(k, canonical[static_cast<std::size_t>(stream->GetId(k))]);
        }
      }
      copy->InsertNextCell(VTK_POLYHEDRON, stream);
      continue;
    }
    mesh->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      ids->SetId(k, canonical[static_cast<std::size_t>(ids->GetId(k))]);
    }
    copy->InsertNextCell(mesh->GetCellType(c), ids);
  }
  if (vtkUnsignedCharArray* ghosts = mesh->GetCellGhostArray())
  {
    copy->GetCellData()->AddArray(ghosts);
  }
  return copy;
}

/// The boundary edges of a 2D `mesh` by counting each edge's cells in a hash map (any 2D cell
/// type), on its canonical points when `facets` has them.
BoundaryFacets EdgesByCounting(vtkUnstructuredGrid* mesh, BoundaryFacets facets)
{
  FindBoundaryEdgesByCounting(
    facets.Canonical.empty() ? mesh : RenumberedCopy(mesh, facets.Canonical).Get(), facets);
  return facets;
}

/// The boundary faces of a 3D `mesh` by counting each face's cells (any cell type), on its
/// canonical points when `facets` has them, sorted.
BoundaryFacets FacesByCounting(vtkUnstructuredGrid* mesh, BoundaryFacets facets)
{
  FindBoundaryFacesByCounting(
    facets.Canonical.empty() ? mesh : RenumberedCopy(mesh, facets.Canonical).Get(), facets);
  return SortedFacets(facets);
}

/// The boundary faces of `mesh` from vtkGeometryFilter, on its canonical points when `facets` has
/// them, sorted.
BoundaryFacets FacetsByGeometryFilter(vtkUnstructuredGrid* mesh, BoundaryFacets facets)
{
  FindBoundaryFacesByGeometryFilter(
    facets.Canonical.empty() ? mesh : RenumberedCopy(mesh, facets.Canonical).Get(), facets);
  return SortedFacets(facets);
}
} // namespace

BoundaryFacets FindBoundaryFacets(vtkUnstructuredGrid* mesh, int dimension, bool distinctPoints)
{
  BoundaryFacets facets;
  if (!distinctPoints) // a merged composite input has no two points at the same place
  {
    facets.Canonical = CanonicalPointIds(mesh);
  }
  const std::array<bool, 256> types = CellTypesPresent(mesh);
  bool has2DCells = false;
  bool polygonsOnly = true;
  Find2DTypes(types, has2DCells, polygonsOnly);
  if (dimension == 2)
  {
    if (polygonsOnly) // quadratic cells' edges have mid-edge nodes: counted the VTK way
    {
      FindBoundaryEdgesByMatching(mesh, facets.Canonical, facets);
      return facets;
    }
    return EdgesByCounting(mesh, std::move(facets));
  }
  if (!VTKFaceCells::CoversAll3DCells(types) || !polygonsOnly)
  {
    return FacesByCounting(mesh, std::move(facets));
  }
  FindBoundaryFacesByMatching(mesh, facets.Canonical, has2DCells, facets);
  return SortedFacets(facets);
}

BoundaryFacets FindBoundaryFacetsByGeometryFilter(
  vtkUnstructuredGrid* mesh, int dimension, bool distinctPoints)
{
  BoundaryFacets facets;
  if (!distinctPoints)
  {
    facets.Canonical = CanonicalPointIds(mesh);
  }
  return dimension == 2 ? EdgesByCounting(mesh, std::move(facets))
                        : FacetsByGeometryFilter(mesh, std::move(facets));
}

BoundaryFacets FindBoundaryFacets(
  vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches, int dimension, bool distinctPoints)
{
  BoundaryFacets facets = FindBoundaryFacets(mesh, dimension, distinctPoints);
  if (!patches || dimension != 3 || patches->GetNumberOfCells() == 0)
  {
    return facets;
  }
  AddPolygons(patches, facets.Canonical, facets);
  return SortedFacets(facets);
}

bool PolygonsCloseTheMesh(vtkUnstructuredGrid* mesh)
{
  return PolygonsCloseTheMesh(mesh, nullptr);
}

bool PolygonsCloseTheMesh(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches)
{
  std::array<bool, 256> types = CellTypesPresent(mesh);
  const std::array<bool, 256> patchTypes =
    patches ? CellTypesPresent(patches) : std::array<bool, 256>{};
  bool has2DCells = false;
  bool polygonsOnly = true;
  for (int type = 0; type < 256; ++type)
  {
    types[type] = types[type] || patchTypes[type];
  }
  Find2DTypes(types, has2DCells, polygonsOnly);
  if (!has2DCells || !polygonsOnly || !VTKFaceCells::CoversAll3DCells(types) ||
    mesh->GetCellGhostArray())
  {
    return false;
  }
  return dgmf::FacesPairUp(FacesAndPolygons(mesh, patches),
    static_cast<std::size_t>(mesh->GetNumberOfPoints()), MakeSMPParallelFor());
}

} // namespace dgmf_vtk
