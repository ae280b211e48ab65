#include "executive/node/executive_node.hpp"

#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include "tests/unit/executive/vlp16_test_packet.hpp"

namespace ifar::executive {
namespace {

constexpr std::int64_t kStartUs = 1'700'000'000'000'000;

/// The node core on a clock of its own: messages in with their receive times, outputs back.
class ExecutiveNodeTest : public ::testing::Test {
 protected:
  ExecutiveNodeTest()
      : node_(ExecutiveSettings{}, ObstacleSettings{}, common::VehicleSettings{},
              std::make_shared<spdlog::logger>("executive_node_test",
                                               std::make_shared<spdlog::sinks::null_sink_mt>()))
  {
  }

  /// Fresh pose, path, force, motor status and a lidar packet (no returns) received at `now`.
  void receiveInputs(std::int64_t now)
  {
    ifar::pose_t pose{};
    pose.utime = now;
    pose.orientation[0] = 1.0;
    node_.onPose(pose, now);
    // After the pose: the executive places a packet's returns with the pose it has.
    ifar::velodyne_packet_t packet{};
    packet.utime = now;
    packet.port = 2368;
    packet.data = testing::TestPacket(0).bytes();
    packet.size = static_cast<std::int32_t>(packet.data.size());
    node_.onVelodynePacket(packet, now);
    ifar::path_t path{};
    path.utime = 1;
    path.goal_id = 3;
    path.sequence = 1;
    path.valid = 1;
    ifar::waypoint_t start{};
    ifar::waypoint_t goal{};
    goal.x = 4.0;
    path.waypoints = {start, goal};
    path.num_waypoints = 2;
    node_.onPath(path, now);
    ifar::force_t force{};
    force.utime = now;
    node_.onForce(force, now);
    ifar::motor_status_t motor{};
    motor.utime = now;
    motor.node_id = 1;
    motor.heartbeat_ok = 1;
    motor.drive_state = ifar::motor_status_t::DRIVE_OPERATION_ENABLED;
    node_.onMotorStatus(motor, now);
  }

  ExecutiveNode node_;
};

TEST_F(ExecutiveNodeTest, FollowsThenStopsOnEStopAndOnExit)
{
  receiveInputs(kStartUs);
  const ExecutiveOutputs first = node_.cycle(kStartUs);
  const ExecutiveOutputs moving = node_.cycle(kStartUs + 20'000);
  EXPECT_EQ(moving.output.status.mode, Mode::Follow);
  EXPECT_EQ(moving.command.utime, kStartUs + 20'000);
  EXPECT_GT(moving.command.linear_velocity, 0.0);
  // The mode change to follow was reported at once.
  ASSERT_TRUE(first.status || moving.status);
  const ifar::exec_status_t& follow_status = first.status ? *first.status : *moving.status;
  EXPECT_EQ(follow_status.mode, ifar::exec_status_t::MODE_FOLLOW);
  EXPECT_EQ(follow_status.goal_id, 3);

  ifar::e_stop_t e_stop{};
  e_stop.utime = kStartUs + 30'000;
  e_stop.engaged = 1;
  e_stop.source = "test";
  node_.onEStop(e_stop, kStartUs + 30'000);
  receiveInputs(kStartUs + 30'000);
  const ExecutiveOutputs stopped = node_.cycle(kStartUs + 40'000);
  ASSERT_TRUE(stopped.status);  // a mode change goes out at once
  EXPECT_EQ(stopped.status->mode, ifar::exec_status_t::MODE_E_STOP);
  EXPECT_DOUBLE_EQ(stopped.command.linear_velocity, 0.0);
  EXPECT_DOUBLE_EQ(stopped.command.angular_velocity, 0.0);

  const ExecutiveOutputs exit = node_.stop(kStartUs + 50'000);
  EXPECT_DOUBLE_EQ(exit.command.linear_velocity, 0.0);
  EXPECT_DOUBLE_EQ(exit.command.left_wheel, 0.0);
  EXPECT_EQ(exit.command.utime, kStartUs + 50'000);
  // On exit the last status goes out once more, so a recorder that missed it still logs how things ended.
  ASSERT_TRUE(exit.status);
  EXPECT_EQ(exit.status->mode, ifar::exec_status_t::MODE_E_STOP);
  EXPECT_EQ(exit.status->goal_id, 3);
  EXPECT_EQ(exit.status->utime, kStartUs + 50'000);
}

TEST_F(ExecutiveNodeTest, StatusGoesOutOnModeChangesAndEveryFifthOtherCycle)
{
  int steady_cycles = 0;
  for (int cycle = 0; cycle < 40; ++cycle) {
    const std::int64_t now = kStartUs + cycle * 20'000;
    receiveInputs(now);
    const ExecutiveOutputs outputs = node_.cycle(now);
    if (outputs.output.mode_changed) {
      EXPECT_TRUE(outputs.status) << "cycle " << cycle;
      continue;
    }
    ++steady_cycles;
    EXPECT_EQ(outputs.status.has_value(), steady_cycles % 5 == 0) << "cycle " << cycle;
  }
  EXPECT_GE(steady_cycles, 35);
}

TEST_F(ExecutiveNodeTest, ExitBeforeAnyCyclePublishesNoStatus)
{
  const ExecutiveOutputs exit = node_.stop(kStartUs);
  EXPECT_DOUBLE_EQ(exit.command.linear_velocity, 0.0);
  EXPECT_FALSE(exit.status);
}

TEST_F(ExecutiveNodeTest, SilentInputsStop)
{
  receiveInputs(kStartUs);
  node_.cycle(kStartUs);
  // Nothing arrives for half a second: pose and force are stale.
  const ExecutiveOutputs outputs = node_.cycle(kStartUs + 500'000);
  EXPECT_EQ(outputs.output.status.mode, Mode::Stop);
  EXPECT_TRUE(outputs.output.command.isZero());
  EXPECT_DOUBLE_EQ(outputs.command.linear_velocity, 0.0);
  EXPECT_NE(outputs.output.status.stale & kStalePose, 0);
}

TEST_F(ExecutiveNodeTest, HealthNamesStaleInputsForTheHeartbeat)
{
  EXPECT_EQ(node_.healthProblem(), "no control cycle yet");
  receiveInputs(kStartUs);
  node_.cycle(kStartUs);
  EXPECT_EQ(node_.healthProblem(), "");
  node_.cycle(kStartUs + 500'000);
  EXPECT_EQ(node_.healthProblem(), "stale inputs: pose, force, motor");  // points hold 0.5 s
}

TEST_F(ExecutiveNodeTest, OdometryIsAnInputThatNeverStopsTheVehicle)
{
  receiveInputs(kStartUs);
  ifar::odometry_t odometry{};
  odometry.utime = kStartUs;
  odometry.linear_velocity = 0.25;
  odometry.angular_velocity = -0.5;
  node_.onOdometry(odometry, kStartUs + 1'000);
  ASSERT_TRUE(node_.inputs().odometry.has_value());
  EXPECT_EQ(node_.inputs().odometry->utime, kStartUs + 1'000);  // the receive time
  EXPECT_DOUBLE_EQ(node_.inputs().odometry->value.linear, 0.25);
  EXPECT_DOUBLE_EQ(node_.inputs().odometry->value.angular, -0.5);
  EXPECT_TRUE(node_.inputs().odometry->value.valid);
  // Wheel odometry goes stale (an old log has none): the other inputs fresh, the vehicle follows on.
  receiveInputs(kStartUs + 500'000);
  const ExecutiveOutputs outputs = node_.cycle(kStartUs + 500'000);
  EXPECT_EQ(outputs.output.status.mode, Mode::Follow);
  EXPECT_EQ(outputs.output.status.stale, 0);
  EXPECT_EQ(node_.healthProblem(), "");
}

// Idle or arrived, no path is expected: only the inputs that must always flow count.
TEST(ExecutiveHealth, AStalePathIsAProblemOnlyWhileAGoalIsDriven)
{
  Status status;
  status.stale = kStalePath;
  status.mode = Mode::Idle;
  EXPECT_EQ(healthProblem(status), "");
  status.mode = Mode::Arrived;
  EXPECT_EQ(healthProblem(status), "");
  status.mode = Mode::Follow;
  EXPECT_EQ(healthProblem(status), "stale inputs: path");
  status.mode = Mode::Idle;
  status.stale = kStalePath | kStaleMotor;
  EXPECT_EQ(healthProblem(status), "stale inputs: motor");
}

}  // namespace
}  // namespace ifar::executive
