#pragma once
// The planner's view at one frame of a headless run as a PNG (ifar-run --graph-png): its global graph,
// this frame's polygons and the path, drawn as ifar-render-graph draws them from a log, with the
// vehicle's trajectory up to that frame, the path's push plans and the world as it really was (thin
// outlines: what perception missed or misjudged shows). For seeing why a run went where it did.

#include <optional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/pose2.hpp"
#include "ifar/dv_graph_t.hpp"
#include "ifar/path_t.hpp"
#include "sim/world/world.hpp"
#include "system/scenario_runner.hpp"
#include "viz/graph_render.hpp"

namespace ifar::runner {

class GraphPicture {
 public:
  /// Keeps the first frame at or after `at_s` simulated seconds, or the last frame when `at_s` is empty.
  /// The picture outlines `world`'s obstacles and its objects where they were at that frame (the world the
  /// run was given; it must outlive this).
  GraphPicture(const sim::World& world, std::optional<double> at_s) : world_(world), at_s_(at_s) {}

  /// A FrameObserver for runScenario.
  void observe(const FrameView& frame);

  /// Whether a frame was kept, and its simulated time.
  bool kept() const { return graph_.has_value(); }
  double keptTimeS() const { return kept_time_s_; }

  /// Writes the kept frame to `path` (all of it, or `options.window`): "" on success, else the error
  /// (naming the path, or saying that no frame was kept).
  std::string writePng(const std::string& path, const viz::RenderOptions& options = {}) const;

 private:
  const sim::World& world_;
  std::optional<double> at_s_;
  std::optional<dv_graph_t> graph_;
  std::optional<path_t> path_;
  std::vector<geometry::Point> trajectory_;
  std::vector<geometry::Pose2> object_poses_;  // ground truth at the kept frame, world-file order
  double kept_time_s_ = 0.0;
};

}  // namespace ifar::runner
