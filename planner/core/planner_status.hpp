#pragma once
// What one planner update reports: a state, input-problem flags (the same bits as planner_status_t's
// FLAG_ constants, so the daemon copies them through), per-stage timings and sizes.

#include <cstdint>
#include <string>

namespace ifar::planner {

enum class PlannerState : std::int8_t { Idle = 0, Planning = 1, NoPath = 2, Arrived = 3, BadInput = 4 };

const char* toString(PlannerState state);

/// Bits of PlannerStatus::flags; values match planner_status_t.FLAG_*.
enum PlannerFlag : std::int32_t {
  kFlagGoalSnapped = 1,  // goal inside an obstacle, moved to the nearest free point
  kFlagGoalOffMap = 2,   // goal outside every layer observed so far: attempted through unknown space
  kFlagBadPoints = 4,    // non-finite points dropped in the frame
  kFlagBadPose = 8,      // a non-finite or out-of-order pose was ignored
  kFlagStaleInput = 16,  // packets out of order or from the future, or no pose near the scan
  kFlagEmptyScan = 32,   // the frame had no obstacle points
};

struct StageTimings {
  double perception_ms = 0.0;
  double local_graph_ms = 0.0;
  double merge_ms = 0.0;
  double interaction_ms = 0.0;
  double search_ms = 0.0;
  double total_ms = 0.0;
};

/// Deterministic measures of one frame's work (tests and benchmarks bound them instead of wall time).
struct FrameWork {
  std::int64_t remembered_cells = 0;  // background memory after the frame
  std::int64_t checked_cells = 0;     // remembered cells tested against the scan's rays
  std::int64_t forgotten_cells = 0;   // ... that the rays saw through for the last time
  std::int64_t layer_cells = 0;       // cells of the frame's raster
  std::int64_t polygon_vertices = 0;  // of the frame's local polygons
};

struct PlannerStatus {
  std::int64_t utime = 0;  // time of the frame (scan start), microseconds
  PlannerState state = PlannerState::Idle;
  std::int32_t flags = 0;
  std::int64_t frames = 0;  // graph updates since start
  StageTimings timings;
  std::int64_t obstacle_points = 0;
  std::int64_t polygons = 0;
  std::int64_t vertices = 0;
  std::int64_t edges = 0;  // visibility and interaction
  std::int64_t interaction_edges = 0;
  std::int64_t bad_inputs = 0;  // inputs rejected since start
  FrameWork work;
  std::string message;  // why the state and flags are what they are
};

}  // namespace ifar::planner
