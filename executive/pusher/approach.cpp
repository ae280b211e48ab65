#include "executive/pusher/approach.hpp"

#include <cmath>

#include <fmt/format.h>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {
namespace {

/// Pose of `pose` in the frame of `frame`: x along frame's heading, y to its left.
geometry::Point relativePosition(const geometry::Pose2& frame, const geometry::Pose2& pose)
{
  const double cosine = std::cos(frame.heading);
  const double sine = std::sin(frame.heading);
  const double dx = pose.x - frame.x;
  const double dy = pose.y - frame.y;
  return {cosine * dx + sine * dy, -sine * dx + cosine * dy};
}

/// True when `pose` stands within `offset_m` of the line of the push lane of `contact`, behind it by at
/// most `behind_m`, heading within `heading_error_rad` of it.
bool inLane(const geometry::Pose2& contact, const geometry::Pose2& pose, const ApproachSettings& settings,
            double offset_m, double behind_m, double heading_error_rad)
{
  const geometry::Point relative = relativePosition(contact, pose);
  return std::abs(relative.y()) <= offset_m && relative.x() <= settings.contact_tolerance_m &&
         relative.x() >= -behind_m && std::abs(wrapToPi(contact.heading - pose.heading)) < heading_error_rad;
}

}  // namespace

const char* approachPhaseName(ApproachPhase phase)
{
  switch (phase) {
    case ApproachPhase::ToStandoff:
      return "to stand-off";
    case ApproachPhase::Align:
      return "align";
    case ApproachPhase::Creep:
      return "creep";
    case ApproachPhase::Done:
      return "done";
  }
  return "unknown";
}

geometry::Point Approach::standoffPoint(const ApproachSettings& settings) const
{
  return {contact_.x - settings.standoff_m * std::cos(contact_.heading),
          contact_.y - settings.standoff_m * std::sin(contact_.heading)};
}

void Approach::begin(const geometry::Pose2& contact, const geometry::Pose2& pose,
                     const ApproachSettings& settings)
{
  contact_ = contact;
  phase_ = inLane(contact, pose, settings, settings.standoff_tolerance_m,
                  settings.standoff_m + settings.standoff_tolerance_m, kPi / 2.0)
               ? ApproachPhase::Align
               : ApproachPhase::ToStandoff;
}

bool Approach::joinLane(const geometry::Pose2& pose, const ApproachSettings& settings)
{
  if (phase_ != ApproachPhase::ToStandoff || !inLane(contact_, pose, settings, settings.lane_join_offset_m,
                                                     settings.lane_join_m, settings.lane_join_heading_rad)) {
    return false;
  }
  phase_ = ApproachPhase::Creep;
  return true;
}

ApproachStep Approach::step(const geometry::Pose2& pose, double force_n,
                            common::Span<const geometry::Point> obstacles, const ApproachSettings& settings,
                            const FollowerSettings& follower, const DifferentialDrive& drive)
{
  ApproachStep result;
  if (phase_ == ApproachPhase::ToStandoff) {
    const geometry::Point standoff = standoffPoint(settings);
    if ((standoff - pose.position()).norm() <= settings.standoff_tolerance_m) {
      phase_ = ApproachPhase::Align;
    } else {
      FollowerSettings toward_standoff = follower;
      toward_standoff.goal_tolerance_m = settings.standoff_tolerance_m;
      const FollowerResult followed = followSqueezing(pose, standoff, settings.stop_at_standoff, obstacles,
                                                      toward_standoff, settings.squeeze_clearance_m, drive);
      if (followed.status == FollowerStatus::Arrived) {
        phase_ = ApproachPhase::Align;
      } else {
        result.command = followed.command;
        result.phase = phase_;
        result.reason = fmt::format("approach: to stand-off point, {}", followed.reason);
        return result;
      }
    }
  }
  if (phase_ == ApproachPhase::Align) {
    const double error = wrapToPi(contact_.heading - pose.heading);
    if (std::abs(error) > settings.heading_tolerance_rad) {
      result.command = turnToHeading(pose, contact_.heading, settings.control);
      result.phase = phase_;
      result.reason = fmt::format("approach: turning to the lane's heading, {:.2f} rad off", error);
      return result;
    }
    phase_ = ApproachPhase::Creep;
  }
  if (phase_ == ApproachPhase::Creep) {
    const geometry::Point relative = relativePosition(contact_, pose);
    const bool at_contact = relative.x() >= -settings.contact_tolerance_m;
    const bool object_felt =
        force_n >= settings.contact_force_n && relative.x() >= -settings.force_contact_reach_m;
    if (at_contact || object_felt) {
      phase_ = ApproachPhase::Done;
    } else {
      // Reference: the point of the push lane beside the vehicle, moving forward at creep speed.
      geometry::Pose2 reference = contact_;
      reference.x += relative.x() * std::cos(contact_.heading);
      reference.y += relative.x() * std::sin(contact_.heading);
      result.command = trackReference(pose, reference, settings.creep_speed, 0.0, settings.control);
      result.phase = phase_;
      result.reason = fmt::format("approach: creeping along the lane, {:.2f} m to go", -relative.x());
      return result;
    }
  }
  result.phase = ApproachPhase::Done;
  result.reason = fmt::format("approach: at contact (force {:.0f} N)", force_n);
  return result;
}

}  // namespace ifar::executive
