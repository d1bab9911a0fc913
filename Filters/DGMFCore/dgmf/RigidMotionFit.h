/**
 * @file RigidMotionFit.h
 * @brief The best rigid motion (least squares) of a body known only by the displacements of its
 * boundary nodes, and the residual that DGMF2 uses as the shape deformation.
 */
#ifndef dgmf_RigidMotionFit_h
#define dgmf_RigidMotionFit_h

#include "dgmf/RigidMotion.h"

#include <cstddef>
#include <cstdint>

namespace dgmf
{

/// How well the points of a body determine its rotation.
enum class RotationFit : int
{
  /// The least-squares rotation is unique: at least 2 distinct points (2D) or 3 non-collinear
  /// points (3D).
  Determined = 0,
  /// 3D only: the points (or their displaced positions) lie on a line, so the twist about that line
  /// is not determined. The smallest rotation turning the line into its new direction is used.
  Collinear = 1,
  /// No rotation can be fitted (no point, all points coincide, or the displaced points collapse
  /// onto one point): R = I, the motion is the mean displacement.
  Undetermined = 2
};

/**
 * @brief The rigid part of a body's displacement: x_i' = c + R (x_i - c) + t + d_i with the d_i
 * as small as possible in the least-squares sense (Kabsch / Procrustes).
 *
 * The centre c is the centroid of the original points, t = centroid(x') - c is the mean
 * displacement, and R minimises sum_i |R (x_i - c) - (x_i' - c - t)|^2 over proper rotations
 * (det R = +1; the SVD solution is corrected when it would be a reflection). R is reported as a
 * unit axis and an angle in [0, 180] degrees (angle 0: axis (0, 0, 1)). In 2D, R is a rotation
 * about z: the axis is (0, 0, 1) or (0, 0, -1), and an angle of exactly 180 degrees gets
 * (0, 0, 1); c's z is the z of the first point and t's z is 0, so the fitted motion keeps the
 * plane bit for bit.
 */
struct FittedMotion
{
  double Center[3] = { 0.0, 0.0, 0.0 };      ///< c, the centroid of the original points
  double Translation[3] = { 0.0, 0.0, 0.0 }; ///< t = centroid(x') - c (the mean displacement)
  double Axis[3] = { 0.0, 0.0, 1.0 };        ///< unit rotation axis
  double AngleDegrees = 0.0;                 ///< rotation angle about Axis, in [0, 180]
  /// R, row-major: the rotation of AngleDegrees about Axis (as RigidMotion::GetRotationMatrix).
  double Rotation[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  /// sqrt(mean |d_i|^2), d_i the residual of ComputeFitResidual.
  double ResidualRMS = 0.0;
  /// max |d_i|.
  double MaximumResidual = 0.0;
  RotationFit Status = RotationFit::Undetermined; ///< whether R is determined by the points
  std::size_t NumberOfPoints = 0;                 ///< number of points fitted

  /// The motion for DGMF: Center, Translation, and the axis rotation (no Euler angles).
  RigidMotion ToRigidMotion() const;
};

/**
 * Relative threshold below which a rotation counts as not determined. With p_i, q_i the centred
 * original and displaced points, n their number, M the largest absolute coordinate of the
 * original and displaced points, and the bounds
 *   relative = tolerance sqrt(sum |p|^2 sum |q|^2),
 *   noise = tolerance M sqrt(n) (sqrt(sum |p|^2) + sqrt(sum |q|^2))   (round-off of coordinates),
 * the fit is Undetermined when |(sum p.q, sum p x q)| (2D) or the largest singular value of
 * H = sum p q^T (3D) is <= max(relative, noise), and Collinear (3D) when the second singular value
 * is <= max(tolerance times the largest, noise). In words: a body smaller than about 1e-12 of its
 * coordinates is a point, and one thinner than about 1e-6 of its length (or than 1e-12 of its
 * coordinates) a line.
 */
constexpr double RotationFitTolerance = 1e-12;

/**
 * Fits the best rigid motion to the displacements of one body.
 * @param dimension 2 (rotation about z only; x and y used) or 3
 * @param points 3 coordinates per node
 * @param displacements 3 components per node: the prescribed displacement D_i, x_i' = x_i + D_i
 * @param nodes the body's node ids into `points` and `displacements`; null: nodes 0..count-1
 * @param count number of nodes of the body
 * Every node counts with the same weight. The rotation is determined up to 180 degrees; a
 * rotation of more than 180 degrees is the same rotation as a smaller one about the opposite axis.
 * Throws std::invalid_argument for a dimension other than 2 or 3, a negative node id or a
 * non-finite coordinate or displacement.
 */
/**
 * Moves the fit's centre onto its rotation axis (Chasles: a rigid motion is a rotation about an
 * axis line plus a translation along it): the point of the axis nearest the centroid, so that the
 * translation keeps only its component along the axis (in 2D: the fixed point of the motion, and
 * no translation). A body given the displacements of a rotation about some centre then gets back
 * that very rotation, and DGMF turns the nodes around it about the same centre at every f. The
 * residual is unchanged: the motion at f = 1 is the same. The centre stays at the centroid when
 * the rotation is (nearly) a translation: when the axis point would be farther than
 * `maximumDistance` from the centroid. Returns true if the centre moved.
 */
bool CentreOnRotationAxis(FittedMotion& fit, double maximumDistance);

/// Axis (unit) and angle (degrees, in [0, 180]) of a rotation matrix R (row-major).
void RotationToAxisAngle(const double R[3][3], double axis[3], double& angleDegrees);

FittedMotion FitRigidMotion(int dimension, const double* points, const double* displacements,
  const std::int32_t* nodes, std::size_t count);

/**
 * The residual d_i = x_i' - (c + R (x_i - c) + t) of a fit, computed with the motion DGMF applies
 * (fit.ToRigidMotion() through DampedRigidMotion at f = 1), so that a node moved by the fitted
 * motion plus its residual lands on x_i + D_i up to one rounding. The residual of node nodes[i]
 * (or i when `nodes` is null) is written to residual + 3 * nodes[i], i.e. where its displacement
 * was read; `residual` may be null (then only the RMS is computed) and may alias `displacements`.
 * Returns sqrt(mean |d_i|^2) (0 for no node).
 */
double ComputeFitResidual(const FittedMotion& fit, const double* points,
  const double* displacements, const std::int32_t* nodes, std::size_t count, double* residual);

} // namespace dgmf

#endif
