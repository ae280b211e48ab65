#pragma once
// The executive daemon's wiring, apart from main() so a test can drive it over an in-process bus:
// subscribes POSE, GLOBAL_PATH, FORCE, MOTOR_STATUS and E_STOP into the executive's inputs, and on each
// control cycle publishes VELOCITY_CMD, EXEC_STATUS (every fifth cycle and on mode changes) and
// AFFORDANCE (on tactile findings).

#include <cstdint>
#include <memory>

#include <spdlog/spdlog.h>

#include "common/bus/run_loop.hpp"
#include "common/vehicle.hpp"
#include "executive/daemon/lcm_conversions.hpp"
#include "executive/modes/executive.hpp"

namespace ifar::executive {

class ExecutiveNode {
 public:
  /// Subscribes on `loop`, which must outlive this node.
  ExecutiveNode(bus::RunLoop& loop, const ExecutiveSettings& settings, const common::VehicleSettings& vehicle,
                std::shared_ptr<spdlog::logger> logger);
  ExecutiveNode(const ExecutiveNode&) = delete;
  ExecutiveNode& operator=(const ExecutiveNode&) = delete;

  /// One control cycle at `now_us` (wall-clock microseconds, the clock of LCM receive times).
  Output cycle(std::int64_t now_us);

  /// Publishes a zero command (when the daemon exits).
  void publishStop(std::int64_t now_us);

  std::int64_t malformedPaths() const { return malformed_paths_; }

 private:
  bus::RunLoop& loop_;
  std::shared_ptr<spdlog::logger> logger_;
  Executive executive_;
  Inputs inputs_;
  MotorStatusCombiner motors_;
  std::int64_t malformed_paths_ = 0;
  int cycles_ = 0;
};

}  // namespace ifar::executive
