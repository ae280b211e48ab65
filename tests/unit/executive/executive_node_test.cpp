#include "executive/daemon/executive_node.hpp"

#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include "common/time.hpp"

namespace ifar::executive {
namespace {

/// The daemon's wiring over an in-process bus (memq://): messages in, commands and status out.
class ExecutiveNodeTest : public ::testing::Test {
 protected:
  ExecutiveNodeTest()
      : logger_(std::make_shared<spdlog::logger>("executive_node_test",
                                                 std::make_shared<spdlog::sinks::null_sink_mt>())),
        loop_("memq://", logger_),
        node_(loop_, ExecutiveSettings{}, common::VehicleSettings{}, logger_)
  {
    loop_.subscribe<ifar::velocity_cmd_t>(
        "VELOCITY_CMD",
        [this](const ifar::velocity_cmd_t& message, std::int64_t) { commands_.push_back(message); });
    loop_.subscribe<ifar::exec_status_t>(
        "EXEC_STATUS",
        [this](const ifar::exec_status_t& message, std::int64_t) { statuses_.push_back(message); });
  }

  /// Publishes fresh pose, path, force and motor status and delivers them.
  void publishInputs()
  {
    const std::int64_t now = common::nowMicroseconds();
    ifar::pose_t pose{};
    pose.utime = now;
    pose.orientation[0] = 1.0;
    loop_.publish("POSE", pose);
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
    loop_.publish("GLOBAL_PATH", path);
    ifar::force_t force{};
    force.utime = now;
    loop_.publish("FORCE", force);
    ifar::motor_status_t motor{};
    motor.utime = now;
    motor.node_id = 1;
    motor.heartbeat_ok = 1;
    motor.drive_state = ifar::motor_status_t::DRIVE_OPERATION_ENABLED;
    loop_.publish("MOTOR_STATUS", motor);
    deliver();
  }

  void deliver()
  {
    for (int round = 0; round < 10; ++round) {
      loop_.spinOnce(0);
    }
  }

  std::shared_ptr<spdlog::logger> logger_;
  bus::RunLoop loop_;
  ExecutiveNode node_;
  std::vector<ifar::velocity_cmd_t> commands_;
  std::vector<ifar::exec_status_t> statuses_;
};

TEST_F(ExecutiveNodeTest, FollowsThenStopsOnEStopAndOnExit)
{
  publishInputs();
  node_.cycle(common::nowMicroseconds());
  const Output moving = node_.cycle(common::nowMicroseconds() + 20'000);
  deliver();
  EXPECT_EQ(moving.status.mode, Mode::Follow);
  ASSERT_EQ(commands_.size(), 2u);
  EXPECT_GT(commands_.back().linear_velocity, 0.0);
  ASSERT_FALSE(statuses_.empty());  // the mode change to follow was reported at once
  EXPECT_EQ(statuses_.back().mode, ifar::exec_status_t::MODE_FOLLOW);
  EXPECT_EQ(statuses_.back().goal_id, 3);

  ifar::e_stop_t e_stop{};
  e_stop.utime = common::nowMicroseconds();
  e_stop.engaged = 1;
  e_stop.source = "test";
  loop_.publish("E_STOP", e_stop);
  publishInputs();
  node_.cycle(common::nowMicroseconds());
  deliver();
  EXPECT_EQ(statuses_.back().mode, ifar::exec_status_t::MODE_E_STOP);
  EXPECT_DOUBLE_EQ(commands_.back().linear_velocity, 0.0);
  EXPECT_DOUBLE_EQ(commands_.back().angular_velocity, 0.0);

  commands_.clear();
  statuses_.clear();
  node_.publishStop(common::nowMicroseconds());
  deliver();
  ASSERT_EQ(commands_.size(), 1u);
  EXPECT_DOUBLE_EQ(commands_.back().linear_velocity, 0.0);
  EXPECT_DOUBLE_EQ(commands_.back().left_wheel, 0.0);
  // On exit the last status goes out once more, so a recorder that missed it still logs how things ended.
  ASSERT_EQ(statuses_.size(), 1u);
  EXPECT_EQ(statuses_.back().mode, ifar::exec_status_t::MODE_E_STOP);
  EXPECT_EQ(statuses_.back().goal_id, 3);
}

TEST_F(ExecutiveNodeTest, ExitBeforeAnyCyclePublishesNoStatus)
{
  node_.publishStop(common::nowMicroseconds());
  deliver();
  EXPECT_EQ(commands_.size(), 1u);
  EXPECT_TRUE(statuses_.empty());
}

TEST_F(ExecutiveNodeTest, SilentInputsStop)
{
  publishInputs();
  node_.cycle(common::nowMicroseconds());
  // Nothing arrives for half a second: pose and force are stale.
  const Output output = node_.cycle(common::nowMicroseconds() + 500'000);
  EXPECT_EQ(output.status.mode, Mode::Stop);
  EXPECT_TRUE(output.command.isZero());
  EXPECT_NE(output.status.stale & kStalePose, 0);
}

TEST_F(ExecutiveNodeTest, HealthNamesStaleInputsForTheHeartbeat)
{
  EXPECT_EQ(node_.healthProblem(), "no control cycle yet");
  publishInputs();
  node_.cycle(common::nowMicroseconds());
  EXPECT_EQ(node_.healthProblem(), "");
  node_.cycle(common::nowMicroseconds() + 500'000);
  EXPECT_EQ(node_.healthProblem(), "stale inputs: pose, force, motor");
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
