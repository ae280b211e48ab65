#include "planner/core/planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "planner/graph/graph_file.hpp"
#include "planner/graph/merge.hpp"
#include "planner/graph/visibility_builder.hpp"
#include "planner/perception/motion_compensation.hpp"
#include "planner/perception/perception_pipeline.hpp"

namespace ifar::planner {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void appendMessage(std::string& message, const std::string& part)
{
  if (!part.empty()) {
    message += message.empty() ? part : "; " + part;
  }
}

/// Obstacle loops of the layer: outer borders as they are, free-space holes reversed so the blocked side
/// stays on the left. Movable outlines carry a per-frame object id (index + 1), background 0.
std::vector<graph::ObstacleLoop> loopsOf(const std::vector<perception::LayerPolygon>& polygons)
{
  std::vector<graph::ObstacleLoop> loops;
  loops.reserve(polygons.size());
  for (std::size_t index = 0; index < polygons.size(); ++index) {
    const perception::LayerPolygon& polygon = polygons[index];
    const std::int64_t object_id = polygon.obstacle_class == perception::ObstacleClass::Movable
                                       ? static_cast<std::int64_t>(index) + 1
                                       : 0;
    if (polygon.boundary == perception::BoundaryKind::Outer) {
      loops.push_back(graph::loopFromPolygon(polygon.vertices, object_id));
    } else {
      graph::ObstacleLoop loop;
      loop.vertices.assign(polygon.vertices.rbegin(), polygon.vertices.rend());
      loop.object_id = object_id;
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

}  // namespace

Planner::Planner(const PlannerSettings& settings) : settings_(settings) {}

bool Planner::setGoal(const Goal& goal)
{
  if (!goal.position.allFinite()) {
    ++bad_inputs_;
    return false;
  }
  goal_ = goal;
  return true;
}

void Planner::clearGoal()
{
  goal_.reset();
}

std::string Planner::loadPriorGraph(const std::string& path)
{
  graph::GraphLoadResult loaded = graph::loadGraph(path);
  if (!loaded.ok()) {
    ++bad_inputs_;
    return loaded.error;
  }
  global_ = std::move(loaded.graph);
  return {};
}

bool Planner::goalOnKnownMap(const geometry::Point& goal) const
{
  if (!known_extent_) {
    return false;
  }
  return goal.x() >= known_extent_->first.x() && goal.y() >= known_extent_->first.y() &&
         goal.x() <= known_extent_->second.x() && goal.y() <= known_extent_->second.y();
}

void Planner::fillSizes(PlannerStatus& status) const
{
  status.frames = frames_;
  status.vertices = static_cast<std::int64_t>(global_.vertexCount());
  status.interaction_edges = static_cast<std::int64_t>(global_.interactionEdgeCount());
  status.edges = static_cast<std::int64_t>(global_.visibilityEdgeCount()) + status.interaction_edges;
  status.bad_inputs = bad_inputs_;
}

FrameResult Planner::processFrame(const FrameInput& frame)
{
  const Clock::time_point frame_start = Clock::now();
  FrameResult result;
  PlannerStatus& status = result.status;
  status.utime = frame.utime;
  status.flags = frame.flags;
  appendMessage(status.message, frame.problems);

  if (!frame.has_motion || !perception::isValidMotion(frame.motion)) {
    ++bad_inputs_;
    status.state = PlannerState::BadInput;
    appendMessage(status.message, frame.has_motion
                                      ? "frame rejected: vehicle motion is not finite or not proper"
                                      : "frame rejected: no pose for the scan");
    result.path = last_path_;
    result.sequence = frames_;
    fillSizes(status);
    status.timings.total_ms = millisecondsSince(frame_start);
    return result;
  }

  // Perception: points to classified world-frame polygons.
  perception::PerceptionInput input;
  input.points = common::Span<const perception::SensorPoint>(frame.points.data(), frame.points.size());
  input.mount = perception::lidarMount(settings_.vehicle);
  input.motion = frame.motion;
  input.detector_polygons = frame.detector_polygons;
  perception::PerceptionResult perceived = perception::runPerception(input, settings_.perception);
  status.timings.perception_ms = perceived.stats.total_ms;
  status.obstacle_points =
      static_cast<std::int64_t>(perceived.stats.background_points + perceived.stats.movable_points);
  if (perceived.stats.non_finite_points > 0) {
    status.flags |= kFlagBadPoints;
    appendMessage(status.message,
                  std::to_string(perceived.stats.non_finite_points) + " non-finite points dropped");
  }
  if (perceived.status == perception::PerceptionStatus::InvalidMotion ||
      perceived.status == perception::PerceptionStatus::InvalidSettings) {
    ++bad_inputs_;
    status.state = PlannerState::BadInput;
    appendMessage(status.message, "frame rejected: " + perceived.message);
    result.path = last_path_;
    result.sequence = frames_;
    fillSizes(status);
    status.timings.total_ms = millisecondsSince(frame_start);
    return result;
  }
  const bool empty_scan = perceived.status == perception::PerceptionStatus::EmptyScan;
  if (empty_scan || perceived.status == perception::PerceptionStatus::NoObstaclePoints) {
    status.flags |= kFlagEmptyScan;
    appendMessage(status.message, perceived.message);
  }
  result.polygons = std::move(perceived.layer.polygons);
  status.polygons = static_cast<std::int64_t>(result.polygons.size());

  const geometry::Point robot = frame.motion.vehicle_at_end.translation().head<2>();
  robot_ = robot;
  const perception::LayerGrid& grid = perceived.layer.grid;
  const geometry::Point layer_max = grid.origin + geometry::Point(grid.sideLength(), grid.sideLength());
  if (known_extent_) {
    known_extent_->first = known_extent_->first.cwiseMin(grid.origin);
    known_extent_->second = known_extent_->second.cwiseMax(layer_max);
  } else {
    known_extent_ = std::make_pair(grid.origin, layer_max);
  }

  // Local DV-graph of this frame's obstacles.
  Clock::time_point stage_start = Clock::now();
  obstacles_.emplace(loopsOf(result.polygons), std::nullopt, settings_.graph.bucket_size_m);
  graph::DvGraph local;
  graph::addReducedVisibilityGraph(*obstacles_, local);
  status.timings.local_graph_ms = millisecondsSince(stage_start);

  // Merge. A scan without any return says nothing about the world (a sensor gap), so it casts no votes.
  stage_start = Clock::now();
  if (!empty_scan) {
    graph::SensorView view;
    view.centre = robot;
    view.radius = settings_.graph.view_radius_m;
    graph::mergeLocalIntoGlobal(graph::toLocalLayer(local), view, settings_.graph, global_);
  }
  status.timings.merge_ms = millisecondsSince(stage_start);
  // TODO(interaction): connectivity analysis and push planning (planner/interaction) go here.
  status.timings.interaction_ms = 0.0;

  ++frames_;
  last_frame_utime_ = frame.utime;
  result.sequence = frames_;
  search(result);
  fillSizes(status);
  status.timings.total_ms = millisecondsSince(frame_start);
  return result;
}

FrameResult Planner::replan()
{
  const Clock::time_point start = Clock::now();
  FrameResult result;
  result.status.utime = last_frame_utime_;
  result.sequence = frames_;
  search(result);
  fillSizes(result.status);
  result.status.timings.total_ms = millisecondsSince(start);
  return result;
}

void Planner::search(FrameResult& result)
{
  PlannerStatus& status = result.status;
  if (!goal_) {
    status.state = PlannerState::Idle;
    last_path_ = PlannedPath{};
    result.path = last_path_;
    return;
  }
  if (!robot_ || !obstacles_) {
    status.state = PlannerState::NoPath;
    appendMessage(status.message, "no frame placed yet: waiting for packets and poses");
    last_path_ = PlannedPath{};
    last_path_.goal_id = goal_->id;
    result.path = last_path_;
    return;
  }
  if (!goalOnKnownMap(goal_->position)) {
    status.flags |= kFlagGoalOffMap;
    appendMessage(status.message, "goal lies outside the observed map: attempted through unknown space");
  }
  const Clock::time_point start = Clock::now();
  const graph::SearchGraph search_graph = graph::SearchGraph::fromDvGraph(global_);
  const graph::SearchResult found =
      graph::findPath(search_graph, *obstacles_, *robot_, goal_->position, scratch_);
  status.timings.search_ms = millisecondsSince(start);

  PlannedPath path;
  path.goal_id = goal_->id;
  if (found.goal_snapped) {
    status.flags |= kFlagGoalSnapped;
    appendMessage(status.message, "goal inside an obstacle: snapped to the nearest free point");
  }
  if (found.status == graph::SearchStatus::Found) {
    path.valid = true;
    path.waypoints = found.path;
    path.length_m = found.length;
    path.cost = found.cost;
    const bool arrived = (*robot_ - found.goal).norm() <= settings_.arrival_radius_m;
    status.state = arrived ? PlannerState::Arrived : PlannerState::Planning;
  } else {
    status.state = PlannerState::NoPath;
    appendMessage(status.message, std::string("search: ") + graph::toString(found.status));
  }
  last_path_ = path;
  result.path = std::move(path);
}

}  // namespace ifar::planner
