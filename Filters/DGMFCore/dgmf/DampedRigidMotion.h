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
   * Apply() for two nodes at once, in the processor's two-lane double-precision vectors: the
   * same operations in the same order as Apply(), so the same bits, at about the cost of one.
   * `d0` and `d1` may be null.
   */
  void ApplyPair(const double f[2], const double* x0, const double* x1, const double* d0,
    const double* d1, double* out0, double* out1) const
  {
    const Pair fv = { f[0], f[1] };
    int k[2];
    const Pair frac = TableSplit(fv, k);
    Pair y[3];
    for (int c = 0; c < 3; ++c)
    {
      y[c] = Pair{ x0[c], x1[c] } - this->Motion.Center[c];
    }
    this->Rotate(y, [&k, frac](const Axis& axis, Pair& s, Pair& c) { axis.SinCos(k, frac, s, c); });
    for (int c = 0; c < 3; ++c)
    {
      const Pair d = { d0 ? d0[c] : 0.0, d1 ? d1[c] : 0.0 };
      const Pair hasD = { d0 ? 1.0 : 0.0, d1 ? 1.0 : 0.0 };
      // As in Apply: c + y + f t + (d ? f d : 0); f d is 0 exactly when there is no d.
      const Pair r =
        this->Motion.Center[c] + y[c] + fv * this->Motion.Translation[c] + hasD * (fv * d);
      out0[c] = r[0];
      out1[c] = r[1];
    }
  }

  /// Number of table intervals per angle.
  static constexpr int Steps = 1024;

  /// Largest angle step (radians; up to about 58 degrees per angle) with the short Taylor series.
  static constexpr double ShortSeriesLimit = 1e-3;

private:
  /// Two doubles processed together (Simd.h).
  using Pair = simd::Double2;

  /// f * Steps split into a table entry k and a remainder, as Axis::SinCos(double) does.
  static Pair TableSplit(Pair f, int k[2])
  {
    const Pair scaled = f * static_cast<double>(Steps);
    for (int l = 0; l < 2; ++l)
    {
      k[l] = static_cast<int>(scaled[l]);
      k[l] = k[l] < 0 ? 0 : (k[l] > Steps ? Steps : k[l]);
    }
    const Pair kd = { static_cast<double>(k[0]), static_cast<double>(k[1]) };
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

    /// SinCos for two factors at once (the same operations, lane by lane), given their table
    /// entries `k` and remainders `frac` (TableSplit: the same for every angle).
    void SinCos(const int k[2], Pair frac, Pair& s, Pair& c) const
    {
      const Pair sk = { this->Sin[static_cast<std::size_t>(k[0])],
        this->Sin[static_cast<std::size_t>(k[1])] };
      const Pair ck = { this->Cos[static_cast<std::size_t>(k[0])],
        this->Cos[static_cast<std::size_t>(k[1])] };
      this->Combine(this->AnglePerStep * frac, sk, ck, s, c);
    }

    /// sin and cos of (table angle + rho) from the table's sk, ck and the Taylor series of rho,
    /// for one node (T = double) or two (T = Pair).
    template <typename T>
    void Combine(T rho, T sk, T ck, T& s, T& c) const
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
   * y <- R(f angles) y for one node (T = double) or two (T = Pair): Rodrigues' formula for an
   * axis rotation, else the rotations about x, y and z in turn. `sinCos(axis, s, c)` gives the
   * sine and cosine of the damped angle of `axis`.
   */
  template <typename T, typename SinCos>
  void Rotate(T y[3], const SinCos& sinCos) const
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
