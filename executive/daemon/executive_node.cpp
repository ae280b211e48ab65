#include "executive/daemon/executive_node.hpp"

#include <utility>

#include <fmt/format.h>

#include "common/time.hpp"
#include "drivers/velodyne/packet_format.hpp"
#include "ifar/velodyne_packet_t.hpp"

namespace ifar::executive {
namespace {

constexpr int kStatusEveryCycles = 5;  // 10 Hz at the 50 Hz control rate
constexpr std::int64_t kPacketWarningIntervalUs = 5'000'000;

}  // namespace

ExecutiveNode::ExecutiveNode(bus::RunLoop& loop, const ExecutiveSettings& settings,
                             const common::VehicleSettings& vehicle, std::shared_ptr<spdlog::logger> logger)
    : ExecutiveNode(loop, settings, ObstacleSettings{}, vehicle, std::move(logger))
{
}

ExecutiveNode::ExecutiveNode(bus::RunLoop& loop, const ExecutiveSettings& settings,
                             const ObstacleSettings& obstacles, const common::VehicleSettings& vehicle,
                             std::shared_ptr<spdlog::logger> logger)
    : loop_(loop),
      logger_(std::move(logger)),
      executive_(settings, vehicle),
      obstacles_(obstacles, vehicle),
      pushed_object_radius_m_(settings.pushed_object.radius_m),
      packet_warnings_(kPacketWarningIntervalUs)
{
  loop_.subscribe<ifar::pose_t>("POSE", [this](const ifar::pose_t& message, std::int64_t receive_utime) {
    inputs_.pose = Stamped<geometry::Pose2>{fromMessage(message), receive_utime};
    obstacles_.addPose(receive_utime, inputs_.pose->value);
  });
  loop_.subscribe<ifar::velodyne_packet_t>(
      obstacles.packet_channel, [this](const ifar::velodyne_packet_t& message, std::int64_t receive_utime) {
        if (message.port == velodyne::kPositionPort) {
          return;  // position packets carry no returns (data packets may come from a configured port)
        }
        const std::int64_t before = obstacles_.malformedPackets();
        obstacles_.addPacket(common::ByteView(message.data.data(), message.data.size()), receive_utime);
        if (obstacles_.malformedPackets() != before &&
            packet_warnings_.allow(common::monotonicMicroseconds())) {
          logger_->warn(
              "{}: malformed lidar packet ({} bytes: {}); {} malformed so far, {} warnings held back",
              message.utime, message.data.size(),
              velodyne::toString(
                  velodyne::inspectPacket(common::ByteView(message.data.data(), message.data.size())).status),
              obstacles_.malformedPackets(), packet_warnings_.takeSuppressed());
        }
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

void ExecutiveNode::updateObstacleInputs(std::int64_t now_us)
{
  const std::int64_t newest = obstacles_.newestPacketUtime();
  if (newest == 0) {
    return;  // no packet yet: the executive reports "no fresh obstacle points"
  }
  // The set as of the newest packet, stamped with it: when the lidar falls silent the executive sees
  // the last points go stale instead of a fresh empty set.
  inputs_.obstacles = Stamped<std::vector<geometry::Point>>{obstacles_.points(newest), newest};
  const std::optional<ObjectObservation> expected = executive_.pushedObjectEstimate();
  if (!expected) {
    return;
  }
  // Follow the object from its last sighting; the plan's expectation starts the search.
  geometry::Point near = expected->position;
  if (inputs_.pushed_object && inputs_.pushed_object->value.object_id == expected->object_id &&
      now_us - inputs_.pushed_object->utime <=
          common::secondsToMicroseconds(executive_.settings().stale.obstacles_s)) {
    near = inputs_.pushed_object->value.position;
  }
  if (const std::optional<geometry::Point> centroid =
          obstacles_.movableCentroid(near, pushed_object_radius_m_, newest)) {
    inputs_.pushed_object =
        Stamped<ObjectObservation>{ObjectObservation{expected->object_id, *centroid}, newest};
  }
}

Output ExecutiveNode::cycle(std::int64_t now_us)
{
  updateObstacleInputs(now_us);
  Output output = executive_.step(now_us, inputs_);
  loop_.publish("VELOCITY_CMD", toVelocityMessage(output, now_us));
  ifar::exec_status_t status = toStatusMessage(output, now_us);
  if (obstacles_.malformedPackets() > 0) {
    status.reason += fmt::format(" [{} malformed lidar packets]", obstacles_.malformedPackets());
  }
  if (output.mode_changed || ++cycles_ % kStatusEveryCycles == 0) {
    loop_.publish("EXEC_STATUS", status);
  }
  last_status_ = std::move(status);
  last_cycle_status_ = output.status;
  if (output.mode_changed) {
    logger_->info("mode {}: {}", modeName(output.status.mode), output.status.reason);
  }
  if (output.affordance) {
    loop_.publish("AFFORDANCE", toAffordanceMessage(*output.affordance, now_us));
    logger_->info("affordance: {}", output.affordance->text);
  }
  if (output.blocked_passage) {
    loop_.publish("BLOCKED_PASSAGE", toBlockedPassageMessage(*output.blocked_passage, now_us));
    logger_->warn("blocked passage: {}", output.blocked_passage->text);
  }
  return output;
}

std::string ExecutiveNode::healthProblem() const
{
  return last_cycle_status_ ? executive::healthProblem(*last_cycle_status_) : "no control cycle yet";
}

void ExecutiveNode::publishStop(std::int64_t now_us)
{
  loop_.publish("VELOCITY_CMD", toVelocityMessage(Output{}, now_us));
  if (last_status_) {
    ifar::exec_status_t status = *last_status_;
    status.utime = now_us;
    loop_.publish("EXEC_STATUS", status);
  }
}

}  // namespace ifar::executive
