/**
 * @file DGMFFilterParameters.h
 * @brief vtkDGMFDeformFilter's properties as the core's terms: the method and its parameters, and
 * the rigid motion of each body (private to the DGMF::Filters module).
 */
#ifndef DGMFFilterParameters_h
#define DGMFFilterParameters_h

#include "dgmf/DeformationMethod.h"
#include "dgmf/RigidMotion.h"
#include "dgmf/Trajectory.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

class vtkDGMFDeformFilter;

namespace dgmf_vtk
{
struct InputNodes;

/// The filter's method (its Method property).
dgmf::Method MethodOf(vtkDGMFDeformFilter* filter);

/// The filter's properties as the parameters of every method.
dgmf::MethodParameters MethodParametersOf(vtkDGMFDeformFilter* filter);

/// The error of properties that cannot go together (Fail On Inverted Cells without Compute
/// Quality), or "".
std::string SettingsError(vtkDGMFDeformFilter* filter);

/// The warning for properties the method ignores (Sub Steps, Repair Threshold with a method other
/// than DGMF), or "".
std::string SettingsWarning(vtkDGMFDeformFilter* filter);

/// Selects the point array `name` at `index` of `filter`; null forgets the selection, so that the
/// default applies again (VTK's SetInputArrayToProcess ignores a null name: the old one stayed).
void SelectPointArray(vtkDGMFDeformFilter* filter, int index, const char* name);

/// The rigid motions given per body (vtkDGMFDeformFilter::SetBodyMotion).
class BodyMotionTable
{
public:
  /// Sets body `bodyId`'s motion; false (nothing set) when the id is not 1, 2, ... up to 1e6:
  /// For() then fails until Clear().
  bool Set(double bodyId, const double translation[3], const double center[3],
    const double anglesDegrees[3]);
  /// Forgets every motion (and a bad row); false when there was none.
  bool Clear();
  /// Number of bodies with a motion.
  std::size_t Size() const { return this->Motions.size(); }
  /**
   * The rigid motion of bodies 1..max(bodies, 1) of `nodes` at time `t`: the trajectory's (if
   * given and it has rows for the body), else the one set for the body, else `properties` (the
   * filter's motion properties at `t`); with RotationCenterMode BODY_CENTROID, the trajectory's and
   * the properties' motions turn about the centroid of the body's moving nodes. Throws
   * std::invalid_argument after a row set with a bad body id, and for a row (or a trajectory's)
   * for a body the mesh does not have.
   */
  std::vector<dgmf::RigidMotion> For(vtkDGMFDeformFilter* filter, const InputNodes& nodes,
    const dgmf::RigidMotion& properties, const dgmf::Trajectory* trajectory, double t) const;

  /**
   * Whether some body of `nodes` moves as the filter's properties say: one without a row (or
   * every body, in Extracted mode, where rows do not count) and without a trajectory.
   */
  bool PropertiesMove(
    vtkDGMFDeformFilter* filter, const InputNodes& nodes, const dgmf::Trajectory* trajectory) const;

private:
  std::map<int, dgmf::RigidMotion> Motions;
  std::string BadRow; ///< the error of a row set with a bad body id, or ""
};

} // namespace dgmf_vtk

#endif
