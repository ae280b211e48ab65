#pragma once
// The pose a state estimator (lidar odometry with loop closures or GNSS fixes) publishes, made from the
// simulator's truth. The estimate is dead reckoning of the true motion with noise: each step's body-frame
// motion is integrated with a random error whose variance grows with the distance travelled and the
// angle turned, so a heading error bends the position the way it does on a vehicle. At Poisson-spaced
// times a correction pulls the estimate most of the way back to the truth (a jump). What is published
// is the estimate of `latency_s` ago, stamped with that time, plus white jitter.
//
// With every setting 0 the estimate is the truth itself, bit for bit.

#include <cstdint>
#include <deque>
#include <random>

#include "common/geometry/pose2.hpp"
#include "sim/sensing/sensing_settings.hpp"

namespace ifar::sim {

/// A pose with its velocity at a time (world frame; angular velocity counter-clockwise).
struct VehicleMotion {
  std::int64_t time_ns = 0;
  geometry::Pose2 pose;
  geometry::Vector linear_velocity = geometry::Vector::Zero();
  double angular_velocity = 0.0;
};

class PoseEstimateModel {
 public:
  /// `seed` is the simulator's seed: the jitter draws from it directly (the sequence the simulator's
  /// pose noise always had), the drift and the corrections from a stream of their own.
  PoseEstimateModel(const PoseModelSettings& settings, std::uint64_t seed);

  /// The truth at its time: once at the start and after every physics step, in time order.
  void advance(const VehicleMotion& truth);

  /// The estimate as published now (before jitter): the newest one at least latency_s old, with the
  /// time it is valid at.
  VehicleMotion published() const;
  /// Adds the white jitter to a published pose (one draw per call).
  void addJitter(geometry::Pose2& pose);

  /// The estimate now minus the truth now: x, y and the wrapped heading difference.
  geometry::Pose2 drift() const;
  std::int64_t corrections() const { return corrections_; }
  const PoseModelSettings& settings() const { return settings_; }

 private:
  void integrate(const VehicleMotion& truth);
  void correct(const VehicleMotion& truth);
  void scheduleCorrection(std::int64_t after_ns);

  PoseModelSettings settings_;
  std::int64_t latency_ns_ = 0;
  std::mt19937_64 jitter_random_;
  std::mt19937_64 drift_random_;
  bool started_ = false;
  VehicleMotion truth_;                // the latest truth
  geometry::Pose2 estimate_;           // the latest estimate (drifted)
  std::deque<VehicleMotion> history_;  // estimates, oldest first, back to the latency
  std::int64_t next_correction_ns_ = -1;
  std::int64_t corrections_ = 0;
};

}  // namespace ifar::sim
