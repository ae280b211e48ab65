#include "executive/pusher/push_tracker.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "executive/follower/arc.hpp"
#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

const char* pushPhaseName(PushPhase phase)
{
  switch (phase) {
    case PushPhase::Pushing:
      return "pushing";
    case PushPhase::BackingOff:
      return "backing off";
    case PushPhase::Switching:
      return "switching contact";
    case PushPhase::Releasing:
      return "releasing";
    case PushPhase::Finished:
      return "finished";
  }
  return "unknown";
}

double projectOntoArc(const geometry::Pose2& start, double linear, double angular, double near_s,
                      const geometry::Pose2& pose)
{
  constexpr double kSmall = 1e-6;
  if (std::abs(angular) < kSmall) {
    if (std::abs(linear) < kSmall) {
      return near_s;
    }
    const double along =
        std::cos(start.heading) * (pose.x - start.x) + std::sin(start.heading) * (pose.y - start.y);
    return along / linear;
  }
  const geometry::Pose2 near = integrateArc(start, linear, angular, near_s);
  if (std::abs(linear) < kSmall) {
    // Turning on the spot: progress is heading.
    return near_s + wrapToPi(pose.heading - near.heading) / angular;
  }
  // Around the arc's centre the position angle advances by angular * t whatever the sign of the radius.
  const double radius = linear / angular;
  const geometry::Point centre(start.x - radius * std::sin(start.heading),
                               start.y + radius * std::cos(start.heading));
  const double near_angle = std::atan2(near.y - centre.y(), near.x - centre.x());
  const double pose_angle = std::atan2(pose.y - centre.y(), pose.x - centre.x());
  return near_s + wrapToPi(pose_angle - near_angle) / angular;
}

geometry::Pose2 PushTracker::stepStart(std::size_t index) const
{
  return index == 0 ? plan_.contact_pose : plan_.controls[index - 1].expected_vehicle_pose;
}

void PushTracker::begin(const PushPlan& plan)
{
  plan_ = plan;
  index_ = 0;
  progress_s_ = 0.0;
  phase_ = plan_.controls.empty() ? PushPhase::Releasing : PushPhase::Pushing;
  reverse_start_ = plan_.contact_pose.position();
  if (!plan_.controls.empty() && plan_.controls.front().kind == PushControlKind::SwitchContact) {
    phase_ = PushPhase::BackingOff;
  }
}

void PushTracker::startControl(std::size_t index, const geometry::Pose2& pose)
{
  index_ = index;
  progress_s_ = 0.0;
  reverse_start_ = pose.position();
  if (index_ >= plan_.controls.size()) {
    phase_ = PushPhase::Releasing;
  } else if (plan_.controls[index_].kind == PushControlKind::SwitchContact) {
    phase_ = PushPhase::BackingOff;
  } else {
    phase_ = PushPhase::Pushing;
  }
}

PushStep PushTracker::step(const geometry::Pose2& pose, double force_n,
                           common::Span<const geometry::Point> obstacles, const PushTrackerSettings& settings,
                           const ApproachSettings& approach, const FollowerSettings& follower,
                           const DifferentialDrive& drive)
{
  PushStep result;
  // Each pass either produces a command and returns or moves to the next phase; a plan has finitely
  // many controls, so the loop ends.
  for (;;) {
    result.phase = phase_;
    result.control_index = index_;
    switch (phase_) {
      case PushPhase::Pushing: {
        const PushControl& control = plan_.controls[index_];
        const geometry::Pose2 start = stepStart(index_);
        const double projected =
            projectOntoArc(start, control.linear_velocity, control.angular_velocity, progress_s_, pose);
        progress_s_ = std::clamp(std::max(progress_s_, projected), 0.0, control.duration_s);
        if (progress_s_ >= control.duration_s - settings.end_tolerance_s) {
          startControl(index_ + 1, pose);
          continue;
        }
        const geometry::Pose2 reference =
            integrateArc(start, control.linear_velocity, control.angular_velocity, progress_s_);
        result.command = trackReference(pose, reference, control.linear_velocity, control.angular_velocity,
                                        settings.control);
        result.expects_contact = true;
        result.reason =
            fmt::format("push: primitive {} of {}, {:.1f} of {:.1f} s (force {:.0f} N)", index_ + 1,
                        plan_.controls.size(), progress_s_, control.duration_s, force_n);
        return result;
      }
      case PushPhase::BackingOff:
      case PushPhase::Releasing: {
        const double wanted = phase_ == PushPhase::BackingOff ? settings.backoff_m : settings.release_m;
        const double travelled = (pose.position() - reverse_start_).norm();
        if (travelled >= wanted) {
          if (phase_ == PushPhase::Releasing) {
            phase_ = PushPhase::Finished;
          } else {
            phase_ = PushPhase::Switching;
            approach_.begin(plan_.controls[index_].expected_vehicle_pose, pose, approach);
          }
          continue;
        }
        result.command = {-settings.reverse_speed, 0.0};
        result.reason = fmt::format("push: {} from the object, {:.2f} of {:.2f} m", pushPhaseName(phase_),
                                    travelled, wanted);
        return result;
      }
      case PushPhase::Switching: {
        const ApproachStep approached = approach_.step(pose, force_n, obstacles, approach, follower, drive);
        if (approached.phase == ApproachPhase::Done) {
          startControl(index_ + 1, pose);
          continue;
        }
        result.command = approached.command;
        result.reason = fmt::format("push: switching to contact edge {}, {}",
                                    plan_.controls[index_].contact_edge, approached.reason);
        return result;
      }
      case PushPhase::Finished:
        result.reason = "push: plan finished";
        return result;
    }
  }
}

}  // namespace ifar::executive
