/**
 * @file MotionLaw.h
 * @brief A scalar law in time for a prescribed motion: constant, harmonic or ramp.
 */
#ifndef dgmf_MotionLaw_h
#define dgmf_MotionLaw_h

namespace dgmf
{

/// The kind of a MotionLaw (the values of the filter's TranslationLaw and RotationLaw).
enum class MotionLawKind
{
  Constant = 0, ///< no time dependence: the motion as given
  Harmonic = 1, ///< Mean + Amplitude sin(2 pi Frequency t + Phase)
  Ramp = 2      ///< Start until StartTime, linear to End at EndTime, End after
};

/**
 * @brief A value that changes in time, for a rotation angle or a translation's length.
 *
 * Parameters, by kind (the four numbers of the filter's law properties, in this order):
 * - Harmonic: mean, amplitude, frequency (periods per unit time, >= 0), phase in degrees:
 *   v(t) = mean + amplitude sin(2 pi (frequency t + phase / 360)). The phase in periods,
 *   frequency t + phase / 360, is reduced to [0, 1) and rounded to 2^-40 of a period before the
 *   sine: times one period apart give the same value, bit for bit, so a periodic motion returns
 *   the mesh to the same points after every period (the rounding changes the value by less than
 *   3e-12 times the amplitude).
 * - Ramp: start value, end value, start time, end time (> start time): v(t) = start value before
 *   the start time, end value after the end time, linear in between.
 * - Constant: not evaluated (the caller keeps the motion as given).
 */
struct MotionLaw
{
  MotionLawKind Kind = MotionLawKind::Constant;
  double Parameters[4] = { 0.0, 0.0, 0.0, 0.0 };

  /// True for a law that depends on time (not Constant).
  bool IsTimeDependent() const { return this->Kind != MotionLawKind::Constant; }

  /// v(t). Calls Check.
  double Evaluate(double t) const;

  /// The largest |v(t)| over all times: |mean| + |amplitude| (harmonic), the larger of |start|
  /// and |end| (ramp); 0 for Constant.
  double LargestMagnitude() const;

  /**
   * Throws std::invalid_argument, naming `what` (e.g. "the rotation law"), for parameters that are
   * not finite, a negative frequency, or a ramp whose end time is not after its start time.
   */
  void Check(const char* what = "the motion law") const;
};

} // namespace dgmf

#endif
