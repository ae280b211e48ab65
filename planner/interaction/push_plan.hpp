#pragma once
// The result of one push search: a plain struct the planner daemon turns into push_plan_t and the
// executive's pusher follows. World frame of the local layer, SI units.

#include <cstddef>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "common/geometry/pose2.hpp"
#include "planner/interaction/plan_status.hpp"

namespace ifar::interaction {

enum class ControlKind {
  Straight,       ///< push with omega = 0
  ArcLeft,        ///< push turning counter-clockwise at the edge's smallest stable radius
  ArcRight,       ///< push turning clockwise
  ContactSwitch,  ///< leave the object and drive round it to another edge (travel, no push)
};

const char* toString(ControlKind kind);

struct PushControl {
  ControlKind kind = ControlKind::Straight;
  std::size_t contact_edge = 0;  ///< footprint edge touched during (for a switch: after) this control
  double linear_mps = 0.0;       ///< v of the vehicle reference point (0 for a switch)
  double angular_radps = 0.0;    ///< omega, counter-clockwise positive (0 for a switch)
  double duration_s = 0.0;
  double distance_m = 0.0;       ///< arc length pushed, or distance travelled for a switch
  double force_n = 0.0;          ///< expected bumper force while pushing (0 for a switch)
  geometry::Pose2 object_pose;   ///< object body pose at the end of the control
  geometry::Pose2 vehicle_pose;  ///< vehicle reference pose at the end (at the contact for a switch)
};

struct PushPlan {
  PlanStatus status = PlanStatus::Exhausted;
  std::size_t contact_edge = 0;       ///< first contact edge (index into `footprint`)
  geometry::Pose2 contact_pose;       ///< vehicle reference pose at first contact
  geometry::Pose2 start_object_pose;  ///< object body pose before pushing
  geometry::Polygon footprint;        ///< body-frame footprint the edge indices refer to
  std::vector<PushControl> controls;
  double expected_force_n = 0.0;  ///< largest push force along the plan
  double push_work_nm = 0.0;      ///< sum of force x distance, N m
  double push_distance_m = 0.0;
  double travel_distance_m = 0.0;    ///< approach from the start waypoint plus contact switches
  double approach_distance_m = 0.0;  ///< of which the approach from the start waypoint to contact_pose
  double cost = 0.0;                 ///< J in equivalent metres: work / reference force + travel
  std::size_t expansions = 0;
  double planning_time_s = 0.0;
};

}  // namespace ifar::interaction
