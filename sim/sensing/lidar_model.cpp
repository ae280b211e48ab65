#include "sim/sensing/lidar_model.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::sim {
namespace {

constexpr double kReferenceReflectivity = 0.1;  // detection_range_m is for a 10 % surface

}  // namespace

LidarReturnModel::LidarReturnModel(const LidarModelSettings& settings, std::uint64_t seed)
    : settings_(settings), active_(settings.active()), random_(sensingStreamSeed(seed, kLidarStream))
{
}

LidarReturn LidarReturnModel::apply(double slant_m, double reflectivity, double cos_incidence, bool ground)
{
  const double surface = std::clamp(reflectivity, 0.0, 1.0);
  LidarReturn out;
  if (settings_.dropout_rate > 0.0 && uniform_(random_) < settings_.dropout_rate) {
    return out;
  }
  if (settings_.detection_range_m > 0.0) {
    const double power = surface * std::clamp(cos_incidence, 0.0, 1.0) / kReferenceReflectivity;
    if (slant_m > settings_.detection_range_m * std::sqrt(power)) {
      return out;
    }
  }
  out.returned = true;
  out.slant_m = slant_m;
  if (settings_.range_noise_m > 0.0) {
    out.slant_m = std::max(0.0, slant_m + settings_.range_noise_m * unit_(random_));
  }
  double value = std::round(surface * 255.0);
  const bool retro = value >= settings_.retro_threshold;
  if (retro && settings_.missed_tag_rate > 0.0 && uniform_(random_) < settings_.missed_tag_rate) {
    value = settings_.missed_tag_reflectivity;
  } else if (!retro && !ground && settings_.false_tag_rate > 0.0 &&
             uniform_(random_) < settings_.false_tag_rate) {
    value = settings_.false_tag_reflectivity;
  }
  if (settings_.reflectivity_noise > 0.0) {
    value += settings_.reflectivity_noise * unit_(random_);
  }
  out.reflectivity = static_cast<std::uint8_t>(std::clamp(std::round(value), 0.0, 255.0));
  return out;
}

}  // namespace ifar::sim
