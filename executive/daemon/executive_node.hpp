#pragma once
// The executive daemon's wiring, apart from main() so a test can drive it over an in-process bus:
// subscribes POSE, GLOBAL_PATH, FORCE, MOTOR_STATUS and E_STOP into the executive's inputs and
// VELODYNE_PACKET (the channel from `obstacles:`) into its own obstacle points, and on each control
// cycle publishes VELOCITY_CMD, EXEC_STATUS (every fifth cycle and on mode changes), AFFORDANCE (on
// tactile findings) and BLOCKED_PASSAGE (when repeated stalls give a passage up).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <spdlog/spdlog.h>

#include "common/bus/run_loop.hpp"
#include "common/rate_limiter.hpp"
#include "common/vehicle.hpp"
#include "executive/daemon/lcm_conversions.hpp"
#include "executive/modes/executive.hpp"
#include "executive/obstacles/local_obstacles.hpp"

namespace ifar::executive {

class ExecutiveNode {
 public:
  /// Subscribes on `loop`, which must outlive this node.
  ExecutiveNode(bus::RunLoop& loop, const ExecutiveSettings& settings, const common::VehicleSettings& vehicle,
                std::shared_ptr<spdlog::logger> logger);
  /// The same with the obstacle settings (and packet channel) of executive.yaml's `obstacles:` section.
  ExecutiveNode(bus::RunLoop& loop, const ExecutiveSettings& settings, const ObstacleSettings& obstacles,
                const common::VehicleSettings& vehicle, std::shared_ptr<spdlog::logger> logger);
  ExecutiveNode(const ExecutiveNode&) = delete;
  ExecutiveNode& operator=(const ExecutiveNode&) = delete;

  /// One control cycle at `now_us` (wall-clock microseconds, the clock of LCM receive times).
  Output cycle(std::int64_t now_us);

  /// Publishes a zero command and, once a cycle has run, the last status again (when the daemon exits:
  /// the last status is often a single datagram, such as the arrival, that a busy recorder may miss).
  void publishStop(std::int64_t now_us);

  std::int64_t malformedPaths() const { return malformed_paths_; }
  std::int64_t malformedPackets() const { return obstacles_.malformedPackets(); }
  /// The inputs the last cycle gave the executive (obstacles and pushed object included).
  const Inputs& inputs() const { return inputs_; }
  /// For the heartbeat: healthProblem() of the last cycle's status, or that no cycle has run yet.
  std::string healthProblem() const;

 private:
  /// Fills inputs_.obstacles and inputs_.pushed_object from the packets received so far.
  void updateObstacleInputs(std::int64_t now_us);

  bus::RunLoop& loop_;
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
