/**
 * @file DampedRigidMotion.h
 * @brief A rigid motion scaled by damping factors f in [0, 1], fast enough for one call per node.
 */
#ifndef dgmf_DampedRigidMotion_h
#define dgmf_DampedRigidMotion_h

#include "dgmf/RigidMotion.h"
#include "dgmf/Simd.h"

#include <vector>

namespace dgmf
{

/**
 * @class DampedRigidMotion
 * @brief Evaluates x' = c + R(f angles)(x - c) + f t + f d for many f in [0, 1] with the same
 * motion, without calling sin and cos per node.
 *
 * For each non-zero angle theta, sin and cos of theta * k / Steps (k = 0..Steps) are tabulated
 * once; for a given f, the angle is split as theta * k / Steps + rho with 0 <= rho < theta / Steps,
 * sin and cos of rho come from their Taylor series (|rho| < 0.02 for |theta| <= 4 pi: the series
 * is exact to round-off), and the addition formulas combine the two. f = 0 and f = 1 are exact
 * table entries. The rotations about x, y and z are applied in that order (R = Rz Ry Rx).
 *
 * A motion with an axis rotation (RigidMotion::AxisAngleDegrees != 0) is tabulated the same way
 * for its one angle, and applied with Rodrigues' formula about the fixed unit axis k:
 * R v = cos(f a) v + sin(f a) (k x v) + (1 - cos(f a)) (k . v) k.
 *
 * The constructor throws std::invalid_argument when an angle is beyond +-720 degrees or not
 * finite, and when the rotation is ill-defined (RigidMotion::CheckRotation: both Euler angles and
 * an axis angle, or a zero axis).
 */
class DampedRigidMotion
{
public:
  explicit DampedRigidMotion(const RigidMotion& motion);

  /// out = c + R(f angles)(x - c) + f t + f d (d may be null). `out` may alias `x`.
  void Apply(double f, const double x[3], const double* d, double out[3]) const
  {
    double y[3] = { x[0] - this->Motion.Center[0], x[1] - this->Motion.Center[1],
      x[2] - this->Motion.Center[2] };
    this->Rotate(y, [f](const Axis& axis, double& s, double& c) { axis.SinCos(f, s, c); });
    for (int c = 0; c < 3; ++c)
    {
      out[c] =
        this->Motion.Center[c] + y[c] + f * this->Motion.Translation[c] + (d ? f * d[c] : 0.0);
    }
  }

  /**
   * Apply() for four nodes at once, in four-lane double-precision vectors (simd::Double4: AVX2 in
   * a caller marked DGMF_SIMD_AVX2_CLONES on a processor that has it): the same operations in the
   * same order as Apply(), so the same bits. `d[l]` may be null.
   */
  DGMF_SIMD_INLINE void ApplyFour(const double f[4], const double* const x[4],
    const double* const d[4], double* const out[4]) const
  {
    const Four fv = { f[0], f[1], f[2], f[3] };
    int k[4];
    const Four frac = TableSplit(fv, k);
    Four y[3];
    for (int c = 0; c < 3; ++c)
    {
      y[c] = Four{ x[0][c], x[1][c], x[2][c], x[3][c] } - this->Motion.Center[c];
    }
    this->Rotate(y, [&k, frac](const Axis& axis, Four& s, Four& c) { axis.SinCos(k, frac, s, c); });
    const Four hasD = { d[0] ? 1.0 : 0.0, d[1] ? 1.0 : 0.0, d[2] ? 1.0 : 0.0, d[3] ? 1.0 : 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      const Four dc = { d[0] ? d[0][c] : 0.0, d[1] ? d[1][c] : 0.0, d[2] ? d[2][c] : 0.0,
        d[3] ? d[3][c] : 0.0 };
      // As in Apply: c + y + f t + (d ? f d : 0); f d is 0 exactly when there is no d.
      const Four r =
        this->Motion.Center[c] + y[c] + fv * this->Motion.Translation[c] + hasD * (fv * dc);
      for (int l = 0; l < 4; ++l)
      {
        out[l][c] = r[l];
      }
    }
  }

  /// Number of table intervals per angle.
  static constexpr int Steps = 1024;

  /// Largest angle step (radians; up to about 58 degrees per angle) with the short Taylor series.
  static constexpr double ShortSeriesLimit = 1e-3;

private:
  /// Four doubles processed together (Simd.h).
  using Four = simd::Double4;

  /// f * Steps split into a table entry k and a remainder, as Axis::SinCos(double) does.
  DGMF_SIMD_INLINE static Four TableSplit(Four f, int k[4])
  {
    const Four scaled = f * static_cast<double>(Steps);
    for (int l = 0; l < 4; ++l)
    {
      k[l] = static_cast<int>(scaled[l]);
      k[l] = k[l] < 0 ? 0 : (k[l] > Steps ? Steps : k[l]);
    }
    const Four kd = { static_cast<double>(k[0]), static_cast<double>(k[1]),
      static_cast<double>(k[2]), static_cast<double>(k[3]) };
    return scaled - kd;
  }

  struct Axis
  {
    int I = 0, J = 1;          ///< the plane of the rotation
    double Angle = 0.0;        ///< radians
    double AnglePerStep = 0.0; ///< Angle / Steps
    /// |AnglePerStep| <= ShortSeriesLimit: the terms beyond rho^5 (sin) and rho^4 (cos) are
    /// below 1e-20 (absolute; the terms are bounded by rho^6 / 720), and are left out.
    bool ShortSeries = false;
    std::vector<double> Sin, Cos; ///< at angle * k / Steps

    void SinCos(double f, double& s, double& c) const
    {
      const double scaled = f * Steps;
      int k = static_cast<int>(scaled);
      k = k < 0 ? 0 : (k > Steps ? Steps : k);
      this->Combine(this->AnglePerStep * (scaled - k), this->Sin[static_cast<std::size_t>(k)],
        this->Cos[static_cast<std::size_t>(k)], s, c);
    }

    /// SinCos for four factors at once (the same operations, lane by lane), given their table
    /// entries `k` and remainders `frac` (TableSplit: the same for every angle).
    DGMF_SIMD_INLINE void SinCos(const int k[4], Four frac, Four& s, Four& c) const
    {
      const Four sk = { this->Sin[static_cast<std::size_t>(k[0])],
        this->Sin[static_cast<std::size_t>(k[1])], this->Sin[static_cast<std::size_t>(k[2])],
        this->Sin[static_cast<std::size_t>(k[3])] };
      const Four ck = { this->Cos[static_cast<std::size_t>(k[0])],
        this->Cos[static_cast<std::size_t>(k[1])], this->Cos[static_cast<std::size_t>(k[2])],
        this->Cos[static_cast<std::size_t>(k[3])] };
      this->Combine(this->AnglePerStep * frac, sk, ck, s, c);
    }

    /// sin and cos of (table angle + rho) from the table's sk, ck and the Taylor series of rho,
    /// for one node (T = double) or four (T = Four).
    template <typename T>
    DGMF_SIMD_INLINE void Combine(T rho, T sk, T ck, T& s, T& c) const
    {
      const T r2 = rho * rho;
      // Taylor series of sin and cos to rho^9 and rho^8 (multiplications by reciprocals of the
      // factorial ratios: divisions here would dominate the cost of a node).
      constexpr double i6 = 1.0 / 6.0, i20 = 1.0 / 20.0, i42 = 1.0 / 42.0, i72 = 1.0 / 72.0;
      constexpr double i2 = 0.5, i12 = 1.0 / 12.0, i30 = 1.0 / 30.0, i56 = 1.0 / 56.0;
      // Angles up to ShortSeriesLimit per step need the series only to rho^5 and rho^4.
      const T sr = this->ShortSeries
        ? rho * (1.0 - r2 * i6 * (1.0 - r2 * i20))
        : rho * (1.0 - r2 * i6 * (1.0 - r2 * i20 * (1.0 - r2 * i42 * (1.0 - r2 * i72))));
      const T cr = this->ShortSeries
        ? 1.0 - r2 * i2 * (1.0 - r2 * i12)
        : 1.0 - r2 * i2 * (1.0 - r2 * i12 * (1.0 - r2 * i30 * (1.0 - r2 * i56)));
      s = sk * cr + ck * sr;
      c = ck * cr - sk * sr;
    }
  };

  /**
   * y <- R(f angles) y for one node (T = double) or four (T = Four): Rodrigues' formula for an
   * axis rotation, else the rotations about x, y and z in turn. `sinCos(axis, s, c)` gives the
   * sine and cosine of the damped angle of `axis`.
   */
  template <typename T, typename SinCos>
  DGMF_SIMD_INLINE void Rotate(T y[3], const SinCos& sinCos) const
  {
    if (this->HasAxisRotation)
    {
      T s, c;
      sinCos(this->AxisRotation, s, c);
      const double* a = this->UnitAxis;
      const T kv = (1.0 - c) * (a[0] * y[0] + a[1] * y[1] + a[2] * y[2]);
      const T w[3] = { a[1] * y[2] - a[2] * y[1], a[2] * y[0] - a[0] * y[2],
        a[0] * y[1] - a[1] * y[0] };
      for (int i = 0; i < 3; ++i)
      {
        y[i] = c * y[i] + s * w[i] + kv * a[i];
      }
    }
    for (int j = 0; j < this->NumberOfAxes; ++j)
    {
      const Axis& axis = this->Axes[j];
      T s, c;
      sinCos(axis, s, c);
      const T u = y[axis.I];
      const T v = y[axis.J];
      y[axis.I] = c * u - s * v;
      y[axis.J] = s * u + c * v;
    }
  }

  RigidMotion Motion;
  Axis Axes[3];
  int NumberOfAxes = 0;
  bool HasAxisRotation = false; ///< the rotation is AxisRotation about UnitAxis (no Euler angles)
  Axis AxisRotation;            ///< table of the axis angle (I, J unused)
  double UnitAxis[3] = { 0.0, 0.0, 1.0 };
};

} // namespace dgmf

#endif
