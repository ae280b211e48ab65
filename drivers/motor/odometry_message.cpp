#include "drivers/motor/odometry_message.hpp"

#include "common/vehicle_model.hpp"

namespace ifar::motor {
namespace {

/// How old the drive's last TPDO1 is at `utime`; -1 before the first.
std::int64_t feedbackAge(const MotorStatus& status, std::int64_t utime)
{
  return status.feedback_us ? utime - *status.feedback_us : -1;
}

bool stale(std::int64_t age_us, std::int64_t timeout_us)
{
  return age_us < 0 || age_us > timeout_us;
}

}  // namespace

ifar::odometry_t toOdometryMessage(const MotorStatus& left, const MotorStatus& right, std::int64_t utime,
                                   const OdometryGeometry& geometry)
{
  ifar::odometry_t message{};
  message.utime = utime;
  message.left_node_id = static_cast<std::int8_t>(left.node_id);
  message.right_node_id = static_cast<std::int8_t>(right.node_id);
  message.left_wheel_rad_s = static_cast<double>(left.actual_velocity) / kDriveUnitsPerRadianPerSecond;
  message.right_wheel_rad_s = static_cast<double>(right.actual_velocity) / kDriveUnitsPerRadianPerSecond;
  const common::BodyVelocity body = common::bodyVelocity(message.left_wheel_rad_s, message.right_wheel_rad_s,
                                                         geometry.wheel_radius_m, geometry.wheel_track_m);
  message.linear_velocity = body.linear;
  message.angular_velocity = body.angular;
  message.left_age_us = feedbackAge(left, utime);
  message.right_age_us = feedbackAge(right, utime);
  message.status =
      (stale(message.left_age_us, geometry.feedback_timeout_us) ? ifar::odometry_t::STATUS_LEFT_STALE : 0) |
      (stale(message.right_age_us, geometry.feedback_timeout_us) ? ifar::odometry_t::STATUS_RIGHT_STALE : 0);
  return message;
}

}  // namespace ifar::motor
