// The executive node's obstacle inputs: VELODYNE_PACKET messages become the executive's obstacle points
// and, while approaching a push, the pushed object's observation; malformed packets are counted and
// reported, position packets ignored.

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include "executive/node/executive_node.hpp"
#include "ifar/velodyne_packet_t.hpp"
#include "tests/unit/executive/vlp16_test_packet.hpp"

namespace ifar::executive {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr std::size_t kLaserMinus1 = 14;  // -1 degree elevation

class ExecutiveNodeObstaclesTest : public ::testing::Test {
 protected:
  ExecutiveNodeObstaclesTest()
      : node_(ExecutiveSettings{}, ObstacleSettings{}, common::VehicleSettings{},
              std::make_shared<spdlog::logger>("executive_node_obstacles_test",
                                               std::make_shared<spdlog::sinks::null_sink_mt>()))
  {
  }

  /// The test's clock: each call is a millisecond later.
  std::int64_t tick()
  {
    now_ += 1'000;
    return now_;
  }

  Output cycle()
  {
    ExecutiveOutputs outputs = node_.cycle(tick());
    if (outputs.status) {
      statuses_.push_back(*outputs.status);
    }
    return outputs.output;
  }

  /// Fresh pose (at the origin facing +x), force and motor status, and `path`.
  void publishInputs(const ifar::path_t& path)
  {
    const std::int64_t now = tick();
    ifar::pose_t pose{};
    pose.utime = now;
    pose.orientation[0] = 1.0;
    node_.onPose(pose, now);
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

  void publishPacket(const std::vector<std::uint8_t>& payload, std::int32_t port = 2368)
  {
    ifar::velodyne_packet_t message{};
    message.utime = tick();
    message.port = port;
    message.size = static_cast<std::int32_t>(payload.size());
    message.data = payload;
    node_.onVelodynePacket(message, message.utime);
  }

  static ifar::waypoint_t waypoint(double x, std::int8_t kind, std::int64_t object_id, std::int32_t plan)
  {
    ifar::waypoint_t result{};
    result.x = x;
    result.kind = kind;
    result.object_id = object_id;
    result.push_plan_index = plan;
    return result;
  }

  static ifar::path_t straightPath()
  {
    ifar::path_t path{};
    path.utime = 1;
    path.goal_id = 3;
    path.sequence = 1;
    path.valid = 1;
    path.waypoints = {waypoint(0.0, ifar::waypoint_t::KIND_FREE, -1, -1),
                      waypoint(4.0, ifar::waypoint_t::KIND_FREE, -1, -1)};
    path.num_waypoints = 2;
    return path;
  }

  /// Object 9 (0.6 m box, centroid at (2.25, 0)) pushed from the contact pose (1.5, 0) along +x; the
  /// topological waypoint (0.5, 0) is within the switch radius of the vehicle at the origin.
  static ifar::path_t pushPath()
  {
    ifar::path_t path = straightPath();
    ifar::push_plan_t plan{};
    plan.object_id = 9;
    plan.contact_x = 1.5;
    ifar::push_control_t control{};
    control.kind = ifar::push_control_t::KIND_PUSH;
    control.linear_velocity = 0.3;
    control.duration_s = 3.0;
    control.vehicle_x = 2.4;
    control.object_x = 3.15;
    plan.controls = {control};
    plan.num_controls = 1;
    plan.expected_force_n = 100.0;
    path.push_plans = {plan};
    path.num_push_plans = 1;
    path.waypoints = {waypoint(0.0, ifar::waypoint_t::KIND_FREE, -1, -1),
                      waypoint(0.5, ifar::waypoint_t::KIND_TOPOLOGICAL, 9, 0),
                      waypoint(3.0, ifar::waypoint_t::KIND_PUSH, 9, 0),
                      waypoint(5.0, ifar::waypoint_t::KIND_FREE, -1, -1)};
    path.num_waypoints = 4;
    return path;
  }

  std::int64_t now_ = 1'700'000'000'000'000;
  ExecutiveNode node_;
  std::vector<ifar::exec_status_t> statuses_;
};

TEST_F(ExecutiveNodeObstaclesTest, PacketsBecomeObstaclePoints)
{
  publishInputs(straightPath());
  cycle();
  EXPECT_FALSE(node_.inputs().obstacles.has_value());  // no packet yet: blind, so stopped
  ASSERT_FALSE(statuses_.empty());
  EXPECT_EQ(statuses_.back().mode, ifar::exec_status_t::MODE_STOP);
  EXPECT_EQ(statuses_.back().stale, ifar::exec_status_t::STALE_OBSTACLES);
  EXPECT_NE(statuses_.back().reason.find("stale input: obstacles"), std::string::npos)
      << statuses_.back().reason;

  testing::TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 10);  // 2 m straight ahead of the lidar
  publishPacket(packet.bytes());
  const std::int64_t packet_received = now_;
  publishInputs(straightPath());
  cycle();
  const auto& obstacles = node_.inputs().obstacles;
  ASSERT_TRUE(obstacles.has_value());
  ASSERT_EQ(obstacles->value.size(), 1u);
  EXPECT_NEAR(obstacles->value[0].x(), 0.2 + 2.0 * std::cos(kDegree), 1e-5);
  EXPECT_NEAR(obstacles->value[0].y(), 0.0, 1e-5);
  EXPECT_EQ(obstacles->utime, packet_received);            // stamped with the newest packet, not the cycle
  EXPECT_FALSE(node_.inputs().pushed_object.has_value());  // following: no pushed object
  EXPECT_EQ(node_.malformedPackets(), 0);
}

TEST_F(ExecutiveNodeObstaclesTest, MalformedPacketsAreCountedAndReportedPositionPacketsIgnored)
{
  publishInputs(straightPath());
  testing::TestPacket packet(0);
  packet.set(0, kLaserMinus1, 1000, 10);
  std::vector<std::uint8_t> truncated = packet.bytes();
  truncated.resize(600);
  publishPacket(truncated);
  publishPacket(std::vector<std::uint8_t>(512, 0x55), 8308);  // a position packet: not for us
  EXPECT_EQ(node_.malformedPackets(), 1);
  publishPacket(packet.bytes());
  EXPECT_EQ(node_.malformedPackets(), 1);

  statuses_.clear();
  for (int count = 0; count < 5; ++count) {
    cycle();
  }
  ASSERT_FALSE(statuses_.empty());
  EXPECT_NE(statuses_.back().reason.find("[1 malformed lidar packets]"), std::string::npos)
      << statuses_.back().reason;
  ASSERT_TRUE(node_.inputs().obstacles.has_value());
  EXPECT_EQ(node_.inputs().obstacles->value.size(), 1u);
}

TEST_F(ExecutiveNodeObstaclesTest, RetroReflectiveReturnsNearTheApproachedObjectBecomeItsObservation)
{
  publishInputs(pushPath());
  publishPacket(testing::TestPacket(0).bytes());  // the lidar runs: nothing in view yet
  const Output first = cycle();
  ASSERT_EQ(first.status.mode, Mode::Approach) << first.status.reason;

  // The object's near face (x = 1.95) seen 1.75 m ahead of the lidar, straight ahead and 2.4 degrees
  // to the right; a diffuse wall far to the left is background.
  testing::TestPacket packet(0);
  packet.set(0, kLaserMinus1, 875, 220);
  packet.set(6, kLaserMinus1, 875, 220);
  publishPacket(packet.bytes());
  testing::TestPacket wall(27000);  // azimuth 270 degrees: the vehicle's left
  wall.set(0, kLaserMinus1, 1500, 20);
  publishPacket(wall.bytes());
  publishInputs(pushPath());
  const Output second = cycle();
  EXPECT_EQ(second.status.mode, Mode::Approach);

  const auto& observed = node_.inputs().pushed_object;
  ASSERT_TRUE(observed.has_value());
  EXPECT_EQ(observed->value.object_id, 9);
  const double horizontal = 1.75 * std::cos(kDegree);
  EXPECT_NEAR(observed->value.position.x(), 0.2 + horizontal * (1.0 + std::cos(2.4 * kDegree)) / 2.0, 1e-5);
  EXPECT_NEAR(observed->value.position.y(), -horizontal * std::sin(2.4 * kDegree) / 2.0, 1e-5);
  ASSERT_TRUE(node_.inputs().obstacles.has_value());
  EXPECT_EQ(node_.inputs().obstacles->value.size(), 3u);  // the object is still an obstacle point
}

}  // namespace
}  // namespace ifar::executive
