// dgmf-core-fingerprint: prints one 64-bit hash of the bits of every result of the core on fixed
// problems (location, every method, several bodies, the quality metric with its two-hexahedra
// path, the quality guard, sub-steps, OpenFOAM's non-orthogonality). Two builds whose fingerprints
// agree compute the same bits: scripts/run-portability-tests.sh compares the main build (GCC,
// vector types) with a build by Clang with the scalar fallback of dgmf/Simd.h forced on.
#include "HexFaceCells.h"
#include "SyntheticNodes.h"
#include "TwoBodyNodes.h"

#include "dgmf/DeformationMethod.h"
#include "dgmf/DelaunayMapping.h"
#include "dgmf/LocalRepair.h"
#include "dgmf/NonOrthogonality.h"
#include "dgmf/ResultNames.h"
#include "dgmf/Simd.h"
#include "dgmf/SizeSkewQuality.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

namespace
{
/// FNV-1a over raw bytes: the fingerprint of everything fed to it.
class Fingerprint
{
public:
  void Add(const void* data, std::size_t bytes)
  {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k)
    {
      this->Hash = (this->Hash ^ p[k]) * 0x100000001b3ull;
    }
  }
  template <typename T>
  void Add(const std::vector<T>& values)
  {
    this->Add(values.data(), values.size() * sizeof(T));
  }
  std::uint64_t Hash = 0xcbf29ce484222325ull;
};

std::vector<double> Deform(dgmf::Method method, const dgmf::MethodParameters& parameters,
  const dgmf::DeformationProblem& problem, const dgmf::DelaunayMapping* mapping,
  Fingerprint& fingerprint)
{
  std::vector<double> deformed(3 * problem.NumberOfNodes);
  dgmf::VectorFieldStore fields(problem.NumberOfNodes);
  const dgmf::DeformationReport report =
    dgmf::CreateMethod(method, parameters)
      ->Deform(
        problem, mapping, dgmf::DeformationOutputs{ deformed.data(), &fields }, dgmf::SerialFor);
  fingerprint.Add(deformed);
  fingerprint.Add(fields.Get(dgmf::names::R));
  fingerprint.Add(fields.Get(dgmf::names::F));
  for (const dgmf::ReportedValue& value : report.Values)
  {
    fingerprint.Add(value.Values);
  }
  return deformed;
}

void Methods(const dgmf_test::NodeSet& set, Fingerprint& fingerprint)
{
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const std::int32_t element = mapping.IsBoundaryNode(i) ? -1 : mapping.GetElementOfNode(i);
    fingerprint.Add(&element, sizeof element);
    fingerprint.Add(mapping.GetWeights(i), sizeof(double) * (set.Dimension + 1));
  }
  dgmf::DeformationProblem problem;
  problem.Dimension = set.Dimension;
  problem.NumberOfNodes = set.Size();
  problem.Points = set.Points.data();
  problem.Kinds = set.Kinds.data();
  std::vector<double> displacement(set.Points.size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    displacement[3 * i] = 0.01 * set.Points[3 * i + 1];
    displacement[3 * i + 1] = -0.02 * set.Points[3 * i];
  }
  problem.Displacement = displacement.data();
  problem.Motions[0].Center[0] = 0.1;
  problem.Motions[0].Translation[1] = 0.3;
  problem.Motions[0].AnglesDegrees[2] = 70.0; // beyond the short Taylor series
  if (set.Dimension == 3)
  {
    problem.Motions[0].AnglesDegrees[0] = 25.0;
    problem.Motions[0].AnglesDegrees[1] = -10.0;
  }
  dgmf::MethodParameters parameters;
  for (const dgmf::MethodInfo& method : dgmf::GetMethods())
  {
    Deform(method.Id, parameters, problem, &mapping, fingerprint);
  }
  parameters.Mode = dgmf::DeformationMode::DGMF1;
  parameters.Damping = dgmf::DampingFunction::U3;
  Deform(dgmf::Method::DGMF, parameters, problem, &mapping, fingerprint);
  problem.Motions[0] = dgmf::RigidMotion(); // an axis rotation, of 5 degrees (short series)
  problem.Motions[0].Axis[0] = set.Dimension == 3 ? 1.0 : 0.0;
  problem.Motions[0].Axis[2] = 1.0;
  problem.Motions[0].AxisAngleDegrees = 5.0;
  Deform(dgmf::Method::DGMF, dgmf::MethodParameters(), problem, &mapping, fingerprint);
}

void Bodies(Fingerprint& fingerprint)
{
  const dgmf_test::BodyNodeSet set = dgmf_test::TwoCirclesInSquare(32, 12, 1500);
  const dgmf::DelaunayMapping mapping(
    set.Dimension, set.Points.data(), set.Size(), set.Kinds.data(), dgmf::SerialFor);
  dgmf::DeformationProblem problem;
  problem.Dimension = set.Dimension;
  problem.NumberOfNodes = set.Size();
  problem.Points = set.Points.data();
  problem.Kinds = set.Kinds.data();
  problem.BodyIds = set.BodyIds.data();
  problem.NumberOfBodies = 2;
  problem.Motions.resize(2);
  problem.Motions[0].AnglesDegrees[2] = 45.0;
  problem.Motions[1].AnglesDegrees[2] = -30.0;
  problem.Motions[1].Translation[0] = 0.2;
  Deform(dgmf::Method::DGMF, dgmf::MethodParameters(), problem, &mapping, fingerprint);
  // The same motions given as displacements, extracted.
  std::vector<double> displacement(set.Points.size(), 0.0);
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    if (set.BodyIds[i] > 0)
    {
      double moved[3];
      problem.Motions[static_cast<std::size_t>(set.BodyIds[i] - 1)].Apply(
        1.0, set.Points.data() + 3 * i, nullptr, moved);
      for (int c = 0; c < 3; ++c)
      {
        displacement[3 * i + c] = moved[c] - set.Points[3 * i + c];
      }
    }
  }
  problem.Displacement = displacement.data();
  problem.ExtractRigidMotion = true;
  Deform(dgmf::Method::DGMF, dgmf::MethodParameters(), problem, &mapping, fingerprint);
}

/// Random hexahedra, tetrahedra and wedges around a unit cell, their quality (pairs of
/// hexahedra too), and the quality guard on a tangled grid of hexahedra.
void Quality(Fingerprint& fingerprint)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const double cube[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  std::vector<double> values;
  for (int trial = 0; trial < 500; ++trial)
  {
    double original[2][24], deformed[2][24];
    for (int h = 0; h < 2; ++h)
    {
      for (int k = 0; k < 8; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          original[h][3 * k + c] = cube[k][c] + 0.1 * jitter(random);
          deformed[h][3 * k + c] = original[h][3 * k + c] + jitter(random);
        }
      }
    }
    // Two hexahedra through the four-lane batch (its last lanes repeat the second cell).
    const double* originals[2] = { original[0], original[1] };
    const double* deformeds[2] = { deformed[0], deformed[1] };
    double references[2];
    dgmf::ComputeHexReferenceSizes(2, originals, references);
    dgmf::CellQuality hexahedra[2];
    dgmf::ComputeHexSizeSkew(2, references, deformeds, hexahedra);
    const dgmf::CellQuality& a = hexahedra[0];
    const dgmf::CellQuality& b = hexahedra[1];
    values.insert(values.end(), { a.SizeSkew, b.SizeSkew, a.Inverted ? 1.0 : 0.0 });
    for (dgmf::CellShape shape : { dgmf::CellShape::Tetra, dgmf::CellShape::Wedge,
           dgmf::CellShape::Pyramid, dgmf::CellShape::Quad, dgmf::CellShape::Triangle })
    {
      values.push_back(dgmf::ComputeSizeSkew(shape, original[0], deformed[0]).SizeSkew);
    }
  }
  fingerprint.Add(values);

  // A 6 x 6 x 6 grid of hexahedra whose centre node is pushed through its neighbours.
  const int n = 7;
  dgmf::CellMesh mesh;
  std::vector<double> points;
  std::vector<dgmf::NodeKind> kinds;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        points.insert(points.end(), { double(i), double(j), double(k) });
        const bool boundary = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
        kinds.push_back(boundary ? dgmf::NodeKind::StaticBoundary : dgmf::NodeKind::Interior);
      }
  mesh.NumberOfPoints = kinds.size();
  mesh.Offsets.push_back(0);
  const auto id = [n](int i, int j, int k) { return std::int64_t(i + n * (j + n * k)); };
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i)
      {
        mesh.Connectivity.insert(mesh.Connectivity.end(),
          { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
            id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) });
        mesh.Offsets.push_back(static_cast<std::int64_t>(mesh.Connectivity.size()));
        mesh.Shapes.push_back(dgmf::CellShape::Hexahedron);
      }
  std::vector<double> tangled = points;
  tangled[3 * id(3, 3, 3)] += 1.6;
  tangled[3 * id(3, 3, 3) + 1] -= 0.7;
  dgmf::RepairParameters repair;
  repair.Threshold = 0.3;
  const dgmf::RepairReport report =
    dgmf::RepairCells(mesh, points.data(), tangled.data(), kinds.data(), repair, dgmf::SerialFor);
  fingerprint.Add(tangled);
  fingerprint.Add(&report.MinimumAfter, sizeof report.MinimumAfter);

  // The same grid in tetrahedra (six per hexahedron, around its diagonal 0-6), the same node
  // pushed: the guard judges tetrahedra through their forms, four at a time.
  dgmf::CellMesh tetrahedra;
  tetrahedra.NumberOfPoints = mesh.NumberOfPoints;
  tetrahedra.Offsets.push_back(0);
  constexpr int kSplit[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 }, { 0, 7, 4, 6 },
    { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
  for (std::size_t c = 0; c + 1 < mesh.Offsets.size(); ++c)
  {
    const std::int64_t* hex = mesh.Connectivity.data() + mesh.Offsets[c];
    for (const auto& tetra : kSplit)
    {
      for (int corner : tetra)
      {
        tetrahedra.Connectivity.push_back(hex[corner]);
      }
      tetrahedra.Offsets.push_back(static_cast<std::int64_t>(tetrahedra.Connectivity.size()));
      tetrahedra.Shapes.push_back(dgmf::CellShape::Tetra);
    }
  }
  std::vector<double> tangledTetrahedra = points;
  tangledTetrahedra[3 * id(3, 3, 3)] += 1.6;
  tangledTetrahedra[3 * id(3, 3, 3) + 1] -= 0.7;
  const dgmf::RepairReport tetraReport = dgmf::RepairCells(
    tetrahedra, points.data(), tangledTetrahedra.data(), kinds.data(), repair, dgmf::SerialFor);
  fingerprint.Add(tangledTetrahedra);
  fingerprint.Add(&tetraReport.MinimumAfter, sizeof tetraReport.MinimumAfter);
}

/// OpenFOAM's non-orthogonality of a block of 7 x 6 x 5 hexahedra with jittered points, before
/// and after a twist: the input's orientation and angles, and every cell's largest angle.
void NonOrthogonality(Fingerprint& fingerprint)
{
  const int nx = 7, ny = 6, nz = 5;
  const auto id = [&](int i, int j, int k)
  { return static_cast<std::int64_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<double> points, twisted;
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        const double x = i + jitter(random), y = j + jitter(random), z = k + jitter(random);
        points.insert(points.end(), { x, y, z });
        const double angle = 0.05 * z;
        twisted.insert(twisted.end(),
          { std::cos(angle) * x - std::sin(angle) * y, std::sin(angle) * x + std::cos(angle) * y,
            z });
      }
    }
  }
  dgmf_test::HexFaceCells cells;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        cells.Corners.push_back(
          { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
            id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) });
      }
    }
  }
  const dgmf::InternalFaces faces =
    dgmf::FindInternalFaces(cells, points.size() / 3, dgmf::SerialFor);
  const dgmf::InputOrientation orientation =
    dgmf::OrientCells(cells, faces, points.data(), dgmf::SerialFor);
  fingerprint.Add(orientation.CellSign);
  fingerprint.Add(&orientation.InputMaximum, sizeof orientation.InputMaximum);
  const dgmf::NonOrthogonalityResult result =
    dgmf::ComputeNonOrthogonality(cells, faces, orientation, twisted.data(), dgmf::SerialFor);
  fingerprint.Add(result.CellMaximum);
  fingerprint.Add(&result.Maximum, sizeof result.Maximum);
}
} // namespace

int main()
{
  Fingerprint fingerprint;
  Methods(dgmf_test::CircleInSquare(48, 16, 2500), fingerprint);
  Methods(dgmf_test::SphereInBox(3000), fingerprint);
  Bodies(fingerprint);
  Quality(fingerprint);
  NonOrthogonality(fingerprint);
  std::printf("%016llx (%s two-lane doubles)\n", static_cast<unsigned long long>(fingerprint.Hash),
    dgmf::simd::IsVectorized ? "vector" : "scalar");
  return 0;
}
