#pragma once
// The planner frame pipeline without LCM: one frame (a revolution placed by its poses) in; perception
// polygons, the local DV-graph merged into the global one, and the global path out, with a status that
// carries per-stage timings and input flags. Deterministic: the same frames and goals give the same graph
// and path. Not thread safe: one thread owns a Planner (the daemon's worker).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/vehicle.hpp"
#include "planner/core/frame_assembler.hpp"
#include "planner/core/planner_status.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/search.hpp"
#include "planner/graph/settings.hpp"
#include "planner/perception/local_layer.hpp"
#include "planner/perception/perception_settings.hpp"

namespace ifar::planner {

struct PlannerSettings {
  perception::PerceptionSettings perception;
  graph::GraphSettings graph;
  common::VehicleSettings vehicle;  // the lidar mount comes from here
  double arrival_radius_m = 0.5;    // the vehicle this close to the goal has arrived
};

struct Goal {
  std::int64_t id = 0;
  geometry::Point position = geometry::Point::Zero();  // world frame, metres
};

struct PlannedPath {
  bool valid = false;
  std::int64_t goal_id = 0;
  std::vector<graph::PathPoint> waypoints;  // robot first, goal last
  double length_m = 0.0;
  double cost = 0.0;
};

struct FrameResult {
  PlannerStatus status;
  std::vector<perception::LayerPolygon> polygons;  // this frame's local polygons, world frame
  PlannedPath path;
  std::int64_t sequence = 0;  // graph updates so far (equals status.frames)
};

class Planner {
 public:
  explicit Planner(const PlannerSettings& settings);

  /// False (and a bad input counted) for a non-finite goal; the previous goal stays.
  bool setGoal(const Goal& goal);
  void clearGoal();
  const std::optional<Goal>& goal() const { return goal_; }

  /// Runs perception, local graph, merge and search for one frame.
  FrameResult processFrame(const FrameInput& frame);
  /// Searches again on the current graph (a new goal between frames); no graph update.
  FrameResult replan();

  /// Starts from a saved global graph (prior map). On a corrupt file the graph stays as it was, a bad
  /// input is counted and the reason (file and line) is returned; empty on success.
  std::string loadPriorGraph(const std::string& path);

  const graph::DvGraph& graph() const { return global_; }
  std::int64_t badInputs() const { return bad_inputs_; }

 private:
  /// Search and state for the current robot position; fills result.path and the status.
  void search(FrameResult& result);
  void fillSizes(PlannerStatus& status) const;
  bool goalOnKnownMap(const geometry::Point& goal) const;

  PlannerSettings settings_;
  graph::DvGraph global_;
  std::optional<graph::ObstacleSet> obstacles_;  // last frame's observed obstacles, for attachment
  std::optional<Goal> goal_;
  std::optional<geometry::Point> robot_;
  // Extent of every local layer so far: the "known map" for the off-map flag.
  std::optional<std::pair<geometry::Point, geometry::Point>> known_extent_;
  graph::SearchScratch scratch_;
  PlannedPath last_path_;
  std::int64_t frames_ = 0;
  std::int64_t bad_inputs_ = 0;
  std::int64_t last_frame_utime_ = 0;
};

}  // namespace ifar::planner
