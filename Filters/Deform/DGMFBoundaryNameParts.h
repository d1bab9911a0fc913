/**
 * @file DGMFBoundaryNameParts.h
 * @brief The parts of a boundary entry and of a block that AssignRoles (DGMFBoundaryNames.h)
 * reads: the block name of an entry, its alternatives, its selector of the block tree; the
 * dimension of a mesh file's group that is no boundary; the ghost volume cells of a patch block.
 * Private to the DGMF::Filters module.
 */
#ifndef DGMFBoundaryNameParts_h
#define DGMFBoundaryNameParts_h

#include "DGMFCompositeMesh.h"

#include "vtkType.h"
#include "vtkUnstructuredGrid.h" // for DGMFCompositeMesh.h's smart pointers

#include <string>
#include <vector>

class vtkCompositeDataSet;
class vtkDataObject;

namespace dgmf_vtk
{
/// The block name of an entry: OpenFOAM region names ("patch/wing") without their prefix.
std::string NameOf(std::string entry);

/// The alternatives of an entry "flap|slat|wing_*" (spaces around each dropped; empty ones too).
std::vector<std::string> Alternatives(const std::string& entry);

/// A selector of the hierarchy for an entry: a path as given, else any node of that name.
std::string SelectorOf(const std::string& entry);

/// The dimension of `name` among the input's named groups that are not boundaries
/// (dgmf::names::NonBoundaryGroups, from a mesh file), or -1.
int NonBoundaryGroupDimension(vtkCompositeDataSet* input, const std::string& name);

/// The file's group of boundaries `block` is in (field data dgmf::names::BoundaryFamily: a CGNS
/// family), or "" (also for null).
std::string FamilyOfBlock(vtkDataObject* block);

/// FamilyOfBlock of the block of `leaf`.
std::string FamilyOf(vtkCompositeDataSet* input, const CompositeMesh::Leaf& leaf);

/// `name` for messages with its family: "wing_upper (family wing)"; the name alone without one
/// or when the family has the name.
std::string WithFamily(const std::string& name, const std::string& family);

/// For a block of `leaf` whose own cells (not ghost) include cells of a lower dimension than
/// `dimension` (a patch): its ghost cells (vtkGhostType) of dimension `dimension` or more; 0 for
/// any other block.
vtkIdType GhostVolumeCellsOfAPatch(
  vtkCompositeDataSet* input, const CompositeMesh::Leaf& leaf, int dimension);
} // namespace dgmf_vtk

#endif
