/**
 * @file RigidMotion.h
 * @brief The rigid part of a boundary motion (translation and rotation about a centre), and its
 * scaling by the damping factor f (paper Eqs. 3-6).
 */
#ifndef dgmf_RigidMotion_h
#define dgmf_RigidMotion_h

namespace dgmf
{

/**
 * @brief Rigid motion: a rotation about a centre followed by a translation.
 *
 * The rotation is given in one of two ways, never both:
 * - Euler angles: three angles in degrees about the x, y and z axes through Center, right-handed
 *   (counter-clockwise seen from the positive axis), applied in that order: first about x, then y,
 *   then z (R = Rz Ry Rx). A 2D mesh uses the angle about z only.
 * - Axis and angle: one rotation of AxisAngleDegrees about the axis through Center along Axis
 *   (right-handed; Axis need not be unit length, it is normalised), used when AxisAngleDegrees is
 *   not 0. This is the form of a fitted motion (RigidMotionFit.h). A 2D mesh needs
 *   Axis = (0, 0, +-1).
 *
 * Setting both (an Euler angle and AxisAngleDegrees non-zero) is an error: GetRotationMatrix, Apply
 * and DampedRigidMotion throw std::invalid_argument, as they do for a zero or non-finite Axis
 * while AxisAngleDegrees is non-zero.
 *
 * DGMF scales the motion by the damping factor f of each node: every angle is multiplied by f
 * (the paper's point: cells near the body turn with it), and so are the translation and the
 * shape deformation d:  x' = c + R(f angles)(x - c) + f t + f d. With an axis, R(f angles) is the
 * rotation of f * AxisAngleDegrees about the same fixed axis (a geodesic from I to R).
 */
struct RigidMotion
{
  double Translation[3] = { 0.0, 0.0, 0.0 };   ///< t
  double Center[3] = { 0.0, 0.0, 0.0 };        ///< rotation centre c
  double AnglesDegrees[3] = { 0.0, 0.0, 0.0 }; ///< rotation angles about x, y, z, in degrees
  double Axis[3] = { 0.0, 0.0, 1.0 };          ///< rotation axis (used when AxisAngleDegrees != 0)
  double AxisAngleDegrees = 0.0;               ///< rotation angle about Axis, in degrees

  /// True if any Euler angle is non-zero.
  bool HasEulerAngles() const;
  /// True if AxisAngleDegrees is non-zero (the rotation is about Axis).
  bool HasAxisRotation() const;
  /// True if any angle (Euler or about the axis) is non-zero.
  bool HasRotation() const;
  /// True if the motion is the identity (no translation, no rotation).
  bool IsIdentity() const;

  /**
   * Axis normalised to unit length. Throws std::invalid_argument when it is zero or not finite.
   */
  void GetUnitAxis(double axis[3]) const;

  /**
   * Throws std::invalid_argument when the rotation is ill-defined: an angle that is not finite or
   * beyond +-MaximumAngleDegrees, both Euler angles and an axis angle, or an axis angle with a
   * zero or non-finite Axis.
   */
  void CheckRotation() const;

  /// CheckRotation, and a finite Translation and Center (std::invalid_argument otherwise).
  void Check() const;

  /**
   * True when the motion keeps a 2D mesh (a plane z = constant) in its plane: no Euler angle
   * about x or y, an axis (if any) along z, no translation along z.
   */
  bool KeepsPlane() const;

  /// Largest rotation angle, in degrees, of either form (two full turns).
  static constexpr double MaximumAngleDegrees = 720.0;

  /// The rotation matrix R(fraction * angles), row-major. Calls CheckRotation.
  void GetRotationMatrix(double fraction, double R[3][3]) const;

  /**
   * Moves `x` by the fraction f of the rigid motion and adds f * d (d may be null):
   * out = c + R(f angles)(x - c) + f t + f d. `out` may alias `x`. Calls CheckRotation.
   */
  void Apply(double f, const double x[3], const double* d, double out[3]) const;
};

} // namespace dgmf

#endif
