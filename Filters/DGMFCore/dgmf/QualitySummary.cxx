// The summary of per-cell SizeSkew values (SizeSkewQuality.h): mean, minimum and counts.
#include "dgmf/SizeSkewQuality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dgmf
{

QualitySummary MergeQualitySummaries(const QualitySummary& a, const QualitySummary& b)
{
  QualitySummary merged;
  merged.Sum = a.Sum + b.Sum;
  merged.Evaluated = a.Evaluated + b.Evaluated;
  merged.Inverted = a.Inverted + b.Inverted;
  merged.InputInvalid = a.InputInvalid + b.InputInvalid;
  merged.NotComputed = a.NotComputed + b.NotComputed;
  if (merged.Evaluated > 0)
  {
    merged.Mean = merged.Sum / static_cast<double>(merged.Evaluated);
    merged.Minimum = a.Evaluated == 0 ? b.Minimum
      : b.Evaluated == 0              ? a.Minimum
                                      : std::min(a.Minimum, b.Minimum);
  }
  return merged;
}

QualitySummary SummarizeQuality(const double* sizeSkew, const std::uint8_t* inverted,
  std::size_t count, const std::uint8_t* skip, const std::uint8_t* inputInvalid)
{
  QualitySummary summary;
  if (sizeSkew == nullptr)
  {
    return summary;
  }
  double sum = 0.0;
  double minimum = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i)
  {
    if (skip != nullptr && skip[i] != 0)
    {
      continue;
    }
    const double value = sizeSkew[i];
    if (std::isnan(value))
    {
      ++summary.NotComputed;
    }
    else
    {
      ++summary.Evaluated;
      sum += value;
      minimum = std::min(minimum, value);
    }
    if (inverted != nullptr && inverted[i] != 0)
    {
      ++summary.Inverted;
    }
    if (inputInvalid != nullptr && inputInvalid[i] != 0)
    {
      ++summary.InputInvalid;
    }
  }
  summary.Sum = sum;
  if (summary.Evaluated > 0)
  {
    summary.Mean = sum / static_cast<double>(summary.Evaluated);
    summary.Minimum = minimum;
  }
  return summary;
}

} // namespace dgmf
