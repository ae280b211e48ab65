#include "executive/daemon/executive_node.hpp"

#include <utility>

namespace ifar::executive {
namespace {

constexpr int kStatusEveryCycles = 5;  // 10 Hz at the 50 Hz control rate

}  // namespace

ExecutiveNode::ExecutiveNode(bus::RunLoop& loop, const ExecutiveSettings& settings,
                             const common::VehicleSettings& vehicle, std::shared_ptr<spdlog::logger> logger)
    : loop_(loop), logger_(std::move(logger)), executive_(settings, vehicle)
{
  loop_.subscribe<ifar::pose_t>("POSE", [this](const ifar::pose_t& message, std::int64_t receive_utime) {
    inputs_.pose = Stamped<geometry::Pose2>{fromMessage(message), receive_utime};
  });
  loop_.subscribe<ifar::path_t>(
      "GLOBAL_PATH", [this](const ifar::path_t& message, std::int64_t receive_utime) {
        int malformed = 0;
        inputs_.path = Stamped<Path>{fromMessage(message, malformed), receive_utime};
        if (malformed > 0) {
          ++malformed_paths_;
          logger_->warn("GLOBAL_PATH {}: {} waypoints or controls of unknown kind ({} such paths so far)",
                        message.sequence, malformed, malformed_paths_);
        }
      });
  loop_.subscribe<ifar::force_t>("FORCE", [this](const ifar::force_t& message, std::int64_t receive_utime) {
    inputs_.force = Stamped<ForceReading>{fromMessage(message), receive_utime};
  });
  loop_.subscribe<ifar::motor_status_t>(
      "MOTOR_STATUS", [this](const ifar::motor_status_t& message, std::int64_t receive_utime) {
        motors_.update(message, receive_utime);
        inputs_.motor = motors_.combined();
      });
  loop_.subscribe<ifar::e_stop_t>(
      "E_STOP", [this](const ifar::e_stop_t& message, std::int64_t receive_utime) {
        inputs_.e_stop = Stamped<EStopSignal>{fromMessage(message), receive_utime};
        logger_->warn("E_STOP {} by {}: {}", message.engaged != 0 ? "engaged" : "released", message.source,
                      message.reason);
      });
}

Output ExecutiveNode::cycle(std::int64_t now_us)
{
  Output output = executive_.step(now_us, inputs_);
  loop_.publish("VELOCITY_CMD", toVelocityMessage(output, now_us));
  if (output.mode_changed || ++cycles_ % kStatusEveryCycles == 0) {
    loop_.publish("EXEC_STATUS", toStatusMessage(output, now_us));
  }
  if (output.mode_changed) {
    logger_->info("mode {}: {}", modeName(output.status.mode), output.status.reason);
  }
  if (output.affordance) {
    loop_.publish("AFFORDANCE", toAffordanceMessage(*output.affordance, now_us));
    logger_->info("affordance: {}", output.affordance->text);
  }
  return output;
}

void ExecutiveNode::publishStop(std::int64_t now_us)
{
  loop_.publish("VELOCITY_CMD", toVelocityMessage(Output{}, now_us));
}

}  // namespace ifar::executive
