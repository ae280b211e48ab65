#include "planner/interaction/push_plan_assembler.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ifar::interaction {

PushPlan PushPlanAssembler::unplanned(PlanStatus status) const
{
  PushPlan plan;
  plan.status = status;
  plan.footprint = object_.model().footprint;
  plan.start_object_pose = object_.model().pose;
  return plan;
}

PushControl PushPlanAssembler::control(ControlKind kind, std::size_t edge, double distance, double radius,
                                       double force, const geometry::Pose2& end_pose) const
{
  PushControl control;
  control.kind = kind;
  control.contact_edge = edge;
  control.distance_m = distance;
  control.force_n = force;
  control.object_pose = end_pose;
  control.vehicle_pose = object_.vehiclePose(end_pose, edge);
  if (kind == ControlKind::ContactSwitch) {
    control.duration_s = distance / search_.travel_speed_mps;
  } else {
    control.linear_mps = search_.push_speed_mps;
    control.angular_radps = std::isfinite(radius) ? search_.push_speed_mps / radius : 0.0;
    control.duration_s = distance / search_.push_speed_mps;
  }
  return control;
}

void PushPlanAssembler::complete(PushPlan& plan, std::size_t edge, double approach_m,
                                 std::vector<PushControl> controls) const
{
  plan.status = PlanStatus::Found;
  plan.contact_edge = edge;
  plan.contact_pose = object_.vehiclePose(object_.model().pose, edge);
  plan.travel_distance_m = approach_m;
  plan.approach_distance_m = approach_m;
  plan.push_distance_m = 0.0;
  plan.push_work_nm = 0.0;
  plan.expected_force_n = 0.0;
  for (const PushControl& control : controls) {
    if (control.kind == ControlKind::ContactSwitch) {
      plan.travel_distance_m += control.distance_m;
    } else {
      plan.push_distance_m += control.distance_m;
      plan.push_work_nm += control.force_n * control.distance_m;
      plan.expected_force_n = std::max(plan.expected_force_n, control.force_n);
    }
  }
  plan.controls = std::move(controls);
  plan.cost = plan.push_work_nm / search_.reference_force_n + plan.travel_distance_m;
}

}  // namespace ifar::interaction
