#pragma once
// Numbers as the result tables print them.

#include <cmath>
#include <cstdio>
#include <string>

namespace ifar::scenarios {

/// `value` with `digits` decimals; "-" when not finite.
inline std::string fixed(double value, int digits)
{
  if (!std::isfinite(value)) {
    return "-";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

}  // namespace ifar::scenarios
