#include "Renumbering.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

namespace dgmf_bench
{

Numbering NumberingFromName(const std::string& name)
{
  if (name == "layered")
    return Numbering::Layered;
  if (name == "hilbert")
    return Numbering::Hilbert;
  if (name == "random")
    return Numbering::Random;
  throw std::invalid_argument("unknown numbering '" + name + "' (layered, hilbert or random)");
}

void Renumber(vtkUnstructuredGrid* mesh, Numbering numbering)
{
  if (numbering == Numbering::Layered)
  {
    return;
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  // newToOld[k]: the old id of new node k.
  std::vector<vtkIdType> newToOld(static_cast<std::size_t>(n));
  std::iota(newToOld.begin(), newToOld.end(), vtkIdType{ 0 });
  if (numbering == Numbering::Random)
  {
    std::mt19937_64 random(20261123);
    std::shuffle(newToOld.begin(), newToOld.end(), random);
  }
  else
  {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_3> points;
    points.reserve(newToOld.size());
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      mesh->GetPoint(i, x);
      points.emplace_back(x[0], x[1], x[2]);
    }
    using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel,
      CGAL::Pointer_property_map<Kernel::Point_3>::type>;
    std::vector<std::size_t> sorted(newToOld.size());
    std::iota(sorted.begin(), sorted.end(), std::size_t{ 0 });
    CGAL::hilbert_sort(sorted.begin(), sorted.end(), Traits(CGAL::make_property_map(points.data())),
      CGAL::Hilbert_sort_median_policy());
    std::copy(sorted.begin(), sorted.end(), newToOld.begin());
  }
  std::vector<vtkIdType> oldToNew(newToOld.size());
  for (std::size_t k = 0; k < newToOld.size(); ++k)
  {
    oldToNew[static_cast<std::size_t>(newToOld[k])] = static_cast<vtkIdType>(k);
  }

  // Points and point data: tuple k of the new arrays is tuple newToOld[k] of the old ones.
  vtkNew<vtkIdList> order;
  order->SetNumberOfIds(n);
  std::copy(newToOld.begin(), newToOld.end(), order->GetPointer(0));
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(n);
  mesh->GetPoints()->GetData()->GetTuples(order, points->GetData());
  vtkPointData* pointData = mesh->GetPointData();
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = pointData->GetArray(a))
    {
      vtkSmartPointer<vtkDataArray> renumbered = vtk::TakeSmartPointer(array->NewInstance());
      renumbered->SetName(array->GetName());
      renumbered->SetNumberOfComponents(array->GetNumberOfComponents());
      renumbered->SetNumberOfTuples(n);
      array->GetTuples(order, renumbered);
      arrays.push_back(renumbered);
    }
  }
  for (const vtkSmartPointer<vtkDataArray>& array : arrays)
  {
    pointData->AddArray(array); // replaces the array of the same name
  }
  mesh->SetPoints(points);

  // Connectivity: every corner id through oldToNew.
  vtkCellArray* cells = mesh->GetCells();
  vtkSmartPointer<vtkCellArray> renumbered = vtkSmartPointer<vtkCellArray>::New();
  renumbered->DeepCopy(cells);
  vtkDataArray* connectivity = renumbered->GetConnectivityArray();
  for (vtkIdType k = 0; k < connectivity->GetNumberOfTuples(); ++k)
  {
    connectivity->SetTuple1(
      k, static_cast<double>(oldToNew[static_cast<std::size_t>(connectivity->GetTuple1(k))]));
  }
  vtkSmartPointer<vtkUnsignedCharArray> types = mesh->GetCellTypesArray();
  mesh->SetCells(types, renumbered);
}

} // namespace dgmf_bench
