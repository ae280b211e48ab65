// Following along a wall at about the follower's clearance: every arc dips a little below it, so the
// follower alone is blocked; the executive retries with the clearance lowered to half what is left.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "executive/follower/follower.hpp"
#include "executive/modes/executive.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;
using geometry::Pose2;

TEST(ExecutiveSqueeze, AlongAWallAtTheClearanceTheVehicleStillMoves)
{
  const ExecutiveSettings settings;
  const common::VehicleSettings vehicle;
  // A wall along y = wall_y, the vehicle's left side 0.15 m (the clearance) below it, heading 1 degree
  // toward it; the target far ahead along the wall.
  const double wall_y = vehicle.width_m / 2.0 + settings.follower.clearance_m + 0.001;
  std::vector<Point> wall;
  for (double x = -3.0; x <= 8.0; x += 0.05) {
    wall.emplace_back(x, wall_y);
  }
  const Pose2 pose{0.0, 0.0, 1.0 * 3.14159265358979323846 / 180.0};
  Path path;
  path.goal_id = 1;
  path.sequence = 1;
  path.valid = true;
  Waypoint start;
  Waypoint goal;
  goal.position = Point(7.0, 0.0);
  path.waypoints = {start, goal};

  // The follower alone: blocked.
  FollowerSettings follower = settings.follower;
  follower.footprint = vehicleFootprint(vehicle, settings.reference_to_bumper_m);
  const FollowerResult alone =
      follow(pose, goal.position, true, common::Span<const Point>(wall.data(), wall.size()), follower,
             DifferentialDrive(vehicle));
  ASSERT_EQ(alone.status, FollowerStatus::Blocked) << alone.reason;

  Executive executive(settings, vehicle);
  const std::int64_t now = 1'000'000'000;
  Inputs inputs;
  inputs.pose = Stamped<Pose2>{pose, now};
  inputs.path = Stamped<Path>{path, now};
  inputs.force = Stamped<ForceReading>{ForceReading{0.0, false}, now};
  inputs.motor = Stamped<MotorReading>{MotorReading{true, false, ""}, now};
  inputs.obstacles = Stamped<std::vector<Point>>{wall, now};
  executive.step(now, inputs);
  inputs.pose->utime = inputs.path->utime = inputs.force->utime = inputs.motor->utime =
      inputs.obstacles->utime = now + 20'000;
  const Output output = executive.step(now + 20'000, inputs);
  EXPECT_EQ(output.status.mode, Mode::Follow);
  EXPECT_FALSE(output.command.isZero());
  EXPECT_NE(output.status.reason.find("squeezing"), std::string::npos) << output.status.reason;
}

}  // namespace
}  // namespace ifar::executive
