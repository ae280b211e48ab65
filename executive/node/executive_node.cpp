#include "executive/node/executive_node.hpp"

#include <utility>

#include <fmt/format.h>

#include "common/time.hpp"
#include "drivers/velodyne/packet_format.hpp"

namespace ifar::executive {
namespace {

constexpr int kStatusEveryCycles = 5;  // 10 Hz at the 50 Hz control rate
constexpr std::int64_t kPacketWarningIntervalUs = 5'000'000;

}  // namespace

std::set<std::string> inputChannels(const std::string& packet_channel)
{
  return {kPoseChannel,        packet_channel,   kPathChannel, kForceChannel,
          kMotorStatusChannel, kOdometryChannel, kEStopChannel};
}

ExecutiveNode::ExecutiveNode(const ExecutiveSettings& settings, const ObstacleSettings& obstacles,
                             const common::VehicleSettings& vehicle, std::shared_ptr<spdlog::logger> logger)
    : logger_(std::move(logger)),
      executive_(settings, vehicle),
      obstacles_(obstacles, vehicle),
      pushed_object_radius_m_(settings.pushed_object.radius_m),
      packet_warnings_(kPacketWarningIntervalUs)
{
}

void ExecutiveNode::onPose(const ifar::pose_t& message, std::int64_t now_us)
{
  inputs_.pose = Stamped<geometry::Pose2>{fromMessage(message), now_us};
  obstacles_.addPose(now_us, inputs_.pose->value);
}

void ExecutiveNode::onVelodynePacket(const ifar::velodyne_packet_t& message, std::int64_t now_us)
{
  if (message.port == velodyne::kPositionPort) {
    return;  // position packets carry no returns (data packets may come from a configured port)
  }
  const common::ByteView payload(message.data.data(), message.data.size());
  const std::int64_t before = obstacles_.malformedPackets();
  obstacles_.addPacket(payload, now_us);
  if (obstacles_.malformedPackets() != before && packet_warnings_.allow(now_us)) {
    logger_->warn("{}: malformed lidar packet ({} bytes: {}); {} malformed so far, {} warnings held back",
                  message.utime, message.data.size(),
                  velodyne::toString(velodyne::inspectPacket(payload).status), obstacles_.malformedPackets(),
                  packet_warnings_.takeSuppressed());
  }
}

void ExecutiveNode::onPath(const ifar::path_t& message, std::int64_t now_us)
{
  int malformed = 0;
  inputs_.path = Stamped<Path>{fromMessage(message, malformed), now_us};
  if (malformed > 0) {
    ++malformed_paths_;
    logger_->warn("GLOBAL_PATH {}: {} waypoints or controls of unknown kind ({} such paths so far)",
                  message.sequence, malformed, malformed_paths_);
  }
}

void ExecutiveNode::onForce(const ifar::force_t& message, std::int64_t now_us)
{
  inputs_.force = Stamped<ForceReading>{fromMessage(message), now_us};
}

void ExecutiveNode::onMotorStatus(const ifar::motor_status_t& message, std::int64_t now_us)
{
  motors_.update(message, now_us);
  inputs_.motor = motors_.combined();
}

void ExecutiveNode::onOdometry(const ifar::odometry_t& message, std::int64_t now_us)
{
  inputs_.odometry = Stamped<OdometryReading>{fromMessage(message), now_us};
}

void ExecutiveNode::onEStop(const ifar::e_stop_t& message, std::int64_t now_us)
{
  inputs_.e_stop = Stamped<EStopSignal>{fromMessage(message), now_us};
  logger_->warn("E_STOP {} by {}: {}", message.engaged != 0 ? "engaged" : "released", message.source,
                message.reason);
}

void ExecutiveNode::updateObstacleInputs(std::int64_t now_us)
{
  const std::int64_t newest = obstacles_.newestPacketUtime();
  if (newest == 0) {
    return;  // no packet yet: the obstacle input is stale and the executive stays stopped
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

ExecutiveOutputs ExecutiveNode::cycle(std::int64_t now_us)
{
  updateObstacleInputs(now_us);
  ExecutiveOutputs outputs;
  outputs.output = executive_.step(now_us, inputs_);
  const Output& output = outputs.output;
  outputs.command = toVelocityMessage(output, now_us);
  ifar::exec_status_t status = toStatusMessage(output, now_us);
  if (obstacles_.malformedPackets() > 0) {
    status.reason += fmt::format(" [{} malformed lidar packets]", obstacles_.malformedPackets());
  }
  if (output.mode_changed || ++cycles_ % kStatusEveryCycles == 0) {
    outputs.status = status;
  }
  last_status_ = std::move(status);
  last_cycle_status_ = output.status;
  if (output.mode_changed) {
    logger_->info("mode {}: {}", modeName(output.status.mode), output.status.reason);
  }
  if (output.affordance) {
    outputs.affordance = toAffordanceMessage(*output.affordance, now_us);
    logger_->info("affordance: {}", output.affordance->text);
  }
  if (output.escalation) {
    logger_->warn("{}", *output.escalation);
  }
  if (output.blocked_passage) {
    outputs.blocked_passage = toBlockedPassageMessage(*output.blocked_passage, now_us);
    logger_->warn("blocked passage: {}", output.blocked_passage->text);
  }
  return outputs;
}

std::string ExecutiveNode::healthProblem() const
{
  return last_cycle_status_ ? executive::healthProblem(*last_cycle_status_) : "no control cycle yet";
}

ExecutiveOutputs ExecutiveNode::stop(std::int64_t now_us) const
{
  ExecutiveOutputs outputs;
  outputs.command = toVelocityMessage(Output{}, now_us);
  if (last_status_) {
    outputs.status = *last_status_;
    outputs.status->utime = now_us;
  }
  return outputs;
}

}  // namespace ifar::executive
