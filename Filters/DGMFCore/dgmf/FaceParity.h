/**
 * @file FaceParity.h
 * @brief Whether every face of a set of cells occurs an even number of times: a mesh closed by
 * its boundary patches (each boundary face of the volume cells is one patch cell), decided in one
 * streaming pass over the cells, without the face matching's memory.
 */
#ifndef dgmf_FaceParity_h
#define dgmf_FaceParity_h

#include "dgmf/FaceMatching.h"
#include "dgmf/ParallelFor.h"

namespace dgmf
{

/**
 * Whether every face of `cells` occurs an even number of times, a face being its set of point
 * ids (order and starting point do not matter). Give the volume cells' faces and each boundary
 * patch cell as one face (a stream of one face): true says that the patch cells are exactly the
 * faces of the volume that no other volume cell has, so that the patches' nodes are all of the
 * volume's boundary nodes.
 *
 * How: the exclusive or of a 64-bit hash of every face, in which faces in pairs cancel. A
 * face's hash is the sum of a 64-bit mix of each of its point ids (splitmix64's finaliser) and
 * of its number of points; a face in odd count leaves the total non-zero but with a probability
 * of about 2^-64 (one wrong "true" in 10^19 meshes: a second 64 bits, which this used to carry,
 * doubled the pass's time). A cell with two faces of the same points (a collapsed cell), or
 * a point id outside [0, numberOfPoints), makes the answer false (the face matching counts such
 * faces as boundary faces, and refuses such ids). O(faces), no memory but a few small vectors per
 * thread (each corner of a standard shape mixed once per cell, FaceCells::GetCornerFaces), on
 * `parallelFor`'s threads, in fixed blocks of cells (the answer does not depend on the
 * threads).
 */
bool FacesPairUp(
  const FaceCells& cells, std::size_t numberOfPoints, const ParallelFor& parallelFor);

} // namespace dgmf

#endif
