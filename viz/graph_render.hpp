#pragma once
// Pictures of the planner's output: the last DV_GRAPH and GLOBAL_PATH of an LCM log drawn as a PNG.
// Background polygons red, movable ones green, visibility edges grey, interaction edges orange, graph
// vertices black, the path blue with its start and goal marked. Over it, what happened in the run: the
// vehicle's trajectory (POSE) black, every push plan the planner sent (its vehicle poses) magenta, and the
// objects' ground-truth tracks (SIM_GROUND_TRUTH, simulated runs only) dark green.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"
#include "ifar/dv_graph_t.hpp"
#include "ifar/path_t.hpp"
#include "viz/canvas.hpp"

namespace ifar::viz {

/// A world-frame rectangle: its low and high corners.
struct Window {
  geometry::Point low = geometry::Point::Zero();
  geometry::Point high = geometry::Point::Zero();
};

struct RenderOptions {
  double metres_per_pixel = 0.05;
  double margin_m = 1.0;         // around everything drawn
  std::optional<Window> window;  // draw this rectangle only (a close look at part of a large map)
};

/// What parseWindow accepts, for error messages.
constexpr const char* kWindowFormat = "X0,Y0,X1,Y1 (four numbers in metres, a rectangle with area)";

/// "X0,Y0,X1,Y1" (metres, any two opposite corners) as a window; empty when the text is not four finite
/// numbers or the rectangle has no area.
std::optional<Window> parseWindow(const std::string& text);

namespace colors {
constexpr viz::Color kBackground{220, 40, 40};
constexpr viz::Color kMovable{40, 170, 60};
constexpr viz::Color kVisibilityEdge{150, 150, 150};
constexpr viz::Color kInteractionEdge{240, 150, 20};
constexpr viz::Color kVertex{0, 0, 0};
constexpr viz::Color kPath{30, 80, 230};
constexpr viz::Color kTrajectory{20, 20, 20};
constexpr viz::Color kPushPlan{200, 40, 200};
constexpr viz::Color kObjectTrack{0, 110, 40};
constexpr viz::Color kTruth{90, 60, 160};
}  // namespace colors

/// What a run did, drawn over the graph; every part may be empty.
struct RunOverlay {
  std::vector<geometry::Point> trajectory;               ///< vehicle positions in time order
  std::vector<std::vector<geometry::Point>> push_plans;  ///< contact pose then each control's end pose
  std::map<std::int64_t, std::vector<geometry::Point>> object_tracks;  ///< per object id, only if it moved
  /// Simulated runs: the world's walls and objects as they really are, thin outlines over the planner's
  /// inflated polygons (what perception missed shows as an outline with no colour under it).
  std::vector<geometry::Polygon> truth;
};

/// Draws the graph (and the path and the run when given) on a canvas sized to their extent plus the margin.
viz::Canvas renderGraph(const dv_graph_t& graph, const std::optional<path_t>& path,
                        const RenderOptions& options, const RunOverlay& run = {});

/// A push plan as the overlay draws it: the contact point, then the vehicle's end pose of each control.
std::vector<geometry::Point> pushPlanPoints(const push_plan_t& plan);

struct LastMessages {
  std::optional<dv_graph_t> graph;
  std::optional<path_t> path;
  RunOverlay run;  ///< trajectory from the POSE channel, push plans from every path, object tracks
  std::size_t undecodable = 0;  // events on the channels that did not decode (skipped)
  std::string error;            // the log could not be opened, or no event in it could be read; else empty
  /// The log is corrupt but some events were read: how many problems, bytes skipped and the first bad
  /// byte (for a warning); empty when the log is clean.
  std::string log_problems;
};

/// The last graph and path of an LCM log file, and the run overlay from its other channels.
LastMessages readLastMessages(const std::string& log_path, const std::string& graph_channel,
                              const std::string& path_channel, const std::string& pose_channel = "POSE",
                              const std::string& truth_channel = "SIM_GROUND_TRUTH");

}  // namespace ifar::viz
