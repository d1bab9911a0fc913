#include "DGMFFilterParameters.h"

#include "DGMFInputNodes.h"
#include "vtkDGMFDeformFilter.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

// The filter's enumerations are the core's values.
static_assert(vtkDGMFDeformFilter::DGMF == static_cast<int>(dgmf::Method::DGMF) &&
    vtkDGMFDeformFilter::DGM == static_cast<int>(dgmf::Method::DGM) &&
    vtkDGMFDeformFilter::DGRBF == static_cast<int>(dgmf::Method::DGRBF) &&
    vtkDGMFDeformFilter::RBF == static_cast<int>(dgmf::Method::RBF) &&
    vtkDGMFDeformFilter::IDW == static_cast<int>(dgmf::Method::IDW),
  "Methods must match Filters/DGMFCore/dgmf/MethodTable.def");
static_assert(vtkDGMFDeformFilter::U1 == static_cast<int>(dgmf::DampingFunction::U1) &&
    vtkDGMFDeformFilter::U7 == static_cast<int>(dgmf::DampingFunction::U7) &&
    vtkDGMFDeformFilter::DGMF1 == static_cast<int>(dgmf::DeformationMode::DGMF1) &&
    vtkDGMFDeformFilter::DGMF2 == static_cast<int>(dgmf::DeformationMode::DGMF2),
  "DampingFunctions and DeformationModes must match the core's");

namespace dgmf_vtk
{

dgmf::Method MethodOf(vtkDGMFDeformFilter* filter)
{
  return static_cast<dgmf::Method>(filter->GetMethod());
}

std::string SettingsError(vtkDGMFDeformFilter* filter)
{
  return filter->GetFailOnInvertedCells() && !filter->GetComputeQuality()
    ? "Fail On Inverted Cells needs Compute Quality (the quality metric counts the inverted "
      "cells): turn Compute Quality on."
    : "";
}

std::string SettingsWarning(vtkDGMFDeformFilter* filter)
{
  if (filter->GetMethod() == vtkDGMFDeformFilter::DGMF ||
    (filter->GetSubSteps() == 1 && filter->GetRepairThreshold() <= 0.0))
  {
    return "";
  }
  return std::string("Sub Steps and Repair Threshold are DGMF's (the quality guard and the "
                     "sub-steps need its damping field): ignored by ") +
    dgmf::GetMethodInfo(MethodOf(filter)).Name + ".";
}

dgmf::MethodParameters MethodParametersOf(vtkDGMFDeformFilter* filter)
{
  dgmf::MethodParameters p;
  p.Damping = static_cast<dgmf::DampingFunction>(filter->GetDampingFunction());
  p.StaticR0 = filter->GetStaticBoundaryR0();
  p.Mode = static_cast<dgmf::DeformationMode>(filter->GetDeformationMode());
  p.SubSteps = filter->GetSubSteps();
  p.RepairThreshold = filter->GetRepairThreshold();
  p.RepairLayers = filter->GetRepairLayers();
  p.RepairPasses = filter->GetRepairPasses();
  p.SupportRadius = filter->GetSupportRadius();
  p.RBFGreedy = filter->GetRBFGreedy();
  p.RBFGreedyTolerance = filter->GetRBFGreedyTolerance();
  p.RBFGreedyMaximumPoints = static_cast<std::size_t>(filter->GetRBFGreedyMaximumPoints());
  p.IDWAlpha = filter->GetIDWAlpha();
  p.IDWReferenceLength = filter->GetIDWReferenceLength();
  return p;
}

bool BodyMotionTable::Set(
  double bodyId, const double translation[3], const double center[3], const double anglesDegrees[3])
{
  if (!(bodyId >= 1.0) || bodyId != std::floor(bodyId) || bodyId > 1e6)
  {
    // Kept until the rows are cleared: every execution fails, instead of moving the mesh without
    // the row.
    std::ostringstream message;
    message << "Body Motions has a row for the body id " << bodyId
            << ": body ids are 1, 2, ... (the body-id array, or the moving boundaries in the "
               "order named).";
    this->BadRow = message.str();
    return false;
  }
  dgmf::RigidMotion& motion = this->Motions[static_cast<int>(bodyId)];
  std::copy_n(translation, 3, motion.Translation);
  std::copy_n(center, 3, motion.Center);
  std::copy_n(anglesDegrees, 3, motion.AnglesDegrees);
  return true;
}

bool BodyMotionTable::Clear()
{
  const bool any = !this->Motions.empty() || !this->BadRow.empty();
  this->Motions.clear();
  this->BadRow.clear();
  return any;
}

namespace
{
/// How bodies are numbered, for the messages about a body the mesh does not have.
constexpr const char* BodyNumbering =
  " (numbered from 1: the body-id array, Body Id Array or dgmf-deform's --body-id, or the moving "
  "boundaries in the order named).";
} // namespace

bool BodyMotionTable::PropertiesMove(
  vtkDGMFDeformFilter* filter, const InputNodes& nodes, const dgmf::Trajectory* trajectory) const
{
  const bool rows = filter->GetRigidMotionMode() == vtkDGMFDeformFilter::PROPERTIES;
  for (std::int32_t k = 1; k <= std::max<std::int32_t>(nodes.NumberOfBodies, 1); ++k)
  {
    if (!(rows && this->Motions.count(k) > 0) && !(trajectory && trajectory->HasBody(k)))
    {
      return true;
    }
  }
  return false;
}

std::vector<dgmf::RigidMotion> BodyMotionTable::For(vtkDGMFDeformFilter* filter,
  const InputNodes& nodes, const dgmf::RigidMotion& properties, const dgmf::Trajectory* trajectory,
  double t) const
{
  const std::int32_t bodies = std::max<std::int32_t>(nodes.NumberOfBodies, 1);
  // The rows count in Properties mode only (Extracted mode fits the motions instead).
  const bool rows = filter->GetRigidMotionMode() == vtkDGMFDeformFilter::PROPERTIES;
  if (rows && !this->BadRow.empty())
  {
    throw std::invalid_argument(this->BadRow);
  }
  if (rows && !this->Motions.empty() && this->Motions.rbegin()->first > bodies)
  {
    throw std::invalid_argument("Body Motions moves body " +
      std::to_string(this->Motions.rbegin()->first) + ", but the mesh has " +
      std::to_string(bodies) + (bodies == 1 ? " moving body" : " moving bodies") + BodyNumbering);
  }
  if (trajectory && trajectory->GetLargestBody() > bodies)
  {
    // A row for a body the mesh does not have would otherwise be ignored, and the mesh not moved.
    throw std::invalid_argument("The trajectory table moves body " +
      std::to_string(trajectory->GetLargestBody()) + ", but the mesh has " +
      std::to_string(bodies) + (bodies == 1 ? " moving body" : " moving bodies") + BodyNumbering);
  }
  // A row for a body id between 1 and the largest that no moving node has (ids 1 and 3, a row for
  // 2) would move nothing, and the body meant not at all: an error too (silent until
  // 2026-11-30). Serial runs only: a piece of a distributed mesh may lack a body's nodes.
  if (bodies > 1 && !nodes.Distributed && !nodes.BodyIds.empty() &&
    ((rows && !this->Motions.empty()) || trajectory))
  {
    std::vector<bool> present(static_cast<std::size_t>(bodies) + 1, false);
    for (std::size_t i = 0; i < nodes.LocalNodes; ++i)
    {
      if (nodes.Kinds[i] == dgmf::NodeKind::MovingBoundary && nodes.BodyIds[i] >= 1 &&
        nodes.BodyIds[i] <= bodies)
      {
        present[static_cast<std::size_t>(nodes.BodyIds[i])] = true;
      }
    }
    for (std::int32_t k = 1; k <= bodies; ++k)
    {
      const bool asked =
        (rows && this->Motions.count(k) > 0) || (trajectory && trajectory->HasBody(k));
      if (asked && !present[static_cast<std::size_t>(k)])
      {
        std::string have;
        for (std::int32_t b = 1; b <= bodies; ++b)
        {
          have += present[static_cast<std::size_t>(b)]
            ? (have.empty() ? "" : ", ") + std::to_string(b)
            : "";
        }
        throw std::invalid_argument(
          std::string(rows && this->Motions.count(k) > 0 ? "Body Motions moves body "
                                                         : "The trajectory table moves body ") +
          std::to_string(k) + ", but no moving node has that body id (the mesh's bodies: " + have +
          ").");
      }
    }
  }
  // With BODY_CENTROID: the centroid of each body's moving nodes; in a distributed run those of
  // every piece (this piece's, then the others' boundary nodes), each position once and in
  // increasing order, so that every process turns about the same centre (each turned about its
  // own piece's centroid until 2026-11-30, and the pieces tore apart).
  std::vector<std::array<double, 4>> sums(static_cast<std::size_t>(bodies), { 0, 0, 0, 0 });
  if (filter->GetRotationCenterMode() == vtkDGMFDeformFilter::BODY_CENTROID)
  {
    std::vector<std::array<double, 4>> moving; // body, x, y, z
    for (std::size_t i = 0; i < (nodes.Distributed ? nodes.NumberOfNodes : nodes.LocalNodes); ++i)
    {
      if (nodes.Kinds[i] == dgmf::NodeKind::MovingBoundary)
      {
        const std::int32_t body = nodes.BodyIds.empty() ? 1 : std::max(nodes.BodyIds[i], 1);
        const double* p = nodes.Points + 3 * i;
        moving.push_back({ static_cast<double>(body), p[0], p[1], p[2] });
      }
    }
    if (nodes.Distributed)
    {
      std::sort(moving.begin(), moving.end());
      moving.erase(std::unique(moving.begin(), moving.end()), moving.end());
    }
    for (const std::array<double, 4>& node : moving)
    {
      std::array<double, 4>& sum = sums[static_cast<std::size_t>(node[0]) - 1];
      for (std::size_t c = 0; c < 3; ++c)
      {
        sum[c] += node[c + 1];
      }
      sum[3] += 1.0;
    }
  }
  std::vector<dgmf::RigidMotion> motions;
  for (int k = 1; k <= bodies; ++k)
  {
    const std::array<double, 4>& sum = sums[static_cast<std::size_t>(k - 1)];
    double center[3];
    for (int c = 0; c < 3; ++c)
    {
      center[c] = sum[3] > 0.0 ? sum[static_cast<std::size_t>(c)] / sum[3] : properties.Center[c];
    }
    const auto found = this->Motions.find(k);
    if (trajectory && trajectory->HasBody(k))
    {
      motions.push_back(trajectory->At(k, t, center));
    }
    else if (found != this->Motions.end())
    {
      motions.push_back(found->second);
    }
    else
    {
      motions.push_back(properties);
      std::copy_n(center, 3, motions.back().Center);
    }
  }
  return motions;
}

void SelectPointArray(vtkDGMFDeformFilter* filter, int index, const char* name)
{
  if (name)
  {
    filter->SetInputArrayToProcess(index, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
    return;
  }
  vtkInformation* info = filter->GetInputArrayInformation(index);
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    info->Remove(vtkDataObject::FIELD_NAME());
    filter->Modified();
  }
}

} // namespace dgmf_vtk
