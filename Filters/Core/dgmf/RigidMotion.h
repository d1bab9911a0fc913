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
 * The rotation is given by three angles in degrees about the x, y and z axes through Center,
 * right-handed (counter-clockwise seen from the positive axis), applied in that order: first
 * about x, then y, then z (R = Rz Ry Rx). A 2D mesh uses the angle about z only.
 *
 * DGMF scales the motion by the damping factor f of each node: every angle is multiplied by f
 * (the paper's point: cells near the body turn with it), and so are the translation and the
 * shape deformation d:  x' = c + R(f angles)(x - c) + f t + f d.
 */
struct RigidMotion
{
  double Translation[3] = { 0.0, 0.0, 0.0 };   ///< t
  double Center[3] = { 0.0, 0.0, 0.0 };        ///< rotation centre c
  double AnglesDegrees[3] = { 0.0, 0.0, 0.0 }; ///< rotation angles about x, y, z, in degrees

  /// True if any angle is non-zero.
  bool HasRotation() const;
  /// True if the motion is the identity (no translation, no rotation).
  bool IsIdentity() const;

  /// The rotation matrix R(fraction * angles), row-major.
  void GetRotationMatrix(double fraction, double R[3][3]) const;

  /**
   * Moves `x` by the fraction f of the rigid motion and adds f * d (d may be null):
   * out = c + R(f angles)(x - c) + f t + f d. `out` may alias `x`.
   */
  void Apply(double f, const double x[3], const double* d, double out[3]) const;
};

} // namespace dgmf

#endif
