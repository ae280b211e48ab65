#pragma once
// Tactile adaptation while pushing (paper section VII.B, Algorithm 2): watches the bumper force and how
// far the object moves, and says when the object is unpushable, jammed against something after sliding, or
// costs clearly more or less than the plan assumed.
//
// Object motion is the vehicle's own forward travel while the bumper is loaded (in a stable push the
// object moves with the bumper), capped by the observed object displacement when perception provides
// one: an object in contact moves no farther than the vehicle follows it, and a wheel that spins on the
// spot is not an object that moves.

#include <cstdint>
#include <optional>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "executive/affordance/affordance_event.hpp"
#include "executive/pusher/push_plan.hpp"

namespace ifar::executive {

struct TactileSettings {
  double contact_force_n = 20.0;     ///< bumper force above this means the object is on the bumper
  double max_force_fraction = 0.9;   ///< "maximum push": force above this fraction of the vehicle's maximum
  double no_motion_time_s = 2.0;     ///< at maximum push without motion this long: unpushable
  double motion_threshold_m = 0.05;  ///< displacement below this is "no motion"
  double min_measured_distance_m = 0.3;  ///< push this far before the cost estimate is trusted
  double cost_threshold = 1.0;           ///< |J measured - J planned| above this (equivalent metres) is news
};

class TactileMonitor {
 public:
  /// `max_push_force_n`: the most the vehicle can push (traction limit, capped by the sensor range).
  TactileMonitor() = default;

  /// Starts watching a push of `plan`. `jammed_before`: this object already jammed once (then a jam is
  /// reported as NoMotion, unpushable).
  void begin(const PushPlan& plan, double max_push_force_n, bool jammed_before = false);

  /// One sensor cycle. `in_contact_expected` is false while backing off or switching contact (then
  /// nothing is measured). Returns an event at most once per kind of finding per plan.
  std::optional<AffordanceEvent> update(std::int64_t now_us, double force_n, const geometry::Pose2& vehicle,
                                        const std::optional<geometry::Point>& object_position,
                                        bool in_contact_expected, const TactileSettings& settings);

  double work() const { return work_; }                         ///< newton metres measured so far
  double measuredDistance() const { return pushed_distance_; }  ///< metres pushed with the bumper loaded
  /// Mean force over the distance pushed; 0 before anything was pushed.
  double meanForce() const { return pushed_distance_ > 0.0 ? work_ / pushed_distance_ : 0.0; }
  /// The plan's J with the push part scaled by meanForce() / expected force.
  double extrapolatedCost() const;

 private:
  AffordanceEvent makeEvent(AffordanceReason reason, double force_n, double measured_cost) const;
  /// Principle 1 while the force is at maximum: the event once the object has not moved for
  /// no_motion_time_s (jammed after sliding, or unpushable).
  std::optional<AffordanceEvent> watchSaturated(std::int64_t now_us, double force_n, double forward_step,
                                                const std::optional<geometry::Point>& object_position,
                                                const TactileSettings& settings);
  /// Principle 2: the event once the measured cost differs from the plan's by more than the threshold.
  std::optional<AffordanceEvent> checkCost(const TactileSettings& settings);

  PushPlan plan_;
  double max_push_force_ = 0.0;
  bool has_last_pose_ = false;
  geometry::Pose2 last_pose_;
  double work_ = 0.0;
  double pushed_distance_ = 0.0;
  // The window in which the force stays at maximum: when it began and where the object was then.
  bool saturated_ = false;
  std::int64_t saturated_since_us_ = 0;
  geometry::Point saturated_object_start_ = geometry::Point::Zero();
  double saturated_vehicle_travel_ = 0.0;
  bool jammed_before_ = false;
  bool reported_no_motion_ = false;
  bool reported_cost_ = false;
};

}  // namespace ifar::executive
