#pragma once
// The bumper force sensor as a field unit behaves: white noise on each reading, a zero that wanders
// (first-order Gauss-Markov, as a load cell's offset follows temperature), hung-firmware episodes in
// which the CAN controller repeats the last frame (value and rolling counter stuck, which the force
// driver flags), and frames lost on the bus (a gap in the counter, which the driver counts).

#include <cstdint>
#include <random>

#include "sim/sensing/sensing_settings.hpp"

namespace ifar::sim {

struct ForceModelReading {
  bool send = true;    // false: this frame is lost
  bool stuck = false;  // the frame repeats the episode's first frame (counter frozen)
  double force_n = 0.0;
};

class ForceSensorModel {
 public:
  /// `seed` is the simulator's seed; the model draws from a stream of its own.
  ForceSensorModel(const ForceModelSettings& settings, std::uint64_t seed);

  /// The frame due at `now_us` (one call per frame slot) for the true contact force.
  ForceModelReading next(std::int64_t now_us, double true_force_n);

  double bias() const { return bias_n_; }
  bool active() const { return active_; }

 private:
  ForceModelSettings settings_;
  bool active_ = false;
  std::mt19937_64 random_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::normal_distribution<double> unit_{0.0, 1.0};
  bool started_ = false;
  std::int64_t last_us_ = 0;
  double bias_n_ = 0.0;  // zeroed (tared) at start-up
  std::int64_t stuck_until_us_ = -1;
  double held_n_ = 0.0;
};

}  // namespace ifar::sim
