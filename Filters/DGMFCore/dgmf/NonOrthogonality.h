/**
 * @file NonOrthogonality.h
 * @brief Face non-orthogonality as OpenFOAM's checkMesh defines it: the angle between the line
 * joining the centres of the two cells of an internal face and the face's area vector, with
 * OpenFOAM's face centres, face areas and cell centres.
 */
#ifndef dgmf_NonOrthogonality_h
#define dgmf_NonOrthogonality_h

#include "dgmf/FaceMatching.h"
#include "dgmf/ParallelFor.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{

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
