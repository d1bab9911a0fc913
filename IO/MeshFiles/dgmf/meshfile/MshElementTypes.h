/**
 * @file MshElementTypes.h
 * @brief The first-order gmsh element types the .msh readers take, as VTK cells (private to the
 * gmsh module's GmshModel.cxx and to MshReader41.cxx, which must read them alike).
 */
#ifndef dgmf_meshfile_MshElementTypes_h
#define dgmf_meshfile_MshElementTypes_h

#include "dgmf/meshfile/NamedMesh.h"

#include <cstdint>

namespace dgmf
{
namespace meshfile
{

/// A gmsh element type as a VTK cell: VTK's type, its nodes, the gmsh node of each VTK node.
struct CellMapping
{
  std::uint8_t Type = 0;
  int Nodes = 0;
  int Order[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  int Dimension = 0;
};

/**
 * gmsh types 15 (point), 1, 2, 3, 4, 5, 6, 7; false for any other. gmsh and VTK number the
 * corners alike except for the prism: gmsh's triangle (0, 1, 2) turns counter-clockwise seen from
 * (3, 4, 5), VTK documents its normal pointing away from (3, 4, 5), so each triangle is read in
 * the opposite order.
 */
inline bool MapGmshType(int gmshType, CellMapping& mapping)
{
  switch (gmshType)
  {
    case 15:
      mapping = { Vertex, 1, { 0 }, 0 };
      return true;
    case 1:
      mapping = { Line, 2, { 0, 1 }, 1 };
      return true;
    case 2:
      mapping = { Triangle, 3, { 0, 1, 2 }, 2 };
      return true;
    case 3:
      mapping = { Quad, 4, { 0, 1, 2, 3 }, 2 };
      return true;
    case 4:
      mapping = { Tetra, 4, { 0, 1, 2, 3 }, 3 };
      return true;
    case 5:
      mapping = { Hexahedron, 8, { 0, 1, 2, 3, 4, 5, 6, 7 }, 3 };
      return true;
    case 6:
      mapping = { Wedge, 6, { 0, 2, 1, 3, 5, 4 }, 3 };
      return true;
    case 7:
      mapping = { Pyramid, 5, { 0, 1, 2, 3, 4 }, 3 };
      return true;
    default:
      return false;
  }
}

} // namespace meshfile
} // namespace dgmf

#endif
