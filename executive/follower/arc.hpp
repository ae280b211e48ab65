#pragma once
// Where a unicycle ends up after driving (v, omega) for t seconds from a pose: the exact arc.

#include <cmath>

#include "common/geometry/pose2.hpp"
#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

inline geometry::Pose2 integrateArc(const geometry::Pose2& start, double linear, double angular,
                                    double time_s)
{
  const double turn = angular * time_s;
  geometry::Pose2 end = start;
  end.heading = start.heading + turn;
  if (std::abs(turn) < 1e-9) {
    end.x += linear * time_s * std::cos(start.heading);
    end.y += linear * time_s * std::sin(start.heading);
  } else {
    const double radius = linear / angular;
    end.x += radius * (std::sin(end.heading) - std::sin(start.heading));
    end.y -= radius * (std::cos(end.heading) - std::cos(start.heading));
  }
  end.heading = wrapToPi(end.heading);
  return end;
}

}  // namespace ifar::executive
