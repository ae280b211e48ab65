#include "executive/modes/standstill_watch.hpp"

#include <algorithm>
#include <cmath>

#include "executive/kinematics/angle.hpp"

namespace ifar::executive {

StandstillWatch::StandstillWatch(double still_distance_m, double still_turn_rad, double timeout_s)
    : still_distance_m_(still_distance_m), still_turn_rad_(still_turn_rad), timeout_s_(timeout_s)
{
}

void StandstillWatch::anchor(const CycleView& view)
{
  anchor_ = view.pose;
  anchor_wheels_ = view.wheels;
  anchor_us_ = view.now_us;
}

bool StandstillWatch::standingStill(const CycleView& view)
{
  double distance = (view.pose.position() - anchor_.position()).norm();
  double turn = std::abs(wrapToPi(view.pose.heading - anchor_.heading));
  if (anchor_wheels_ && view.wheels) {
    if (const std::optional<WheelMotion> wheels = wheelMotion(*anchor_wheels_, *view.wheels)) {
      distance = std::min(distance, wheels->distance_m);
      turn = std::min(turn, wheels->turn_rad);
    }
  }
  if (distance > still_distance_m_ || turn > still_turn_rad_) {
    anchor(view);
  }
  return static_cast<double>(view.now_us - anchor_us_) * 1e-6 > timeout_s_;
}

}  // namespace ifar::executive
