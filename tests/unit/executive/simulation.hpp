#pragma once
// A perfect unicycle for closed-loop tests: applies a command for one time step.

#include "common/geometry/pose2.hpp"
#include "executive/follower/arc.hpp"
#include "executive/kinematics/velocity_command.hpp"

namespace ifar::executive::testing {

inline geometry::Pose2 drive(const geometry::Pose2& pose, const VelocityCommand& command, double time_s)
{
  return integrateArc(pose, command.linear, command.angular, time_s);
}

}  // namespace ifar::executive::testing
