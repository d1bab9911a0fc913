/**
 * @file DGMFInputNodes.h
 * @brief The input mesh's nodes as the core reads them: the selected arrays found and checked for
 * shape, the points and displacement as doubles, the node kinds (from the marker, or from the
 * mesh's boundary) and the body ids (private to the DGMF::Filters module). The core checks the
 * values (dgmf::ValidateProblem).
 */
#ifndef DGMFInputNodes_h
#define DGMFInputNodes_h

#include "DGMFBoundaryDetection.h"
#include "DGMFContentKey.h"

#include "dgmf/DeformationProblem.h"
#include "dgmf/NodeKind.h"

#include "vtkType.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkUnstructuredGrid;

namespace dgmf_vtk
{

/// Indices of the filter's arrays in SetInputArrayToProcess.
enum InputArrayIndex
{
  DisplacementArrayIndex = 0,
  MarkerArrayIndex = 1,
  BodyIdArrayIndex = 2
};

/// The point arrays the user selected; "" for none (ParaView's "None" also means none).
struct SelectedArrays
{
  std::string Displacement;
  std::string Marker;
  std::string BodyIds;
};

/// The names given to `algorithm` with SetInputArrayToProcess at the InputArrayIndex indices.
SelectedArrays GetSelectedArrays(vtkAlgorithm* algorithm);

/// The nodes of the input mesh, with the copies the core needs (the other processes' boundary
/// nodes follow this piece's in a distributed run).
struct InputNodes
{
  std::size_t LocalNodes = 0;    ///< this piece's nodes, the first ones
  std::size_t NumberOfNodes = 0; ///< with the other processes' boundary nodes
  int Dimension = 3;
  const double* Points = nullptr;
  std::vector<double> PointCopy; ///< the points as doubles, when they are not already
  const double* Displacement = nullptr;
  std::vector<double> DisplacementCopy; ///< the displacement as doubles, when it is not already
  std::vector<dgmf::NodeKind> Kinds;
  std::vector<std::int32_t> BodyIds; ///< per node, when a body-id array is selected
  std::int32_t NumberOfBodies = 0;   ///< the largest body id

  /// The nodes as a core problem (one default rigid motion: the caller sets the motions).
  dgmf::DeformationProblem ToProblem() const;
};

/**
 * Gathers the input nodes of one mesh, and keeps between executions what depends only on
 * unchanged inputs: the node kinds of an unchanged marker array, and the mesh's boundary facets.
 */
class InputGatherer
{
public:
  /**
   * Fills `nodes` from `mesh`, of `dimension` (2 or 3; 0: found from the mesh: 2 without 3D cells).
   * Throws std::invalid_argument, with the message for the user, for an empty mesh, a 2D mesh off
   * a plane z = constant, a selected array that is missing or has the wrong number of components,
   * no array selected, or array values the core does not allow. `distributed`: the mesh is one
   * piece of a distributed mesh (an empty piece is allowed, and without a marker the pieces need
   * ghost cells).
   */
  void Gather(vtkUnstructuredGrid* mesh, const SelectedArrays& arrays, int dimension,
    bool distributed, InputNodes& nodes);

  /// The boundary facets of `mesh` (cached while its cells are unchanged).
  const BoundaryFacets& GetBoundaryFacets(vtkUnstructuredGrid* mesh, int dimension);

  /// Memory kept between executions, in bytes.
  std::size_t GetMemorySize() const;

private:
  void GatherKinds(vtkUnstructuredGrid* mesh, const SelectedArrays& arrays, vtkDataArray* marker,
    int dimension, bool distributed, InputNodes& nodes);
  // The kinds of the last marker array (checked once).
  vtkDataArray* Marker = nullptr;
  vtkMTimeType MarkerMTime = 0;
  std::vector<dgmf::NodeKind> MarkerKinds;
  // The boundary facets depend on the cells only.
  ContentKey Cells;
  std::unique_ptr<BoundaryFacets> Facets;
};

} // namespace dgmf_vtk

#endif
