#include "executive/modes/standstill_watch.hpp"

#include <cmath>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

StandstillWatch::StandstillWatch(double still_distance_m, double still_turn_rad, double timeout_s)
    : still_distance_m_(still_distance_m), still_turn_rad_(still_turn_rad), timeout_s_(timeout_s)
{
}

void StandstillWatch::anchor(const geometry::Pose2& pose, std::int64_t now_us)
{
  anchor_ = pose;
  anchor_us_ = now_us;
}

bool StandstillWatch::standingStill(const geometry::Pose2& pose, std::int64_t now_us)
{
  if ((pose.position() - anchor_.position()).norm() > still_distance_m_ ||
      std::abs(wrapToPi(pose.heading - anchor_.heading)) > still_turn_rad_) {
    anchor(pose, now_us);
  }
  return static_cast<double>(now_us - anchor_us_) * 1e-6 > timeout_s_;
}

}  // namespace ifar::executive
