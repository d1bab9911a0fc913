#include "DGMFCoreDeformation.h"

#include "DGMFArrayAllocation.h"
#include "DGMFTupleAllocation.h"

#include "DGMFBoundaryDetection.h"
#include "DGMFBoundaryNodes.h"
#include "DGMFCompositeMesh.h"
#include "DGMFMemoryGuard.h"
#include "DGMFMeshConversion.h"

#include "dgmf/ExtrudedLayers.h"
#include "dgmf/NumberText.h"
#include "dgmf/ResultNames.h"

#include "vtkDoubleArray.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <new>
#include <set>
#include <stdexcept>

namespace dgmf_vtk
{
namespace
{
/// The boundary facets of a one-cell-thick mesh that lie on one of its two planes (`onPlane`) or
/// across them (the others).
BoundaryFacets SelectFacets(const BoundaryFacets& facets, const double* points,
  const dgmf::ExtrudedLayers& layers, bool onPlane, double plane)
{
  BoundaryFacets selected;
  for (std::size_t f = 0; f < facets.Size(); ++f)
  {
    const vtkIdType* begin = facets.Ids.data() + facets.Offsets[f];
    const vtkIdType* end = facets.Ids.data() + facets.Offsets[f + 1];
    const int side = layers.PlaneOf(points, begin, static_cast<std::size_t>(end - begin));
    const bool planar = side >= 0 && (!onPlane || (side == 0 ? layers.Low : layers.High) == plane);
    if (planar == onPlane)
    {
      selected.Ids.insert(selected.Ids.end(), begin, end);
      selected.Offsets.push_back(static_cast<vtkIdType>(selected.Ids.size()));
    }
  }
  return selected;
}

/// The 2D cells of a one-cell-thick mesh's first layer: its faces on the Low plane.
dgmf::CellMesh LayerCells(
  const BoundaryFacets& facets, const double* points, const dgmf::ExtrudedLayers& layers)
{
  const BoundaryFacets front = SelectFacets(facets, points, layers, true, layers.Low);
  dgmf::CellMesh cells;
  cells.NumberOfPoints = layers.Front.size();
  cells.Offsets.push_back(0);
  // A face given twice (the volume's own face and the patch's polygon of a composite input) is
  // one cell of the layer: the guard's counts are the layer's cells.
  std::set<std::vector<std::int64_t>> seen;
  for (std::size_t f = 0; f < front.Size(); ++f)
  {
    const vtkIdType count = front.Offsets[f + 1] - front.Offsets[f];
    std::vector<std::int64_t> key;
    for (vtkIdType k = 0; k < count; ++k)
    {
      key.push_back(layers.Layer[static_cast<std::size_t>(front.Ids[front.Offsets[f] + k])]);
    }
    const std::vector<std::int64_t> ordered = key;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second)
    {
      continue;
    }
    cells.Connectivity.insert(cells.Connectivity.end(), ordered.begin(), ordered.end());
    cells.Offsets.push_back(static_cast<std::int64_t>(cells.Connectivity.size()));
    cells.Shapes.push_back(count == 4 ? dgmf::CellShape::Quad : dgmf::CellShape::Triangle);
    cells.Covered.push_back(count == 3 || count == 4 ? 1 : 0);
  }
  return cells;
}

/// A new point array `name` with the layer's values for every node of both layers.
vtkSmartPointer<vtkDoubleArray> Expanded(
  vtkDoubleArray* layerValues, const dgmf::ExtrudedLayers& layers, const char* name)
{
  auto values = vtkSmartPointer<vtkDoubleArray>::New();
  values->SetName(name);
  AllocateTuples(values, static_cast<vtkIdType>(layers.Layer.size()));
  dgmf::ExpandValuesFromLayer(layers, layerValues->GetPointer(0), values->GetPointer(0));
  return values;
}

/**
 * A warning when the motion takes moving nodes that lie on a slip plane (the body's rim on a
 * symmetry or wedge plane) off it: moving wins over slip, so the plane is no longer flat and the
 * solver's check of it fails (a half model pitched about an axis across its symmetry plane). A
 * node is off when its displacement across the plane is more than 1e-6 of the largest such
 * node's displacement and more than 1e-12 of the coordinates' magnitude (in-plane motions, and
 * motions of round-off size, leave only round-off). Empty when none is.
 */
std::string MovingNodesOffSlipPlanes(const InputNodes& nodes, const double* deformed)
{
  std::string said;
  for (const InputNodes::MovingOnPlane& entry : nodes.MovingOnSlip)
  {
    const double* normal = nodes.Slip.Planes[static_cast<std::size_t>(entry.Plane)].Normal;
    double largestMove = 0.0, largestAcross = 0.0, magnitude = 0.0;
    std::vector<double> across;
    for (const std::int32_t node : entry.Nodes)
    {
      const double* x = nodes.Points + 3 * static_cast<std::size_t>(node);
      const double* y = deformed + 3 * static_cast<std::size_t>(node);
      magnitude = std::max({ magnitude, std::abs(x[0]), std::abs(x[1]), std::abs(x[2]) });
      const double d[3] = { y[0] - x[0], y[1] - x[1], y[2] - x[2] };
      largestMove = std::max(largestMove, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      across.push_back(std::abs(d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]));
      largestAcross = std::max(largestAcross, across.back());
    }
    const double floor = std::max(1e-6 * largestMove, 1e-12 * magnitude);
    const auto off = std::count_if(
      across.begin(), across.end(), [&](double distance) { return distance > floor; });
    if (off > 0)
    {
      said += (said.empty() ? "" : " ") + std::string("The motion takes ") + std::to_string(off) +
        " nodes of the moving boundaries that lie on the slip boundary '" + entry.Name +
        "' off its plane, by up to " + dgmf::NumberText(largestAcross) +
        " (moving wins over slip): the plane is no longer flat, and a solver's check of a "
        "symmetry or wedge plane fails. Keep the body's motion in the plane: a rotation about its "
        "normal, a translation along it.";
    }
  }
  return said;
}
} // namespace

CoreDeformation DeformThroughCore(const dgmf::DeformationMethod& method,
  const dgmf::DeformationProblem& problem, const InputNodes& nodes, vtkUnstructuredGrid* mesh,
  bool distributed, DeformationCaches& caches, vtkDoubleArray* deformed,
  const dgmf::ParallelFor& parallelFor, const dgmf::Progress& progress)
{
  CoreDeformation result;
  const dgmf::ExtrudedLayers& layers = nodes.Layers;
  const bool extruded = layers.Found();
  dgmf::LayerProblemStorage storage;
  dgmf::DeformationProblem solved =
    extruded ? dgmf::ReduceToLayer(layers, problem, storage) : problem;
  result.Needs = method.GetNeeds(solved);
  const dgmf::MethodNeeds& needs = result.Needs;
  dgmf::CellMesh cells;
  if (needs.Cells)
  {
    if (distributed)
    {
      throw std::invalid_argument(
        "Sub-steps and the quality guard are not available in distributed runs.");
    }
    cells = extruded
      ? LayerCells(caches.Inputs.GetBoundaryFacets(mesh, nodes.Patches, nodes.Dimension),
          nodes.Points, layers)
      : ToCellMesh(mesh, nodes.Patches);
    solved.Cells = &cells;
  }
  std::vector<double> weights;
  if (needs.BoundaryWeights && distributed)
  {
    // A piece knows only the boundary faces it holds: the area of a node on a partition
    // interface would be partial, and a remote node's unknown (measured: 0.2 off the serial run).
    throw std::invalid_argument("IDW is not available in distributed runs (its boundary weights "
                                "need every boundary face); use DGMF, DGM, DGRBF or RBF.");
  }
  if (needs.BoundaryWeights)
  {
    const BoundaryFacets& facets =
      caches.Inputs.GetBoundaryFacets(mesh, nodes.Patches, nodes.Dimension);
    weights = ComputeBoundaryNodeWeights(
      extruded ? SelectFacets(facets, nodes.Points, layers, false, 0.0) : facets, nodes.Points,
      static_cast<vtkIdType>(nodes.NumberOfNodes), nodes.Dimension);
    if (extruded) // a layer node stands for itself and its partner
    {
      std::vector<double> layerWeights(layers.Front.size(), 0.0);
      for (std::size_t i = 0; i < weights.size(); ++i)
      {
        layerWeights[static_cast<std::size_t>(layers.Layer[i])] += weights[i];
      }
      weights.swap(layerWeights);
    }
    solved.BoundaryWeights = weights.data();
  }
  std::vector<double> layerDeformed(extruded ? 3 * solved.NumberOfNodes : 0);
  double* out = extruded ? layerDeformed.data() : deformed->GetPointer(0);

  const dgmf::DelaunayMapping* mapping = nullptr;
  // What the gathering left for later (keys' hashes) runs beside the graph's insertion.
  const dgmf::DelaunayGraph::SideJobs deferred = caches.Inputs.TakeDeferredJobs();
  if (!needs.Graph)
  {
    for (const std::function<void()>& job : deferred)
    {
      job();
    }
  }
  else
  {
    // A new graph: r and f are computed anew, and their arrays and the output points are first
    // touched while the graph is built (on another thread), off the critical path.
    mapping = &caches.Mapping.Update(
      solved, mesh->GetPoints()->GetData(),
      [mesh, extruded, &nodes]()
      { return extruded ? std::size_t(0) : HintStrideOf(mesh, nodes.Patches); },
      [&]()
      {
        caches.Fields.Reset(solved.NumberOfNodes);
        std::vector<vtkDoubleArray*> touched = caches.Fields.Prepare(needs.R, needs.F);
        touched.push_back(deformed);
        return touched;
      },
      deferred, parallelFor, result.GraphReused, result.Report.Warnings);
    if (!result.GraphReused)
    {
      result.GraphSeconds = mapping->GetGraphSeconds();
      result.LocationSeconds = mapping->GetLocationSeconds();
    }
  }
  progress.Report(0.5);
  solved.Progress = progress.Part(0.5, 1.0); // sub-steps and the quality guard
  const auto start = std::chrono::steady_clock::now();
  dgmf::DeformationReport report =
    method.Deform(solved, mapping, dgmf::DeformationOutputs{ out, &caches.Fields }, parallelFor);
  result.DeformationSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.GraphSeconds += report.GraphSeconds;
  result.LocationSeconds += report.LocationSeconds;
  report.Warnings.insert(
    report.Warnings.begin(), result.Report.Warnings.begin(), result.Report.Warnings.end());
  result.Report = std::move(report);
  if (needs.R)
  {
    vtkDoubleArray* r = caches.Fields.GetArray(dgmf::names::R);
    result.R = extruded ? Expanded(r, layers, dgmf::names::R) : vtkSmartPointer<vtkDoubleArray>(r);
  }
  if (needs.F)
  {
    vtkDoubleArray* f = caches.Fields.GetArray(dgmf::names::F);
    result.F = extruded ? Expanded(f, layers, dgmf::names::F) : vtkSmartPointer<vtkDoubleArray>(f);
  }
  if (extruded)
  {
    dgmf::ExpandFromLayer(layers, nodes.Points, layerDeformed.data(), deformed->GetPointer(0));
  }
  const std::string off = MovingNodesOffSlipPlanes(nodes, deformed->GetPointer(0));
  if (!off.empty())
  {
    result.Report.Warnings.push_back(off);
  }
  return result;
}

std::string GatherInputNodes(vtkUnstructuredGrid* input, const CompositeMesh* composite,
  const BoundarySelection& boundaries, bool findLayers, GatherOptions& options,
  DeformationCaches& caches, InputNodes& nodes)
{
  try
  {
    std::string error = CheckDeformationMemory(static_cast<double>(input->GetNumberOfPoints()),
      static_cast<double>(CellsWithPatches(input, composite ? composite->GetPatches() : nullptr)));
    if (!error.empty())
    {
      return error;
    }
    if (composite && !boundaries.Empty())
    {
      auto& kept = caches.Roles;
      const std::uint64_t generation = caches.Composite.GetGeneration();
      if (!kept.Valid || kept.Generation != generation || !(kept.Selection == boundaries) ||
        kept.FindLayers != findLayers || kept.Roles.Found.empty() == options.Distributed)
      {
        kept.Valid = false;
        kept.Roles = AssignRoles(*composite, boundaries, input, findLayers, options.Distributed,
          options.Dimension); // throws for a bad name (of a serial mesh)
        kept.Generation = generation;
        kept.Selection = boundaries;
        kept.FindLayers = findLayers;
        kept.Valid = true;
      }
      options.Roles = &kept.Roles;
    }
    caches.Inputs.Gather(input, options, nodes);
    return std::string();
  }
  catch (const std::bad_alloc&)
  {
    throw; // the filter's out-of-memory error
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
}

} // namespace dgmf_vtk
