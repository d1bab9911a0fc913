#include "DGMFBoundaryNames.h"

#include "DGMFCompositeMesh.h"
#include "DGMFMeshConversion.h"
#include "DGMFSMPTools.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataAssembly.h"
#include "vtkDataAssemblyUtilities.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace dgmf_vtk
{
namespace
{
/// The block name of an entry: OpenFOAM region names ("patch/wing") without their prefix.
std::string NameOf(std::string entry)
{
  for (const char* prefix : { "patch/", "boundary/" })
  {
    if (entry.rfind(prefix, 0) == 0)
    {
      entry = entry.substr(std::string(prefix).size());
    }
  }
  return entry;
}

/// A selector of the hierarchy for an entry: a path as given, else any node of that name.
std::string SelectorOf(const std::string& entry)
{
  if (!entry.empty() && entry[0] == '/')
  {
    return entry;
  }
  return "//" + vtkDataAssembly::MakeValidNodeName(NameOf(entry).c_str());
}

/// Rank of a role: a moving body over static over slip over nothing.
enum Rank : int
{
  None = 0,
  SlipRank = 1,
  StaticRank = 2,
  MovingRank = 3
};
} // namespace

NodeRoles AssignRoles(const CompositeMesh& mesh, const BoundarySelection& selection,
  vtkUnstructuredGrid* merged, bool findLayers)
{
  std::vector<double> copy;
  const double* xyz = PointsAsDouble(merged->GetPoints(), copy);
  dgmf::ExtrudedLayers layers = findLayers
    ? dgmf::FindExtrudedLayers(
        xyz, static_cast<std::size_t>(merged->GetNumberOfPoints()), MakeSMPParallelFor())
    : dgmf::ExtrudedLayers();
  NodeRoles roles = AssignRoles(mesh, selection, layers);
  roles.Layers = std::move(layers);
  return roles;
}

std::string ListBlockNames(const CompositeMesh& mesh)
{
  std::string names;
  for (const CompositeMesh::Leaf& leaf : mesh.GetLeaves())
  {
    names += (names.empty() ? "" : ", ") +
      (leaf.Name.empty() ? "(block " + std::to_string(leaf.FlatIndex) + ")" : leaf.Name);
  }
  return names;
}

NodeRoles AssignRoles(
  const CompositeMesh& mesh, const BoundarySelection& selection, const dgmf::ExtrudedLayers& layers)
{
  // The block hierarchy of a multiblock (selectors such as "/Root/boundary/wing"); a partitioned
  // data set collection (ParaView's IOSS reader) has none that VTK 9.2 can generate: its blocks
  // are found by their names.
  vtkNew<vtkDataAssembly> hierarchy;
  const bool hasHierarchy = !vtkPartitionedDataSetCollection::SafeDownCast(mesh.GetInput()) &&
    vtkDataAssemblyUtilities::GenerateHierarchy(mesh.GetInput(), hierarchy);
  const std::vector<CompositeMesh::Leaf>& leaves = mesh.GetLeaves();
  std::map<unsigned int, std::size_t> leafOfFlatIndex;
  int dimension = 0;
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    leafOfFlatIndex[leaves[l].FlatIndex] = l;
    dimension = std::max(dimension, leaves[l].CellDimension);
  }
  // The leaves of an entry.
  const auto leavesOf = [&](const std::string& entry)
  {
    std::vector<std::size_t> found;
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
      const std::string name = NameOf(entry);
      for (std::size_t l = 0; l < leaves.size(); ++l)
      {
        if (leaves[l].Name == name)
        {
          found.push_back(l);
        }
      }
    }
    if (found.empty())
    {
      throw std::invalid_argument("No block of the input is named '" + entry +
        "'. The input's blocks are: " + ListBlockNames(mesh) + ".");
    }
    return found;
  };

  const std::size_t n = static_cast<std::size_t>(mesh.GetMergedMesh()->GetNumberOfPoints());
  std::vector<int> rank(n, None);
  std::vector<std::int32_t> body(n, 0);
  std::vector<std::int32_t> slipEntry(n, -1); // the slip entry of a node, or -2 on two planes
  const auto mark = [&](std::size_t l, int role, std::int32_t bodyId, std::int32_t entry)
  {
    for (vtkIdType node : leaves[l].NodeOf)
    {
      const auto i = static_cast<std::size_t>(node);
      if (role == SlipRank)
      {
        slipEntry[i] = slipEntry[i] == -1 || slipEntry[i] == entry ? entry : -2;
      }
      if (role > rank[i] || (role == MovingRank && rank[i] == MovingRank && body[i] == 0))
      {
        rank[i] = role;
        body[i] = bodyId;
      }
    }
  };
  std::vector<std::uint8_t> chosen(leaves.size(), 0);
  for (std::size_t k = 0; k < selection.Moving.size(); ++k)
  {
    for (std::size_t l : leavesOf(selection.Moving[k]))
    {
      chosen[l] = 1;
      mark(l, MovingRank, static_cast<std::int32_t>(k + 1), -1);
    }
  }
  for (const std::string& entry : selection.Static)
  {
    for (std::size_t l : leavesOf(entry))
    {
      chosen[l] = 1;
      mark(l, StaticRank, 0, -1);
    }
  }
  for (std::size_t k = 0; k < selection.Slip.size(); ++k)
  {
    for (std::size_t l : leavesOf(selection.Slip[k]))
    {
      chosen[l] = 1;
      mark(l, SlipRank, 0, static_cast<std::int32_t>(k));
    }
  }
  // Boundary blocks not chosen are static, but for the two planes of a one-cell-thick mesh.
  const double* xyz =
    static_cast<const double*>(mesh.GetMergedMesh()->GetPoints()->GetData()->GetVoidPointer(0));
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    if (chosen[l] || leaves[l].CellDimension >= dimension)
    {
      continue;
    }
    const auto onPlane = [&](double plane)
    {
      return std::all_of(leaves[l].NodeOf.begin(), leaves[l].NodeOf.end(),
        [&](vtkIdType node)
        { return xyz[3 * static_cast<std::size_t>(node) + layers.Axis] == plane; });
    };
    const bool inPlane = layers.Found() && (onPlane(layers.Low) || onPlane(layers.High));
    if (!inPlane)
    {
      mark(l, StaticRank, 0, -1);
    }
  }

  NodeRoles roles;
  roles.Kinds.assign(n, dgmf::NodeKind::Interior);
  roles.SlipNodes.resize(selection.Slip.size());
  roles.SlipNames = selection.Slip;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (rank[i] == SlipRank && slipEntry[i] == -2)
    {
      rank[i] = StaticRank; // on two slip planes: it cannot slide in both
    }
    switch (rank[i])
    {
      case MovingRank:
        roles.Kinds[i] = dgmf::NodeKind::MovingBoundary;
        break;
      case StaticRank:
        roles.Kinds[i] = dgmf::NodeKind::StaticBoundary;
        break;
      case SlipRank:
        roles.Kinds[i] = dgmf::NodeKind::SlipBoundary;
        roles.SlipNodes[static_cast<std::size_t>(slipEntry[i])].push_back(
          static_cast<std::int32_t>(i));
        break;
      default:
        break;
    }
  }
  if (selection.Moving.size() > 1)
  {
    roles.BodyIds = std::move(body);
  }
  return roles;
}

} // namespace dgmf_vtk
