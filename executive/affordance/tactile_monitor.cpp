#include "executive/affordance/tactile_monitor.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace ifar::executive {

const char* affordanceReasonName(AffordanceReason reason)
{
  switch (reason) {
    case AffordanceReason::NoMotion:
      return "no motion under maximum push";
    case AffordanceReason::CostHigher:
      return "cost higher than planned";
    case AffordanceReason::CostLower:
      return "cost lower than planned";
    case AffordanceReason::Jammed:
      return "jammed after sliding";
    case AffordanceReason::ContactNotReached:
      return "contact not reached";
  }
  return "unknown";
}

void TactileMonitor::begin(const PushPlan& plan, double max_push_force_n, bool jammed_before)
{
  *this = TactileMonitor();
  plan_ = plan;
  max_push_force_ = max_push_force_n;
  jammed_before_ = jammed_before;
}

double TactileMonitor::extrapolatedCost() const
{
  const double planned_push_cost = plan_.expected_cost - plan_.travel_m;
  if (plan_.expected_force_n > 0.0 && planned_push_cost > 0.0) {
    return plan_.travel_m + planned_push_cost * meanForce() / plan_.expected_force_n;
  }
  // A plan without a usable force model: price the push at the vehicle's maximum force per metre.
  return plan_.travel_m + plan_.push_distance_m * meanForce() / std::max(max_push_force_, 1.0);
}

AffordanceEvent TactileMonitor::makeEvent(AffordanceReason reason, double force_n, double measured_cost) const
{
  AffordanceEvent event;
  event.object_id = plan_.object_id;
  event.reason = reason;
  event.pushable = reason != AffordanceReason::NoMotion;
  event.push_force_n = force_n;
  // mu scales with the force it takes: mu_new = mu_planned * F_measured / F_planned.
  event.affordance =
      plan_.expected_force_n > 0.0 ? plan_.affordance * force_n / plan_.expected_force_n : plan_.affordance;
  event.planned_cost = plan_.expected_cost;
  event.measured_cost = measured_cost;
  return event;
}

double TactileMonitor::work() const
{
  return wheelsCount() ? work_by_wheels_ : work_by_pose_;
}

double TactileMonitor::measuredDistance() const
{
  return std::max(0.0, std::min(pushed_by_pose_, pushed_by_wheels_));
}

double TactileMonitor::meanForce() const
{
  const double distance = measuredDistance();
  return distance > 0.0 ? work() / distance : 0.0;
}

TravelSteps TactileMonitor::stepsTo(std::int64_t now_us, const geometry::Pose2& vehicle,
                                    std::optional<double> wheel_travel_m, const TactileSettings& settings)
{
  TravelSteps steps;
  if (!has_last_pose_) {
    smoothed_ = vehicle.position();
    smoothed_samples_ = 1;
  } else {
    // Exponential smoothing over pose_smoothing_s of elapsed time; a running mean until the filter
    // holds that many samples, so its start is not one sample's jitter.
    const double dt = std::max(0.0, static_cast<double>(now_us - last_us_) * 1e-6);
    const double alpha =
        settings.pose_smoothing_s > 0.0 ? 1.0 - std::exp(-dt / settings.pose_smoothing_s) : 1.0;
    ++smoothed_samples_;
    const double weight = std::max(alpha, 1.0 / smoothed_samples_);
    const geometry::Point previous = smoothed_;
    smoothed_ += weight * (vehicle.position() - smoothed_);
    // Forward along the heading the vehicle had (backing off is negative).
    const geometry::Point forward(std::cos(last_pose_.heading), std::sin(last_pose_.heading));
    steps.pose = forward.dot(vehicle.position() - last_pose_.position());
    steps.smoothed = forward.dot(smoothed_ - previous);
  }
  const bool wheels_known = wheel_travel_m && last_wheel_travel_;
  steps.wheels = wheels_known ? *wheel_travel_m - *last_wheel_travel_ : steps.pose;
  steps.wheels_smoothed = wheels_known ? steps.wheels : steps.smoothed;
  last_pose_ = vehicle;
  last_us_ = now_us;
  last_wheel_travel_ = wheel_travel_m;
  has_last_pose_ = true;
  return steps;
}

std::optional<AffordanceEvent> TactileMonitor::update(std::int64_t now_us, double force_n,
                                                      const geometry::Pose2& vehicle,
                                                      std::optional<double> wheel_travel_m,
                                                      const std::optional<geometry::Point>& object_position,
                                                      bool in_contact_expected,
                                                      const TactileSettings& settings)
{
  if (!std::isfinite(force_n) || !std::isfinite(vehicle.x) || !std::isfinite(vehicle.y)) {
    return std::nullopt;
  }
  if (wheel_travel_m && !std::isfinite(*wheel_travel_m)) {
    wheel_travel_m.reset();
  }
  const TravelSteps steps = stepsTo(now_us, vehicle, wheel_travel_m, settings);

  const bool loaded = in_contact_expected && force_n >= settings.contact_force_n;
  if (loaded) {
    pushed_by_pose_ += steps.pose;
    work_by_pose_ += force_n * steps.pose;
    pushed_by_wheels_ += steps.wheels;
    work_by_wheels_ += force_n * steps.wheels;
  }

  // Principle 1: no object motion after maximum push effort for the configured time.
  const bool at_maximum = in_contact_expected && force_n >= settings.max_force_fraction * max_push_force_;
  if (!at_maximum) {
    saturated_ = false;
  } else if (std::optional<AffordanceEvent> event =
                 watchSaturated(now_us, force_n, steps, object_position, settings)) {
    return event;
  }
  // Principle 2: the measured cost differs from the planned J by more than the threshold.
  return checkCost(settings);
}

std::optional<AffordanceEvent> TactileMonitor::watchSaturated(
    std::int64_t now_us, double force_n, const TravelSteps& steps,
    const std::optional<geometry::Point>& object_position, const TactileSettings& settings)
{
  if (!saturated_) {
    saturated_ = true;
    saturated_since_us_ = now_us;
    saturated_pose_travel_ = 0.0;
    saturated_wheel_travel_ = 0.0;
    saturated_object_start_ = object_position.value_or(geometry::Point::Zero());
  } else {
    saturated_pose_travel_ += steps.smoothed;
    saturated_wheel_travel_ += steps.wheels_smoothed;
  }
  // The vehicle advanced only as far as pose and wheels agree. In contact the object moves no farther
  // than the vehicle follows it. The observed centroid alone is not enough: while the bumper hides the
  // near face it wanders by up to ~8 cm, which restarted the window for a minute against a box that
  // never moved.
  const double travel = std::min(saturated_pose_travel_, saturated_wheel_travel_);
  const double moved =
      object_position ? std::min((*object_position - saturated_object_start_).norm(), travel) : travel;
  if (moved > settings.motion_threshold_m) {
    // It moves: start a new window here.
    saturated_since_us_ = now_us;
    saturated_pose_travel_ = 0.0;
    saturated_wheel_travel_ = 0.0;
    saturated_object_start_ = object_position.value_or(geometry::Point::Zero());
    return std::nullopt;
  }
  if (reported_no_motion_ ||
      !(static_cast<double>(now_us - saturated_since_us_) >= settings.no_motion_time_s * 1e6)) {
    return std::nullopt;
  }
  reported_no_motion_ = true;
  // An object that slid at least min_measured_distance_m below the maximum force and then stopped has
  // met something (a wall, a corner, another object): it is light enough, only blocked where it stands,
  // and calling it unpushable would send the vehicle round a box it can push. A second jam of the same
  // object is taken as unpushable, so a push planned into the same corner is not tried forever.
  const double sliding_force = meanForce();
  const double pushed = measuredDistance();
  if (!jammed_before_ && pushed >= settings.min_measured_distance_m &&
      sliding_force < settings.max_force_fraction * max_push_force_) {
    AffordanceEvent event = makeEvent(AffordanceReason::Jammed, sliding_force, extrapolatedCost());
    event.text = fmt::format(
        "object {} jammed: slid {:.2f} m at mean {:.0f} N, then did not move ({:.3f} m) for {:.1f} s "
        "at {:.0f} N: pushable, blocked where it stands",
        plan_.object_id, pushed, sliding_force, moved, settings.no_motion_time_s, force_n);
    return event;
  }
  AffordanceEvent event = makeEvent(AffordanceReason::NoMotion, force_n, extrapolatedCost());
  event.text = fmt::format(
      "object {} did not move ({:.3f} m) for {:.1f} s at {:.0f} N (maximum {:.0f} N): "
      "unpushable",
      plan_.object_id, moved, settings.no_motion_time_s, force_n, max_push_force_);
  return event;
}

std::optional<AffordanceEvent> TactileMonitor::checkCost(const TactileSettings& settings)
{
  if (reported_cost_ || !(measuredDistance() >= settings.min_measured_distance_m)) {
    return std::nullopt;
  }
  const double measured = extrapolatedCost();
  const double difference = measured - plan_.expected_cost;
  if (!(std::abs(difference) > settings.cost_threshold)) {
    return std::nullopt;
  }
  reported_cost_ = true;
  const AffordanceReason reason =
      difference > 0.0 ? AffordanceReason::CostHigher : AffordanceReason::CostLower;
  AffordanceEvent event = makeEvent(reason, meanForce(), measured);
  event.text = fmt::format(
      "object {}: measured cost {:.2f} vs planned {:.2f} after {:.2f} m at mean {:.0f} N "
      "(planned {:.0f} N)",
      plan_.object_id, measured, plan_.expected_cost, measuredDistance(), meanForce(),
      plan_.expected_force_n);
  return event;
}

}  // namespace ifar::executive
