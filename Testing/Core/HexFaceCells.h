/**
 * @file HexFaceCells.h
 * @brief Hexahedra given by their corners, as dgmf::FaceCells (the face streams of VTK's
 * hexahedron face table), for the core tests and the fingerprint.
 */
#ifndef dgmf_test_HexFaceCells_h
#define dgmf_test_HexFaceCells_h

#include "dgmf/CellFaces.h"
#include "dgmf/FaceMatching.h"

#include <cstdint>
#include <vector>

namespace dgmf_test
{

/// Cells given by the hexahedron face table (the faces a polyhedron of the same shape has).
class HexFaceCells : public dgmf::FaceCells
{
public:
  std::vector<std::vector<std::int64_t>> Corners; ///< 8 point ids per cell, VTK order

  std::size_t GetNumberOfCells() const override { return this->Corners.size(); }
  void GetFaces(std::size_t cell, std::vector<std::int64_t>& stream) const override
  {
    const std::int64_t* local = dgmf::GetShapeFaceStream(dgmf::CellShape::Hexahedron);
    stream.assign(local, local + dgmf::FaceStreamLength(local));
    for (std::int64_t f = 0, at = 1; f < local[0]; ++f, at += 1 + local[at])
    {
      for (std::int64_t k = 0; k < local[at]; ++k)
      {
        stream[at + 1 + k] = this->Corners[cell][local[at + 1 + k]];
      }
    }
  }
};

} // namespace dgmf_test

#endif
