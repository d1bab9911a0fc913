#include "dgmf/MotionLaw.h"

#include "dgmf/NumberText.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dgmf
{

void MotionLaw::Check(const char* what) const
{
  for (double p : this->Parameters)
  {
    if (!std::isfinite(p))
    {
      throw std::invalid_argument(std::string(what) + " has a parameter that is not finite");
    }
  }
  if (this->Kind == MotionLawKind::Harmonic && this->Parameters[2] < 0.0)
  {
    throw std::invalid_argument(std::string(what) + ": the frequency must not be negative (got " +
      std::to_string(this->Parameters[2]) + ")");
  }
  if (this->Kind == MotionLawKind::Ramp && !(this->Parameters[3] > this->Parameters[2]))
  {
    // The parameters are shared with the harmonic law, whose defaults (0 10 1 0) are not a ramp:
    // say what each one is.
    throw std::invalid_argument(std::string(what) +
      ": a ramp's four parameters are its start value, end value, start time and end time, and "
      "its end time (" +
      NumberText(this->Parameters[3]) + ") must be after its start time (" +
      NumberText(this->Parameters[2]) + ")");
  }
  if (this->Kind != MotionLawKind::Constant && this->Kind != MotionLawKind::Harmonic &&
    this->Kind != MotionLawKind::Ramp)
  {
    throw std::invalid_argument(std::string(what) + ": unknown kind");
  }
}

double MotionLaw::LargestMagnitude() const
{
  const double* p = this->Parameters;
  switch (this->Kind)
  {
    case MotionLawKind::Harmonic:
      // A frequency of 0 holds one value (it ran before the bound was checked up front).
      return p[2] == 0.0 ? std::abs(this->Evaluate(0.0)) : std::abs(p[0]) + std::abs(p[1]);
    case MotionLawKind::Ramp:
      return std::max(std::abs(p[0]), std::abs(p[1]));
    default:
      return 0.0;
  }
}

double MotionLaw::Evaluate(double t) const
{
  this->Check();
  const double* p = this->Parameters;
  switch (this->Kind)
  {
    case MotionLawKind::Harmonic:
    {
      if (!std::isfinite(t))
      {
        throw std::invalid_argument("the time must be finite");
      }
      // The phase in periods, reduced and rounded: t and t + one period give the same bits.
      double periods = p[2] * t + p[3] / 360.0;
      periods -= std::floor(periods);
      constexpr double Steps = 1099511627776.0; // 2^40 per period
      periods = std::nearbyint(periods * Steps) / Steps;
      periods = periods >= 1.0 ? 0.0 : periods; // rounded up to the next period's start
      constexpr double TwoPi = 6.283185307179586476925286766559;
      return p[0] + p[1] * std::sin(TwoPi * periods);
    }
    case MotionLawKind::Ramp:
    {
      if (t <= p[2])
      {
        return p[0];
      }
      if (t >= p[3])
      {
        return p[1];
      }
      return p[0] + (p[1] - p[0]) * ((t - p[2]) / (p[3] - p[2]));
    }
    default:
      return 0.0;
  }
}

} // namespace dgmf
