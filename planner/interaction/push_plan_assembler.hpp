#pragma once
// Writes push plans for one object: each control's speeds, duration and poses, and a found plan's
// distances, work and cost J = work / reference force + travel (paper VI.C).

#include <cstddef>
#include <vector>

#include "common/geometry/pose2.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/plan_status.hpp"
#include "planner/interaction/push_object.hpp"
#include "planner/interaction/push_plan.hpp"

namespace ifar::interaction {

class PushPlanAssembler {
 public:
  /// `object` must outlive the assembler.
  PushPlanAssembler(const PushObject& object, const SearchSettings& search) : object_(object), search_(search)
  {
  }

  /// A plan without controls: the object's footprint and start pose, and `status`.
  PushPlan unplanned(PlanStatus status) const;
  /// A control at `edge` ending with the object at `end_pose`; `radius` is infinite for a straight push.
  PushControl control(ControlKind kind, std::size_t edge, double distance, double radius, double force,
                      const geometry::Pose2& end_pose) const;
  /// Fills a found plan: first contact on `edge` of the unmoved object after `approach_m` from the start
  /// waypoint, its controls, distances and cost.
  void complete(PushPlan& plan, std::size_t edge, double approach_m, std::vector<PushControl> controls) const;

 private:
  const PushObject& object_;
  SearchSettings search_;
};

}  // namespace ifar::interaction
