/**
 * @file DGMFBoundaryNames.h
 * @brief Boundaries chosen by name on composite input (the OpenFOAM reader's patches, Exodus side
 * sets, any named block): which merged nodes move, stay or slip (private to the DGMF::Filters
 * module).
 */
#ifndef DGMFBoundaryNames_h
#define DGMFBoundaryNames_h

#include "dgmf/ExtrudedLayers.h"
#include "dgmf/FirstTouch.h"
#include "dgmf/NodeKind.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace dgmf_vtk
{
class CompositeMesh;

/**
 * Blocks chosen by name: each entry is a plain block name ("wing"; an OpenFOAM region name such
 * as "patch/wing" works too), or a selector of the input's hierarchy ("/Root/boundary/wing", or
 * any vtkDataAssembly path query such as "//wing", as ParaView's block tree gives them).
 */
struct BoundarySelection
{
  std::vector<std::string> Moving; ///< one moving body each, in order (body 1, 2, ...)
  std::vector<std::string> Static;
  std::vector<std::string> Slip; ///< each a plane the nodes slide in

  bool Empty() const { return this->Moving.empty() && this->Static.empty() && this->Slip.empty(); }

  bool operator==(const BoundarySelection& other) const
  {
    return this->Moving == other.Moving && this->Static == other.Static && this->Slip == other.Slip;
  }

  /// Appends `name` to `list` (one of the three above); false (no change) for null or empty.
  static bool Add(std::vector<std::string>& list, const char* name)
  {
    if (!name || !*name)
    {
      return false;
    }
    list.emplace_back(name);
    return true;
  }
};

/// The role of every merged node, from the selection.
struct NodeRoles
{
  dgmf::UninitializedVector<dgmf::NodeKind> Kinds; ///< written in blocks on the threads
  std::vector<std::int32_t> BodyIds;               ///< with several moving bodies, else empty
  /// per slip entry, its slip nodes (a node on two entries' planes is in both); they fit its
  /// plane, and those still SlipBoundary when it is fitted are held to it (FitSlipPlanes: an edge
  /// on a boundary no block was read for is static by then, MakeSlipEdgesStatic)
  std::vector<std::vector<std::int32_t>> SlipNodes;
  std::vector<std::string> SlipNames; ///< the entries, for messages
  /// The planes of a one-cell-thick mesh the roles were assigned with (the gathering reuses them)
  dgmf::ExtrudedLayers Layers;
  /// A piece of a distributed mesh: per entry (moving, then static, then slip, as selected),
  /// whether a block of this piece has its name (the others' pieces may: AgreeOnNamedBoundaries).
  std::vector<std::uint8_t> Found;
  std::string BlockNames; ///< this piece's blocks, for the message of an entry found nowhere
  std::vector<std::string> Warnings; ///< for the user (moving nodes on static boundaries)
  /// Per slip entry, the nodes of its blocks that are moving (the body's rim on a symmetry
  /// plane): a motion out of the plane takes them off it (MovingNodesOffSlipPlanes).
  std::vector<std::vector<std::int32_t>> MovingOnSlip;
  /// One block of a slip entry of several: its name, its slip nodes and its moving nodes.
  struct SlipBlock
  {
    std::string Name;
    std::vector<std::int32_t> Slip, Moving;
  };
  /// Per slip entry of several blocks (alternatives, a wildcard, an OpenFOAM patch group such as
  /// "wedge"), its blocks; empty for an entry of one block. Such an entry is one plane when its
  /// nodes fit one (a plane cut into patches), else a plane per block (FitSlipPlanes).
  std::vector<std::vector<SlipBlock>> SlipBlocks;
};

/**
 * The roles of `mesh`'s merged nodes. A node's role comes from the blocks that contain it: a
 * moving block (the first one listed wins between two bodies), over a static one, over a slip
 * one; the slip nodes of each slip entry are listed (a node on several entries' planes in each:
 * FitSlipPlanes makes it a line's or a static node once the planes are fitted). Boundary blocks
 * that are not selected (blocks whose cells are of a lower dimension than the mesh's: OpenFOAM
 * patches, side sets) are static, except the two planes of a one-cell-thick mesh (`layers`, if
 * Found()), which are not boundaries. Throws std::invalid_argument for an entry that matches no
 * block; the message lists the names of the input's blocks. With `piece` (one piece of a
 * distributed mesh), an entry that matches no block of the piece is not an error here: `Found` says
 * which did (AgreeOnNamedBoundaries), and `meshDimension` (> 0) is the whole mesh's dimension (a
 * piece may hold only patches).
 */
NodeRoles AssignRoles(const CompositeMesh& mesh, const BoundarySelection& selection,
  const dgmf::ExtrudedLayers& layers, bool piece = false, int meshDimension = 0);

/**
 * The roles of the merged nodes of `mesh` (whose merged grid is `merged`), with the planes of a
 * one-cell-thick mesh found in `merged`'s points when `findLayers` is on (kept in the roles'
 * Layers).
 */
NodeRoles AssignRoles(const CompositeMesh& mesh, const BoundarySelection& selection,
  vtkUnstructuredGrid* merged, bool findLayers, bool piece = false, int meshDimension = 0);

/// The names of the blocks of `mesh` (the merged leaves), for messages.
std::string ListBlockNames(const CompositeMesh& mesh);

} // namespace dgmf_vtk

#endif
