#include "drivers/motor/motor_driver_node.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "sim/can_nodes/drive_emulator.hpp"

namespace ifar::motor {
namespace {

constexpr std::int64_t kEpoch = 1'700'000'000'000'000;  // the clock starts somewhere in 2023

std::string hex(const can::Frame& frame)
{
  char text[40];
  std::snprintf(text, sizeof(text), "%03X#", static_cast<unsigned>(frame.id));
  std::string result = text;
  for (int index = 0; index < frame.dlc; ++index) {
    std::snprintf(text, sizeof(text), "%02X", frame.data[static_cast<std::size_t>(index)]);
    result += text;
  }
  return result;
}

/// config/can.yaml's motor section as the daemon reads it, for config/vehicle.yaml's geometry.
MotorConfig projectConfig()
{
  MotorConfig config;
  for (MotorClientSettings* client : {&config.drive.left, &config.drive.right}) {
    client->command_timeout_us = 150'000;
  }
  config.drive.left.node_id = 1;
  config.drive.right.node_id = 2;
  return config;
}

ifar::velocity_cmd_t command(std::int64_t utime, double linear, double angular)
{
  ifar::velocity_cmd_t message{};
  message.utime = utime;
  message.linear_velocity = linear;
  message.angular_velocity = angular;
  return message;
}

/// The node and two simulated drives in lock-step, 10 ms cycles, a fresh command (if any) each cycle.
class MotorDriverNodeTest : public ::testing::Test {
 protected:
  MotorDriverNode node{projectConfig(), common::VehicleSettings{}};
  sim::DriveEmulator left{sim::DriveEmulatorSettings{1, 100'000, 10'000, true, 20'000.0}};
  sim::DriveEmulator right{sim::DriveEmulatorSettings{2, 100'000, 10'000, true, 20'000.0}};
  std::int64_t now = kEpoch;
  std::vector<can::Frame> sent;        // everything the node sent, in order
  std::vector<can::Frame> drive_sent;  // everything the drives sent
  bool node_alive = true;              // false: the node neither cycles nor hears (a frozen driver)
  bool left_powered = true;            // false: the left drive is silent (unplugged, powered off)

  void step(const std::optional<std::pair<double, double>>& velocity)
  {
    now += 10'000;
    if (node_alive) {
      if (velocity) {
        node.onVelocityCommand(command(now, velocity->first, velocity->second), now);
      }
      for (const can::Frame& frame : node.cycle(now)) {
        sent.push_back(frame);
        left.onFrame(frame, now);
        right.onFrame(frame, now);
      }
    }
    for (sim::DriveEmulator* drive : {&left, &right}) {
      if (drive == &left && !left_powered) {
        continue;
      }
      for (const can::Frame& frame : drive->update(now)) {
        drive_sent.push_back(frame);
        if (node_alive) {
          node.onFrame(frame, now);
        }
      }
    }
  }
  void run(int cycles, double linear, double angular)
  {
    for (int index = 0; index < cycles; ++index) {
      step(std::make_pair(linear, angular));
    }
  }
  /// RPDO1 target velocities the node sent to `node_id` from `from` on.
  std::vector<std::int32_t> targets(std::uint8_t node_id, std::size_t from = 0) const
  {
    std::vector<std::int32_t> result;
    for (std::size_t index = from; index < sent.size(); ++index) {
      if (const auto rpdo = decodeRpdo1(sent[index], node_id)) {
        result.push_back(rpdo->target_velocity);
      }
    }
    return result;
  }
};

TEST_F(MotorDriverNodeTest, StartsWithItsHeartbeatThenConfiguresBothDrivesBeforeEnablingThem)
{
  run(3, 0.0, 0.0);
  ASSERT_GE(sent.size(), 3u);
  EXPECT_EQ(hex(sent[0]), "77F#05");  // this driver, node 127, operational
  EXPECT_EQ(hex(sent[1]), "601#2F60600003000000");
  EXPECT_EQ(hex(sent[2]), "602#2F60600003000000");
  run(40, 0.0, 0.0);
  EXPECT_TRUE(node.running(now));
  EXPECT_EQ(left.objects().max_profile_velocity, 9066u);
  EXPECT_EQ(right.objects().consumer_heartbeat, 0x007F0096u);
  EXPECT_EQ(right.objects().rpdo_event_timer_ms, 100);
  EXPECT_EQ(node.wheelVelocityLimit(), 9066);
  // The heartbeat every 50 ms.
  int beats = 0;
  for (const can::Frame& frame : sent) {
    beats += frame.id == 0x77F ? 1 : 0;
  }
  EXPECT_EQ(beats, 9);  // at 10, 60, ..., 410 ms
}

TEST_F(MotorDriverNodeTest, NoCommandEverPutsMoreThanTheWheelLimitIntoRpdo1)
{
  run(40, 0.0, 0.0);
  ASSERT_TRUE(node.running(now));
  const std::size_t start = sent.size();
  run(200, 1e9, 0.0);
  // Accelerating at 1 m/s^2: 0.01 m/s more per cycle, 66.7 units at the wheel; 1 m/s = 6667.
  const std::vector<std::int32_t> ramp = targets(1, start);
  ASSERT_GE(ramp.size(), 3u);
  EXPECT_EQ(ramp[0], 67);
  EXPECT_EQ(ramp[1], 133);
  EXPECT_EQ(ramp.back(), 6667);
  EXPECT_EQ(targets(2, start).back(), 6667);
  run(100, 5.0, 0.0);
  EXPECT_EQ(targets(1).back(), 6667);
  run(300, -1e9, 0.0);
  EXPECT_EQ(targets(1).back(), -6667);
  // Full speed on the tightest turn: the outer wheel at (1.0 + 1.2 x 0.3) / 0.15 = 9066.7, held to 9066.
  run(300, 1.0, 1.2);
  EXPECT_EQ(targets(1).back(), 4267);
  EXPECT_EQ(targets(2).back(), 9066);
  run(300, 1e9, -1e9);  // curvature -1 at the linear limit: 1 m/s, -1 rad/s
  EXPECT_EQ(targets(1).back(), 8667);
  EXPECT_EQ(targets(2).back(), 4667);
  for (std::uint8_t node_id : {1, 2}) {
    for (const std::int32_t target : targets(node_id)) {
      EXPECT_LE(std::abs(target), 9066);
    }
  }
  EXPECT_EQ(node.commandCounters().refused(), 0);
  EXPECT_EQ(node.commandCounters().limited, 900);
}

TEST_F(MotorDriverNodeTest, NotANumberIsRefusedAndCounted)
{
  run(40, 0.0, 0.0);
  run(100, 0.5, 0.0);
  const std::int32_t before = targets(1).back();
  EXPECT_EQ(before, 3333);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  node.onVelocityCommand(command(now, nan, 0.0), now);
  node.onVelocityCommand(command(now, 0.0, std::numeric_limits<double>::infinity()), now);
  EXPECT_EQ(node.commandCounters().non_finite, 2);
  step(std::nullopt);
  EXPECT_EQ(targets(1).back(), before);  // the last good command holds until it goes stale
  const auto report = node.takeRefusalReport(now);
  ASSERT_TRUE(report);
  EXPECT_EQ(*report,
            "refused 2 velocity command(s) since the last report; the latest: not a number: linear "
            "0.000000 m/s, angular inf rad/s");
  EXPECT_FALSE(node.takeRefusalReport(now));
  EXPECT_EQ(node.takeHealthProblem(now), "2 velocity commands refused");
  EXPECT_EQ(node.takeHealthProblem(now), "");
}

TEST_F(MotorDriverNodeTest, SaysWhichDriveItWaitsFor)
{
  EXPECT_EQ(node.readinessProblem(now),
            "no heartbeat from drive 1 since start; no heartbeat from drive 2 since start");
  run(40, 0.0, 0.0);
  ASSERT_TRUE(node.running(now));
  EXPECT_EQ(node.readinessProblem(now), "");
  EXPECT_EQ(node.takeHealthProblem(now), "");
  left_powered = false;
  run(20, 0.0, 0.0);  // 200 ms: within the 300 ms heartbeat timeout
  EXPECT_EQ(node.readinessProblem(now), "");
  run(20, 0.0, 0.0);
  EXPECT_EQ(node.readinessProblem(now), "drive 1 heartbeat lost");
  left_powered = true;
  run(60, 0.0, 0.0);
  EXPECT_EQ(node.readinessProblem(now), "");
}

TEST_F(MotorDriverNodeTest, CommandsAreStaleByTheirOwnUtime)
{
  // A replayed log: 50 s old commands, arriving now at 50 Hz. Nothing moves.
  for (int index = 0; index < 100; ++index) {
    now += 10'000;
    node.onVelocityCommand(command(now - 50'000'000, 0.8, 0.0), now);
    for (const can::Frame& frame : node.cycle(now)) {
      sent.push_back(frame);
      left.onFrame(frame, now);
      right.onFrame(frame, now);
    }
    for (sim::DriveEmulator* drive : {&left, &right}) {
      if (drive == &left && !left_powered) {
        continue;
      }
      for (const can::Frame& frame : drive->update(now)) {
        node.onFrame(frame, now);
      }
    }
  }
  EXPECT_EQ(node.commandCounters().stale, 100);
  EXPECT_EQ(node.commandCounters().accepted, 0);
  EXPECT_FALSE(node.running(now));
  EXPECT_EQ(left.driveState(), DriveState::kSwitchOnDisabled);  // never enabled
  for (const std::int32_t target : targets(1)) {
    EXPECT_EQ(target, 0);
  }
  const auto report = node.takeRefusalReport(now);
  ASSERT_TRUE(report);
  EXPECT_NE(report->find("stale: utime 1699999951000000 is 50.000 s old (limit 0.150 s)"), std::string::npos)
      << *report;
  // Just inside the limit is taken, just outside is not.
  node.onVelocityCommand(command(now - 150'000, 0.1, 0.0), now);
  EXPECT_EQ(node.commandCounters().accepted, 1);
  node.onVelocityCommand(command(now - 150'001, 0.1, 0.0), now);
  EXPECT_EQ(node.commandCounters().stale, 101);
}

TEST_F(MotorDriverNodeTest, CommandsFromTheFutureOrOutOfOrderAreRefused)
{
  node.onVelocityCommand(command(now + 1'000'000, 0.5, 0.0), now);
  EXPECT_EQ(node.commandCounters().future, 1);
  node.onVelocityCommand(command(now + 50'000, 0.5, 0.0), now);  // within the 50 ms tolerance
  EXPECT_EQ(node.commandCounters().accepted, 1);
  node.onVelocityCommand(command(now + 40'000, 0.5, 0.0), now);
  EXPECT_EQ(node.commandCounters().out_of_order, 1);
  const auto report = node.takeRefusalReport(now);
  ASSERT_TRUE(report);
  EXPECT_NE(
      report->find("out of order: utime 1700000000040000 is 0.010 s older than a command already taken"),
      std::string::npos)
      << *report;
}

TEST_F(MotorDriverNodeTest, AFrozenDriverIsStoppedByTheDrivesWithin110Milliseconds)
{
  run(40, 0.0, 0.0);
  run(150, 0.8, 0.0);
  ASSERT_EQ(left.commandedVelocity(), 5333);
  ASSERT_EQ(right.commandedVelocity(), 5333);
  const std::int64_t frozen_at = now;  // the last RPDO1 went out in this cycle
  const std::size_t drive_frames_before = drive_sent.size();
  node_alive = false;
  std::int64_t stopped_at = 0;
  while (stopped_at == 0 && now < frozen_at + 1'000'000) {
    step(std::nullopt);
    if (left.commandedVelocity() == 0 && right.commandedVelocity() == 0) {
      stopped_at = now;
    }
  }
  // The RPDO deadline (100 ms) trips at the first drive update after it: 110 ms on a 10 ms cycle.
  EXPECT_EQ(stopped_at - frozen_at, 110'000);
  EXPECT_EQ(left.driveState(), DriveState::kQuickStopActive);
  std::vector<std::string> emergencies;
  for (std::size_t index = drive_frames_before; index < drive_sent.size(); ++index) {
    if (drive_sent[index].id == 0x081 || drive_sent[index].id == 0x082) {
      emergencies.push_back(hex(drive_sent[index]));
    }
  }
  EXPECT_EQ(emergencies, (std::vector<std::string>{"081#5082110000000000", "082#5082110000000000"}));
  // Later the driver's heartbeat is missed too (150 ms): a second EMCY each.
  for (int index = 0; index < 10; ++index) {
    step(std::nullopt);
  }
  int heartbeat_errors = 0;
  for (std::size_t index = drive_frames_before; index < drive_sent.size(); ++index) {
    const auto emergency =
        decodeEmergency(drive_sent[index], static_cast<std::uint8_t>(drive_sent[index].id & 0x7F));
    heartbeat_errors += emergency && emergency->error_code == kEmergencyHeartbeatError ? 1 : 0;
  }
  EXPECT_EQ(heartbeat_errors, 2);

  // Thawed: the commands that queued up meanwhile are stale and refused; fresh ones run the drives
  // again through the whole enable sequence.
  node_alive = true;
  node.onVelocityCommand(command(frozen_at + 10'000, 0.8, 0.0), now);
  EXPECT_EQ(node.commandCounters().stale, 1);
  run(250, 0.8, 0.0);
  EXPECT_TRUE(node.running(now));
  EXPECT_EQ(left.commandedVelocity(), 5333);
  const auto status = node.statusMessages(now);
  ASSERT_EQ(status.size(), 2u);
  EXPECT_EQ(status[0].node_id, 1);
  EXPECT_EQ(status[1].node_id, 2);
  EXPECT_EQ(status[0].emergency_code, 0);  // the drives' "error reset" once the driver was back
  EXPECT_EQ(status[0].reason, "");
}

TEST_F(MotorDriverNodeTest, StopAndDisableLeavesTheDrivesStandingAndDisabled)
{
  run(40, 0.0, 0.0);
  run(100, 0.5, 0.0);
  node.stopAndDisable();
  run(50, 0.5, 0.0);  // commands keep arriving: they do not re-enable
  EXPECT_EQ(left.commandedVelocity(), 0);
  EXPECT_EQ(left.driveState(), DriveState::kReadyToSwitchOn);
  EXPECT_EQ(node.statusMessages(now)[0].reason, "disabled by operator");
}

}  // namespace
}  // namespace ifar::motor

namespace ifar::motor {
namespace {

can::Frame tpdo1(std::uint8_t node_id, std::int32_t actual_velocity)
{
  return encodeTpdo1(node_id, VelocityFeedback{0x0627, actual_velocity});
}

TEST(MotorDriverNodeOdometry, TheDrivesActualVelocitiesBecomeWheelAndBodyVelocities)
{
  MotorDriverNode node{projectConfig(), common::VehicleSettings{}};  // radius 0.15 m, track 0.6 m
  node.onFrame(tpdo1(1, 2000), kEpoch);                              // left wheel 2 rad/s
  node.onFrame(tpdo1(2, 3000), kEpoch + 3'000);                      // right wheel 3 rad/s
  node.onFrame(tpdo1(3, 9000), kEpoch + 4'000);                      // another node's: not a wheel
  const ifar::odometry_t odometry = node.odometry(kEpoch + 10'000);
  EXPECT_EQ(odometry.utime, kEpoch + 10'000);
  EXPECT_EQ(odometry.left_node_id, 1);
  EXPECT_EQ(odometry.right_node_id, 2);
  EXPECT_DOUBLE_EQ(odometry.left_wheel_rad_s, 2.0);
  EXPECT_DOUBLE_EQ(odometry.right_wheel_rad_s, 3.0);
  EXPECT_DOUBLE_EQ(odometry.linear_velocity, 0.375);  // 0.15 x (3 + 2) / 2
  EXPECT_DOUBLE_EQ(odometry.angular_velocity, 0.25);  // 0.15 x (3 - 2) / 0.6
  EXPECT_EQ(odometry.left_age_us, 10'000);
  EXPECT_EQ(odometry.right_age_us, 7'000);
  EXPECT_EQ(odometry.status, 0);
}

TEST(MotorDriverNodeOdometry, ReversingAndTurningOnTheSpot)
{
  MotorDriverNode node{projectConfig(), common::VehicleSettings{}};
  node.onFrame(tpdo1(1, -1000), kEpoch);
  node.onFrame(tpdo1(2, 1000), kEpoch);
  ifar::odometry_t odometry = node.odometry(kEpoch);
  EXPECT_DOUBLE_EQ(odometry.linear_velocity, 0.0);
  EXPECT_DOUBLE_EQ(odometry.angular_velocity, 0.5);  // 0.15 x 2 / 0.6, counter-clockwise
  node.onFrame(tpdo1(1, -1500), kEpoch + 10'000);
  node.onFrame(tpdo1(2, -1500), kEpoch + 10'000);
  odometry = node.odometry(kEpoch + 10'000);
  EXPECT_DOUBLE_EQ(odometry.left_wheel_rad_s, -1.5);
  EXPECT_DOUBLE_EQ(odometry.linear_velocity, -0.225);
  EXPECT_DOUBLE_EQ(odometry.angular_velocity, 0.0);
}

TEST(MotorDriverNodeOdometry, ADriveWithoutTpdo1WithinTheTimeoutIsFlaggedStale)
{
  MotorDriverNode node{projectConfig(), common::VehicleSettings{}};  // odometry timeout 50 ms
  ifar::odometry_t odometry = node.odometry(kEpoch);
  EXPECT_EQ(odometry.left_age_us, -1);  // nothing heard yet
  EXPECT_EQ(odometry.right_age_us, -1);
  EXPECT_EQ(odometry.status, ifar::odometry_t::STATUS_LEFT_STALE | ifar::odometry_t::STATUS_RIGHT_STALE);
  node.onFrame(tpdo1(1, 1000), kEpoch);
  node.onFrame(tpdo1(2, 1000), kEpoch);
  EXPECT_EQ(node.odometry(kEpoch + 50'000).status, 0);  // 50 ms old: still fresh
  node.onFrame(tpdo1(2, 1200), kEpoch + 40'000);
  odometry = node.odometry(kEpoch + 50'001);
  EXPECT_EQ(odometry.status, ifar::odometry_t::STATUS_LEFT_STALE);
  EXPECT_EQ(odometry.left_age_us, 50'001);
  EXPECT_EQ(odometry.right_age_us, 10'001);
  EXPECT_DOUBLE_EQ(odometry.left_wheel_rad_s, 1.0);  // the last one received, flagged
  EXPECT_DOUBLE_EQ(odometry.right_wheel_rad_s, 1.2);
}

TEST_F(MotorDriverNodeTest, OdometryFollowsTheDrivesInClosedLoop)
{
  run(60, 0.0, 0.0);  // configured and enabled
  ASSERT_TRUE(node.running(now));
  run(100, 0.3, 0.0);  // 1 s: the wheels reach 2 rad/s within the ramp
  const ifar::odometry_t odometry = node.odometry(now);
  EXPECT_EQ(odometry.status, 0);
  EXPECT_LE(odometry.left_age_us, 10'000);
  EXPECT_DOUBLE_EQ(odometry.left_wheel_rad_s, left.actualVelocity() / 1000.0);
  EXPECT_DOUBLE_EQ(odometry.right_wheel_rad_s, right.actualVelocity() / 1000.0);
  EXPECT_NEAR(odometry.linear_velocity, 0.3, 1e-3);
  EXPECT_NEAR(odometry.angular_velocity, 0.0, 1e-9);
}

}  // namespace
}  // namespace ifar::motor
