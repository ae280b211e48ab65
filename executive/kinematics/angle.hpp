#pragma once
// Angle helpers used in the executive's inner loops.

#include <cmath>

namespace ifar::executive {

constexpr double kPi = 3.14159265358979323846;

/// Wraps to [-pi, pi] (std::remainder keeps it branch-free).
inline double wrapToPi(double radians)
{
  return std::remainder(radians, 2.0 * kPi);
}

}  // namespace ifar::executive
