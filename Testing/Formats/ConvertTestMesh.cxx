// dgmf-test-convert-mesh IN OUT [BOUNDARY=FAMILY ...]: the test meshes of test_formats.py (gmsh
// files of tetrahedra or triangles with named boundaries) written as Exodus II or CGNS by those
// formats' own libraries (ParaView's vtkexodusII and vtkcgns), so that the round trips start from
// files the project's readers did not write:
// - Exodus (.exo): one element block; each named boundary a side set of that name, each face as
//   (element, local side) in Exodus's side numbering.
// - CGNS (.cgns): one unstructured zone; the volume cells one section, each named boundary a
//   section of its faces and a boundary condition of type BCWall with a family of its name (the
//   form ParaView 5.11's CGNS reader shows as a patch; BOUNDARY=FAMILY puts it in FAMILY instead),
//   points as an element range, GridLocation FaceCenter (EdgeCenter in 2D).
// Test tool only: tetrahedra (3D) or triangles (2D).
#include "dgmf/meshfile/MeshFileFormat.h"

#include <vtkcgns/src/cgnslib.h>
#include <vtkexodusII/include/exodusII.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace mf = dgmf::meshfile;

namespace
{
void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    throw std::runtime_error("cannot write " + what);
  }
}

/// Exodus's local sides of a tetrahedron and a triangle (0-based corners).
const std::vector<std::vector<int>>& SidesOf(int dimension)
{
  static const std::vector<std::vector<int>> tetra = { { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 },
    { 0, 2, 1 } };
  static const std::vector<std::vector<int>> triangle = { { 0, 1 }, { 1, 2 }, { 2, 0 } };
  return dimension == 3 ? tetra : triangle;
}

std::vector<std::int64_t> Sorted(std::vector<std::int64_t> nodes)
{
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

void WriteExodus(const mf::NamedMesh& mesh, const std::string& path)
{
  const std::uint8_t cellType = mesh.Dimension == 3 ? mf::Tetra : mf::Triangle;
  const int corners = mf::NodesOfCellType(cellType);
  // (sorted face nodes) -> (1-based element, 1-based side)
  std::map<std::vector<std::int64_t>, std::pair<std::int64_t, std::int64_t>> sideOf;
  for (std::size_t c = 0; c < mesh.Volume.Size(); ++c)
  {
    Check(mesh.Volume.Types[c] == cellType, path + ": only tetrahedra or triangles");
    const std::int64_t* cell = mesh.Volume.Connectivity.data() + mesh.Volume.Offsets[c];
    const auto& sides = SidesOf(mesh.Dimension);
    for (std::size_t s = 0; s < sides.size(); ++s)
    {
      std::vector<std::int64_t> face;
      for (int corner : sides[s])
      {
        face.push_back(cell[corner]);
      }
      sideOf[Sorted(face)] = { static_cast<std::int64_t>(c + 1), static_cast<std::int64_t>(s + 1) };
    }
  }
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  Check(id >= 0, path);
  ex_set_int64_status(id, EX_ALL_INT64_API);
  ex_init_params p{};
  std::snprintf(p.title, sizeof(p.title), "DGMF test mesh");
  p.num_dim = mesh.Dimension;
  p.num_nodes = static_cast<std::int64_t>(mesh.NumberOfNodes());
  p.num_elem = static_cast<std::int64_t>(mesh.Volume.Size());
  p.num_elem_blk = 1;
  p.num_side_sets = static_cast<std::int64_t>(mesh.Boundaries.size());
  Check(ex_put_init_ext(id, &p) >= 0, "the Exodus header");
  std::vector<double> x, y, z;
  for (std::size_t i = 0; i < mesh.NumberOfNodes(); ++i)
  {
    x.push_back(mesh.Points[3 * i]);
    y.push_back(mesh.Points[3 * i + 1]);
    z.push_back(mesh.Points[3 * i + 2]);
  }
  Check(ex_put_coord(id, x.data(), y.data(), mesh.Dimension == 3 ? z.data() : nullptr) >= 0,
    "the coordinates");
  Check(ex_put_block(id, EX_ELEM_BLOCK, 1, mesh.Dimension == 3 ? "TETRA" : "TRI3", p.num_elem,
          corners, 0, 0, 0) >= 0,
    "the block");
  std::vector<std::int64_t> connectivity;
  for (std::int64_t node : mesh.Volume.Connectivity)
  {
    connectivity.push_back(node + 1);
  }
  Check(ex_put_conn(id, EX_ELEM_BLOCK, 1, connectivity.data(), nullptr, nullptr) >= 0, "cells");
  Check(ex_put_name(id, EX_ELEM_BLOCK, 1, "fluid") >= 0, "the block's name");
  for (std::size_t b = 0; b < mesh.Boundaries.size(); ++b)
  {
    const mf::Cells& faces = mesh.Boundaries[b].Faces;
    std::vector<std::int64_t> elements, sides;
    for (std::size_t f = 0; f < faces.Size(); ++f)
    {
      const auto found = sideOf.find(Sorted({ faces.Connectivity.begin() + faces.Offsets[f],
        faces.Connectivity.begin() + faces.Offsets[f + 1] }));
      Check(found != sideOf.end(), "a face that is no side of a cell");
      elements.push_back(found->second.first);
      sides.push_back(found->second.second);
    }
    const auto setId = static_cast<std::int64_t>(b + 1);
    Check(
      ex_put_set_param(id, EX_SIDE_SET, setId, static_cast<std::int64_t>(elements.size()), 0) >= 0,
      "a side set");
    Check(ex_put_set(id, EX_SIDE_SET, setId, elements.data(), sides.data()) >= 0, "a side set");
    Check(ex_put_name(id, EX_SIDE_SET, setId, mesh.Boundaries[b].Name.c_str()) >= 0, "a name");
  }
  Check(ex_close(id) >= 0, path);
}

void WriteCGNS(const mf::NamedMesh& mesh, const std::string& path)
{
  // Simplices only, as the Exodus writer (another cell written as one would be a wrong file).
  const std::uint8_t cellType = mesh.Dimension == 3 ? mf::Tetra : mf::Triangle;
  for (std::size_t c = 0; c < mesh.Volume.Size(); ++c)
  {
    Check(mesh.Volume.Types[c] == cellType, path + ": only tetrahedra or triangles");
  }

  int fn = 0, base = 0, zone = 0, section = 0, coordinate = 0, boco = 0, family = 0;
  std::set<std::string> families;
  Check(cg_open(path.c_str(), CG_MODE_WRITE, &fn) == CG_OK, path);
  const int d = mesh.Dimension;
  Check(cg_base_write(fn, "Base", d, d, &base) == CG_OK, "the base");
  cgsize_t sizes[3] = { static_cast<cgsize_t>(mesh.NumberOfNodes()),
    static_cast<cgsize_t>(mesh.Volume.Size()), 0 };
  Check(cg_zone_write(fn, base, "Fluid", sizes, CGNS_ENUMV(Unstructured), &zone) == CG_OK, "zone");
  const char* names[3] = { "CoordinateX", "CoordinateY", "CoordinateZ" };
  for (int c = 0; c < d; ++c)
  {
    std::vector<double> values;
    for (std::size_t i = 0; i < mesh.NumberOfNodes(); ++i)
    {
      values.push_back(mesh.Points[3 * i + static_cast<std::size_t>(c)]);
    }
    Check(cg_coord_write(
            fn, base, zone, CGNS_ENUMV(RealDouble), names[c], values.data(), &coordinate) == CG_OK,
      names[c]);
  }
  const auto write =
    [&](const char* name, CGNS_ENUMT(ElementType_t) type, const mf::Cells& cells, cgsize_t first)
  {
    std::vector<cgsize_t> connectivity;
    for (std::int64_t node : cells.Connectivity)
    {
      connectivity.push_back(static_cast<cgsize_t>(node + 1));
    }
    const cgsize_t last = first + static_cast<cgsize_t>(cells.Size()) - 1;
    Check(cg_section_write(
            fn, base, zone, name, type, first, last, 0, connectivity.data(), &section) == CG_OK,
      name);
    return last;
  };
  cgsize_t last = write("Volume", d == 3 ? CGNS_ENUMV(TETRA_4) : CGNS_ENUMV(TRI_3), mesh.Volume, 1);
  for (const mf::NamedBoundary& boundary : mesh.Boundaries)
  {
    const cgsize_t first = last + 1;
    last = write(
      boundary.Name.c_str(), d == 3 ? CGNS_ENUMV(TRI_3) : CGNS_ENUMV(BAR_2), boundary.Faces, first);
    const cgsize_t range[2] = { first, last };
    const std::string familyName = boundary.Family.empty() ? boundary.Name : boundary.Family;
    if (families.insert(familyName).second)
    {
      Check(cg_family_write(fn, base, familyName.c_str(), &family) == CG_OK, "a family");
    }
    Check(cg_boco_write(fn, base, zone, boundary.Name.c_str(), CGNS_ENUMV(BCWall),
            CGNS_ENUMV(PointRange), 2, range, &boco) == CG_OK,
      boundary.Name);
    Check(cg_boco_gridlocation_write(fn, base, zone, boco,
            d == 3 ? CGNS_ENUMV(FaceCenter) : CGNS_ENUMV(EdgeCenter)) == CG_OK,
      "a grid location");
    Check(cg_goto(fn, base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", boco, "end") == CG_OK &&
        cg_famname_write(familyName.c_str()) == CG_OK,
      "a family name");
  }
  Check(cg_close(fn) == CG_OK, path);
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: dgmf-test-convert-mesh IN.msh OUT.exo|OUT.cgns [BOUNDARY=FAMILY ...]\n";
    return 2;
  }
  try
  {
    mf::NamedMesh mesh = mf::ReadMeshFile(argv[1]);
    for (int a = 3; a < argc; ++a)
    {
      const std::string given = argv[a];
      const std::size_t equals = given.rfind('=');
      const auto named = std::find_if(mesh.Boundaries.begin(), mesh.Boundaries.end(),
        [&](const mf::NamedBoundary& b) { return b.Name == given.substr(0, equals); });
      Check(equals != std::string::npos && named != mesh.Boundaries.end(), "no boundary " + given);
      named->Family = given.substr(equals + 1);
    }
    const std::string out = argv[2];
    if (mf::FormatOfFileName(out) == mf::MeshFileFormat::Exodus)
    {
      WriteExodus(mesh, out);
    }
    else if (mf::FormatOfFileName(out) == mf::MeshFileFormat::CGNS)
    {
      WriteCGNS(mesh, out);
    }
    else
    {
      throw std::runtime_error("the output must end in .exo or .cgns");
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "dgmf-test-convert-mesh: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
