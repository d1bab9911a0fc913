#include "dgmf/Progress.h"

#include <algorithm>

namespace dgmf
{

Progress::Progress(Callback callback, double begin, double end)
  : Function(callback ? std::make_shared<const Callback>(std::move(callback)) : nullptr)
  , Begin(begin)
  , End(end)
{
}

void Progress::Report(double fraction) const
{
  if (this->Function &&
    !(*this->Function)(this->Begin + std::clamp(fraction, 0.0, 1.0) * (this->End - this->Begin)))
  {
    throw Aborted();
  }
}

Progress Progress::Part(double from, double to) const
{
  Progress part(*this);
  part.Begin = this->Begin + from * (this->End - this->Begin);
  part.End = this->Begin + to * (this->End - this->Begin);
  return part;
}

} // namespace dgmf
