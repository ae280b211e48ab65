#include "executive/daemon/executive_daemon.hpp"

#include <utility>

namespace ifar::executive {

ExecutiveDaemon::ExecutiveDaemon(bus::RunLoop& loop, const ExecutiveSettings& settings,
                                 const ObstacleSettings& obstacles, const common::VehicleSettings& vehicle,
                                 std::shared_ptr<spdlog::logger> logger)
    : loop_(loop),
      node_(settings, obstacles, vehicle, std::move(logger)),
      journal_(loop, kJournalChannel, "executive", loop.now(), inputChannels(obstacles.packet_channel))
{
  loop_.subscribe<ifar::pose_t>(kPoseChannel,
                                [this](const ifar::pose_t& message, std::int64_t receive_utime) {
                                  node_.onPose(message, receive_utime);
                                });
  loop_.subscribe<ifar::velodyne_packet_t>(
      obstacles.packet_channel, [this](const ifar::velodyne_packet_t& message, std::int64_t receive_utime) {
        node_.onVelodynePacket(message, receive_utime);
      });
  loop_.subscribe<ifar::path_t>(kPathChannel,
                                [this](const ifar::path_t& message, std::int64_t receive_utime) {
                                  node_.onPath(message, receive_utime);
                                });
  loop_.subscribe<ifar::force_t>(kForceChannel,
                                 [this](const ifar::force_t& message, std::int64_t receive_utime) {
                                   node_.onForce(message, receive_utime);
                                 });
  loop_.subscribe<ifar::motor_status_t>(
      kMotorStatusChannel, [this](const ifar::motor_status_t& message, std::int64_t receive_utime) {
        node_.onMotorStatus(message, receive_utime);
      });
  loop_.subscribe<ifar::odometry_t>(kOdometryChannel,
                                    [this](const ifar::odometry_t& message, std::int64_t receive_utime) {
                                      node_.onOdometry(message, receive_utime);
                                    });
  loop_.subscribe<ifar::e_stop_t>(kEStopChannel,
                                  [this](const ifar::e_stop_t& message, std::int64_t receive_utime) {
                                    node_.onEStop(message, receive_utime);
                                  });
  loop_.every(kControlPeriodS, [this] {
    const std::int64_t now = loop_.now();
    journal_.recorder().timer(kControlCycleTimer, now);
    publish(node_.cycle(now));
  });
}

void ExecutiveDaemon::publish(const ExecutiveOutputs& outputs)
{
  loop_.publish(kCommandChannel, outputs.command);
  if (outputs.status) {
    loop_.publish(kStatusChannel, *outputs.status);
  }
  if (outputs.affordance) {
    loop_.publish(kAffordanceChannel, *outputs.affordance);
  }
  if (outputs.blocked_passage) {
    loop_.publish(kBlockedPassageChannel, *outputs.blocked_passage);
  }
}

void ExecutiveDaemon::publishStop()
{
  const std::int64_t now = loop_.now();
  journal_.recorder().stop(now);
  publish(node_.stop(now));
}

}  // namespace ifar::executive
