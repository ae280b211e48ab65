#pragma once
// Tactile adaptation while pushing (paper section VII.B, Algorithm 2): watches the bumper force and how
// far the object moves, and says when the object is unpushable, jammed against something after sliding, or
// costs clearly more or less than the plan assumed.
//
// Object motion is the vehicle's own forward travel while the bumper is loaded (in a stable push the
// object moves with the bumper), capped by the observed object displacement when perception provides
// one: an object in contact moves no farther than the vehicle follows it, and a wheel that spins on the
// spot is not an object that moves.
//
// Travel is net displacement, never a sum of positive steps: a state estimator's pose jitters by
// centimetres every sample, and summing only the forward parts of that jitter reads as steady progress.
// With wheel odometry, travel counts only as far as the pose and the wheels agree (the lesser of the
// two): wheels slipping against a heavy object roll on while the pose stays, and a jittery pose moves
// while the wheels stand. Over the no-motion window the pose is smoothed first (pose_smoothing_s), so
// jitter far below the motion threshold cannot restart it; without odometry (an old log) the smoothed
// pose alone decides.

#include <cstdint>
#include <optional>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "executive/affordance/affordance_event.hpp"
#include "executive/pusher/push_plan.hpp"

namespace ifar::executive {

/// One cycle's forward travel (metres, signed) as each source sees it.
struct TravelSteps {
  double pose = 0.0;             ///< the pose's
  double smoothed = 0.0;         ///< the smoothed pose's
  double wheels = 0.0;           ///< the wheels' (the pose's where odometry is missing)
  double wheels_smoothed = 0.0;  ///< the wheels' (the smoothed pose's where odometry is missing)
};

struct TactileSettings {
  double contact_force_n = 20.0;     ///< bumper force above this means the object is on the bumper
  double max_force_fraction = 0.9;   ///< "maximum push": force above this fraction of the vehicle's maximum
  double no_motion_time_s = 2.0;     ///< at maximum push without motion this long: unpushable
  double motion_threshold_m = 0.05;  ///< displacement below this is "no motion"
  double min_measured_distance_m = 0.3;  ///< push this far before the cost estimate is trusted
  double cost_threshold = 1.0;           ///< |J measured - J planned| above this (equivalent metres) is news
  /// The no-motion window compares the pose averaged over about this long (an exponential filter):
  /// centimetres of estimator jitter per sample shrink well below motion_threshold_m. 0: the raw pose.
  double pose_smoothing_s = 0.1;
};

class TactileMonitor {
 public:
  /// `max_push_force_n`: the most the vehicle can push (traction limit, capped by the sensor range).
  TactileMonitor() = default;

  /// Starts watching a push of `plan`. `jammed_before`: this object already jammed once (then a jam is
  /// reported as NoMotion, unpushable).
  void begin(const PushPlan& plan, double max_push_force_n, bool jammed_before = false);

  /// One sensor cycle. `wheel_travel_m`: the signed distance the wheels have rolled (any origin, one
  /// continuous count), empty while odometry is stale or absent. `in_contact_expected` is false while
  /// backing off or switching contact (then nothing is measured). Returns an event at most once per kind
  /// of finding per plan.
  std::optional<AffordanceEvent> update(std::int64_t now_us, double force_n, const geometry::Pose2& vehicle,
                                        std::optional<double> wheel_travel_m,
                                        const std::optional<geometry::Point>& object_position,
                                        bool in_contact_expected, const TactileSettings& settings);
  /// The same without odometry: the pose alone.
  std::optional<AffordanceEvent> update(std::int64_t now_us, double force_n, const geometry::Pose2& vehicle,
                                        const std::optional<geometry::Point>& object_position,
                                        bool in_contact_expected, const TactileSettings& settings)
  {
    return update(now_us, force_n, vehicle, std::nullopt, object_position, in_contact_expected, settings);
  }

  double work() const;              ///< newton metres measured so far
  double measuredDistance() const;  ///< metres pushed with the bumper loaded, >= 0
  /// Mean force over the distance pushed; 0 before anything was pushed.
  double meanForce() const;
  /// The plan's J with the push part scaled by meanForce() / expected force.
  double extrapolatedCost() const;

 private:
  AffordanceEvent makeEvent(AffordanceReason reason, double force_n, double measured_cost) const;
  /// Principle 1 while the force is at maximum: the event once the object has not moved for
  /// no_motion_time_s (jammed after sliding, or unpushable).
  std::optional<AffordanceEvent> watchSaturated(std::int64_t now_us, double force_n, const TravelSteps& steps,
                                                const std::optional<geometry::Point>& object_position,
                                                const TactileSettings& settings);
  /// This cycle's forward steps of the pose, the smoothed pose and the wheels; advances the filter.
  TravelSteps stepsTo(std::int64_t now_us, const geometry::Pose2& vehicle,
                      std::optional<double> wheel_travel_m, const TactileSettings& settings);
  /// True while the wheels' count of distance pushed is the lesser (the one that counts).
  bool wheelsCount() const { return pushed_by_wheels_ < pushed_by_pose_; }
  /// Principle 2: the event once the measured cost differs from the plan's by more than the threshold.
  std::optional<AffordanceEvent> checkCost(const TactileSettings& settings);

  PushPlan plan_;
  double max_push_force_ = 0.0;
  bool has_last_pose_ = false;
  geometry::Pose2 last_pose_;
  std::int64_t last_us_ = 0;
  std::optional<double> last_wheel_travel_;
  geometry::Point smoothed_ = geometry::Point::Zero();  // the pose's position, exponentially smoothed
  int smoothed_samples_ = 0;                            // short of a full filter: a running mean
  // Distance pushed with the bumper loaded and force x distance, by the pose and by the wheels (the
  // pose's step where odometry is missing): signed sums, so jitter cancels out instead of adding up.
  double pushed_by_pose_ = 0.0;
  double work_by_pose_ = 0.0;
  double pushed_by_wheels_ = 0.0;
  double work_by_wheels_ = 0.0;
  // The window in which the force stays at maximum: when it began, where the object was then, and the
  // vehicle's travel since, by the smoothed pose and by the wheels.
  bool saturated_ = false;
  std::int64_t saturated_since_us_ = 0;
  geometry::Point saturated_object_start_ = geometry::Point::Zero();
  double saturated_pose_travel_ = 0.0;
  double saturated_wheel_travel_ = 0.0;
  bool jammed_before_ = false;
  bool reported_no_motion_ = false;
  bool reported_cost_ = false;
};

}  // namespace ifar::executive
