/**
 * @file CGNSFile.h
 * @brief CGNS files (.cgns, HDF5 or ADF), read with their boundary conditions as boundary names and
 * written back with new coordinates, through the CGNS library ParaView's own CGNS reader uses
 * (ParaView's vtkcgns: the mid-level library, its symbols prefixed).
 *
 * What is read: the first base, and its one zone, which must be unstructured (a structured or a
 * second zone is a FileError: the project deforms one unstructured mesh). Its GridCoordinates
 * (CoordinateX, CoordinateY, and CoordinateZ when the physical dimension is 3) are the nodes, in
 * the file's order; NodeIds are 1..N, CGNS's own numbering. Element sections of the linear
 * types (BAR_2, TRI_3, QUAD_4, TETRA_4, PYRA_5, PENTA_6, HEXA_8, and MIXED sections of these) give
 * the cells: those of the mesh's dimension (the cell dimension of the base) form Volume, CGNS's
 * node order being VTK's for these types. Every boundary condition (BC_t under ZoneBC) is a
 * NamedBoundary named after it: on faces when its points are elements (ElementRange, ElementList,
 * or PointRange/PointList with GridLocation FaceCenter, EdgeCenter in 2D), the faces of those
 * elements; on nodes when its GridLocation is Vertex, one Vertex cell per node. Higher-order
 * types, NGON_n/NFACE_n polyhedra, and elements a boundary condition names that are not faces of
 * the mesh are a FileError.
 */
#ifndef dgmf_meshfile_CGNSFile_h
#define dgmf_meshfile_CGNSFile_h

#include "dgmf/meshfile/NamedMesh.h"

#include <string>

namespace dgmf
{
namespace meshfile
{

/// Reads the .cgns file `path` (see the file's comment). Throws FileError naming the file and
/// the node of the tree (base, zone, section, boundary condition) it could not read.
NamedMesh ReadCGNS(const std::string& path);

/**
 * Writes a copy of the .cgns file `source` to `target` in which only the zone's coordinates
 * change: `points` holds 3 per node in ReadCGNS's order (z ignored in 2D), `count` must be the
 * zone's number of nodes, and every coordinate finite. Each coordinate array keeps its name and
 * its data type (RealSingle or RealDouble); every other node of the tree is the source's, byte
 * for byte. Written beside `target` and renamed over it; `target` may be `source`. Throws
 * FileError; the target is then unchanged.
 */
void WriteCGNSWithPoints(
  const std::string& source, const std::string& target, const double* points, std::size_t count);

} // namespace meshfile
} // namespace dgmf

#endif
