#include "DGMFBoundaryNames.h"

#include "DGMFBoundaryNameParts.h"

#include "DGMFCompositeMesh.h"
#include "DGMFMeshConversion.h"
#include "DGMFSMPTools.h"
#include "dgmf/HugePages.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataAssembly.h"
#include "vtkDataAssemblyUtilities.h"
#include "vtkDataSet.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <fnmatch.h>
#include <map>
#include <stdexcept>

namespace dgmf_vtk
{
namespace
{
/// Rank of a role: a moving body over static over slip over nothing.
enum Rank : int
{
  None = 0,
  SlipRank = 1,
  StaticRank = 2,
  MovingRank = 3
};

/**
 * True when every cell of `leaf` lies in one of the two planes of the one-cell-thick mesh
 * `layers` (a `front`, a `back`, or one `frontAndBack` patch holding both), or, for a leaf without
 * cells, when all its points lie in one of them. A side patch (a wall between the planes) has
 * faces across both.
 */
bool InLayerPlanes(const CompositeMesh& mesh, const CompositeMesh::Leaf& leaf, const double* xyz,
  const dgmf::ExtrudedLayers& layers)
{
  if (leaf.Cells == 0)
  {
    std::vector<vtkIdType> nodes(static_cast<std::size_t>(leaf.NumberOfPoints));
    for (vtkIdType point = 0; point < leaf.NumberOfPoints; ++point)
    {
      nodes[static_cast<std::size_t>(point)] = leaf.Node(point);
    }
    return layers.PlaneOf(xyz, nodes.data(), nodes.size()) >= 0;
  }
  vtkUnstructuredGrid* grid = leaf.InPatches ? mesh.GetPatches() : mesh.GetMergedMesh();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = leaf.FirstCell; c < leaf.FirstCell + leaf.Cells; ++c)
  {
    grid->GetCellPoints(c, ids);
    if (layers.PlaneOf(xyz, ids->GetPointer(0), static_cast<std::size_t>(ids->GetNumberOfIds())) <
      0)
    {
      return false;
    }
  }
  return true;
}
/// A block's name, or "(block N)" (its flat index) when it has none.
std::string LabelOf(const CompositeMesh::Leaf& leaf)
{
  return leaf.Name.empty() ? "(block " + std::to_string(leaf.FlatIndex) + ")" : leaf.Name;
}

/**
 * A warning when nodes of the moving boundaries also lie on static blocks (`staticLeaves`; named
 * says whether each was chosen as static or is static for not being named): such nodes move with
 * the body (moving wins), so the static boundary's faces around them stretch or shear (a wedge
 * or cyclic patch, a ground plane under a wheel: checkMesh then fails). Empty when there are none.
 */
std::string MovingNodesOnStaticBlocks(const std::vector<CompositeMesh::Leaf>& leaves,
  const std::vector<std::size_t>& staticLeaves, const std::vector<bool>& named,
  const std::vector<std::uint8_t>& rank)
{
  std::string listed;
  std::size_t blocks = 0;
  for (std::size_t k = 0; k < staticLeaves.size(); ++k)
  {
    const CompositeMesh::Leaf& leaf = leaves[staticLeaves[k]];
    std::size_t shared = 0;
    for (vtkIdType point = 0; point < leaf.NumberOfPoints; ++point)
    {
      shared += rank[static_cast<std::size_t>(leaf.Node(point))] == MovingRank ? 1 : 0;
    }
    // A node set (an Exodus file's boundaries as meshio writes them) wholly on the body shears
    // nothing; one partly on it is a boundary the body drags (no warning for them until
    // 2026-11-30).
    const bool nodeSet = leaf.CellDimension == 0;
    if (shared > 0 && (!nodeSet || shared < static_cast<std::size_t>(leaf.NumberOfPoints)) &&
      ++blocks <= 5)
    {
      listed += std::string(listed.empty() ? "" : ", ") + "'" + LabelOf(leaf) + "' (" +
        std::to_string(shared) + (named[k] ? "" : ", static for not being named") + ")";
    }
  }
  if (blocks == 0)
  {
    return std::string();
  }
  return "Nodes of the moving boundaries also lie on static boundaries: " + listed +
    (blocks > 5 ? " and " + std::to_string(blocks - 5) + " more" : std::string()) +
    ". They move with the body, so the static boundary's faces around them stretch or shear "
    "(a wedge, symmetry or cyclic patch, a ground plane: the solver's mesh check may fail). Name "
    "a plane the body slides along as a slip boundary (a symmetry or wedge plane; not the two "
    "planes of a cyclic pair, which would then no longer match); check the result otherwise.";
}

/**
 * Fills roles.MovingOnSlip (per slip entry, the moving nodes of its blocks) and roles.SlipBlocks
 * (per entry of several blocks, each block's slip and moving nodes), from the entries' blocks
 * `slipLeaves`, the nodes' ranks and roles.Kinds.
 */
void AddSlipBlocks(const std::vector<CompositeMesh::Leaf>& leaves,
  const std::vector<std::vector<std::size_t>>& slipLeaves, const std::vector<std::uint8_t>& rank,
  NodeRoles& roles)
{
  const auto nodesOf = [&](std::size_t l, bool moving)
  {
    std::vector<std::int32_t> found;
    for (vtkIdType point = 0; point < leaves[l].NumberOfPoints; ++point)
    {
      const auto i = static_cast<std::size_t>(leaves[l].Node(point));
      if (moving ? rank[i] == MovingRank : roles.Kinds[i] == dgmf::NodeKind::SlipBoundary)
      {
        found.push_back(static_cast<std::int32_t>(i));
      }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  };
  roles.MovingOnSlip.resize(slipLeaves.size());
  roles.SlipBlocks.resize(slipLeaves.size());
  for (std::size_t k = 0; k < slipLeaves.size(); ++k)
  {
    std::vector<std::int32_t>& moving = roles.MovingOnSlip[k];
    for (std::size_t l : slipLeaves[k])
    {
      const std::vector<std::int32_t> more = nodesOf(l, true);
      moving.insert(moving.end(), more.begin(), more.end());
      if (slipLeaves[k].size() > 1)
      {
        roles.SlipBlocks[k].push_back({ LabelOf(leaves[l]), nodesOf(l, false), more });
      }
    }
    std::sort(moving.begin(), moving.end());
    moving.erase(std::unique(moving.begin(), moving.end()), moving.end());
  }
}
} // namespace

NodeRoles AssignRoles(const CompositeMesh& mesh, const BoundarySelection& selection,
  vtkUnstructuredGrid* merged, bool findLayers, bool piece, int meshDimension)
{
  std::vector<double> copy;
  const double* xyz = PointsAsDouble(merged->GetPoints(), copy);
  dgmf::ExtrudedLayers layers = findLayers
    ? dgmf::FindExtrudedLayers(
        xyz, static_cast<std::size_t>(merged->GetNumberOfPoints()), MakeSMPParallelFor())
    : dgmf::ExtrudedLayers();
  NodeRoles roles = AssignRoles(mesh, selection, layers, piece, meshDimension);
  roles.Layers = std::move(layers);
  return roles;
}

std::string ListBlockNames(const CompositeMesh& mesh)
{
  std::string names;
  for (const CompositeMesh::Leaf& leaf : mesh.GetLeaves())
  {
    names +=
      (names.empty() ? "" : ", ") + WithFamily(LabelOf(leaf), FamilyOf(mesh.GetInput(), leaf));
  }
  return names;
}

NodeRoles AssignRoles(const CompositeMesh& mesh, const BoundarySelection& selection,
  const dgmf::ExtrudedLayers& layers, bool piece, int meshDimension)
{
  // The block hierarchy of a multiblock (selectors such as "/Root/boundary/wing"); a partitioned
  // data set collection (ParaView's IOSS reader) has none that VTK 9.2 can generate: its blocks
  // are found by their names, or by the last name of a selector.
  vtkNew<vtkDataAssembly> hierarchy;
  const bool hasHierarchy = !vtkPartitionedDataSetCollection::SafeDownCast(mesh.GetInput()) &&
    vtkDataAssemblyUtilities::GenerateHierarchy(mesh.GetInput(), hierarchy);
  const std::vector<CompositeMesh::Leaf>& leaves = mesh.GetLeaves();
  const std::size_t n = static_cast<std::size_t>(mesh.GetMergedMesh()->GetNumberOfPoints());
  // An entry named twice (twice as a body, or in two roles) is a mistake: which was meant?
  std::map<std::string, std::string> roleOf;
  for (const auto& [entries, role] : { std::pair{ &selection.Moving, "moving" },
         std::pair{ &selection.Static, "static" }, std::pair{ &selection.Slip, "slip" } })
  {
    for (const std::string& entry : *entries)
    {
      const auto [named, first] = roleOf.emplace(NameOf(entry), role);
      if (!first)
      {
        throw std::invalid_argument("The boundary '" + entry + "' is named twice (as " +
          named->second + " and as " + role + "): name each boundary once.");
      }
    }
  }
  std::map<unsigned int, std::size_t> leafOfFlatIndex;
  int dimension = 0;
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    leafOfFlatIndex[leaves[l].FlatIndex] = l;
    dimension = std::max(dimension, leaves[l].CellDimension);
  }
  // A piece of a distributed mesh may hold only patches: the whole mesh's dimension.
  dimension = piece && meshDimension > 0 ? meshDimension : dimension;
  // ParaView's Ghost Cells Generator puts volume cells into the patch blocks of a multiblock:
  // their nodes would be taken for the patch's (the whole mesh turned with a moving one).
  for (const CompositeMesh::Leaf& leaf : leaves)
  {
    const vtkIdType ghosts = GhostVolumeCellsOfAPatch(mesh.GetInput(), leaf, dimension);
    if (ghosts > 0)
    {
      throw std::invalid_argument("The boundary block '" + leaf.Name + "' holds " +
        std::to_string(ghosts) +
        " ghost cells of the volume's dimension (a Ghost Cells Generator adds them to the patch "
        "blocks of a multiblock): boundaries chosen by name need no ghost cells; take the Ghost "
        "Cells Generator out of the pipeline.");
    }
  }
  // The cells of the mesh's dimension, all blocks together.
  vtkIdType volumeCells = 0;
  for (const CompositeMesh::Leaf& leaf : leaves)
  {
    volumeCells += leaf.CellDimension == dimension ? leaf.Cells : 0;
  }
  // The leaves of an entry.
  std::vector<std::uint8_t> foundEntries(
    piece ? selection.Moving.size() + selection.Static.size() + selection.Slip.size() : 0, 0);
  std::size_t entryIndex = 0;
  // The leaves an entry names as it is: a block name or a selector.
  const auto literalLeaves = [&](const std::string& entry)
  {
    std::vector<std::size_t> found;
    // Blocks of that very name first: a file's group named "boundary" or "patch/wing" is that
    // group, not the reader's container "boundary" (every patch: the whole mesh turned) or the
    // path to a block "wing" (until 2026-11-30).
    for (const std::string& name : { entry, NameOf(entry) }) // as given, then without "patch/"
    {
      for (std::size_t l = 0; l < leaves.size(); ++l)
      {
        if (leaves[l].Name == name)
        {
          found.push_back(l);
        }
      }
      if (!found.empty())
      {
        return found;
      }
    }
    // A name that is no block's is not a container's either ("boundary", the reader's group of
    // patches: every boundary moving, the mesh turned rigidly): only a selector ("/Root/...")
    // reaches into the reader's tree. (A piece of a distributed mesh without the block finds
    // none here: another piece holds it.)
    if (entry.empty() || entry[0] != '/')
    {
      return found;
    }
    if (hasHierarchy)
    {
      for (unsigned int id : vtkDataAssemblyUtilities::GetSelectedCompositeIds(
             { SelectorOf(entry) }, hierarchy, nullptr, true))
      {
        const auto leaf = leafOfFlatIndex.find(id);
        if (leaf != leafOfFlatIndex.end())
        {
          found.push_back(leaf->second);
        }
      }
    }
    else
    {
      // A selector of ParaView's block tree for a partitioned data set collection
      // ("/Root/wing", or "/Root/boundary/wing" from its assembly) names the block last, made a
      // valid node name (vtkDataAssembly::MakeValidNodeName).
      std::string name = NameOf(entry);
      const bool selector = !name.empty() && name[0] == '/';
      name = selector ? name.substr(name.rfind('/') + 1) : name;
      for (std::size_t l = 0; l < leaves.size(); ++l)
      {
        if (leaves[l].Name == name ||
          (selector && vtkDataAssembly::MakeValidNodeName(leaves[l].Name.c_str()) == name))
        {
          found.push_back(l);
        }
      }
    }
    return found;
  };
  // The blocks of a file's group of boundaries (a CGNS family) of the name `name`, when no block
  // has that name (a block of the very name wins, as over containers).
  const auto familyLeaves = [&](const std::string& name)
  {
    std::vector<std::size_t> found;
    for (std::size_t l = 0; l < leaves.size() && !name.empty() && name[0] != '/'; ++l)
    {
      if (FamilyOf(mesh.GetInput(), leaves[l]) == name)
      {
        found.push_back(l);
      }
    }
    return found;
  };
  // One entry, one role (one body): a block, or several ("wing_*", "flap|slat": a patch group,
  // a family, a body of several patches), each alternative naming at least one block.
  const auto leavesOf = [&](const std::string& entry)
  {
    const std::size_t index = entryIndex++;
    std::vector<std::size_t> found = literalLeaves(entry);
    if (found.empty() && entry.find_first_of("|*?") == std::string::npos)
    {
      found = familyLeaves(entry);
    }
    if (found.empty() && entry.find_first_of("|*?") != std::string::npos)
    {
      for (const std::string& alternative : Alternatives(entry))
      {
        const std::string pattern = NameOf(alternative);
        std::vector<std::size_t> more;
        for (std::size_t l = 0; l < leaves.size(); ++l)
        {
          if (pattern.find_first_of("*?") != std::string::npos
              ? fnmatch(pattern.c_str(), leaves[l].Name.c_str(), 0) == 0
              : leaves[l].Name == pattern)
          {
            more.push_back(l);
          }
        }
        more = more.empty() && pattern.find_first_of("*?") == std::string::npos
          ? literalLeaves(alternative)
          : more;
        more = more.empty() && pattern.find_first_of("*?") == std::string::npos
          ? familyLeaves(pattern)
          : more;
        if (more.empty() && !piece)
        {
          throw std::invalid_argument("No block of the input matches '" + alternative +
            "' (of the boundary '" + entry + "'). The input's blocks are: " + ListBlockNames(mesh) +
            ".");
        }
        for (std::size_t l : more)
        {
          if (std::find(found.begin(), found.end(), l) == found.end())
          {
            found.push_back(l);
          }
        }
      }
    }
    if (piece)
    {
      foundEntries[index] = found.empty() ? 0 : 1;
      if (found.empty())
      {
        return found; // another piece may hold it (AgreeOnNamedBoundaries)
      }
    }
    if (found.empty())
    {
      const int groupDimension = NonBoundaryGroupDimension(mesh.GetInput(), entry);
      if (groupDimension >= 0)
      {
        throw std::invalid_argument("'" + entry + "' is a physical group of dimension " +
          std::to_string(groupDimension) +
          " in the mesh file, not a boundary: the boundaries are the groups one dimension below "
          "the mesh's cells (surfaces of a 3D mesh, curves of a 2D mesh). The input's blocks "
          "are: " +
          ListBlockNames(mesh) + ".");
      }
      throw std::invalid_argument("No block of the input is named '" + entry +
        "'. The input's blocks are: " + ListBlockNames(mesh) + ".");
    }
    for (std::size_t l : found)
    {
      // Every cell of the mesh's dimension from this block: its volume (by the cells, not the
      // points: a piece of a redistributed mesh may hold patch points its volume piece lacks).
      if (leaves[l].CellDimension == dimension && leaves[l].Cells > 0 &&
        leaves[l].Cells == volumeCells)
      {
        throw std::invalid_argument("'" + entry +
          "' is the whole mesh (its volume block), not a boundary: name the boundary patches "
          "that move, stay or slide. The input's blocks are: " +
          ListBlockNames(mesh) + ".");
      }
    }
    return found;
  };
  // Per node: its role's rank, and only where there are several bodies, its body (the arrays are
  // as large as the merged mesh: not made for nothing).
  // Large arrays on huge pages (a 4 KiB page fault is costly on virtual machines: speed.md).
  std::vector<std::uint8_t> rank;
  dgmf::AssignOnHugePages(rank, n, std::uint8_t(None));
  std::vector<std::int32_t> body(selection.Moving.size() > 1 ? n : 0, 0);
  std::size_t movingNodes = 0;
  const auto mark = [&](std::size_t l, int role, std::int32_t bodyId)
  {
    for (vtkIdType point = 0; point < leaves[l].NumberOfPoints; ++point)
    {
      const auto i = static_cast<std::size_t>(leaves[l].Node(point));
      if (role > rank[i] ||
        (role == MovingRank && rank[i] == MovingRank && !body.empty() && body[i] == 0))
      {
        movingNodes += role == MovingRank && rank[i] != MovingRank ? 1 : 0;
        rank[i] = static_cast<std::uint8_t>(role);
        if (!body.empty())
        {
          body[i] = bodyId;
        }
      }
    }
  };
  // The entry that chose each block: a block chosen by two entries (a wildcard, alternatives or
  // a patch group besides another entry) is a mistake, as a name given twice is.
  std::vector<std::string> chosenBy(leaves.size());
  const auto choose = [&](std::size_t l, const std::string& entry, const char* role)
  {
    const std::string by = "'" + entry + "' as " + role;
    if (!chosenBy[l].empty())
    {
      throw std::invalid_argument("The block '" + LabelOf(leaves[l]) +
        "' is named by two entries (" + chosenBy[l] + " and " + by + "): name each boundary once.");
    }
    chosenBy[l] = by;
  };
  // Entries whose blocks hold no point (an OpenFOAM patch of 0 faces): no effect, said.
  std::vector<std::string> emptyEntries;
  const auto noteIfEmpty =
    [&](const std::vector<std::size_t>& found, const std::string& entry, const char* role)
  {
    vtkIdType points = 0;
    for (std::size_t l : found)
    {
      points += leaves[l].NumberOfPoints;
    }
    if (!piece && points == 0)
    {
      emptyEntries.push_back("'" + entry + "' (" + role + ")");
    }
    return found;
  };
  for (std::size_t k = 0; k < selection.Moving.size(); ++k)
  {
    for (std::size_t l : noteIfEmpty(leavesOf(selection.Moving[k]), selection.Moving[k], "moving"))
    {
      choose(l, selection.Moving[k], "moving");
      mark(l, MovingRank, static_cast<std::int32_t>(k + 1));
    }
  }
  // Moving boundaries that hold every node (the empty patch of a 2D mesh, "frontAndBack": both
  // planes of a one-cell-thick mesh) leave nothing to interpolate: one body would move the mesh
  // as itself, as its volume block would (refused); several bodies may be meant (a film between
  // two moving walls: said). (A piece of a distributed mesh may lie on the body alone.)
  std::string everyNodeMoving;
  if (!piece && n > 0 && movingNodes == n)
  {
    std::string names;
    for (const std::string& entry : selection.Moving)
    {
      names += (names.empty() ? "'" : ", '") + entry + "'";
    }
    everyNodeMoving = "The moving boundaries (" + names +
      ") hold every node of the mesh (the two planes of a one-cell-thick mesh, as an empty patch "
      "frontAndBack, hold them all): nothing is interpolated, every node moves as its body. ";
    if (selection.Moving.size() == 1)
    {
      throw std::invalid_argument(everyNodeMoving +
        "Name the patches of the body that moves. The input's blocks are: " + ListBlockNames(mesh) +
        ".");
    }
  }
  std::vector<std::size_t> staticLeaves; // for the warning of moving nodes on them
  std::vector<bool> staticNamed;
  for (const std::string& entry : selection.Static)
  {
    for (std::size_t l : noteIfEmpty(leavesOf(entry), entry, "static"))
    {
      choose(l, entry, "static");
      mark(l, StaticRank, 0);
      staticLeaves.push_back(l);
      staticNamed.push_back(true);
    }
  }
  std::vector<std::vector<std::size_t>> slipLeaves(selection.Slip.size());
  for (std::size_t k = 0; k < selection.Slip.size(); ++k)
  {
    for (std::size_t l : noteIfEmpty(leavesOf(selection.Slip[k]), selection.Slip[k], "slip"))
    {
      choose(l, selection.Slip[k], "slip");
      mark(l, SlipRank, 0);
      slipLeaves[k].push_back(l);
    }
  }
  // Boundary blocks not chosen are static, but for the two planes of a one-cell-thick mesh.
  const double* xyz =
    static_cast<const double*>(mesh.GetMergedMesh()->GetPoints()->GetData()->GetVoidPointer(0));
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    if (!chosenBy[l].empty() || leaves[l].CellDimension >= dimension)
    {
      continue;
    }
    const bool inPlane = layers.Found() && InLayerPlanes(mesh, leaves[l], xyz, layers);
    if (!inPlane)
    {
      mark(l, StaticRank, 0);
      staticLeaves.push_back(l);
      staticNamed.push_back(false);
    }
  }

  NodeRoles roles;
  if (!everyNodeMoving.empty())
  {
    roles.Warnings.push_back(everyNodeMoving + "Check that these are the bodies meant.");
  }
  if (!emptyEntries.empty())
  {
    std::string listed;
    for (const std::string& entry : emptyEntries)
    {
      listed += (listed.empty() ? "" : ", ") + entry;
    }
    roles.Warnings.push_back("The boundaries " + listed +
      " hold no point of the input (a patch of no faces): they have no effect.");
  }
  const std::string shared = MovingNodesOnStaticBlocks(leaves, staticLeaves, staticNamed, rank);
  if (!shared.empty())
  {
    roles.Warnings.push_back(shared);
  }
  roles.Kinds.resize(n); // every kind written below, on the threads
  roles.SlipNodes.resize(selection.Slip.size());
  roles.SlipNames = selection.Slip;
  const auto kindOf = [&](std::size_t i)
  {
    switch (rank[i])
    {
      case MovingRank:
        return dgmf::NodeKind::MovingBoundary;
      case StaticRank:
        return dgmf::NodeKind::StaticBoundary;
      case SlipRank:
        // On several planes: a line, or static (FitSlipPlanes, once the planes are known: two
        // patches of one plane are one plane).
        return dgmf::NodeKind::SlipBoundary;
      default:
        return dgmf::NodeKind::Interior;
    }
  };
  dgmf::ForEachIndex(MakeSMPParallelFor(), n, std::size_t(1) << 16,
    [&](std::size_t i) { roles.Kinds[i] = kindOf(i); });
  // Each entry's slip nodes (a node on several entries' planes is in each).
  for (std::size_t k = 0; k < slipLeaves.size(); ++k)
  {
    std::vector<std::int32_t>& slipNodes = roles.SlipNodes[k];
    for (std::size_t l : slipLeaves[k])
    {
      for (vtkIdType point = 0; point < leaves[l].NumberOfPoints; ++point)
      {
        const vtkIdType i = leaves[l].Node(point);
        if (rank[static_cast<std::size_t>(i)] == SlipRank)
        {
          slipNodes.push_back(static_cast<std::int32_t>(i));
        }
      }
    }
    std::sort(slipNodes.begin(), slipNodes.end());
    slipNodes.erase(std::unique(slipNodes.begin(), slipNodes.end()), slipNodes.end());
  }
  AddSlipBlocks(leaves, slipLeaves, rank, roles);
  if (selection.Moving.size() > 1)
  {
    roles.BodyIds = std::move(body);
  }
  if (piece)
  {
    roles.Found = std::move(foundEntries);
    roles.BlockNames = ListBlockNames(mesh);
  }
  return roles;
}

} // namespace dgmf_vtk
