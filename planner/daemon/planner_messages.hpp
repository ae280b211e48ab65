#pragma once
// Planner results as LCM messages (dv_graph_t, path_t, planner_status_t) and LCM inputs as planner
// values. Only the daemon and tools include this.

#include <cstdint>
#include <string>

#include "ifar/dv_graph_t.hpp"
#include "ifar/object_polygons_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "planner/core/planner.hpp"

namespace ifar::planner {

struct PlannerMessages {
  dv_graph_t graph;
  path_t path;
  planner_status_t status;
};

/// The global graph with this frame's polygons, the path and the status of one finished update. Polygons:
/// obstacle outlines counter-clockwise, free-space holes inside an obstacle (a room) clockwise.
PlannerMessages toMessages(const Planner& planner, const FrameResult& result, std::int64_t now_utime);

planner_status_t toStatusMessage(const PlannerStatus& status);

PoseSample toPoseSample(const pose_t& pose);

/// Outlines of the movable objects a detector published; polygons with fewer than 3 points or with
/// mismatched coordinate counts are skipped and counted in `skipped`.
std::vector<geometry::Polygon> toPolygons(const object_polygons_t& message, std::int64_t& skipped);

}  // namespace ifar::planner
