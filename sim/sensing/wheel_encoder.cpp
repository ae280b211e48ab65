#include "sim/sensing/wheel_encoder.hpp"

#include <algorithm>
#include <cmath>

#include "common/geometry/angle.hpp"

namespace ifar::sim {

WheelEncoder::WheelEncoder(const WheelModelSettings& settings, double wheel_radius_m)
    : settings_(settings),
      radius_m_(wheel_radius_m),
      window_us_(std::max<std::int64_t>(1, std::llround(settings.velocity_window_s * 1e6)))
{
}

double WheelEncoder::measure(std::int64_t now_us, double rim_speed)
{
  if (settings_.encoder_counts_per_rev <= 0 || !(radius_m_ > 0.0)) {
    return rim_speed;
  }
  const double counts_per_radian = settings_.encoder_counts_per_rev / (2.0 * geometry::kPi);
  if (!started_) {
    started_ = true;
    last_us_ = now_us;
    window_start_us_ = now_us;
    window_start_edges_ = std::floor(position_counts_);
    return measured_;
  }
  const double elapsed_s = static_cast<double>(now_us - last_us_) * 1e-6;
  last_us_ = now_us;
  position_counts_ += rim_speed / radius_m_ * elapsed_s * counts_per_radian;
  if (now_us - window_start_us_ >= window_us_) {
    const double edges = std::floor(position_counts_);
    const double window_s = static_cast<double>(now_us - window_start_us_) * 1e-6;
    measured_ = (edges - window_start_edges_) / counts_per_radian / window_s * radius_m_;
    window_start_us_ = now_us;
    window_start_edges_ = edges;
  }
  return measured_;
}

}  // namespace ifar::sim
