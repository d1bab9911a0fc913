/**
 * @file DelaunayGraphCgal.h
 * @brief The CGAL triangulations behind DelaunayGraph (private to its source files: the
 * construction in DelaunayGraph.cxx, the queries in DelaunayGraphQueries.cxx).
 */
#ifndef dgmf_DelaunayGraphCgal_h
#define dgmf_DelaunayGraphCgal_h

#include "dgmf/DelaunayGraph.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dgmf
{
namespace graph_cgal
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Elements per block of the loops over elements (fixed, so no result depends on the threads).
constexpr std::size_t ElementBlock = 4096;

using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, Kernel>;
using Fb2 = CGAL::Triangulation_face_base_with_info_2<std::int32_t, Kernel>;
using Tds2 = CGAL::Triangulation_data_structure_2<Vb2, Fb2>;
using Delaunay2 = CGAL::Delaunay_triangulation_2<Kernel, Tds2>;

using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, Kernel>;
using Cb3 = CGAL::Triangulation_cell_base_with_info_3<std::int32_t, Kernel,
  CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3, Cb3>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<Kernel, Tds3>;
} // namespace graph_cgal

/// The 2D triangulation, and its faces by element number.
struct DelaunayGraph::Impl2
{
  graph_cgal::Delaunay2 Triangulation;
  std::vector<graph_cgal::Delaunay2::Face_handle> Faces;
};

/// The 3D triangulation, and its cells by element number.
struct DelaunayGraph::Impl3
{
  graph_cgal::Delaunay3 Triangulation;
  std::vector<graph_cgal::Delaunay3::Cell_handle> Cells;
};

} // namespace dgmf

#endif
