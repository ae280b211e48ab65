#include "sim/sensing/force_model.hpp"

#include <cmath>

namespace ifar::sim {

ForceSensorModel::ForceSensorModel(const ForceModelSettings& settings, std::uint64_t seed)
    : settings_(settings),
      active_(settings.noise_n > 0.0 || settings.bias_sigma_n > 0.0 || settings.stuck_interval_s > 0.0 ||
              settings.drop_rate > 0.0),
      random_(sensingStreamSeed(seed, kForceStream))
{
}

ForceModelReading ForceSensorModel::next(std::int64_t now_us, double true_force_n)
{
  ForceModelReading reading;
  reading.force_n = true_force_n;
  if (!active_) {
    return reading;
  }
  const double elapsed_s = started_ ? static_cast<double>(now_us - last_us_) * 1e-6 : 0.0;
  started_ = true;
  last_us_ = now_us;
  if (settings_.bias_sigma_n > 0.0 && settings_.bias_time_s > 0.0 && elapsed_s > 0.0) {
    const double decay = std::exp(-elapsed_s / settings_.bias_time_s);
    bias_n_ = decay * bias_n_ + settings_.bias_sigma_n * std::sqrt(1.0 - decay * decay) * unit_(random_);
  }
  if (now_us < stuck_until_us_) {
    reading.stuck = true;
    reading.force_n = held_n_;
    return reading;
  }
  // The frame after an episode is a healthy one: the firmware is back before it can hang again.
  const bool recovering = stuck_until_us_ >= 0;
  stuck_until_us_ = -1;
  double value = true_force_n + bias_n_;
  if (settings_.noise_n > 0.0) {
    value += settings_.noise_n * unit_(random_);
  }
  reading.force_n = value;
  if (!recovering && settings_.stuck_interval_s > 0.0 && elapsed_s > 0.0 &&
      uniform_(random_) < 1.0 - std::exp(-elapsed_s / settings_.stuck_interval_s)) {
    stuck_until_us_ = now_us + std::llround(settings_.stuck_duration_s * 1e6);
    held_n_ = value;
    reading.stuck = true;
    return reading;
  }
  if (settings_.drop_rate > 0.0 && uniform_(random_) < settings_.drop_rate) {
    reading.send = false;
  }
  return reading;
}

}  // namespace ifar::sim
