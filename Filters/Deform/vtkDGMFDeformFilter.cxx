#include "vtkDGMFDeformFilter.h"

#include "DGMFBoundaryDetection.h"
#include "DGMFCellQuality.h"
#include "DGMFCompositeMesh.h"
#include "DGMFDistributed.h"
#include "DGMFSMPTools.h"

#include "dgmf/BoundaryMotion.h"
#include "dgmf/DGMDeformation.h"
#include "dgmf/DGMFDeformation.h"
#include "dgmf/DGRBFDeformation.h"
#include "dgmf/DampingField.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/HintStride.h"
#include "dgmf/IDWDeformation.h"
#include "dgmf/MultiBodyDeformation.h"
#include "dgmf/RBFDeformation.h"
#include "dgmf/RigidMotionFit.h"
#include "dgmf/SubStepDeformation.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

vtkStandardNewMacro(vtkDGMFDeformFilter);

namespace
{
/// Index of each input array in SetInputArrayToProcess.
enum InputArrays
{
  DisplacementArray = 0,
  MarkerArray = 1,
  BodyIdArray = 2
};

/// 2 when the mesh is planar (no 3D cell, all z equal), 3 otherwise; -1 for 2D cells off a z plane.
int DetectDimension(vtkUnstructuredGrid* mesh, const double* xyz, std::size_t n)
{
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const int type = mesh->GetCellType(c);
    if (type != VTK_EMPTY_CELL && vtkCellTypes::GetDimension(static_cast<unsigned char>(type)) == 3)
    {
      return 3;
    }
  }
  for (std::size_t i = 1; i < n; ++i)
  {
    if (xyz[3 * i + 2] != xyz[2])
    {
      return -1;
    }
  }
  return 2;
}

void AddFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

void AddFieldCount(vtkFieldData* fieldData, const char* name, std::size_t value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->InsertNextValue(static_cast<vtkIdType>(value));
  fieldData->AddArray(array);
}

/// Boundary nodes that carry no facet weight (marked, but on no boundary facet) get the mean.
void FillMissingWeights(std::vector<double>& weights)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (double w : weights)
  {
    sum += w;
    count += w > 0.0 ? 1 : 0;
  }
  const double mean = count > 0 ? sum / static_cast<double>(count) : 1.0;
  for (double& w : weights)
  {
    w = w > 0.0 ? w : mean;
  }
}

bool AllFinite(const double* values, std::size_t count)
{
  // A double is finite when its exponent bits are not all ones: tested without a branch per value
  // (the points of a large mesh are a few hundred megabytes).
  constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
  for (std::size_t i = 0; i < count;)
  {
    const std::size_t end = std::min(count, i + 4096);
    std::uint64_t bad = 0;
    for (; i < end; ++i)
    {
      std::uint64_t bits;
      std::memcpy(&bits, values + i, sizeof(bits));
      bad |= (bits & exponent) == exponent ? 1 : 0;
    }
    if (bad)
    {
      return false;
    }
  }
  return true;
}

/**
 * Name given to input array `index` with SetInputArrayToProcess, or "" if none. "None" (the
 * ParaView panel's choice for no array) also means none.
 */
std::string SelectedArrayName(vtkAlgorithm* algorithm, int index)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(index);
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    const char* name = info->Get(vtkDataObject::FIELD_NAME());
    const std::string selected = name ? name : "";
    return selected == "None" ? std::string() : selected;
  }
  return "";
}
/**
 * Node kinds from a boundary-marker array of any value type (through vtkArrayDispatch, without a
 * virtual call per value); `bad` is the first point whose value is not 0, 1 or 2 (-1 if none).
 */
struct MarkerToKinds
{
  template <typename ArrayType>
  void operator()(ArrayType* array, dgmf::NodeKind* kinds, vtkIdType& bad, double& badValue) const
  {
    const auto values = vtk::DataArrayValueRange<1>(array);
    vtkIdType i = 0;
    for (const auto value : values)
    {
      const double v = static_cast<double>(value);
      if (v != 0.0 && v != 1.0 && v != 2.0)
      {
        bad = i;
        badValue = v;
        return;
      }
      kinds[i++] = static_cast<dgmf::NodeKind>(static_cast<int>(v));
    }
  }
};

/// A fast 64-bit hash of raw memory (not cryptographic: it tells equal content from changed).
/// Four independent lanes of 8-byte words, so the multiplications overlap (200 MB in ~20 ms).
std::uint64_t HashBytes(
  const void* data, std::size_t bytes, std::uint64_t seed = 0x9e3779b97f4a7c15ull)
{
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t lane[4] = { seed ^ (bytes * 0xff51afd7ed558ccdull), seed + 1, seed + 2, seed + 3 };
  std::size_t k = 0;
  for (; k + 32 <= bytes; k += 32)
  {
    for (int l = 0; l < 4; ++l)
    {
      std::uint64_t word;
      std::memcpy(&word, p + k + 8 * l, 8);
      lane[l] = (lane[l] ^ word) * 0x100000001b3ull;
      lane[l] ^= lane[l] >> 32;
    }
  }
  std::uint64_t h = lane[0];
  for (int l = 1; l < 4; ++l)
  {
    h = (h ^ lane[l]) * 0xff51afd7ed558ccdull;
    h ^= h >> 33;
  }
  for (; k < bytes; ++k)
  {
    h = (h ^ p[k]) * 0x100000001b3ull;
  }
  return h;
}

std::uint64_t HashArray(vtkDataArray* array, std::uint64_t seed = 0)
{
  return HashBytes(array->GetVoidPointer(0),
    static_cast<std::size_t>(array->GetNumberOfValues()) *
      static_cast<std::size_t>(array->GetDataTypeSize()),
    seed + static_cast<std::uint64_t>(array->GetDataType()));
}

/**
 * Identifies the content of an input object between executions: the object and its MTime, and
 * when either changed (a reader that reads the same mesh again at each time step, a composite
 * input merged anew), a hash of the content.
 */
struct ContentKey
{
  const void* Object = nullptr;
  vtkMTimeType MTime = 0;
  std::uint64_t Hash = 0;
  bool Valid = false;

  /// True when `object` has the content the key was set for; refreshes the object and MTime.
  template <typename HashFunction>
  bool Matches(vtkObject* object, const HashFunction& hash)
  {
    if (!this->Valid)
    {
      return false;
    }
    if (this->Object == object && this->MTime == object->GetMTime())
    {
      return true;
    }
    if (hash() != this->Hash)
    {
      return false;
    }
    this->Object = object;
    this->MTime = object->GetMTime();
    return true;
  }

  template <typename HashFunction>
  void Set(vtkObject* object, const HashFunction& hash)
  {
    this->Object = object;
    this->MTime = object->GetMTime();
    this->Hash = hash();
    this->Valid = true;
  }
};
} // namespace

/// What the filter keeps between executions: the graph and node locations, r, and the boundary.
struct vtkDGMFDeformFilter::Cache
{
  // The key of the mapping: the points, the dimension (and the node kinds, kept by the mapping).
  ContentKey Points;
  int Dimension = 0;
  // The cached mapping, r (for StaticR0) and f (for DampingFunction), shared with the output.
  std::unique_ptr<dgmf::DelaunayMapping> Mapping;
  double StaticR0 = 0.0;
  vtkSmartPointer<vtkDoubleArray> R;
  int Damping = 0;
  vtkSmartPointer<vtkDoubleArray> F;
  // Inputs already checked: the points (finite) and the marker (its kinds).
  vtkDataArray* CheckedPoints = nullptr;
  vtkMTimeType CheckedPointsMTime = 0;
  vtkDataArray* Marker = nullptr;
  vtkMTimeType MarkerMTime = 0;
  std::vector<dgmf::NodeKind> MarkerKinds;
  // The mesh's boundary facets depend on the cells only.
  ContentKey Cells;
  std::unique_ptr<dgmf_vtk::BoundaryFacets> Facets;
  // The points of the last output, reused by the next execution when nobody else holds them.
  vtkSmartPointer<vtkPoints> OutputPoints;
};

namespace
{
/**
 * The output points for `n` nodes: the last output's points when only this filter and its output
 * hold them (no downstream filter, shallow copy or array reference from user code: their data
 * would change underneath them), otherwise new ones. A repeated deformation of a large mesh then
 * writes into memory that is already mapped: first touches of new pages cost about as much as
 * the mapping itself here.
 */
vtkSmartPointer<vtkPoints> OutputPointsFor(vtkSmartPointer<vtkPoints>& last,
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, std::size_t n)
{
  if (last && input->GetPoints() != last.GetPointer())
  {
    const int holders = output->GetPoints() == last.GetPointer() ? 2 : 1;
    vtkDataArray* data = last->GetData();
    if (last->GetReferenceCount() == holders && data->GetReferenceCount() == 1 &&
      vtkDoubleArray::SafeDownCast(data) && data->GetNumberOfComponents() == 3 &&
      data->GetNumberOfTuples() == static_cast<vtkIdType>(n))
    {
      return last;
    }
  }
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(n));
  last = vtkSmartPointer<vtkPoints>::New();
  last->SetData(coordinates);
  return last;
}

/**
 * A point array `name` of `n` doubles for a new r or f: `cached` itself when only the cache holds
 * it (prepared by UpdateMapping, or no longer in any output), otherwise a new array (an output or
 * user code keeps the old values). Returns the array, now also in `cached`.
 */
vtkDoubleArray* FreshArray(vtkSmartPointer<vtkDoubleArray>& cached, const char* name, std::size_t n)
{
  if (!cached || cached->GetReferenceCount() != 1 || cached->GetNumberOfComponents() != 1 ||
    cached->GetNumberOfTuples() != static_cast<vtkIdType>(n))
  {
    cached = vtkSmartPointer<vtkDoubleArray>::New();
    cached->SetName(name);
    cached->SetNumberOfTuples(static_cast<vtkIdType>(n));
  }
  cached->Modified();
  return cached;
}
} // namespace

/// Everything one execution works from, checked.
struct vtkDGMFDeformFilter::Inputs
{
  std::size_t NumberOfNodes = 0; ///< with the other processes' boundary nodes (distributed run)
  std::size_t LocalNodes = 0;    ///< this piece's nodes, the first ones
  int Dimension = 3;
  const double* Points = nullptr;
  std::vector<double> PointCopy;        ///< the points as doubles, when they are not already
  const double* Displacement = nullptr; ///< 3 per node, null when no array is selected
  std::vector<double> DisplacementCopy; ///< the displacement as doubles, when it is not already
  std::string DisplacementName;
  std::vector<dgmf::NodeKind> Kinds;
  std::vector<std::int32_t> BodyIds; ///< per node, when a body-id array is selected
  std::int32_t NumberOfBodies = 0;   ///< the largest body id
  dgmf::RigidMotion Motion;
  dgmf::ParallelFor Parallel;
};

/// Per-body rigid motions set with SetBodyMotion.
struct vtkDGMFDeformFilter::BodyMotions
{
  std::map<int, dgmf::RigidMotion> Motions;
};

vtkDGMFDeformFilter::vtkDGMFDeformFilter()
  : GraphCache(new Cache)
  , PerBodyMotions(new BodyMotions)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkCxxSetObjectMacro(vtkDGMFDeformFilter, Controller, vtkMultiProcessController);

void vtkDGMFDeformFilter::SetBodyMotion(double bodyId, double tx, double ty, double tz, double cx,
  double cy, double cz, double ax, double ay, double az)
{
  if (!(bodyId >= 1.0) || bodyId != std::floor(bodyId) || bodyId > 1e6)
  {
    vtkErrorMacro("SetBodyMotion: the body id must be 1, 2, ... (got " << bodyId << ").");
    return;
  }
  dgmf::RigidMotion motion;
  const double values[3][3] = { { tx, ty, tz }, { cx, cy, cz }, { ax, ay, az } };
  for (int c = 0; c < 3; ++c)
  {
    motion.Translation[c] = values[0][c];
    motion.Center[c] = values[1][c];
    motion.AnglesDegrees[c] = values[2][c];
  }
  this->PerBodyMotions->Motions[static_cast<int>(bodyId)] = motion;
  this->Modified();
}

void vtkDGMFDeformFilter::RemoveAllBodyMotions()
{
  if (!this->PerBodyMotions->Motions.empty())
  {
    this->PerBodyMotions->Motions.clear();
    this->Modified();
  }
}

void vtkDGMFDeformFilter::SetBodyIdArrayName(const char* name)
{
  this->SetInputArrayToProcess(BodyIdArray, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
}

vtkDGMFDeformFilter::~vtkDGMFDeformFilter()
{
  this->SetController(nullptr);
}

void vtkDGMFDeformFilter::ReleaseCache()
{
  this->GraphCache.reset(new Cache);
}

namespace
{
/// Checks that a rigid motion keeps a 2D mesh in its plane.
bool StaysInPlane(const dgmf::RigidMotion& motion)
{
  double axis[3] = { 0.0, 0.0, 1.0 };
  if (motion.HasAxisRotation())
  {
    motion.GetUnitAxis(axis);
  }
  const bool axisOk = axis[0] == 0.0 && axis[1] == 0.0;
  return axisOk && motion.AnglesDegrees[0] == 0.0 && motion.AnglesDegrees[1] == 0.0 &&
    motion.Translation[2] == 0.0;
}
} // namespace

std::vector<dgmf::RigidMotion> vtkDGMFDeformFilter::PropertyBodyMotions(const Inputs& inputs) const
{
  std::vector<dgmf::RigidMotion> motions;
  for (std::int32_t k = 1; k <= std::max<std::int32_t>(inputs.NumberOfBodies, 1); ++k)
  {
    const auto found = this->PerBodyMotions->Motions.find(k);
    motions.push_back(found != this->PerBodyMotions->Motions.end() ? found->second : inputs.Motion);
  }
  return motions;
}

std::vector<std::int32_t> vtkDGMFDeformFilter::BodyIdsOrMovingNodes(const Inputs& inputs) const
{
  if (!inputs.BodyIds.empty())
  {
    return inputs.BodyIds;
  }
  std::vector<std::int32_t> ids(inputs.NumberOfNodes, 0);
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    ids[i] = inputs.Kinds[i] == dgmf::NodeKind::MovingBoundary ? 1 : 0;
  }
  return ids;
}

std::vector<double> vtkDGMFDeformFilter::TotalBodyDisplacement(const Inputs& inputs) const
{
  const std::size_t n = inputs.NumberOfNodes;
  std::vector<double> total(3 * n, 0.0);
  if (this->RigidMotionMode == EXTRACTED)
  {
    if (inputs.Displacement)
    {
      std::copy(inputs.Displacement, inputs.Displacement + 3 * n, total.begin());
    }
    return total;
  }
  const std::vector<std::int32_t> ids = this->BodyIdsOrMovingNodes(inputs);
  const std::vector<dgmf::RigidMotion> motions = this->PropertyBodyMotions(inputs);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (ids[i] > 0)
    {
      const double* x = inputs.Points + 3 * i;
      double moved[3];
      motions[static_cast<std::size_t>(ids[i] - 1)].Apply(
        1.0, x, inputs.Displacement ? inputs.Displacement + 3 * i : nullptr, moved);
      for (int c = 0; c < 3; ++c)
      {
        total[3 * i + c] = moved[c] - x[c];
      }
    }
  }
  return total;
}

bool vtkDGMFDeformFilter::DeformBodies(Inputs& inputs, vtkFieldData* fieldData, double* out)
{
  Cache& cache = *this->GraphCache;
  const dgmf::DelaunayMapping& mapping = *cache.Mapping;
  const std::size_t n = inputs.NumberOfNodes;
  const std::vector<std::int32_t> ids = this->BodyIdsOrMovingNodes(inputs);
  const std::int32_t bodies = std::max<std::int32_t>(inputs.NumberOfBodies, 1);
  std::vector<dgmf::BodyMotion> motions(static_cast<std::size_t>(bodies));
  std::vector<double> residual;
  if (this->RigidMotionMode == EXTRACTED)
  {
    if (!inputs.Displacement)
    {
      vtkErrorMacro(
        "RigidMotionMode EXTRACTED fits the motion to the displacement array: select one.");
      return false;
    }
    residual.resize(3 * n);
    std::vector<dgmf::FittedMotion> fits = dgmf::ExtractBodyMotions(
      inputs.Dimension, inputs.Points, inputs.Displacement, n, ids.data(), bodies, residual.data());
    // Each body turns about its rotation axis (not its centroid): a rotation given as
    // displacements about some centre is recovered about that centre. Near-translations (an axis
    // farther than 100 body sizes) keep the centroid.
    std::vector<double> size(fits.size(), 0.0);
    for (std::size_t i = 0; i < n; ++i)
    {
      if (ids[i] > 0)
      {
        const dgmf::FittedMotion& fit = fits[static_cast<std::size_t>(ids[i] - 1)];
        const double* x = inputs.Points + 3 * i;
        const double d = std::sqrt((x[0] - fit.Center[0]) * (x[0] - fit.Center[0]) +
          (x[1] - fit.Center[1]) * (x[1] - fit.Center[1]) +
          (x[2] - fit.Center[2]) * (x[2] - fit.Center[2]));
        size[static_cast<std::size_t>(ids[i] - 1)] =
          std::max(size[static_cast<std::size_t>(ids[i] - 1)], d);
      }
    }
    for (std::size_t k = 0; k < fits.size(); ++k)
    {
      dgmf::CentreOnRotationAxis(fits[k], 100.0 * size[k]);
    }
    vtkNew<vtkDoubleArray> translation, center, axis, angle, rms;
    translation->SetName("FittedTranslation");
    center->SetName("FittedRotationCenter");
    axis->SetName("FittedRotationAxis");
    angle->SetName("FittedRotationAngle");
    rms->SetName("FittedResidualRMS");
    for (vtkDoubleArray* a : { translation.Get(), center.Get(), axis.Get() })
    {
      a->SetNumberOfComponents(3);
    }
    for (std::size_t k = 0; k < fits.size(); ++k)
    {
      motions[k].Motion = fits[k].ToRigidMotion();
      motions[k].Displacement = residual.data();
      translation->InsertNextTuple(fits[k].Translation);
      center->InsertNextTuple(fits[k].Center);
      axis->InsertNextTuple(fits[k].Axis);
      angle->InsertNextValue(fits[k].AngleDegrees);
      rms->InsertNextValue(fits[k].ResidualRMS);
    }
    for (vtkDoubleArray* a :
      { translation.Get(), center.Get(), axis.Get(), angle.Get(), rms.Get() })
    {
      fieldData->AddArray(a);
    }
  }
  else
  {
    const std::vector<dgmf::RigidMotion> properties = this->PropertyBodyMotions(inputs);
    for (std::size_t k = 0; k < motions.size(); ++k)
    {
      motions[k].Motion = properties[k];
      motions[k].Displacement = inputs.Displacement;
      if (inputs.Dimension == 2 && !StaysInPlane(properties[k]))
      {
        vtkErrorMacro(
          "Body " << k + 1 << " of this 2D mesh must rotate about z and move in its plane.");
        return false;
      }
    }
  }
  // f is min(1, sum of the bodies' damping factors); r has no single meaning with several bodies.
  FreshArray(cache.F, "f", n);
  cache.Damping = 0; // not the single-body f: recomputed next time
  dgmf::DeformMultiBody(mapping, ids.data(), motions, this->StaticBoundaryR0,
    static_cast<dgmf::DampingFunction>(this->DampingFunction),
    static_cast<dgmf::DeformationMode>(this->DeformationMode), inputs.Points, out,
    cache.F->GetPointer(0), inputs.Parallel);
  return true;
}

namespace
{
/// The grid's cells in the corner order of the size-skew metric (pixels and voxels reordered).
dgmf::CellMesh ToCellMesh(vtkUnstructuredGrid* mesh)
{
  dgmf::CellMesh cells;
  cells.NumberOfPoints = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  cells.Offsets.push_back(0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    static const int pixel[4] = { 0, 1, 3, 2 };
    static const int voxel[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
    const int type = mesh->GetCellType(c);
    mesh->GetCellPoints(c, ids);
    const int* order = type == VTK_PIXEL ? pixel : type == VTK_VOXEL ? voxel : nullptr;
    dgmf::CellShape shape = dgmf::CellShape::Triangle;
    bool covered = true;
    switch (type)
    {
      case VTK_TRIANGLE:
        shape = dgmf::CellShape::Triangle;
        break;
      case VTK_QUAD:
      case VTK_PIXEL:
        shape = dgmf::CellShape::Quad;
        break;
      case VTK_TETRA:
        shape = dgmf::CellShape::Tetra;
        break;
      case VTK_HEXAHEDRON:
      case VTK_VOXEL:
        shape = dgmf::CellShape::Hexahedron;
        break;
      case VTK_WEDGE:
        shape = dgmf::CellShape::Wedge;
        break;
      case VTK_PYRAMID:
        shape = dgmf::CellShape::Pyramid;
        break;
      default:
        covered = false;
    }
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      cells.Connectivity.push_back(ids->GetId(order && k < 8 ? order[k] : k));
    }
    cells.Offsets.push_back(static_cast<std::int64_t>(cells.Connectivity.size()));
    cells.Shapes.push_back(shape);
    cells.Covered.push_back(covered ? 1 : 0);
  }
  return cells;
}
} // namespace

bool vtkDGMFDeformFilter::DeformInSubSteps(
  vtkUnstructuredGrid* input, Inputs& inputs, vtkFieldData* fieldData, double* out)
{
  if (inputs.LocalNodes < inputs.NumberOfNodes)
  {
    vtkErrorMacro("Sub-steps and the quality guard are not available in distributed runs.");
    return false;
  }
  dgmf::SubStepParameters parameters;
  parameters.SubSteps = this->SubSteps;
  parameters.RepairThreshold = this->RepairThreshold;
  parameters.Repair = this->RepairThreshold > 0.0;
  parameters.RepairLayers = this->RepairLayers;
  parameters.RepairPasses = this->RepairPasses;
  parameters.Damping = static_cast<dgmf::DampingFunction>(this->DampingFunction);
  parameters.StaticR0 = this->StaticBoundaryR0;
  const dgmf::CellMesh cells = ToCellMesh(input);
  const dgmf::SubStepReport report = dgmf::DeformInSubSteps(inputs.Dimension, inputs.Points,
    inputs.NumberOfNodes, inputs.Kinds.data(), cells, inputs.Motion, inputs.Displacement,
    parameters, out, inputs.Parallel, this->GraphCache->Mapping.get());
  AddFieldCount(fieldData, "SubStepsUsed", static_cast<std::size_t>(report.SubSteps));
  AddFieldCount(fieldData, "RejectedSubSteps", static_cast<std::size_t>(report.RejectedSteps));
  AddFieldCount(fieldData, "RepairedCellCount", report.RepairedCells);
  AddFieldCount(fieldData, "UnrepairedCellCount", report.BadCellsLeft);
  this->LastGraphSeconds += report.GraphSeconds;
  this->LastLocationSeconds += report.LocationSeconds;
  return true;
}

std::size_t vtkDGMFDeformFilter::GetCacheMemorySize() const
{
  const Cache& cache = *this->GraphCache;
  std::size_t bytes = cache.MarkerKinds.capacity() * sizeof(dgmf::NodeKind);
  if (cache.Mapping)
  {
    bytes += cache.Mapping->GetMemorySize();
  }
  if (cache.Facets)
  {
    bytes += (cache.Facets->Offsets.capacity() + cache.Facets->Ids.capacity()) * sizeof(vtkIdType);
  }
  return bytes;
}

void vtkDGMFDeformFilter::SetDisplacementArrayName(const char* name)
{
  this->SetInputArrayToProcess(
    DisplacementArray, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
}

void vtkDGMFDeformFilter::SetBoundaryMarkerArrayName(const char* name)
{
  this->SetInputArrayToProcess(MarkerArray, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
}

vtkTypeBool vtkDGMFDeformFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkDGMFDeformFilter::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  // A distributed mesh without a marker array needs one layer of ghost cells, so that the faces
  // between pieces are not taken for the boundary: ask upstream (e.g. Ghost Cells Generator) for
  // it.
  if (dgmf_vtk::IsDistributed(this->Controller) && SelectedArrayName(this, MarkerArray).empty())
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    const int requested =
      inInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
      ? inInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
      : 0;
    inInfo->Set(
      vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), std::max(requested, 1));
  }
  return 1;
}

int vtkDGMFDeformFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkDGMFDeformFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkDGMFDeformFilter::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The output has the input's type: an unstructured grid, or the same kind of composite.
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    if (!output || !output->IsA(composite->GetClassName()))
    {
      vtkSmartPointer<vtkDataObject> created = vtk::TakeSmartPointer(composite->NewInstance());
      outInfo->Set(vtkDataObject::DATA_OBJECT(), created);
    }
  }
  else if (!vtkUnstructuredGrid::SafeDownCast(output))
  {
    vtkNew<vtkUnstructuredGrid> created;
    outInfo->Set(vtkDataObject::DATA_OBJECT(), created);
  }
  return 1;
}

int vtkDGMFDeformFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* inputObject = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* outputObject = vtkDataObject::GetData(outputVector, 0);
  auto* compositeInput = vtkCompositeDataSet::SafeDownCast(inputObject);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(outputObject);
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::SafeDownCast(inputObject);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::SafeDownCast(outputObject);
  std::unique_ptr<dgmf_vtk::CompositeMesh> composite;
  vtkNew<vtkUnstructuredGrid> mergedOutput;
  if (compositeInput && compositeOutput)
  {
    // The blocks as one mesh (merged at coincident nodes), deformed below, scattered back after.
    std::vector<std::string> arrays;
    for (int index : { DisplacementArray, MarkerArray })
    {
      const std::string name = SelectedArrayName(this, index);
      if (!name.empty())
      {
        arrays.push_back(name);
      }
    }
    composite = std::make_unique<dgmf_vtk::CompositeMesh>(
      compositeInput, arrays, SelectedArrayName(this, MarkerArray));
    if (composite->GetNumberOfSkippedBlocks() > 0)
    {
      vtkWarningMacro(<< composite->GetNumberOfSkippedBlocks()
                      << " blocks without explicit points (e.g. image data) are passed unchanged.");
    }
    input = composite->GetMergedMesh();
    output = mergedOutput;
  }
  if (!input || !output)
  {
    vtkErrorMacro("The input must be a vtkUnstructuredGrid or a composite dataset of meshes.");
    return 0;
  }
  const bool distributed = dgmf_vtk::IsDistributed(this->Controller);
  if (distributed)
  {
    this->DistributedDimension =
      dgmf_vtk::AgreeOnDimension(this->Controller, input, this->DistributedZ);
  }
  int status = 0;
  try
  {
    dgmf_vtk::RunWithThreads(
      this->NumberOfThreads, [&]() { status = this->Execute(input, output); });
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory while deforming " << input->GetNumberOfPoints() << " points ("
                                                   << input->GetNumberOfCells() << " cells).");
    status = 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    status = 0;
  }
  if (distributed)
  {
    this->ReduceAcrossProcesses(status, output);
  }
  if (composite)
  {
    compositeOutput->Initialize();
    if (status)
    {
      composite->Scatter(output, { "r", "f" }, { "SizeSkew", "Inverted" }, compositeOutput);
      vtkNew<vtkFieldData> fieldData;
      fieldData->PassData(compositeInput->GetFieldData());
      for (int k = 0; k < output->GetFieldData()->GetNumberOfArrays(); ++k)
      {
        fieldData->AddArray(output->GetFieldData()->GetAbstractArray(k));
      }
      compositeOutput->SetFieldData(fieldData);
    }
    return status;
  }
  if (!status)
  {
    output->Initialize();
  }
  return status;
}

int vtkDGMFDeformFilter::Execute(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  this->LastExecutionReusedGraph = false;
  this->LastGraphSeconds = this->LastLocationSeconds = 0.0;
  this->LastDeformationSeconds = this->LastQualitySeconds = 0.0;
  Inputs inputs;
  bool ok = this->CheckMemory(input) && this->GatherInputs(input, inputs);
  if (dgmf_vtk::IsDistributed(this->Controller))
  {
    // Every process reaches this point: it fails on all if it fails on one (no process may wait
    // for another in the exchange below).
    ok = dgmf_vtk::AllProcessesAgree(this->Controller, ok);
    if (ok)
    {
      this->AppendRemoteBoundaryNodes(inputs);
    }
  }
  if (!ok)
  {
    return 0;
  }
  if (inputs.LocalNodes == 0)
  {
    output->ShallowCopy(input); // an empty piece of a distributed mesh
    return 1;
  }
  this->UpdateProgress(0.1);
  if (this->Method == DGMF || this->Method == DGM || this->Method == DGRBF)
  {
    if (!this->UpdateMapping(input, inputs, output))
    {
      return 0;
    }
  }
  this->UpdateProgress(0.6);
  if (this->GetAbortExecute())
  {
    return 0;
  }
  return this->Deform(input, inputs, output) ? 1 : 0;
}

bool vtkDGMFDeformFilter::CheckMemory(vtkUnstructuredGrid* input)
{
  // Per node: node kinds (up to 3 copies), element and barycentric coordinates (36 bytes), the new
  // points (24), r and f (16), the points and displacement as doubles if they are not (48); per
  // cell: SizeSkew and Inverted (9); per boundary node, the graph (measured: about 1.5 kB).
  // The boundary count is not known yet: a tenth of the nodes is assumed, which overestimates
  // volume meshes.
  const double nodes = static_cast<double>(input->GetNumberOfPoints());
  const double cells = static_cast<double>(input->GetNumberOfCells());
  const double needed = nodes * (3 + 36 + 24 + 16 + 48) + cells * 9 + 0.1 * nodes * 1500.0;
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  if (pages > 0 && pageSize > 0)
  {
    const double available = static_cast<double>(pages) * static_cast<double>(pageSize);
    // Free memory excludes the page cache, which the system gives back: allow twice as much.
    if (needed > 2.0 * available)
    {
      vtkErrorMacro("Deforming " << input->GetNumberOfPoints() << " points needs about "
                                 << needed / 1073741824.0 << " GiB; only "
                                 << available / 1073741824.0
                                 << " GiB of memory is free. Deform the mesh in parts, or on "
                                    "a machine with more memory.");
      return false;
    }
  }
  return true;
}

bool vtkDGMFDeformFilter::GatherInputs(vtkUnstructuredGrid* input, Inputs& inputs)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints == 0 && dgmf_vtk::IsDistributed(this->Controller))
  {
    return true; // an empty piece: it still takes part in the exchanges
  }
  if (numberOfPoints == 0 || input->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input mesh is empty (" << numberOfPoints << " points, "
                                              << input->GetNumberOfCells() << " cells).");
    return false;
  }
  const auto n = static_cast<std::size_t>(numberOfPoints);
  inputs.NumberOfNodes = n;
  inputs.LocalNodes = n;
  inputs.Parallel = dgmf_vtk::MakeSMPParallelFor();
  inputs.Points = dgmf_vtk::PointsAsDouble(input->GetPoints(), inputs.PointCopy);
  Cache& cache = *this->GraphCache;
  vtkDataArray* pointsArray = input->GetPoints()->GetData();
  if (cache.CheckedPoints != pointsArray || cache.CheckedPointsMTime != pointsArray->GetMTime())
  {
    if (!AllFinite(inputs.Points, 3 * n))
    {
      vtkErrorMacro("The input mesh has NaN or infinite point coordinates.");
      return false;
    }
    cache.CheckedPoints = pointsArray;
    cache.CheckedPointsMTime = pointsArray->GetMTime();
  }
  inputs.Dimension = dgmf_vtk::IsDistributed(this->Controller)
    ? this->DistributedDimension
    : DetectDimension(input, inputs.Points, n);
  if (inputs.Dimension < 0)
  {
    vtkErrorMacro("The mesh has no 3D cell but its points do not all have the same z: 2D meshes "
                  "must lie in a plane z = constant.");
    return false;
  }

  // The displacement (index 0) and the boundary marker (index 1).
  inputs.DisplacementName = SelectedArrayName(this, DisplacementArray);
  const std::string markerName = SelectedArrayName(this, MarkerArray);
  vtkDataArray* displacementArray = nullptr;
  vtkDataArray* markerArray = nullptr;
  if (!inputs.DisplacementName.empty())
  {
    displacementArray = input->GetPointData()->GetArray(inputs.DisplacementName.c_str());
    if (!displacementArray)
    {
      vtkErrorMacro("The displacement array '" << inputs.DisplacementName
                                               << "' is not a point array of the input.");
      return false;
    }
    if (displacementArray->GetNumberOfComponents() != 3)
    {
      vtkErrorMacro("The displacement array '" << inputs.DisplacementName << "' has "
                                               << displacementArray->GetNumberOfComponents()
                                               << " components; it must have 3.");
      return false;
    }
  }
  if (!markerName.empty())
  {
    markerArray = input->GetPointData()->GetArray(markerName.c_str());
    if (!markerArray)
    {
      vtkErrorMacro(
        "The boundary-marker array '" << markerName << "' is not a point array of the input.");
      return false;
    }
    if (markerArray->GetNumberOfComponents() != 1)
    {
      vtkErrorMacro("The boundary-marker array '"
        << markerName << "' must have 1 component (0 = interior, 1 = static boundary, "
        << "2 = moving boundary).");
      return false;
    }
  }
  if (!displacementArray && !markerArray)
  {
    vtkErrorMacro("Select a boundary-marker array (0 = interior, 1 = static, 2 = moving) or a "
                  "displacement array (boundary nodes with a non-zero displacement move).");
    return false;
  }
  if (displacementArray)
  {
    auto* doubles = vtkDoubleArray::SafeDownCast(displacementArray);
    if (doubles)
    {
      inputs.Displacement = doubles->GetPointer(0);
    }
    else
    {
      inputs.DisplacementCopy.resize(3 * n);
      for (vtkIdType i = 0; i < numberOfPoints; ++i)
      {
        displacementArray->GetTuple(i, inputs.DisplacementCopy.data() + 3 * i);
      }
      inputs.Displacement = inputs.DisplacementCopy.data();
    }
    if (!AllFinite(inputs.Displacement, 3 * n))
    {
      vtkErrorMacro(
        "The displacement array '" << inputs.DisplacementName << "' has NaN or infinite values.");
      return false;
    }
  }

  // The rigid motion.
  dgmf::RigidMotion& motion = inputs.Motion;
  for (int c = 0; c < 3; ++c)
  {
    motion.Translation[c] = this->Translation[c];
    motion.Center[c] = this->RotationCenter[c];
    motion.AnglesDegrees[c] = this->RotationAngles[c];
  }
  if (!AllFinite(motion.Translation, 3) || !AllFinite(motion.Center, 3) ||
    !AllFinite(motion.AnglesDegrees, 3))
  {
    vtkErrorMacro("Translation, RotationCenter and RotationAngles must be finite.");
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    if (std::abs(motion.AnglesDegrees[c]) > 720.0)
    {
      vtkErrorMacro("Rotation angles must be within [-720, 720] degrees (got "
        << motion.AnglesDegrees[c] << ").");
      return false;
    }
  }
  if (inputs.Dimension == 2)
  {
    if (motion.AnglesDegrees[0] != 0.0 || motion.AnglesDegrees[1] != 0.0 ||
      motion.Translation[2] != 0.0)
    {
      vtkErrorMacro("This is a 2D mesh (all points at z = "
        << inputs.Points[2] << "): it can only rotate about z and translate in x and y. Set the "
        << "rotation angles about x and y and the z translation to 0.");
      return false;
    }
    for (std::size_t i = 0; inputs.Displacement && i < 3 * n; i += 3)
    {
      if (inputs.Displacement[i + 2] != 0.0)
      {
        vtkErrorMacro("This is a 2D mesh, but the displacement array '"
          << inputs.DisplacementName << "' has a non-zero z component (node " << i / 3 << ").");
        return false;
      }
    }
  }

  // The kind of every node: from the marker, or from the mesh's boundary and the displacement.
  inputs.Kinds.assign(n, dgmf::NodeKind::Interior);
  if (markerArray && cache.Marker == markerArray && cache.MarkerMTime == markerArray->GetMTime() &&
    cache.MarkerKinds.size() == n)
  {
    inputs.Kinds = cache.MarkerKinds; // checked before
  }
  else if (markerArray)
  {
    vtkIdType bad = -1;
    double badValue = 0.0;
    MarkerToKinds worker;
    if (!vtkArrayDispatch::Dispatch::Execute(
          markerArray, worker, inputs.Kinds.data(), bad, badValue))
    {
      worker(
        markerArray, inputs.Kinds.data(), bad, badValue); // an array type outside the dispatch list
    }
    if (bad >= 0)
    {
      vtkErrorMacro("The boundary-marker array '"
        << markerName << "' has the value " << badValue << " at point " << bad
        << "; allowed values are 0 (interior), 1 (static boundary) and 2 (moving boundary).");
      return false;
    }
    cache.Marker = markerArray;
    cache.MarkerMTime = markerArray->GetMTime();
    cache.MarkerKinds = inputs.Kinds;
  }
  else
  {
    if (dgmf_vtk::IsDistributed(this->Controller) && !input->GetCellGhostArray())
    {
      vtkErrorMacro("In a distributed run without a boundary-marker array, the pieces need ghost "
                    "cells (e.g. ParaView's Ghost Cells Generator), or the faces between pieces "
                    "would be taken for the mesh's boundary. Add ghost cells or select a marker.");
      return false;
    }
    const std::vector<std::uint8_t> flags =
      dgmf_vtk::FlagBoundaryNodes(this->GetBoundaryFacets(input, inputs.Dimension), numberOfPoints);
    for (std::size_t i = 0; i < n; ++i)
    {
      if (flags[i])
      {
        const double* d = inputs.Displacement + 3 * i;
        inputs.Kinds[i] = (d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0)
          ? dgmf::NodeKind::MovingBoundary
          : dgmf::NodeKind::StaticBoundary;
      }
    }
  }
  if (!this->GatherBodyIds(input, inputs))
  {
    return false;
  }
  if (std::find(inputs.Kinds.begin(), inputs.Kinds.end(), dgmf::NodeKind::MovingBoundary) ==
    inputs.Kinds.end())
  {
    vtkWarningMacro("No node is marked as moving: the output has the input's points.");
  }
  return true;
}

void vtkDGMFDeformFilter::AppendRemoteBoundaryNodes(Inputs& inputs)
{
  const std::size_t n = inputs.LocalNodes;
  std::vector<dgmf_vtk::RemoteBoundaryNode> local;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (inputs.Kinds[i] == dgmf::NodeKind::Interior)
    {
      continue;
    }
    dgmf_vtk::RemoteBoundaryNode node;
    for (int c = 0; c < 3; ++c)
    {
      node.Position[c] = inputs.Points[3 * i + c];
      node.Displacement[c] = inputs.Displacement ? inputs.Displacement[3 * i + c] : 0.0;
    }
    node.Kind = static_cast<std::int32_t>(inputs.Kinds[i]);
    node.BodyId = inputs.BodyIds.empty() ? 0 : inputs.BodyIds[i];
    local.push_back(node);
  }
  const std::vector<dgmf_vtk::RemoteBoundaryNode> remote =
    dgmf_vtk::ExchangeBoundaryNodes(this->Controller, local);
  if (remote.empty())
  {
    return;
  }
  // A ghost node on the mesh's boundary may look interior here (its boundary face belongs to a
  // ghost cell, whose faces are left out): it takes the kind its owner found for it.
  {
    std::map<std::array<double, 3>, dgmf::NodeKind> remoteKind;
    for (const dgmf_vtk::RemoteBoundaryNode& node : remote)
    {
      auto& kind = remoteKind[{ node.Position[0], node.Position[1], node.Position[2] }];
      kind = std::max(kind, static_cast<dgmf::NodeKind>(node.Kind));
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      if (inputs.Kinds[i] == dgmf::NodeKind::Interior)
      {
        const auto found = remoteKind.find(
          { inputs.Points[3 * i], inputs.Points[3 * i + 1], inputs.Points[3 * i + 2] });
        if (found != remoteKind.end())
        {
          inputs.Kinds[i] = found->second;
        }
      }
    }
  }
  // The other pieces' boundary nodes follow this piece's nodes (coincident copies of the same
  // node, on several pieces, share one graph vertex).
  if (inputs.PointCopy.empty())
  {
    inputs.PointCopy.assign(inputs.Points, inputs.Points + 3 * n);
  }
  if (inputs.Displacement && inputs.DisplacementCopy.empty())
  {
    inputs.DisplacementCopy.assign(inputs.Displacement, inputs.Displacement + 3 * n);
  }
  for (const dgmf_vtk::RemoteBoundaryNode& node : remote)
  {
    inputs.PointCopy.insert(inputs.PointCopy.end(), node.Position, node.Position + 3);
    if (inputs.Displacement)
    {
      inputs.DisplacementCopy.insert(
        inputs.DisplacementCopy.end(), node.Displacement, node.Displacement + 3);
    }
    inputs.Kinds.push_back(static_cast<dgmf::NodeKind>(node.Kind));
    if (!inputs.BodyIds.empty())
    {
      inputs.BodyIds.push_back(node.BodyId);
      inputs.NumberOfBodies = std::max(inputs.NumberOfBodies, node.BodyId);
    }
  }
  inputs.Points = inputs.PointCopy.data();
  if (inputs.Displacement)
  {
    inputs.Displacement = inputs.DisplacementCopy.data();
  }
  inputs.NumberOfNodes = n + remote.size();
}

void vtkDGMFDeformFilter::ReduceAcrossProcesses(int& status, vtkUnstructuredGrid* output)
{
  vtkFieldData* fieldData = output->GetFieldData();
  auto value = [fieldData](const char* name)
  {
    vtkDataArray* array = fieldData->GetArray(name);
    return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : 0.0;
  };
  dgmf::QualitySummary summary;
  summary.Evaluated = static_cast<std::size_t>(value("SizeSkewEvaluatedCells"));
  summary.Sum = value("SizeSkewMean") * static_cast<double>(summary.Evaluated);
  summary.Minimum = value("SizeSkewMinimum");
  summary.Inverted = static_cast<std::size_t>(value("InvertedCellCount"));
  std::size_t outside = static_cast<std::size_t>(value("OutsideNodeCount"));
  bool ok = status != 0;
  dgmf_vtk::ReduceSummary(this->Controller, ok, summary, outside);
  status = ok ? 1 : 0;
  if (!ok)
  {
    output->Initialize();
    return;
  }
  auto set = [fieldData](const char* name, double v)
  {
    if (vtkDataArray* array = fieldData->GetArray(name))
    {
      array->SetTuple1(0, v);
    }
  };
  set("SizeSkewMean", summary.Mean);
  set("SizeSkewMinimum", summary.Minimum);
  set("InvertedCellCount", static_cast<double>(summary.Inverted));
  set("SizeSkewEvaluatedCells", static_cast<double>(summary.Evaluated));
  set("OutsideNodeCount", static_cast<double>(outside));
}

bool vtkDGMFDeformFilter::GatherBodyIds(vtkUnstructuredGrid* input, Inputs& inputs)
{
  const std::string name = SelectedArrayName(this, BodyIdArray);
  if (name.empty())
  {
    return true;
  }
  vtkDataArray* array = input->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    vtkErrorMacro("The body-id array '" << name << "' is not a point array of the input.");
    return false;
  }
  if (array->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The body-id array '" << name << "' must have 1 component.");
    return false;
  }
  const std::size_t n = inputs.NumberOfNodes;
  inputs.BodyIds.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double value = array->GetTuple1(static_cast<vtkIdType>(i));
    if (!(value >= 0.0) || value != std::floor(value) || value > 1e6)
    {
      vtkErrorMacro("The body-id array '" << name << "' has the value " << value << " at point "
                                          << i << "; body ids are 0 (no body) or 1, 2, ...");
      return false;
    }
    const auto id = static_cast<std::int32_t>(value);
    inputs.BodyIds[i] = id;
    inputs.NumberOfBodies = std::max(inputs.NumberOfBodies, id);
    // A node on a body is a moving boundary node; the other boundary nodes are static.
    dgmf::NodeKind& kind = inputs.Kinds[i];
    if (id > 0 && kind == dgmf::NodeKind::Interior)
    {
      vtkErrorMacro("Point " << i << " has the body id " << id
                             << " but is not a boundary node (marker 0, or not on the boundary).");
      return false;
    }
    if (id > 0)
    {
      kind = dgmf::NodeKind::MovingBoundary;
    }
    else if (kind == dgmf::NodeKind::MovingBoundary)
    {
      if (SelectedArrayName(this, MarkerArray).empty())
      {
        kind = dgmf::NodeKind::StaticBoundary; // no body: static, whatever its displacement
      }
      else
      {
        vtkErrorMacro("Point " << i << " is marked moving (2) but has the body id 0.");
        return false;
      }
    }
  }
  return true;
}

const dgmf_vtk::BoundaryFacets& vtkDGMFDeformFilter::GetBoundaryFacets(
  vtkUnstructuredGrid* input, int dimension)
{
  Cache& cache = *this->GraphCache;
  vtkCellArray* cells = input->GetCells();
  auto hashCells = [&]()
  {
    std::uint64_t h = HashArray(cells->GetConnectivityArray());
    h = HashArray(cells->GetOffsetsArray(), h);
    return HashArray(input->GetCellTypesArray(), h);
  };
  if (!cache.Facets || !cache.Cells.Matches(cells, hashCells))
  {
    cache.Facets =
      std::make_unique<dgmf_vtk::BoundaryFacets>(dgmf_vtk::FindBoundaryFacets(input, dimension));
    cache.Cells.Set(cells, hashCells);
  }
  return *cache.Facets;
}

namespace
{
/// The mesh's hint stride for the point location (dgmf::FindHintStride), from up to 4,096 cells
/// spread over the mesh.
std::size_t HintStrideOf(vtkUnstructuredGrid* mesh)
{
  const vtkIdType cells = mesh->GetNumberOfCells();
  const vtkIdType samples = std::min<vtkIdType>(cells, 4096);
  std::vector<std::vector<std::int64_t>> sampled;
  sampled.reserve(static_cast<std::size_t>(samples));
  for (vtkIdType s = 0; s < samples; ++s)
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    mesh->GetCellPoints(s * cells / samples, count, ids);
    sampled.emplace_back(ids, ids + count);
  }
  return dgmf::FindHintStride(sampled);
}
} // namespace

bool vtkDGMFDeformFilter::UpdateMapping(
  vtkUnstructuredGrid* input, Inputs& inputs, vtkUnstructuredGrid* output)
{
  Cache& cache = *this->GraphCache;
  vtkDataArray* pointsArray = input->GetPoints()->GetData();
  auto hashPoints = [&]()
  { return HashBytes(inputs.Points, 3 * inputs.NumberOfNodes * sizeof(double)); };
  const bool reuse = cache.Mapping && cache.Dimension == inputs.Dimension &&
    cache.Mapping->GetNodeKinds() == inputs.Kinds && cache.Points.Matches(pointsArray, hashPoints);
  this->LastExecutionReusedGraph = reuse;
  if (reuse)
  {
    return true;
  }
  cache.Mapping.reset();
  // The output's points, r and f are allocated now and first touched while the graph is built
  // (on another thread): the page faults of a few hundred megabytes are then off the critical
  // path. They are computed later (StaticR0 and Damping mark them as not computed).
  const std::size_t n = inputs.NumberOfNodes;
  cache.StaticR0 = std::numeric_limits<double>::quiet_NaN();
  cache.Damping = 0;
  std::vector<vtkDoubleArray*> prepared;
  prepared.push_back(
    vtkDoubleArray::SafeDownCast(OutputPointsFor(cache.OutputPoints, input, output, n)->GetData()));
  if (this->Method == DGMF)
  {
    if (inputs.NumberOfBodies == 0 && this->RigidMotionMode != EXTRACTED)
    {
      prepared.push_back(FreshArray(cache.R, "r", n)); // r has no meaning with several bodies
    }
    prepared.push_back(FreshArray(cache.F, "f", n));
  }
  // The cache key's hash of the points is computed there too.
  std::uint64_t pointsHash = 0;
  auto touch = [&prepared, &pointsHash, &hashPoints]()
  {
    for (vtkDoubleArray* array : prepared)
    {
      std::memset(
        array->GetPointer(0), 0, static_cast<std::size_t>(array->GetDataSize()) * sizeof(double));
    }
    pointsHash = hashPoints();
  };
  cache.Mapping = std::make_unique<dgmf::DelaunayMapping>(inputs.Dimension, inputs.Points,
    inputs.NumberOfNodes, inputs.Kinds.data(), inputs.Parallel, HintStrideOf(input), touch);
  cache.Points.Set(pointsArray, [pointsHash]() { return pointsHash; });
  cache.Dimension = inputs.Dimension;
  const dgmf::DelaunayMapping& mapping = *cache.Mapping;
  this->LastGraphSeconds = mapping.GetGraphSeconds();
  this->LastLocationSeconds = mapping.GetLocationSeconds();
  if (mapping.GetNumberOfConflictingNodes() > 0)
  {
    vtkWarningMacro(<< mapping.GetNumberOfConflictingNodes()
                    << " static boundary nodes coincide with moving ones; they stay in place, and "
                       "their shared graph vertex moves.");
  }
  if (mapping.GetNumberOfOutsideNodes() > 0)
  {
    vtkWarningMacro(<< mapping.GetNumberOfOutsideNodes()
                    << " nodes lie outside the Delaunay graph of the boundary nodes (is the whole "
                       "outer boundary marked?); they use the nearest hull element.");
  }
  return true;
}

namespace
{
const char* MethodName(int method)
{
  static const char* const names[] = { "DGMF", "DGM", "DGRBF", "RBF", "IDW" };
  return names[method];
}
} // namespace

void vtkDGMFDeformFilter::UpdateDampingField(Inputs& inputs)
{
  // r depends on r0s, f on r and the damping function: both are kept, and shared with the
  // output (written anew only when nothing else holds them, see FreshArray).
  Cache& cache = *this->GraphCache;
  const std::size_t n = inputs.NumberOfNodes;
  if (!cache.R || cache.StaticR0 != this->StaticBoundaryR0)
  {
    dgmf::ComputeBoundaryDistanceField(*cache.Mapping, this->StaticBoundaryR0,
      FreshArray(cache.R, "r", n)->GetPointer(0), inputs.Parallel);
    cache.StaticR0 = this->StaticBoundaryR0;
    cache.Damping = 0; // f follows r
  }
  if (!cache.F || cache.Damping != this->DampingFunction)
  {
    dgmf::ComputeDampingFactor(*cache.Mapping,
      static_cast<dgmf::DampingFunction>(this->DampingFunction), cache.R->GetPointer(0),
      FreshArray(cache.F, "f", n)->GetPointer(0), inputs.Parallel);
    cache.Damping = this->DampingFunction;
  }
}

bool vtkDGMFDeformFilter::Deform(
  vtkUnstructuredGrid* input, Inputs& inputs, vtkUnstructuredGrid* output)
{
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const std::size_t n = inputs.NumberOfNodes;
  const double* displacement = inputs.Displacement;
  const vtkSmartPointer<vtkPoints> newPoints =
    OutputPointsFor(this->GraphCache->OutputPoints, input, output, n);
  vtkDoubleArray* newCoordinates = vtkDoubleArray::SafeDownCast(newPoints->GetData());
  double* out = newCoordinates->GetPointer(0);

  // Copy the input's structure and arrays first; the method adds its own arrays and values.
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());
  vtkFieldData* fieldData = output->GetFieldData();

  const bool largeMotion = this->SubSteps != 1 || this->RepairThreshold > 0.0;
  if (this->Method == DGMF && largeMotion)
  {
    if (inputs.NumberOfBodies > 0 || this->RigidMotionMode == EXTRACTED)
    {
      vtkErrorMacro("Sub-steps and the quality guard work with one body whose motion is given by "
                    "the properties (no body-id array, RigidMotionMode Properties).");
      return false;
    }
    Cache& cache = *this->GraphCache;
    if (!this->DeformInSubSteps(input, inputs, fieldData, out))
    {
      return false;
    }
    // r and f describe the input mesh's graph (the first step).
    this->UpdateDampingField(inputs);
    output->GetPointData()->AddArray(cache.R);
    output->GetPointData()->AddArray(cache.F);
    AddFieldCount(fieldData, "OutsideNodeCount", cache.Mapping->GetNumberOfOutsideNodes());
  }
  else if (this->Method == DGMF &&
    (inputs.NumberOfBodies > 0 || this->RigidMotionMode == EXTRACTED))
  {
    if (!this->DeformBodies(inputs, fieldData, out))
    {
      return false;
    }
    output->GetPointData()->AddArray(this->GraphCache->F);
    AddFieldCount(
      fieldData, "OutsideNodeCount", this->GraphCache->Mapping->GetNumberOfOutsideNodes());
  }
  else if (this->Method == DGMF)
  {
    Cache& cache = *this->GraphCache;
    const dgmf::DelaunayMapping& mapping = *cache.Mapping;
    this->UpdateDampingField(inputs);
    dgmf::DeformDGMF(mapping, cache.F->GetPointer(0), inputs.Motion, displacement,
      static_cast<dgmf::DeformationMode>(this->DeformationMode), inputs.Points, out,
      inputs.Parallel);
    output->GetPointData()->AddArray(cache.R);
    output->GetPointData()->AddArray(cache.F);
    AddFieldCount(fieldData, "OutsideNodeCount", mapping.GetNumberOfOutsideNodes());
  }
  else
  {
    // The comparison methods interpolate the total boundary motion.
    std::vector<double> total;
    const dgmf::RigidMotion* motion = &inputs.Motion;
    const dgmf::RigidMotion none;
    if (inputs.NumberOfBodies > 0 || this->RigidMotionMode == EXTRACTED)
    {
      // Each moving node's total displacement: its body's motion (or, extracted, the array itself).
      total = this->TotalBodyDisplacement(inputs);
      displacement = total.data();
      motion = &none;
    }
    dgmf::BoundaryMotion boundary = dgmf::GatherBoundaryMotion(
      inputs.Dimension, inputs.Points, n, inputs.Kinds.data(), *motion, displacement);
    if (this->Method == DGM)
    {
      const dgmf::DelaunayMapping& mapping = *this->GraphCache->Mapping;
      const std::size_t inverted =
        dgmf::DeformDGM(mapping, boundary, inputs.Points, out, inputs.Parallel);
      AddFieldCount(fieldData, "InvertedGraphElementCount", inverted);
      AddFieldCount(fieldData, "OutsideNodeCount", mapping.GetNumberOfOutsideNodes());
      if (inverted > 0)
      {
        vtkWarningMacro(<< inverted
                        << " Delaunay graph elements are inverted by the motion: "
                           "DGM's mesh may be invalid (see InvertedCellCount).");
      }
    }
    else if (this->Method == DGRBF)
    {
      const dgmf::DelaunayMapping& mapping = *this->GraphCache->Mapping;
      dgmf::DeformDGRBF(
        mapping, boundary, this->SupportRadius, inputs.Points, out, inputs.Parallel);
      AddFieldCount(fieldData, "OutsideNodeCount", mapping.GetNumberOfOutsideNodes());
    }
    else if (this->Method == RBF)
    {
      dgmf::RBFParameters parameters;
      parameters.SupportRadius = this->SupportRadius;
      parameters.Greedy = this->RBFGreedy;
      parameters.GreedyTolerance = this->RBFGreedyTolerance;
      parameters.GreedyMaximumPoints = static_cast<std::size_t>(this->RBFGreedyMaximumPoints);
      const dgmf::RBFInterpolation rbf(boundary, parameters);
      dgmf::DeformRBF(rbf, inputs.Points, n, out, inputs.Parallel);
      AddFieldCount(fieldData, "RBFCentreCount", rbf.GetNumberOfCentres());
      AddFieldValue(fieldData, "RBFBoundaryError", rbf.GetBoundaryError());
    }
    else
    {
      const std::vector<double> weights =
        dgmf_vtk::ComputeBoundaryNodeWeights(this->GetBoundaryFacets(input, inputs.Dimension),
          inputs.Points, static_cast<vtkIdType>(n), inputs.Dimension);
      boundary.Weights.resize(boundary.Size());
      for (std::size_t b = 0; b < boundary.Size(); ++b)
      {
        // A marked node that is on no boundary facet counts as an average node.
        boundary.Weights[b] = weights[static_cast<std::size_t>(boundary.Nodes[b])];
      }
      FillMissingWeights(boundary.Weights);
      dgmf::IDWParameters parameters;
      parameters.Alpha = this->IDWAlpha;
      parameters.ReferenceLength = this->IDWReferenceLength;
      const double referenceLength =
        dgmf::DeformIDW(boundary, parameters, inputs.Points, n, out, inputs.Parallel);
      AddFieldValue(fieldData, "IDWReferenceLength", referenceLength);
    }
  }
  const Clock::time_point deformed = Clock::now();
  this->LastDeformationSeconds = std::chrono::duration<double>(deformed - start).count();
  if (this->Method == DGMF || this->Method == DGM || this->Method == DGRBF)
  {
    AddFieldCount(fieldData, "GraphReused", this->LastExecutionReusedGraph ? 1 : 0);
  }
  vtkNew<vtkStringArray> methodName;
  methodName->SetName("Method");
  methodName->InsertNextValue(MethodName(this->Method));
  fieldData->AddArray(methodName);
  this->UpdateProgress(0.8);

  // A distributed run also deformed the other pieces' boundary nodes: keep this piece's nodes.
  const auto localNodes = static_cast<vtkIdType>(inputs.LocalNodes);
  if (inputs.LocalNodes < inputs.NumberOfNodes)
  {
    newCoordinates->Resize(localNodes);
    newCoordinates->SetNumberOfTuples(localNodes);
    for (const char* name : { "r", "f" })
    {
      if (vtkDataArray* shared = output->GetPointData()->GetArray(name))
      {
        vtkNew<vtkDoubleArray> local;
        local->SetName(name);
        local->SetNumberOfTuples(localNodes);
        for (vtkIdType i = 0; i < localNodes; ++i)
        {
          local->SetValue(i, shared->GetTuple1(i));
        }
        output->GetPointData()->AddArray(local);
      }
    }
  }
  newCoordinates->Modified();
  newPoints->Modified();
  output->SetPoints(newPoints);

  if (this->ComputeQuality)
  {
    vtkNew<vtkDoubleArray> sizeSkew;
    sizeSkew->SetName("SizeSkew");
    vtkNew<vtkUnsignedCharArray> inverted;
    inverted->SetName("Inverted");
    const dgmf::QualitySummary summary =
      dgmf_vtk::ComputeCellQuality(input, inputs.Points, out, sizeSkew, inverted, inputs.Parallel);
    output->GetCellData()->AddArray(sizeSkew);
    output->GetCellData()->AddArray(inverted);
    AddFieldValue(fieldData, "SizeSkewMean", summary.Mean);
    AddFieldValue(fieldData, "SizeSkewMinimum", summary.Minimum);
    AddFieldCount(fieldData, "InvertedCellCount", summary.Inverted);
    AddFieldCount(fieldData, "SizeSkewEvaluatedCells", summary.Evaluated);
    this->LastQualitySeconds = std::chrono::duration<double>(Clock::now() - deformed).count();
    if (this->FailOnInvertedCells && summary.Inverted > 0)
    {
      vtkErrorMacro(
        "The deformation inverts " << summary.Inverted << " cells (FailOnInvertedCells is on).");
      return false;
    }
  }
  this->UpdateProgress(1.0);
  return true;
}

void vtkDGMFDeformFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << MethodName(this->Method) << "\n";
  os << indent << "DampingFunction: U" << this->DampingFunction << "\n";
  os << indent << "StaticBoundaryR0: " << this->StaticBoundaryR0 << "\n";
  os << indent << "Translation: (" << this->Translation[0] << ", " << this->Translation[1] << ", "
     << this->Translation[2] << ")\n";
  os << indent << "RotationCenter: (" << this->RotationCenter[0] << ", " << this->RotationCenter[1]
     << ", " << this->RotationCenter[2] << ")\n";
  os << indent << "RotationAngles: (" << this->RotationAngles[0] << ", " << this->RotationAngles[1]
     << ", " << this->RotationAngles[2] << ")\n";
  os << indent << "DeformationMode: DGMF" << this->DeformationMode << "\n";
  os << indent
     << "RigidMotionMode: " << (this->RigidMotionMode == EXTRACTED ? "Extracted" : "Properties")
     << " (" << this->PerBodyMotions->Motions.size() << " body motions set)\n";
  os << indent << "SupportRadius: " << this->SupportRadius << "\n";
  os << indent << "RBFGreedy: " << (this->RBFGreedy ? "on" : "off") << "\n";
  os << indent << "RBFGreedyTolerance: " << this->RBFGreedyTolerance << "\n";
  os << indent << "RBFGreedyMaximumPoints: " << this->RBFGreedyMaximumPoints << "\n";
  os << indent << "IDWAlpha: " << this->IDWAlpha << "\n";
  os << indent << "IDWReferenceLength: " << this->IDWReferenceLength << "\n";
  os << indent << "SubSteps: " << this->SubSteps << "\n";
  os << indent << "RepairThreshold: " << this->RepairThreshold << " (layers " << this->RepairLayers
     << ", passes " << this->RepairPasses << ")\n";
  os << indent << "ComputeQuality: " << (this->ComputeQuality ? "on" : "off") << "\n";
  os << indent << "FailOnInvertedCells: " << (this->FailOnInvertedCells ? "on" : "off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
