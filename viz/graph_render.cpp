#include "viz/graph_render.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/lcm_log/log_reader.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/world_state_t.hpp"
#include "lcmtypes/checked_decode.hpp"

namespace ifar::viz {

namespace {

struct Extent {
  geometry::Point min = geometry::Point::Constant(std::numeric_limits<double>::infinity());
  geometry::Point max = geometry::Point::Constant(-std::numeric_limits<double>::infinity());
  void add(double x, double y)
  {
    if (std::isfinite(x) && std::isfinite(y)) {
      min = min.cwiseMin(geometry::Point(x, y));
      max = max.cwiseMax(geometry::Point(x, y));
    }
  }
  bool empty() const { return !(min.x() <= max.x()); }
};

geometry::Polygon outline(const polygon_t& polygon)
{
  geometry::Polygon points;
  const std::size_t count = std::min(polygon.x.size(), polygon.y.size());
  for (std::size_t index = 0; index < count; ++index) {
    points.emplace_back(polygon.x[index], polygon.y[index]);
  }
  return points;
}

}  // namespace

viz::Canvas renderGraph(const dv_graph_t& graph, const std::optional<path_t>& path,
                        const RenderOptions& options, const RunOverlay& run)
{
  Extent extent;
  for (const polygon_t& polygon : graph.polygons) {
    for (std::size_t index = 0; index < std::min(polygon.x.size(), polygon.y.size()); ++index) {
      extent.add(polygon.x[index], polygon.y[index]);
    }
  }
  for (const graph_vertex_t& vertex : graph.vertices) {
    extent.add(vertex.x, vertex.y);
  }
  if (path) {
    for (const waypoint_t& waypoint : path->waypoints) {
      extent.add(waypoint.x, waypoint.y);
    }
  }
  for (const geometry::Point& point : run.trajectory) {
    extent.add(point.x(), point.y());
  }
  for (const auto& plan : run.push_plans) {
    for (const geometry::Point& point : plan) {
      extent.add(point.x(), point.y());
    }
  }
  for (const auto& [id, track] : run.object_tracks) {
    for (const geometry::Point& point : track) {
      extent.add(point.x(), point.y());
    }
  }
  if (extent.empty()) {
    extent.add(0.0, 0.0);
  }
  const geometry::Point margin = geometry::Point::Constant(options.margin_m);
  viz::Canvas canvas = options.window
                           ? viz::Canvas(options.window->low, options.window->high, options.metres_per_pixel)
                           : viz::Canvas(extent.min - margin, extent.max + margin, options.metres_per_pixel);

  // Outlines are counter-clockwise, free-space holes clockwise (planner_messages.hpp): each class is
  // filled, then its holes are cleared. Background first so movable objects stay visible on top.
  const viz::Color cleared{255, 255, 255};
  for (const std::int8_t kind : {polygon_t::KIND_BACKGROUND, polygon_t::KIND_MOVABLE}) {
    const viz::Color color = kind == polygon_t::KIND_MOVABLE ? colors::kMovable : colors::kBackground;
    for (const bool holes : {false, true}) {
      for (const polygon_t& polygon : graph.polygons) {
        const geometry::Polygon points = outline(polygon);
        if (polygon.kind != kind || (geometry::signedArea(points) < 0.0) != holes) {
          continue;
        }
        canvas.drawPolygon(points,
                           holes ? viz::ShapeStyle{cleared, color, 2} : viz::ShapeStyle{color, color, 1});
      }
    }
  }
  std::unordered_map<std::int64_t, geometry::Point> positions;
  for (const graph_vertex_t& vertex : graph.vertices) {
    positions[vertex.id] = geometry::Point(vertex.x, vertex.y);
  }
  for (const graph_edge_t& edge : graph.edges) {
    const auto from = positions.find(edge.from_id);
    const auto to = positions.find(edge.to_id);
    if (from == positions.end() || to == positions.end()) {
      continue;  // an edge naming a vertex the message does not hold: skipped
    }
    const bool interaction = edge.kind == graph_edge_t::KIND_INTERACTION;
    canvas.drawSegment(from->second, to->second,
                       interaction ? colors::kInteractionEdge : colors::kVisibilityEdge, interaction ? 3 : 2);
  }
  for (const auto& entry : positions) {
    canvas.drawCircle(entry.second, 0.05, viz::ShapeStyle{colors::kVertex, std::nullopt, 1});
  }
  if (path && path->valid && !path->waypoints.empty()) {
    std::vector<geometry::Point> points;
    for (const waypoint_t& waypoint : path->waypoints) {
      points.emplace_back(waypoint.x, waypoint.y);
    }
    canvas.drawPolyline(points, colors::kPath, 3);
    canvas.drawCircle(points.front(), 0.15, viz::ShapeStyle{colors::kPath, colors::kVertex, 1});
    canvas.drawCircle(points.back(), 0.15, viz::ShapeStyle{std::nullopt, colors::kPath, 3});
  }
  std::vector<viz::LegendEntry> legend = {{"background", colors::kBackground},
                                          {"movable", colors::kMovable},
                                          {"visibility edge", colors::kVisibilityEdge},
                                          {"interaction edge", colors::kInteractionEdge},
                                          {"path", colors::kPath}};
  for (const auto& plan : run.push_plans) {
    canvas.drawPolyline(plan, colors::kPushPlan, 2);
    if (!plan.empty()) {
      canvas.drawCircle(plan.front(), 0.12, viz::ShapeStyle{colors::kPushPlan, std::nullopt, 1});
    }
  }
  for (const auto& [id, track] : run.object_tracks) {
    canvas.drawPolyline(track, colors::kObjectTrack, 2);
  }
  for (const geometry::Polygon& outline : run.truth) {
    canvas.drawPolygon(outline, viz::ShapeStyle{std::nullopt, colors::kTruth, 2});
  }
  if (!run.trajectory.empty()) {
    canvas.drawPolyline(run.trajectory, colors::kTrajectory, 2);
  }
  if (!run.push_plans.empty()) {
    legend.push_back({"push plan", colors::kPushPlan});
  }
  if (!run.object_tracks.empty()) {
    legend.push_back({"object track", colors::kObjectTrack});
  }
  if (!run.truth.empty()) {
    legend.push_back({"ground truth", colors::kTruth});
  }
  if (!run.trajectory.empty()) {
    legend.push_back({"trajectory", colors::kTrajectory});
  }
  canvas.drawLegend(legend);
  return canvas;
}

namespace {

/// Adds `point` to `points` unless it is within `spacing_m` of the last one (keeps pictures light).
void appendSpaced(std::vector<geometry::Point>& points, const geometry::Point& point, double spacing_m)
{
  if (point.allFinite() && (points.empty() || (points.back() - point).norm() >= spacing_m)) {
    points.push_back(point);
  }
}

/// A push plan is drawn once: plans that start at the same contact point for the same object are one.
bool samePlan(const std::vector<geometry::Point>& first, const std::vector<geometry::Point>& second)
{
  return !first.empty() && !second.empty() && (first.front() - second.front()).norm() < 0.05 &&
         (first.back() - second.back()).norm() < 0.05;
}

}  // namespace

std::optional<Window> parseWindow(const std::string& text)
{
  std::array<double, 4> values{};
  std::istringstream stream(text);
  for (std::size_t index = 0; index < values.size(); ++index) {
    if (index > 0 && stream.get() != ',') {
      return std::nullopt;
    }
    if (!(stream >> values[index]) || !std::isfinite(values[index])) {
      return std::nullopt;
    }
  }
  if (stream.peek() != std::char_traits<char>::eof()) {
    return std::nullopt;
  }
  Window window{{std::min(values[0], values[2]), std::min(values[1], values[3])},
                {std::max(values[0], values[2]), std::max(values[1], values[3])}};
  if (!(window.high.x() > window.low.x() && window.high.y() > window.low.y())) {
    return std::nullopt;
  }
  return window;
}

std::vector<geometry::Point> pushPlanPoints(const push_plan_t& plan)
{
  std::vector<geometry::Point> points = {geometry::Point(plan.contact_x, plan.contact_y)};
  for (const push_control_t& control : plan.controls) {
    points.emplace_back(control.vehicle_x, control.vehicle_y);
  }
  return points;
}

LastMessages readLastMessages(const std::string& log_path, const std::string& graph_channel,
                              const std::string& path_channel, const std::string& pose_channel,
                              const std::string& truth_channel)
{
  constexpr double kSpacingM = 0.05;
  std::map<std::int64_t, geometry::Point> object_starts;
  LastMessages last;
  lcm_log::LogReader log = lcm_log::LogReader::open(log_path);
  if (!log.openError().empty()) {
    last.error = "cannot read an LCM log: " + log.openError();  // names the file
    return last;
  }
  lcm_log::LogEvent event;
  while (log.next(event)) {
    if (event.channel == graph_channel) {
      dv_graph_t graph{};
      if (!lcmtypes::decodeLcm(graph, event.data.data(), event.data.size()).ok()) {
        ++last.undecodable;
      } else {
        last.graph = std::move(graph);
      }
    } else if (event.channel == path_channel) {
      path_t path{};
      if (!lcmtypes::decodeLcm(path, event.data.data(), event.data.size()).ok()) {
        ++last.undecodable;
      } else {
        for (const push_plan_t& plan : path.push_plans) {
          std::vector<geometry::Point> points = pushPlanPoints(plan);
          const bool known = std::any_of(last.run.push_plans.begin(), last.run.push_plans.end(),
                                         [&](const auto& drawn) { return samePlan(drawn, points); });
          if (!known) {
            last.run.push_plans.push_back(std::move(points));
          }
        }
        last.path = std::move(path);
      }
    } else if (event.channel == pose_channel) {
      pose_t pose{};
      if (!lcmtypes::decodeLcm(pose, event.data.data(), event.data.size()).ok()) {
        ++last.undecodable;
      } else {
        appendSpaced(last.run.trajectory, geometry::Point(pose.position[0], pose.position[1]), kSpacingM);
      }
    } else if (event.channel == truth_channel) {
      world_state_t truth{};
      if (!lcmtypes::decodeLcm(truth, event.data.data(), event.data.size()).ok()) {
        ++last.undecodable;
        continue;
      }
      for (const object_state_t& object : truth.objects) {
        const geometry::Point position(object.x, object.y);
        const auto start = object_starts.emplace(object.id, position).first;
        // Objects that never moved have no track worth drawing.
        if ((position - start->second).norm() >= kSpacingM || last.run.object_tracks.count(object.id) != 0) {
          auto& track = last.run.object_tracks[object.id];
          if (track.empty()) {
            track.push_back(start->second);
          }
          appendSpaced(track, position, kSpacingM);
        }
      }
    }
  }
  if (!log.clean()) {
    if (log.eventCount() == 0) {
      last.error = log_path + ": no LCM event could be read: " + log.problemSummary();
    } else {
      last.log_problems = log.problemSummary();
    }
  }
  return last;
}

}  // namespace ifar::viz
