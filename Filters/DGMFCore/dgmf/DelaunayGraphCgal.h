/**
 * @file DelaunayGraphCgal.h
 * @brief The CGAL triangulations behind DelaunayGraph (private to its source files: the
 * construction in DelaunayGraph.cxx, the queries in DelaunayGraphQueries.cxx).
 */
#ifndef dgmf_DelaunayGraphCgal_h
#define dgmf_DelaunayGraphCgal_h

#include "dgmf/DelaunayGraph.h"
#include "dgmf/HugePageArena.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_ds_cell_base_3.h>
#include <CGAL/Triangulation_ds_vertex_base_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_3.h>
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

/**
 * CGAL's vertex with the node number as info, as a type of our own: CGAL's containers take their
 * allocator from `std::allocator` of the element type (CGAL_ALLOCATOR), which is specialised
 * below for this type, so that the vertices are stored in the huge-page arena.
 */
template <typename Tds = void>
class GraphVertex3
  : public CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, Kernel,
      CGAL::Triangulation_vertex_base_3<Kernel, CGAL::Triangulation_ds_vertex_base_3<Tds>>>
{
public:
  using Base = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, Kernel,
    CGAL::Triangulation_vertex_base_3<Kernel, CGAL::Triangulation_ds_vertex_base_3<Tds>>>;
  using Base::Base;
  template <typename Tds2>
  struct Rebind_TDS
  {
    using Other = GraphVertex3<Tds2>;
  };
};

/// CGAL's Delaunay cell with the element number as info, as a type of our own for the same
/// reason (GraphVertex3).
template <typename Tds = void>
class GraphCell3
  : public CGAL::Triangulation_cell_base_with_info_3<std::int32_t, Kernel,
      CGAL::Delaunay_triangulation_cell_base_3<Kernel,
        CGAL::Triangulation_cell_base_3<Kernel, CGAL::Triangulation_ds_cell_base_3<Tds>>>>
{
public:
  using Base = CGAL::Triangulation_cell_base_with_info_3<std::int32_t, Kernel,
    CGAL::Delaunay_triangulation_cell_base_3<Kernel,
      CGAL::Triangulation_cell_base_3<Kernel, CGAL::Triangulation_ds_cell_base_3<Tds>>>>;
  using Base::Base;
  template <typename Tds2>
  struct Rebind_TDS
  {
    using Other = GraphCell3<Tds2>;
  };
};
} // namespace graph_cgal
} // namespace dgmf

namespace std
{
/**
 * The graph's cells and vertices are allocated from the huge-page arena (dgmf/HugePageArena.h):
 * CGAL's Compact_container allocates them in hundreds of small blocks, each faulted in 4 KiB
 * pages otherwise (about 4,700 faults for the 260,000 cells of 41,000 boundary nodes, on the
 * insertion's path; speed.md). A specialisation for types of our own, as the standard allows.
 */
template <typename Tds>
class allocator<dgmf::graph_cgal::GraphCell3<Tds>>
  : public dgmf::HugePageArenaAllocator<dgmf::graph_cgal::GraphCell3<Tds>>
{
public:
  allocator() noexcept = default;
  template <typename U>
  allocator(const allocator<U>&) noexcept
  {
  }
};

/// The vertices' blocks, the same way.
template <typename Tds>
class allocator<dgmf::graph_cgal::GraphVertex3<Tds>>
  : public dgmf::HugePageArenaAllocator<dgmf::graph_cgal::GraphVertex3<Tds>>
{
public:
  allocator() noexcept = default;
  template <typename U>
  allocator(const allocator<U>&) noexcept
  {
  }
};
} // namespace std

namespace dgmf
{
namespace graph_cgal
{
using Vb3 = GraphVertex3<>;
using Cb3 = GraphCell3<>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3, Cb3>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<Kernel, Tds3>;
} // namespace graph_cgal

/// The 2D triangulation, and its faces by element number.
struct DelaunayGraph::Impl2
{
  graph_cgal::Delaunay2 Triangulation;
  UninitializedVector<graph_cgal::Delaunay2::Face_handle> Faces;
};

/// The 3D triangulation, and its cells by element number.
struct DelaunayGraph::Impl3
{
  graph_cgal::Delaunay3 Triangulation;
  UninitializedVector<graph_cgal::Delaunay3::Cell_handle> Cells;
};

} // namespace dgmf

#endif
