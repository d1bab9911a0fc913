/**
 * @file FirstAndRepeated.h
 * @brief The benchmark's two measurements of a filter: a first deformation (from an empty cache,
 * with its phases) and a repeated one (a new motion, the graph kept).
 */
#ifndef dgmf_bench_FirstAndRepeated_h
#define dgmf_bench_FirstAndRepeated_h

#include <vector>

class vtkDGMFDeformFilter;

namespace dgmf_bench
{

/// Medians over the repeats, in seconds.
struct FirstAndRepeated
{
  double First = 0.0, Graph = 0.0, Location = 0.0, Mapping = 0.0, Repeated = 0.0;
  bool GraphAlwaysReused = true; ///< every repeated deformation reused the graph
};

/**
 * Times `filter` (its input, arrays, method and threads set by the caller) `repeats` times: repeat
 * r releases the cache and rotates by (5, 10, 15 + r) degrees (the first deformation), then by
 * (5, 10, 20 + r) degrees (the repeated one).
 */
FirstAndRepeated TimeFirstAndRepeated(vtkDGMFDeformFilter* filter, int repeats);

/// The median of `values` (the mean of the middle two for an even count).
double Median(std::vector<double> values);

} // namespace dgmf_bench

#endif
