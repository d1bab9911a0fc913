/**
 * @file NonOrthogonality.h
 * @brief Face non-orthogonality as OpenFOAM's checkMesh defines it: the angle between the line
 * joining the centres of the two cells of an internal face and the face's area vector, with
 * OpenFOAM's face centres, face areas and cell centres.
 */
#ifndef dgmf_NonOrthogonality_h
#define dgmf_NonOrthogonality_h

#include "dgmf/ParallelFor.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

/// The faces of the cells of a mesh, for the non-orthogonality (the adapter gives VTK's).
class FaceCells
{
public:
  virtual ~FaceCells() = default;
  virtual std::size_t GetNumberOfCells() const = 0;
  /**
   * The faces of `cell` as a face stream with the mesh's point ids (CellFaces.h): the number of
   * faces, then each face's number of points and its points in order around it. A stream of 0
   * faces for cells that take no part (2D cells, cells without faces). Called concurrently.
   */
  virtual void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const = 0;
};

/// The faces shared by two cells, each once, in increasing order of owner.
struct InternalFaces
{
  std::vector<std::int64_t> Owner;     ///< the cell whose face stream gives the face
  std::vector<std::int64_t> Neighbour; ///< the other cell
  std::vector<std::int32_t> Face;      ///< the face's position in the owner's stream

  std::size_t Size() const { return this->Owner.size(); }
};

/**
 * The internal faces of `cells` (faces with the same set of points in two cells), found by
 * bucketing the faces by their smallest point id: O(faces). `numberOfPoints` bounds the ids.
 */
InternalFaces FindInternalFaces(const FaceCells& cells, std::size_t numberOfPoints);

/// What the non-orthogonality takes from the mesh before the deformation.
struct InputOrientation
{
  /// Per cell, +1 when its faces, as GetFaces lists them, turn outwards, -1 when inwards.
  std::vector<std::int8_t> CellSign;
  double InputMaximum = 0.0; ///< the largest non-orthogonality of the input, degrees
};

/**
 * The orientation of the cells of `cells` with the points `original` (the sign of the volume
 * their face pyramids give), and the input's own largest non-orthogonality.
 */
InputOrientation OrientCells(const FaceCells& cells, const InternalFaces& faces,
  const double* original, const ParallelFor& parallelFor);

/// The non-orthogonality of a mesh's internal faces.
struct NonOrthogonalityResult
{
  double Maximum = 0.0;            ///< degrees, over the internal faces (0 without any)
  std::vector<double> CellMaximum; ///< per cell, the largest over its internal faces (0 if none)
};

/**
 * The non-orthogonality of the internal faces `faces` of `cells` with the points `points`
 * (3 doubles per point), in degrees: acos(d.Sf / (|d| |Sf|)), d from the owner's centre to the
 * neighbour's, as checkMesh computes it (face centres and areas from the triangles about the
 * face's vertex average, cell centres from the pyramids on the faces). The area vectors point out
 * of the owner as its faces do in the input (`orientation`), so a face whose neighbour centre
 * passes behind it scores over 90 degrees.
 */
NonOrthogonalityResult ComputeNonOrthogonality(const FaceCells& cells, const InternalFaces& faces,
  const InputOrientation& orientation, const double* points, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
