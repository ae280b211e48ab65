#pragma once
// A drive's velocity as it measures it: the edges its encoder counted over the last window, times the
// angle per edge, over the window's length. The reading steps by 2 pi / (counts x window) rad/s and
// averages to the true speed. With counts_per_rev 0 it is the wheel speed itself.

#include <cstdint>

#include "sim/sensing/sensing_settings.hpp"

namespace ifar::sim {

class WheelEncoder {
 public:
  WheelEncoder(const WheelModelSettings& settings, double wheel_radius_m);

  /// The wheel turned at `rim_speed` (m/s) since the previous call; returns the drive's measured rim
  /// speed (m/s) at `now_us`, held between windows.
  double measure(std::int64_t now_us, double rim_speed);

 private:
  WheelModelSettings settings_;
  double radius_m_;
  std::int64_t window_us_ = 0;
  bool started_ = false;
  std::int64_t last_us_ = 0;
  double position_counts_ = 0.0;  // encoder position in edges (fractional: where the wheel really is)
  std::int64_t window_start_us_ = 0;
  double window_start_edges_ = 0.0;
  double measured_ = 0.0;
};

}  // namespace ifar::sim
