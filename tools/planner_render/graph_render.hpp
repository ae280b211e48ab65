#pragma once
// Pictures of the planner's output: the last DV_GRAPH and GLOBAL_PATH of an LCM log drawn as a PNG.
// Background polygons red, movable ones green, visibility edges grey, interaction edges orange, graph
// vertices black, the path blue with its start and goal marked.

#include <optional>
#include <string>

#include "ifar/dv_graph_t.hpp"
#include "ifar/path_t.hpp"
#include "tools/render/canvas.hpp"

namespace ifar::planner_render {

struct RenderOptions {
  double metres_per_pixel = 0.05;
  double margin_m = 1.0;  // around everything drawn
};

namespace colors {
constexpr render::Color kBackground{220, 40, 40};
constexpr render::Color kMovable{40, 170, 60};
constexpr render::Color kVisibilityEdge{150, 150, 150};
constexpr render::Color kInteractionEdge{240, 150, 20};
constexpr render::Color kVertex{0, 0, 0};
constexpr render::Color kPath{30, 80, 230};
}  // namespace colors

/// Draws the graph (and the path when given) on a canvas sized to their extent plus the margin.
render::Canvas renderGraph(const dv_graph_t& graph, const std::optional<path_t>& path,
                           const RenderOptions& options);

struct LastMessages {
  std::optional<dv_graph_t> graph;
  std::optional<path_t> path;
  std::size_t undecodable = 0;  // events on the channels that did not decode (skipped)
  std::string error;            // the log could not be opened; empty otherwise
};

/// The last message on each channel of an LCM log file.
LastMessages readLastMessages(const std::string& log_path, const std::string& graph_channel,
                              const std::string& path_channel);

}  // namespace ifar::planner_render
