#include "sim/sensing/pose_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/geometry/angle.hpp"

namespace ifar::sim {
namespace {

geometry::Vector rotated(const geometry::Vector& vector, double angle)
{
  const double cosine = std::cos(angle);
  const double sine = std::sin(angle);
  return {cosine * vector.x() - sine * vector.y(), sine * vector.x() + cosine * vector.y()};
}

}  // namespace

PoseEstimateModel::PoseEstimateModel(const PoseModelSettings& settings, std::uint64_t seed)
    : settings_(settings),
      latency_ns_(std::llround(std::max(settings.latency_s, 0.0) * 1e9)),
      jitter_random_(seed),
      drift_random_(sensingStreamSeed(seed, kPoseDriftStream))
{
}

void PoseEstimateModel::advance(const VehicleMotion& truth)
{
  if (!started_) {
    started_ = true;
    estimate_ = truth.pose;
    if (settings_.drifts() && settings_.correction_interval_s > 0.0) {
      scheduleCorrection(truth.time_ns);
    }
  } else if (settings_.drifts()) {
    integrate(truth);
    if (next_correction_ns_ >= 0 && truth.time_ns >= next_correction_ns_) {
      correct(truth);
      scheduleCorrection(truth.time_ns);
    }
  } else {
    estimate_ = truth.pose;
  }
  truth_ = truth;
  VehicleMotion estimate = truth;
  if (settings_.drifts()) {
    // The estimator's velocity is the true one seen through its heading error.
    const double heading_error = std::remainder(estimate_.heading - truth.pose.heading, 2.0 * geometry::kPi);
    estimate.pose = estimate_;
    estimate.linear_velocity = rotated(truth.linear_velocity, heading_error);
  }
  history_.push_back(estimate);
  // Keep one estimate at or before now - latency, and everything after it.
  while (history_.size() > 1 && history_[1].time_ns <= truth.time_ns - latency_ns_) {
    history_.pop_front();
  }
}

void PoseEstimateModel::integrate(const VehicleMotion& truth)
{
  const geometry::Pose2 step = truth_.pose.inverse().compose(truth.pose);
  const double distance = std::hypot(step.x, step.y);
  const double turn = std::abs(std::remainder(step.heading, 2.0 * geometry::kPi));
  if (distance <= 0.0 && turn <= 0.0) {
    return;  // standing still: nothing to integrate, nothing to drift
  }
  std::normal_distribution<double> unit(0.0, 1.0);
  const double position_sigma = settings_.drift_position_m_per_sqrt_m * std::sqrt(distance);
  const double heading_sigma =
      std::sqrt(settings_.drift_heading_rad_per_sqrt_m * settings_.drift_heading_rad_per_sqrt_m * distance +
                settings_.drift_heading_rad_per_sqrt_rad * settings_.drift_heading_rad_per_sqrt_rad * turn);
  geometry::Pose2 noisy = step;
  noisy.x += position_sigma * unit(drift_random_);
  noisy.y += position_sigma * unit(drift_random_);
  noisy.heading += heading_sigma * unit(drift_random_);
  estimate_ = estimate_.compose(noisy);
}

void PoseEstimateModel::correct(const VehicleMotion& truth)
{
  const double keep = 1.0 - std::clamp(settings_.correction_fraction, 0.0, 1.0);
  const double heading_error = std::remainder(estimate_.heading - truth.pose.heading, 2.0 * geometry::kPi);
  estimate_.x = truth.pose.x + keep * (estimate_.x - truth.pose.x);
  estimate_.y = truth.pose.y + keep * (estimate_.y - truth.pose.y);
  estimate_.heading = geometry::wrapAngle(truth.pose.heading + keep * heading_error);
  ++corrections_;
}

void PoseEstimateModel::scheduleCorrection(std::int64_t after_ns)
{
  std::exponential_distribution<double> interval(1.0 / settings_.correction_interval_s);
  next_correction_ns_ = after_ns + std::max<std::int64_t>(1, std::llround(interval(drift_random_) * 1e9));
}

VehicleMotion PoseEstimateModel::published() const
{
  if (history_.empty()) {
    return truth_;
  }
  return history_.front();
}

void PoseEstimateModel::addJitter(geometry::Pose2& pose)
{
  // A fresh distribution per draw and this order (x, y, then heading) is the sequence the simulator's
  // pose noise has always drawn, so old configurations give the same poses.
  if (settings_.jitter_position_m > 0.0) {
    std::normal_distribution<double> position_noise(0.0, settings_.jitter_position_m);
    pose.x += position_noise(jitter_random_);
    pose.y += position_noise(jitter_random_);
  }
  if (settings_.jitter_heading_rad > 0.0) {
    std::normal_distribution<double> heading_noise(0.0, settings_.jitter_heading_rad);
    pose.heading = geometry::wrapAngle(pose.heading + heading_noise(jitter_random_));
  }
}

geometry::Pose2 PoseEstimateModel::drift() const
{
  return {estimate_.x - truth_.pose.x, estimate_.y - truth_.pose.y,
          std::remainder(estimate_.heading - truth_.pose.heading, 2.0 * geometry::kPi)};
}

}  // namespace ifar::sim
