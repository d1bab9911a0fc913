// The gatherer's part that finds the mesh's own boundary (InputGatherer, DGMFInputNodes.h): the
// boundary facets of the cells (kept while the cells are the same), the nodes on them, whether
// the roles' patches close the mesh, and the slip edges on a boundary no block was read for.
#include "DGMFInputNodes.h"

#include "DGMFBoundaryDetection.h"
#include "DGMFBoundaryNodes.h"
#include "DGMFContentKey.h"
#include "DGMFMeshConversion.h"

#include "vtkCellArray.h"
#include "vtkCellTypes.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <iterator>

namespace dgmf_vtk
{

std::vector<std::uint8_t> InputGatherer::FlagMeshBoundary(
  vtkUnstructuredGrid* mesh, const InputNodes& nodes)
{
  const std::size_t n = nodes.NumberOfNodes;
  this->Searched = true;
  const BoundaryFacets& facets = this->GetBoundaryFacets(mesh, nodes.Patches, nodes.Dimension);
  std::vector<std::uint8_t> flags = FlagBoundaryNodes(facets, static_cast<vtkIdType>(n));
  if (nodes.Layers.Found())
  {
    // A one-cell-thick mesh: its two planes are not boundaries, only the faces across them are.
    std::fill(flags.begin(), flags.end(), 0);
    const dgmf::ExtrudedLayers& layers = nodes.Layers;
    for (std::size_t f = 0; f < facets.Size(); ++f)
    {
      const vtkIdType* begin = facets.Ids.data() + facets.Offsets[f];
      const vtkIdType* end = facets.Ids.data() + facets.Offsets[f + 1];
      if (layers.PlaneOf(nodes.Points, begin, static_cast<std::size_t>(end - begin)) < 0)
      {
        std::for_each(begin, end, [&](vtkIdType id) { flags[static_cast<std::size_t>(id)] = 1; });
      }
    }
  }
  return flags;
}

bool InputGatherer::RolesCoverTheBoundary(vtkUnstructuredGrid* mesh, const InputNodes& nodes)
{
  if (nodes.Dimension != 3)
  {
    return false;
  }
  vtkCellArray* cells = mesh->GetCells();
  vtkUnstructuredGrid* patches = nodes.Patches;
  if (!this->ClosingCells.Matches(cells, [&]() { return HashCells(mesh); }) ||
    !this->ClosingPatches.Matches(patches))
  {
    this->ClosingPolygons.clear();
    if (PolygonsCloseTheMesh(mesh, patches))
    {
      const auto polygonsOf = [](vtkUnstructuredGrid* grid)
      {
        std::array<bool, 256> is2D = CellTypesPresent(grid);
        for (int type = 0; type < 256; ++type)
        {
          is2D[type] =
            is2D[type] && vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 2;
        }
        return CellsOfTypes(grid, is2D);
      };
      this->ClosingPolygons = polygonsOf(mesh);
      if (patches) // numbered after the mesh's cells
      {
        for (vtkIdType c : polygonsOf(patches))
        {
          this->ClosingPolygons.push_back(mesh->GetNumberOfCells() + c);
        }
      }
    }
    // The key's hash is for the next execution: computed beside the graph's insertion.
    this->ClosingCells.SetHashLater(cells);
    this->Deferred.emplace_back(
      [this, mesh]() { this->ClosingCells.SetHash(HashCells(mesh, false)); });
    this->ClosingPatches.Set(patches);
  }
  if (this->ClosingPolygons.empty())
  {
    return false;
  }
  // The polygons' nodes are the boundary's: FlagMeshBoundary would flag those that are off the
  // planes of a one-cell-thick mesh.
  const dgmf::ExtrudedLayers& layers = nodes.Layers;
  vtkNew<vtkIdList> scratch;
  const vtkIdType meshCells = mesh->GetNumberOfCells();
  for (vtkIdType c : this->ClosingPolygons)
  {
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    if (c < meshCells)
    {
      cells->GetCellAtId(c, npts, pts, scratch);
    }
    else
    {
      patches->GetCells()->GetCellAtId(c - meshCells, npts, pts, scratch);
    }
    if (layers.PlaneOf(nodes.Points, pts, static_cast<std::size_t>(npts)) >= 0)
    {
      continue;
    }
    if (std::any_of(pts, pts + npts,
          [&](vtkIdType id)
          { return nodes.Kinds[static_cast<std::size_t>(id)] == dgmf::NodeKind::Interior; }))
    {
      return false;
    }
  }
  return true;
}

void InputGatherer::MakeSlipEdgesStatic(
  vtkUnstructuredGrid* mesh, const std::vector<std::uint8_t>& unread, InputNodes& nodes)
{
  // Where a slip plane meets the boundary no block was read for, the nodes of their common edge
  // are static, as they are when that boundary is read as a static patch (static over slip): a
  // face of that boundary with a node of it and slip nodes makes them static. Otherwise the slip
  // plane lies outside the graph of the static and moving nodes, and its nodes barely move (a
  // half model read with its symmetry planes but not its far field: inverted cells until
  // 2026-11-30). The slip plane's own faces have no node of the unread boundary.
  const BoundaryFacets& facets = this->GetBoundaryFacets(mesh, nodes.Patches, nodes.Dimension);
  if (!facets.Canonical.empty() || nodes.Layers.Found() ||
    std::none_of(nodes.Kinds.begin(), nodes.Kinds.end(),
      [](dgmf::NodeKind kind) { return kind == dgmf::NodeKind::SlipBoundary; }))
  {
    return; // (coincident points, one-cell-thick layers: not done)
  }
  std::vector<vtkIdType> edge;
  for (std::size_t f = 0; f < facets.Size(); ++f)
  {
    const vtkIdType* begin = facets.Ids.data() + facets.Offsets[f];
    const vtkIdType* end = facets.Ids.data() + facets.Offsets[f + 1];
    if (std::any_of(begin, end, [&](vtkIdType id) { return unread[static_cast<std::size_t>(id)]; }))
    {
      std::copy_if(begin, end, std::back_inserter(edge),
        [&](vtkIdType id)
        { return nodes.Kinds[static_cast<std::size_t>(id)] == dgmf::NodeKind::SlipBoundary; });
    }
  }
  for (vtkIdType id : edge)
  {
    nodes.Kinds[static_cast<std::size_t>(id)] = dgmf::NodeKind::StaticBoundary;
  }
}

const BoundaryFacets& InputGatherer::GetBoundaryFacets(
  vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* patches, int dimension)
{
  vtkCellArray* cells = mesh->GetCells();
  const auto hashCells = [&]() { return HashCells(mesh); };
  if (!this->Facets || !this->Cells.Matches(cells, hashCells) ||
    !this->FacetPatches.Matches(patches))
  {
    this->Facets = std::make_unique<BoundaryFacets>(
      FindBoundaryFacets(mesh, patches, dimension, this->DistinctPoints));
    this->Cells.Set(cells, hashCells);
    this->FacetPatches.Set(patches);
  }
  return *this->Facets;
}

} // namespace dgmf_vtk
