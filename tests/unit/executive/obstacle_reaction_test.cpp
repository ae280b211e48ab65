// Closed loop with the simulator: the executive decodes the simulated VLP-16 packets itself, so a box
// that appears in front of the vehicle driving at speed changes the command within 100 ms (simulated
// time) of the first packet that sees it, and the vehicle never touches it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "executive/modes/executive.hpp"
#include "executive/obstacles/local_obstacles.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"

namespace ifar::executive {
namespace {

using geometry::Point;
using geometry::Pose2;

constexpr double kSimStepS = 0.01;
constexpr int kStepsPerCycle = 2;  // the executive runs at 50 Hz
constexpr double kRunS = 4.5;
constexpr double kBoxSideM = 0.6;
constexpr double kBumperToBoxM = 1.0;  // gap ahead of the bumper when the box appears

struct Trace {
  std::vector<std::int64_t> cycle_utimes;
  std::vector<VelocityCommand> commands;
  std::vector<Pose2> poses;  // ground truth, one per cycle
  std::int64_t first_box_packet_us = -1;
  std::int64_t appear_utime = -1;
  std::size_t points_per_cycle = 0;  // obstacle points the executive got, at the last cycle
};

/// The parameter: how long after the start the box appears, seconds (the lidar's phase differs).
class ObstacleReactionTest : public ::testing::TestWithParam<double> {
 protected:
  ObstacleReactionTest()
  {
    const auto root = common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/executive.yaml");
    settings_ = loadExecutiveSettings(root);
    obstacle_settings_ = loadObstacleSettings(root.child("obstacles"));
    vehicle_ = common::loadVehicleSettings(
        common::ConfigNode::loadFile(std::string(IFAR_SOURCE_DIR) + "/config/vehicle.yaml"));
    room_ = sim::builtinRoom(14.0);
  }

  Path straightPath() const
  {
    Path path;
    path.goal_id = 1;
    path.sequence = 1;
    path.valid = true;
    Waypoint start;
    start.position = room_.start.position();
    Waypoint goal;
    goal.position = room_.start.position() + Point(10.0, 0.0);
    path.waypoints = {start, goal};
    return path;
  }

  /// Drives toward the goal; with `box` set, the packets come from a world holding it once
  /// `appear_s` has passed (before that both worlds give the same packets and the same motion).
  Trace drive(const std::optional<sim::StaticObstacle>& box, double appear_s) const
  {
    sim::World boxed = room_;
    if (box) {
      boxed.obstacles.push_back(*box);
    }
    sim::Simulator without(room_, vehicle_, sim::SimulatorSettings{});
    sim::Simulator with(boxed, vehicle_, sim::SimulatorSettings{});
    LocalObstacles obstacles(obstacle_settings_, vehicle_);
    Executive executive(settings_, vehicle_);
    const Path path = straightPath();
    Trace trace;
    const int steps = static_cast<int>(kRunS / kSimStepS + 0.5);
    for (int step = 1; step <= steps; ++step) {
      const sim::StepOutput clear = without.step(kSimStepS);
      const sim::StepOutput blocked = with.step(kSimStepS);
      const bool appeared = box && step * kSimStepS >= appear_s - 1e-9;
      const sim::StepOutput& output = appeared ? blocked : clear;
      if (appeared && trace.appear_utime < 0) {
        trace.appear_utime = output.utime;
      }
      obstacles.addPose(output.utime, output.pose_estimate.pose);
      for (std::size_t index = 0; index < output.packets.size(); ++index) {
        const auto& packet = output.packets[index];
        if (appeared && trace.first_box_packet_us < 0 && index < clear.packets.size() &&
            packet != clear.packets[index]) {
          trace.first_box_packet_us = output.utime;
        }
        obstacles.addPacket(common::ByteView(packet.data(), packet.size()), output.utime);
      }
      if (step % kStepsPerCycle != 0) {
        continue;
      }
      const std::int64_t now = output.utime;
      Inputs inputs;
      inputs.pose = Stamped<Pose2>{output.pose_estimate.pose, now};
      inputs.path = Stamped<Path>{path, now};
      inputs.force = Stamped<ForceReading>{ForceReading{output.bumper_force_n, false}, now};
      inputs.motor = Stamped<MotorReading>{MotorReading{true, false, ""}, now};
      inputs.obstacles = Stamped<std::vector<Point>>{obstacles.points(now), obstacles.newestPacketUtime()};
      trace.points_per_cycle = inputs.obstacles->value.size();
      const Output result = executive.step(now, inputs);
      without.setVelocityCommand(result.command.linear, result.command.angular);
      with.setVelocityCommand(result.command.linear, result.command.angular);
      trace.cycle_utimes.push_back(now);
      trace.commands.push_back(result.command);
      trace.poses.push_back(output.vehicle.pose);
    }
    return trace;
  }

  ExecutiveSettings settings_;
  ObstacleSettings obstacle_settings_;
  common::VehicleSettings vehicle_;
  sim::World room_;
};

/// Smallest distance from the footprint at each pose to the box outline (sampled every 2 cm).
double closestApproach(const std::vector<Pose2>& poses, const geometry::Polygon& outline,
                       const Footprint& footprint)
{
  double closest = 1e9;
  for (const Pose2& pose : poses) {
    for (std::size_t corner = 0; corner < outline.size(); ++corner) {
      const Point from = outline[corner];
      const Point to = outline[(corner + 1) % outline.size()];
      for (int sample = 0; sample <= 30; ++sample) {
        closest = std::min(closest, footprint.distance(pose, from + (to - from) * (sample / 30.0)));
      }
    }
  }
  return closest;
}

TEST_P(ObstacleReactionTest, CommandChangesWithin100MsOfTheFirstPacketSeeingANewBox)
{
  const double appear_s = GetParam();
  const Trace baseline = drive(std::nullopt, appear_s);
  // Where the vehicle is when the box appears (the same in both runs up to the first box packet).
  const auto appear_cycle = static_cast<std::size_t>(appear_s / (kSimStepS * kStepsPerCycle)) - 1;
  ASSERT_LT(appear_cycle, baseline.poses.size());
  const Pose2 at_appear = baseline.poses[appear_cycle];
  ASSERT_GT(baseline.commands[appear_cycle].linear, 0.6) << "the vehicle should be at speed";

  const double centre_ahead = settings_.reference_to_bumper_m + kBumperToBoxM + kBoxSideM / 2.0;
  const Point centre = at_appear.transform(Point(centre_ahead, 0.0));
  sim::StaticObstacle box;
  box.name = "appearing_box";
  box.height_m = 1.0;
  const double half = kBoxSideM / 2.0;
  box.outline = {centre + Point(-half, -half), centre + Point(half, -half), centre + Point(half, half),
                 centre + Point(-half, half)};
  const Trace trace = drive(box, appear_s);

  ASSERT_GE(trace.first_box_packet_us, trace.appear_utime);
  ASSERT_LE(trace.first_box_packet_us - trace.appear_utime, 100'000) << "the lidar sweeps at 10 Hz";
  std::int64_t reaction_us = -1;
  for (std::size_t cycle = 0; cycle < trace.commands.size(); ++cycle) {
    const VelocityCommand& now = trace.commands[cycle];
    const VelocityCommand& before = baseline.commands[cycle];
    const bool changed = now.linear < before.linear - 0.02 || std::abs(now.angular - before.angular) > 0.02;
    if (trace.cycle_utimes[cycle] < trace.first_box_packet_us) {
      ASSERT_FALSE(changed) << "command changed before any packet saw the box, cycle " << cycle;
      continue;
    }
    if (changed) {
      reaction_us = trace.cycle_utimes[cycle] - trace.first_box_packet_us;
      break;
    }
  }
  ASSERT_GE(reaction_us, 0) << "the executive never reacted to the box";
  EXPECT_LE(reaction_us, 100'000);
  std::cout << "first box packet " << (trace.first_box_packet_us - trace.appear_utime) / 1000.0
            << " ms after it appeared; command changed " << reaction_us / 1000.0
            << " ms after that packet; obstacle points per cycle " << trace.points_per_cycle << "\n";

  const Footprint footprint = vehicleFootprint(vehicle_, settings_.reference_to_bumper_m);
  const std::vector<Pose2> after(trace.poses.begin() + static_cast<std::ptrdiff_t>(appear_cycle),
                                 trace.poses.end());
  EXPECT_GT(closestApproach(after, box.outline, footprint), 0.05) << "the vehicle touched the box";
  // Without the box the vehicle drives straight through where it stands.
  EXPECT_LT(closestApproach(baseline.poses, box.outline, footprint), 0.0 + 1e-9);
}

// At 1.5 s the lidar (10 Hz) points ahead; at 1.55 s it points behind, so the box is seen ~50 ms later.
INSTANTIATE_TEST_SUITE_P(LidarPhase, ObstacleReactionTest, ::testing::Values(1.5, 1.55));

}  // namespace
}  // namespace ifar::executive
