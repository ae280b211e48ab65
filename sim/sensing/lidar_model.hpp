#pragma once
// What becomes of one VLP-16 laser return between the surface and the packet: a return can be lost at
// random or because the surface is too dark or too oblique for its distance (the received power falls
// with reflectivity x cos(incidence) / range^2), its range gets Gaussian noise, and its calibrated
// reflectivity gets noise, with now and then a diffuse surface read as a retro-reflector (a glint) or a
// retro-reflective tag read as the diffuse board behind it. The scanner applies it per laser.

#include <cstdint>
#include <random>

#include "sim/sensing/sensing_settings.hpp"

namespace ifar::sim {

struct LidarReturn {
  bool returned = false;
  double slant_m = 0.0;
  std::uint8_t reflectivity = 0;  // calibrated, 0..255
};

class LidarReturnModel {
 public:
  /// `seed` is the simulator's seed; the model draws from a stream of its own.
  LidarReturnModel(const LidarModelSettings& settings, std::uint64_t seed);

  bool active() const { return active_; }
  /// A return from a surface of `reflectivity` (0..1) at `slant_m`, met at an angle whose cosine is
  /// `cos_incidence`; `ground` says it is the ground (never read as a tag). Does not apply the sensor's
  /// minimum and maximum range.
  LidarReturn apply(double slant_m, double reflectivity, double cos_incidence, bool ground);

  const LidarModelSettings& settings() const { return settings_; }

 private:
  LidarModelSettings settings_;
  bool active_ = false;
  std::mt19937_64 random_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::normal_distribution<double> unit_{0.0, 1.0};
};

}  // namespace ifar::sim
