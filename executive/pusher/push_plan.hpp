#pragma once
// A push plan as the executive uses it: the interaction strategy the planner made for one object
// (paper section VI), without LCM. The daemon converts push_plan_t into this.

#include <cstdint>
#include <vector>

#include "common/geometry/pose2.hpp"

namespace ifar::executive {

enum class PushControlKind {
  Push,           ///< drive (linear, angular) for duration_s with the object on the bumper
  SwitchContact,  ///< leave the object and drive to expected_vehicle_pose, the next contact pose
};

struct PushControl {
  PushControlKind kind = PushControlKind::Push;
  int contact_edge = 0;
  double linear_velocity = 0.0;   ///< m/s, forward positive
  double angular_velocity = 0.0;  ///< rad/s, counter-clockwise positive
  double duration_s = 0.0;
  geometry::Pose2 expected_vehicle_pose;  ///< world frame, at the end of this step
  geometry::Pose2 expected_object_pose;   ///< world frame centroid and heading change, at the end
};

struct PushPlan {
  std::int64_t object_id = -1;
  geometry::Pose2 contact_pose;  ///< vehicle pose at first contact, world frame
  std::vector<PushControl> controls;
  double expected_force_n = 0.0;  ///< force to keep the object sliding, newtons
  double push_distance_m = 0.0;   ///< distance the object is pushed in total
  double travel_m = 0.0;          ///< vehicle travel for approach and contact switches
  double expected_cost = 0.0;     ///< J, equivalent metres
  double affordance = 0.0;        ///< push affordance mu the plan assumed (friction force / weight)
};

}  // namespace ifar::executive
