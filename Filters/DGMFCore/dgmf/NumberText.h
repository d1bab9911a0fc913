/**
 * @file NumberText.h
 * @brief A number in messages as short as it reads back exactly.
 */
#ifndef dgmf_NumberText_h
#define dgmf_NumberText_h

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace dgmf
{

/// `value` as short as it reads back exactly (2.0000001 is not shown as 2, 720.0000001 not as
/// 720.000000).
inline std::string NumberText(double value)
{
  std::ostringstream text;
  for (int digits = 6; digits <= 17; ++digits)
  {
    text.str("");
    text.precision(digits);
    text << value;
    if (!std::isfinite(value) || std::strtod(text.str().c_str(), nullptr) == value)
    {
      break;
    }
  }
  return text.str();
}

} // namespace dgmf

#endif
