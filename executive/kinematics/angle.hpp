#pragma once
// Angle helpers used in the executive's inner loops.

#include <cmath>

#include "common/geometry/angle.hpp"

namespace ifar::executive {

using geometry::kPi;

/// Wraps to [-pi, pi] (std::remainder keeps it branch-free).
inline double wrapToPi(double radians)
{
  return std::remainder(radians, 2.0 * kPi);
}

}  // namespace ifar::executive
