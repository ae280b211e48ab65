#pragma once
// Small feedback laws on poses: go to a point, turn to a heading, and track a moving reference pose.

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "executive/kinematics/velocity_command.hpp"

namespace ifar::executive {

struct PoseControllerSettings {
  double linear_gain = 1.0;           ///< 1/s, speed per metre of distance
  double angular_gain = 2.0;          ///< 1/s, turn rate per radian of heading error
  double turn_in_place_error = 0.6;   ///< rad: above this heading error, turn before driving
  double max_linear_velocity = 0.4;   ///< m/s
  double max_angular_velocity = 0.8;  ///< rad/s
  // Tracking law gains (Kanayama et al. 1990): along-track, cross-track and heading.
  double track_along_gain = 1.0;    ///< 1/s
  double track_cross_gain = 8.0;    ///< 1/m^2 (scaled by the reference speed)
  double track_heading_gain = 5.0;  ///< 1/m (scaled by the reference speed)
};

/// Forward-driving go-to-point: turns toward the point first when it is far off the heading.
VelocityCommand driveToPoint(const geometry::Pose2& pose, const geometry::Point& target,
                             const PoseControllerSettings& settings);

/// Turns on the spot toward `heading`.
VelocityCommand turnToHeading(const geometry::Pose2& pose, double heading,
                              const PoseControllerSettings& settings);

/// Tracks a reference pose moving with (reference_linear, reference_angular): the reference velocity plus
/// corrections for the along-track, cross-track and heading errors expressed in the vehicle frame.
VelocityCommand trackReference(const geometry::Pose2& pose, const geometry::Pose2& reference,
                               double reference_linear, double reference_angular,
                               const PoseControllerSettings& settings);

}  // namespace ifar::executive
