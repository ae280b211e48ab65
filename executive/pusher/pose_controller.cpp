#include "executive/pusher/pose_controller.hpp"

#include <algorithm>
#include <cmath>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

VelocityCommand driveToPoint(const geometry::Pose2& pose, const geometry::Point& target,
                             const PoseControllerSettings& settings)
{
  const geometry::Point offset = target - pose.position();
  const double distance = offset.norm();
  const double heading_error = wrapToPi(std::atan2(offset.y(), offset.x()) - pose.heading);
  const double angular = std::clamp(settings.angular_gain * heading_error, -settings.max_angular_velocity,
                                    settings.max_angular_velocity);
  if (std::abs(heading_error) > settings.turn_in_place_error) {
    return {0.0, angular};
  }
  // Slow down while the heading is still off so the path does not swing wide.
  const double linear =
      std::min(settings.linear_gain * distance, settings.max_linear_velocity) * std::cos(heading_error);
  return {std::max(linear, 0.0), angular};
}

VelocityCommand turnToHeading(const geometry::Pose2& pose, double heading,
                              const PoseControllerSettings& settings)
{
  const double error = wrapToPi(heading - pose.heading);
  return {0.0, std::clamp(settings.angular_gain * error, -settings.max_angular_velocity,
                          settings.max_angular_velocity)};
}

VelocityCommand trackReference(const geometry::Pose2& pose, const geometry::Pose2& reference,
                               double reference_linear, double reference_angular,
                               const PoseControllerSettings& settings)
{
  const double cosine = std::cos(pose.heading);
  const double sine = std::sin(pose.heading);
  const double dx = reference.x - pose.x;
  const double dy = reference.y - pose.y;
  const double along_error = cosine * dx + sine * dy;
  const double cross_error = -sine * dx + cosine * dy;
  const double heading_error = wrapToPi(reference.heading - pose.heading);
  const double speed = std::abs(reference_linear);
  // Reversing flips which side a cross-track error must be corrected toward.
  const double direction = reference_linear < 0.0 ? -1.0 : 1.0;
  return {reference_linear * std::cos(heading_error) + settings.track_along_gain * along_error,
          reference_angular + direction * speed * settings.track_cross_gain * cross_error +
              speed * settings.track_heading_gain * std::sin(heading_error)};
}

}  // namespace ifar::executive
