/**
 * @file Renumbering.h
 * @brief Node numberings of a benchmark mesh: the generator's, a space-filling curve's, random.
 */
#ifndef dgmf_bench_Renumbering_h
#define dgmf_bench_Renumbering_h

#include <string>

class vtkUnstructuredGrid;

namespace dgmf_bench
{

/// How the benchmark numbers the nodes of its mesh.
enum class Numbering
{
  Layered, ///< the generator's: layer by layer (what a structured O-grid writes)
  Hilbert, ///< CGAL's Hilbert sort of the node coordinates (a renumbered unstructured mesh)
  Random   ///< a random permutation, fixed seed (a mesh reassembled from many pieces)
};

/// "layered", "hilbert" or "random"; throws std::invalid_argument for anything else.
Numbering NumberingFromName(const std::string& name);

/// Renumbers the nodes of `mesh` in place: points, point data and cell connectivity.
void Renumber(vtkUnstructuredGrid* mesh, Numbering numbering);

} // namespace dgmf_bench

#endif
