#pragma once
// Planner results as LCM messages (dv_graph_t, path_t, planner_status_t) and LCM inputs as planner
// values: the planner node's conversions (planner_node.hpp), also used by tools.

#include <cstdint>
#include <string>

#include "ifar/affordance_t.hpp"
#include "ifar/blocked_passage_t.hpp"
#include "ifar/dv_graph_t.hpp"
#include "ifar/object_polygons_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/push_plan_t.hpp"
#include "planner/core/planner.hpp"

namespace ifar::planner {

struct PlannerMessages {
  dv_graph_t graph;
  path_t path;
  planner_status_t status;
};

/// polygon_t.id of background polygon i of a frame (movable polygons carry their tracked object id,
/// small positive numbers, so the two never collide).
constexpr std::int64_t kBackgroundPolygonIdBase = 1'000'000'000;

/// One push of a path as push_plan_t (controls as push_control_t, object headings relative to the
/// object's pose at planning time), not yet stamped (stampPath).
push_plan_t toPushPlanMessage(const PathPush& push);

/// The global graph with this frame's polygons. Polygons: obstacle outlines counter-clockwise, free-space
/// holes inside an obstacle (a room) clockwise.
dv_graph_t toGraphMessage(const Planner& planner, const FrameResult& result);

/// The path of one finished update, stamped `now_utime`. Waypoint kinds: KIND_TOPOLOGICAL where a push
/// starts (a topological vertex of `graph`), KIND_PUSH (object id, index into push_plans) where it ends.
path_t toPathMessage(const graph::DvGraph& graph, const FrameResult& result, std::int64_t now_utime);

/// Sets the time a path and its push plans carry: when the update was finished, so a path built before
/// its stamp is known (a replayed job) gets the same bytes as one built at once.
void stampPath(path_t& path, std::int64_t now_utime);

/// The three messages of one finished update (toGraphMessage, toPathMessage, toStatusMessage).
PlannerMessages toMessages(const Planner& planner, const FrameResult& result, std::int64_t now_utime);

planner_status_t toStatusMessage(const PlannerStatus& status);

PoseSample toPoseSample(const pose_t& pose);

/// The executive's estimate as the planner takes it (values passed through; the planner checks them).
AffordanceUpdate toAffordanceUpdate(const affordance_t& message);

/// The executive's report of a passage it could not get through (values passed through; the planner
/// checks them).
BlockedPassage toBlockedPassage(const blocked_passage_t& message);

/// Outlines of the movable objects a detector published; polygons with fewer than 3 points or with
/// mismatched coordinate counts are skipped and counted in `skipped`.
std::vector<geometry::Polygon> toPolygons(const object_polygons_t& message, std::int64_t& skipped);

}  // namespace ifar::planner
