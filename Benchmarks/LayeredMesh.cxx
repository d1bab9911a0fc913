#include "LayeredMesh.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace dgmf_bench
{

LayeredMeshSize PaperSize(int index)
{
  // 30^3 box grid: 5,048 nodes per layer; 60 x 60 x 59: 20,652 nodes per layer.
  switch (index)
  {
    case 0:
      return { "201,920", 30, 30, 30, 40 };
    case 1:
      return { "403,840", 30, 30, 30, 80 };
    case 2:
      return { "826,080", 60, 60, 59, 40 };
    case 3:
      return { "8,260,800", 60, 60, 59, 400 };
    default:
      throw std::out_of_range("paper sizes are 0..3");
  }
}

vtkSmartPointer<vtkUnstructuredGrid> MakeLayeredMesh(const LayeredMeshSize& size)
{
  const int A = size.A, B = size.B, C = size.C;
  // Surface grid: the lattice points on the boundary of the A x B x C box grid, numbered face by
  // face (a node on an edge or corner belongs to the first face that has it), row by row within a
  // face, as a structured multi-block mesh would number them.
  std::vector<int> surfaceIndex(static_cast<std::size_t>(A) * B * C, -1);
  std::vector<std::array<double, 3>> unit; // position on the box [-1, 1]^3
  auto lattice = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * B + j) * A + i; };
  const int dims[3] = { A, B, C };
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
      for (int b = 0; b < dims[v]; ++b)
        for (int a = 0; a < dims[u]; ++a)
        {
          int ijk[3];
          ijk[axis] = side ? dims[axis] - 1 : 0;
          ijk[u] = a;
          ijk[v] = b;
          int& index = surfaceIndex[lattice(ijk[0], ijk[1], ijk[2])];
          if (index < 0)
          {
            index = static_cast<int>(unit.size());
            unit.push_back({ 2.0 * ijk[0] / (A - 1) - 1.0, 2.0 * ijk[1] / (B - 1) - 1.0,
              2.0 * ijk[2] / (C - 1) - 1.0 });
          }
        }
  }
  const auto ns = static_cast<vtkIdType>(unit.size());

  // Surface quads, oriented with outward normals: for each of the 6 faces, (u, v) axes with
  // u x v pointing out of the box.
  std::vector<std::array<vtkIdType, 4>> quads;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      for (int b = 0; b + 1 < dims[v]; ++b)
        for (int a = 0; a + 1 < dims[u]; ++a)
        {
          auto id = [&](int du, int dv)
          {
            int ijk[3];
            ijk[axis] = side ? dims[axis] - 1 : 0;
            ijk[u] = a + du;
            ijk[v] = b + dv;
            return static_cast<vtkIdType>(surfaceIndex[lattice(ijk[0], ijk[1], ijk[2])]);
          };
          if (side) // outward normal +axis = u x v
            quads.push_back({ id(0, 0), id(1, 0), id(1, 1), id(0, 1) });
          else
            quads.push_back({ id(0, 0), id(0, 1), id(1, 1), id(1, 0) });
        }
    }
  }

  const int layers = size.Layers;
  const vtkIdType nodes = ns * layers;
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(nodes);
  vtkNew<vtkIntArray> marker;
  marker->SetName("BoundaryMarker");
  marker->SetNumberOfTuples(nodes);
  for (int l = 0; l < layers; ++l)
  {
    const double t = static_cast<double>(l) / (layers - 1);
    for (vtkIdType s = 0; s < ns; ++s)
    {
      const auto& p = unit[static_cast<std::size_t>(s)];
      const double norm = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      double* x = xyz->GetPointer(3 * (l * ns + s));
      for (int c = 0; c < 3; ++c)
      {
        const double inner = p[c] / norm;
        const double outer = size.Scale * p[c];
        x[c] = inner + t * (outer - inner);
      }
      marker->SetValue(l * ns + s, l == 0 ? 2 : l == layers - 1 ? 1 : 0);
    }
  }

  // Hexahedra between consecutive layers: the quad on layer l, then on layer l + 1.
  const auto cells = static_cast<vtkIdType>(quads.size()) * (layers - 1);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(cells + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(8 * cells);
  vtkIdType cell = 0;
  for (int l = 0; l + 1 < layers; ++l)
    for (const auto& q : quads)
    {
      vtkIdType* hex = connectivity->GetPointer(8 * cell);
      for (int k = 0; k < 4; ++k)
      {
        hex[k] = l * ns + q[k];
        hex[4 + k] = (l + 1) * ns + q[k];
      }
      offsets->SetValue(cell, 8 * cell);
      ++cell;
    }
  offsets->SetValue(cells, 8 * cells);
  vtkNew<vtkCellArray> cellArray;
  cellArray->SetData(offsets, connectivity);
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfTuples(cells);
  types->FillValue(VTK_HEXAHEDRON);

  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  mesh->SetPoints(points);
  mesh->SetCells(types, cellArray);
  mesh->GetPointData()->AddArray(marker);
  return mesh;
}

} // namespace dgmf_bench
