#pragma once
// One push plan from start to end (paper section VII.B, Algorithm 2): the approach to the contact pose,
// the push primitives with their contact switches and release, and the tactile monitor's verdicts on the
// way. The pushed object's own returns are no obstacle meanwhile (objectFreeObstacles); everything else
// is, and the guard checks every command the follower does not plan.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/geometry/point.hpp"
#include "common/span.hpp"
#include "common/vehicle.hpp"
#include "executive/affordance/affordance_event.hpp"
#include "executive/affordance/tactile_monitor.hpp"
#include "executive/kinematics/differential_drive.hpp"
#include "executive/modes/collision_guard.hpp"
#include "executive/modes/cycle.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/modes/inputs.hpp"
#include "executive/modes/standstill_watch.hpp"
#include "executive/pusher/approach.hpp"
#include "executive/pusher/push_plan.hpp"
#include "executive/pusher/push_tracker.hpp"

namespace ifar::executive {

class PushSequence {
 public:
  /// `settings.follower.footprint` must be the vehicle's; `vehicle` gives the most it can push.
  PushSequence(const ExecutiveSettings& settings, const common::VehicleSettings& vehicle,
               const DifferentialDrive& drive);

  /// A new goal: objects jammed on the way to the last one may be tried again.
  void startGoal() { jammed_objects_.clear(); }
  /// Starts the approach to `plan`'s contact pose.
  void begin(const PushPlan& plan, const CycleView& view);
  const PushPlan& plan() const { return plan_; }

  enum class Next {
    Drive,          ///< the request holds this cycle's command
    Escape,         ///< stuck on the approach's collision-free leg: escape once as following does
    WaitForReplan,  ///< the plan no longer holds: `affordance` says why; stop and wait for the replan
    Push,           ///< at the contact: the push starts (call push() this cycle)
    Finished,       ///< the push and its release are done
  };
  struct Step {
    Next next = Next::Drive;
    std::optional<AffordanceEvent> affordance;      ///< to publish this cycle
    std::optional<geometry::Point> object_left_at;  ///< where the push left its object (when it ended)
    geometry::Point target = geometry::Point::Zero();
  };
  /// One cycle of the approach.
  Step approach(const CycleView& view, const CollisionGuard& guard, MotionRequest& request);
  /// One cycle of the push (after approach() said Push).
  Step push(const CycleView& view, const CollisionGuard& guard, MotionRequest& request);

  /// AFFORDANCE "contact not reached" for the plan's object: the loop made no progress with it (`why`).
  AffordanceEvent givenUpForProgress(const std::string& why) const
  {
    return notReached(fmt::format("object {}: {}: push given up for now", plan_.object_id, why));
  }

  /// Where the plan expects the object's centroid: at first contact while approaching (`pushing` false),
  /// at the start of the current primitive while pushing; none when the plan says nothing of it.
  std::optional<geometry::Point> objectEstimate(bool pushing) const;
  /// The fresh obstacle points without the returns on the object: those within pushed_object.radius_m of
  /// the object's expected centroid path or of its observed centroid.
  common::Span<const geometry::Point> objectFreeObstacles(const CycleView& view);

 private:
  /// The expected centroid path of the plan's object: at first contact, then after each primitive.
  void startObjectPath();
  /// The fresh observation of the plan's object, if any.
  std::optional<geometry::Point> observedObject(const CycleView& view) const;
  /// Aligning at the stand-off point turns on the spot; when a point ahead would stop that turn, backs
  /// straight up (at most approach.align_backup_m per approach) until the turn is free. True while it does.
  bool backUpToAlign(const CycleView& view, common::Span<const geometry::Point> obstacles,
                     const CollisionGuard& guard, MotionRequest& request);
  /// The approach is done: the push starts.
  void startPush(const CycleView& view);
  /// The tactile monitor's verdict this cycle, when it has one (cheaper than planned: the push goes on).
  std::optional<AffordanceEvent> tactileVerdict(const CycleView& view, const PushStep& tracked,
                                                const std::optional<geometry::Point>& observed);
  /// AFFORDANCE "contact not reached" with `text`: the vehicle stood still on its way to where the plan
  /// needs it; the object stays pushable.
  AffordanceEvent notReached(const std::string& text) const;
  /// notReached() for a contact (`contact`) that cannot be reached.
  AffordanceEvent unreachable(const std::string& contact) const;

  ExecutiveSettings settings_;
  DifferentialDrive drive_;
  double max_push_force_n_;

  PushPlan plan_;
  std::vector<geometry::Point> object_path_;  // see startObjectPath()
  std::size_t control_index_ = 0;             // the tracker's current primitive
  PushPhase phase_ = PushPhase::Pushing;      // its phase last cycle: motion is re-anchored on a change
  std::vector<geometry::Point> object_free_;  // reused buffer of objectFreeObstacles()
  Approach approach_;
  PushTracker tracker_;
  TactileMonitor tactile_;
  StandstillWatch standstill_;
  std::optional<std::int64_t> escaped_object_;         // the object whose approach used its one escape
  std::optional<geometry::Point> align_backup_start_;  // where this approach began backing up to align
  // Objects that jammed after sliding, this goal: a second jam of one is reported unpushable.
  std::vector<std::int64_t> jammed_objects_;
};

}  // namespace ifar::executive
