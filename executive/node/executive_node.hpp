#pragma once
// The executive node's core: everything between the bus and the Executive, without a bus. It takes the
// executive's input messages (POSE, GLOBAL_PATH, FORCE, MOTOR_STATUS, ODOMETRY, E_STOP and the lidar's
// VELODYNE_PACKET, decoded into its own obstacle points) with their receive times, and on each control
// cycle returns what to publish: VELOCITY_CMD, EXEC_STATUS (every fifth cycle and on mode changes),
// AFFORDANCE (on tactile findings) and BLOCKED_PASSAGE (when repeated stalls give a passage up).
// The daemon (executive/daemon) wraps it in the LCM run loop at 50 Hz; the headless runner (system/)
// drives the same node on simulated time. One clock, `now_us`: microseconds, the clock of the receive
// times (wall clock in the daemon, simulated in the runner).

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <spdlog/spdlog.h>

#include "common/rate_limiter.hpp"
#include "common/vehicle.hpp"
#include "executive/modes/executive.hpp"
#include "executive/node/executive_messages.hpp"
#include "executive/obstacles/local_obstacles.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/e_stop_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/force_t.hpp"
#include "ifar/motor_status_t.hpp"
#include "ifar/odometry_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "ifar/velodyne_packet_t.hpp"

namespace ifar::executive {

/// The executive's control period (50 Hz) and its channels, as the daemon subscribes and publishes them.
inline constexpr double kControlPeriodS = 0.02;
inline constexpr const char* kPoseChannel = "POSE";
inline constexpr const char* kPathChannel = "GLOBAL_PATH";
inline constexpr const char* kForceChannel = "FORCE";
inline constexpr const char* kMotorStatusChannel = "MOTOR_STATUS";
inline constexpr const char* kOdometryChannel = "ODOMETRY";
inline constexpr const char* kEStopChannel = "E_STOP";
inline constexpr const char* kCommandChannel = "VELOCITY_CMD";
inline constexpr const char* kStatusChannel = "EXEC_STATUS";
inline constexpr const char* kAffordanceChannel = "AFFORDANCE";
inline constexpr const char* kBlockedPassageChannel = "BLOCKED_PASSAGE";
inline constexpr const char* kJournalChannel = "EXECUTIVE_JOURNAL";
/// The node's inputs, `packet_channel` the lidar's (ObstacleSettings): what the daemon subscribes to for it.
std::set<std::string> inputChannels(const std::string& packet_channel);
/// The daemon's one timer as its journal names it (node_journal_t KIND_TIMER code).
inline constexpr std::int16_t kControlCycleTimer = 0;

/// What one control cycle publishes.
struct ExecutiveOutputs {
  ifar::velocity_cmd_t command;
  std::optional<ifar::exec_status_t> status;  // every fifth cycle and when the mode changed
  std::optional<ifar::affordance_t> affordance;
  std::optional<ifar::blocked_passage_t> blocked_passage;
  Output output;  // the library's own result, for the runner's summary and tests
};

class ExecutiveNode {
 public:
  /// `logger` receives the node's warnings and mode changes; it must not be null. Throws
  /// std::invalid_argument when the vehicle does not fit the executive (see Executive).
  ExecutiveNode(const ExecutiveSettings& settings, const ObstacleSettings& obstacles,
                const common::VehicleSettings& vehicle, std::shared_ptr<spdlog::logger> logger);
  ExecutiveNode(const ExecutiveNode&) = delete;
  ExecutiveNode& operator=(const ExecutiveNode&) = delete;

  // Inputs, each with its receive time. None of them throws on bad content: it is counted and reported.
  void onPose(const ifar::pose_t& message, std::int64_t now_us);
  void onVelodynePacket(const ifar::velodyne_packet_t& message, std::int64_t now_us);
  void onPath(const ifar::path_t& message, std::int64_t now_us);
  void onForce(const ifar::force_t& message, std::int64_t now_us);
  void onMotorStatus(const ifar::motor_status_t& message, std::int64_t now_us);
  void onOdometry(const ifar::odometry_t& message, std::int64_t now_us);
  void onEStop(const ifar::e_stop_t& message, std::int64_t now_us);

  /// One control cycle at `now_us`.
  ExecutiveOutputs cycle(std::int64_t now_us);

  /// What to publish when the node stops: a zero command and, once a cycle has run, the last status again
  /// (the last status is often a single datagram, such as the arrival, that a busy recorder may miss).
  ExecutiveOutputs stop(std::int64_t now_us) const;

  std::int64_t malformedPaths() const { return malformed_paths_; }
  std::int64_t malformedPackets() const { return obstacles_.malformedPackets(); }
  /// The inputs the last cycle gave the executive (obstacles and pushed object included).
  const Inputs& inputs() const { return inputs_; }
  /// While approaching or pushing: the object's id and where the plan expects it (Executive).
  std::optional<ObjectObservation> pushedObjectEstimate() const { return executive_.pushedObjectEstimate(); }
  /// For the heartbeat: healthProblem() of the last cycle's status, or that no cycle has run yet.
  std::string healthProblem() const;

 private:
  /// Fills inputs_.obstacles and inputs_.pushed_object from the packets received so far.
  void updateObstacleInputs(std::int64_t now_us);

  std::shared_ptr<spdlog::logger> logger_;
  Executive executive_;
  Inputs inputs_;
  MotorStatusCombiner motors_;
  std::int64_t malformed_paths_ = 0;
  int cycles_ = 0;
  std::optional<ifar::exec_status_t> last_status_;
  std::optional<Status> last_cycle_status_;
  LocalObstacles obstacles_;
  double pushed_object_radius_m_;
  common::RateLimiter packet_warnings_;
};

}  // namespace ifar::executive
