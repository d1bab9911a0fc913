/**
 * @file Progress.h
 * @brief How a long computation of the core tells its caller how far it is, and how the caller
 * stops it (ParaView's progress bar and its abort button, the command line's progress lines).
 */
#ifndef dgmf_Progress_h
#define dgmf_Progress_h

#include <functional>
#include <memory>
#include <stdexcept>

namespace dgmf
{

/// Thrown by Progress::Report when the caller asked to stop; nothing the computation wrote is
/// valid.
class Aborted : public std::runtime_error
{
public:
  Aborted()
    : std::runtime_error("The deformation was aborted; there is no output.")
  {
  }
};

/**
 * A fraction of the caller's whole run: Report(x) for x in [0, 1] tells the caller that x of this
 * part is done, as Begin + x (End - Begin) of the whole. Cheap to copy; an empty Progress (the
 * default) reports nothing and never stops.
 */
class Progress
{
public:
  /// Receives the fraction of the whole run done, in [0, 1]; returns false to stop the run.
  using Callback = std::function<bool(double fraction)>;

  Progress() = default;
  explicit Progress(Callback callback, double begin = 0.0, double end = 1.0);

  /// Reports `fraction` of this part done; throws Aborted if the caller says stop.
  void Report(double fraction) const;

  /// The part [from, to] (fractions of this part) as a Progress of its own.
  Progress Part(double from, double to) const;

private:
  std::shared_ptr<const Callback> Function;
  double Begin = 0.0;
  double End = 1.0;
};

} // namespace dgmf

#endif
