#include "planner/core/planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "planner/core/occupancy_rectangles.hpp"
#include "planner/core/passage_seal.hpp"
#include "planner/graph/graph_file.hpp"
#include "planner/graph/merge.hpp"
#include "planner/graph/path_check.hpp"
#include "planner/graph/visibility_builder.hpp"
#include "planner/perception/line_of_sight.hpp"
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
/// stays on the left. Movable outlines carry their tracked object's id, background 0.
std::vector<graph::ObstacleLoop> loopsOf(const std::vector<perception::LayerPolygon>& polygons,
                                         const std::vector<std::int64_t>& polygon_ids)
{
  std::vector<graph::ObstacleLoop> loops;
  loops.reserve(polygons.size());
  for (std::size_t index = 0; index < polygons.size(); ++index) {
    const perception::LayerPolygon& polygon = polygons[index];
    const std::int64_t object_id = index < polygon_ids.size() ? polygon_ids[index] : 0;
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

PlannerSettings completed(PlannerSettings settings)
{
  // The pusher is the vehicle: always derived from it, whatever the caller left in the struct.
  settings.interaction.pusher = interaction::PusherSettings::fromVehicle(settings.vehicle);
  // So is the lidar: which returns are obstacles is the sensor's and its mount's (vehicle.yaml lidar:).
  settings.perception = perception::withLidarFilter(settings.perception, settings.vehicle.lidar);
  return settings;
}

TrackerSettings trackerSettings(const PlannerSettings& settings)
{
  TrackerSettings tracker;
  tracker.association_distance_m = settings.interaction.loop.track_association_m;
  tracker.drop_after_frames = settings.interaction.loop.track_drop_frames;
  tracker.view_radius_m = settings.graph.view_radius_m;
  return tracker;
}

// How near the line from the vehicle to the point it could not reach a movable object must come to bound
// the blocked passage: the inflation is in its outline already, so touching.
constexpr double kObjectBesidePassageM = 0.15;

}  // namespace

Planner::Planner(const PlannerSettings& settings)
    : settings_(completed(settings)),
      tracker_(trackerSettings(settings_)),
      interaction_(settings_.interaction, settings_.perception.cell_size_m),
      background_memory_(settings_.perception.cell_size_m, settings_.perception.background_votes),
      sealed_(settings_.perception.cell_size_m),
      known_(settings_.perception.cell_size_m),
      object_seals_(settings_.perception.cell_size_m),
      affordances_(trackerSettings(settings_).association_distance_m),
      outline_memory_(settings_.interaction_enabled ? settings_.interaction.loop.outline_memory_restart_m
                                                    : 0.0)
{
}

bool Planner::setGoal(const Goal& goal)
{
  if (!goal.position.allFinite()) {
    ++bad_inputs_;
    return false;
  }
  if (!goal_ || goal_->id != goal.id) {
    no_path_forgets_ = 0;
    last_forget_at_.reset();
    interaction_.startGoal();
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

std::size_t Planner::rememberKnownObstacles(common::Span<const geometry::Polygon> outlines)
{
  std::size_t cells = 0;
  for (const geometry::Polygon& outline : outlines) {
    const std::size_t added = known_.rememberOutline(outline);
    cells += added;
    if (added == 0) {
      continue;  // nothing new (or a non-finite vertex): the extent stays
    }
    // A goal among the known walls is on the map, not attempted through unknown space.
    for (const geometry::Point& vertex : outline) {
      extendKnownMap(vertex, vertex);
    }
  }
  return cells;
}

void Planner::extendKnownMap(const geometry::Point& minimum, const geometry::Point& maximum)
{
  if (known_extent_) {
    known_extent_->first = known_extent_->first.cwiseMin(minimum);
    known_extent_->second = known_extent_->second.cwiseMax(maximum);
  } else {
    known_extent_ = std::make_pair(minimum, maximum);
  }
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
  std::vector<geometry::Point> remembered;
  std::vector<geometry::Point> kept;
  {
    const auto end = frame.motion.vehicle_at_end.translation();
    const geometry::Point half_layer = geometry::Point::Constant(settings_.perception.layer_size_m / 2.0);
    const geometry::Point minimum = geometry::Point(end.x(), end.y()) - half_layer;
    const geometry::Point maximum = geometry::Point(end.x(), end.y()) + half_layer;
    if (settings_.perception.remember_background) {
      remembered = background_memory_.cellsWithin(minimum, maximum);
    }
    for (const perception::BackgroundMemory* memory : {&sealed_, &known_}) {
      const std::vector<geometry::Point> cells = memory->cellsWithin(minimum, maximum);
      kept.insert(kept.end(), cells.begin(), cells.end());
    }
    input.remembered_background = common::Span<const geometry::Point>(remembered.data(), remembered.size());
    input.kept_background = common::Span<const geometry::Point>(kept.data(), kept.size());
  }
  perception::PerceptionResult perceived = perception::runPerception(input, settings_.perception);
  const Clock::time_point memory_start = Clock::now();
  updateBackgroundMemory(perceived, status.work);
  status.timings.perception_ms = perceived.stats.total_ms + millisecondsSince(memory_start);
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
  status.work.layer_cells = static_cast<std::int64_t>(perceived.layer.grid.cells) *
                            static_cast<std::int64_t>(perceived.layer.grid.cells);
  for (const perception::LayerPolygon& polygon : result.polygons) {
    status.work.polygon_vertices += static_cast<std::int64_t>(polygon.vertices.size());
  }

  const geometry::Point robot = frame.motion.vehicle_at_end.translation().head<2>();
  robot_ = robot;
  const perception::LayerGrid& grid = perceived.layer.grid;
  const perception::LayerGrid& extent = perceived.layer.extent;
  const geometry::Point layer_max = extent.origin + geometry::Point::Constant(extent.sideLength());
  extendKnownMap(extent.origin, layer_max);
  if (settings_.graph.unseen_cost > 0.0 && !empty_scan) {
    seen_.markView(perceived.layer, robot, settings_.graph.seen_range_m,
                   settings_.perception.inflation_radius_m);
  }

  // Stable ids for the movable outlines.
  std::vector<geometry::Polygon> movable_outlines;
  std::vector<std::size_t> movable_polygons;
  for (std::size_t index = 0; index < result.polygons.size(); ++index) {
    const perception::LayerPolygon& polygon = result.polygons[index];
    if (polygon.obstacle_class == perception::ObstacleClass::Movable &&
        polygon.boundary == perception::BoundaryKind::Outer) {
      movable_outlines.push_back(polygon.vertices);
      movable_polygons.push_back(index);
    }
  }
  // An object behind a wall or door post is not missing: it keeps its id (and its waypoints, edges and
  // plans) while the vehicle drives round through a side room, instead of coming back as a new object.
  constexpr double kSightSkipM = 0.5;
  TrackingResult tracked = tracker_.update(movable_outlines, robot, [&](const geometry::Point& centroid) {
    return perception::backgroundClearAlong(perceived.layer, robot, centroid, kSightSkipM);
  });
  result.polygon_ids.assign(result.polygons.size(), 0);
  for (std::size_t outline = 0; outline < movable_polygons.size(); ++outline) {
    result.polygon_ids[movable_polygons[outline]] = tracked.polygon_ids[outline];
  }
  shapeOutlines(tracked, movable_polygons, robot, result);
  affordances_.seen(tracked.seen);
  for (const std::int64_t dropped : tracked.dropped) {
    releaseObjectSeal(dropped, true);
    interaction_.drop(dropped, global_);
    affordances_.dropped(dropped);
    outline_memory_.forget(dropped);
  }
  for (const TrackedObject& object : tracked.seen) {
    if (const std::optional<LearnedAffordance> learned = affordances_.inherit(object.id, object.centroid)) {
      interaction_.applyAffordance(object.id, true, learned->pushable, learned->physics, nullptr, global_);
      appendMessage(status.message, "object " + std::to_string(object.id) +
                                        " is where a lost object was: keeps its affordance");
    }
  }

  // Local DV-graph of this frame's obstacles.
  Clock::time_point stage_start = Clock::now();
  obstacles_.emplace(loopsOf(result.polygons, result.polygon_ids), std::nullopt,
                     settings_.graph.bucket_size_m);
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
  // Interaction: waypoints and push plans for the movable objects within reach (paper Algorithm 1).
  stage_start = Clock::now();
  if (settings_.interaction_enabled && !empty_scan) {
    InteractionFrame interaction_frame;
    interaction_frame.robot = robot;
    interaction_frame.utime = frame.utime;
    geometry::Point region_minimum = geometry::Point::Constant(std::numeric_limits<double>::infinity());
    geometry::Point region_maximum = -region_minimum;
    for (TrackedObject& object : tracked.seen) {
      if ((object.centroid - robot).norm() <= settings_.interaction.loop.reach_m) {
        for (const geometry::Point& point : object.outline) {
          region_minimum = region_minimum.cwiseMin(point);
          region_maximum = region_maximum.cwiseMax(point);
        }
      }
      interaction_frame.scene.movable.push_back(object.outline);
      interaction_frame.objects.push_back(std::move(object));
    }
    if (region_minimum.allFinite()) {
      // Everything the connectivity window and the push search can reach around the objects.
      const double margin = interaction::sceneMargin(settings_.interaction);
      interaction_frame.scene.background = occupancyRectangles(
          grid, perceived.layer.background_occupancy, region_minimum - geometry::Point::Constant(margin),
          region_maximum + geometry::Point::Constant(margin));
      interaction_.update(interaction_frame, *obstacles_, global_);
    }
  }
  status.timings.interaction_ms = millisecondsSince(stage_start);

  ++frames_;
  last_frame_utime_ = frame.utime;
  result.sequence = frames_;
  search(result);
  fillSizes(status);
  status.timings.total_ms = millisecondsSince(frame_start);
  return result;
}

void Planner::updateBackgroundMemory(const perception::PerceptionResult& perceived, FrameWork& work)
{
  const bool placed = perceived.status == perception::PerceptionStatus::Ok ||
                      perceived.status == perception::PerceptionStatus::NoObstaclePoints;
  if (!settings_.perception.remember_background || !placed) {
    return;
  }
  // What this scan's rays passed through first, then what they hit: a cell both seen through and hit
  // keeps its votes.
  const perception::ForgetStats forgotten =
      background_memory_.forgetSeenThrough(perceived.free_space, settings_.perception.carve_range_m);
  work.checked_cells = static_cast<std::int64_t>(forgotten.checked);
  work.forgotten_cells = static_cast<std::int64_t>(forgotten.forgotten);
  scan_first_mark_ = background_memory_.markCount() + 1;
  background_memory_.remember(perceived.observed_background, perceived.observed_background_heights_m);
  if (!settings_.interaction_enabled) {
    // FAR mode knows no movable objects: what it saw is an obstacle it remembers like any other (as
    // FAR's own map does), or a corridor closed by a box looks open from the room beside it.
    background_memory_.remember(perceived.observed_movable, perceived.observed_movable_heights_m);
  }
  work.remembered_cells = static_cast<std::int64_t>(background_memory_.size());
}

void Planner::shapeOutlines(TrackingResult& tracked, const std::vector<std::size_t>& movable_polygons,
                            const geometry::Point& robot, FrameResult& result)
{
  for (TrackedObject& object : tracked.seen) {
    if (!outline_memory_.enabled() && !object_seals_.holds(object.id)) {
      continue;
    }
    // An object the sensor split into several outlines is planned with their hull already; its pieces
    // stay as they are in the frame's polygons.
    std::size_t polygons = 0;
    std::size_t polygon = 0;
    for (std::size_t outline = 0; outline < movable_polygons.size(); ++outline) {
      if (tracked.polygon_ids[outline] == object.id) {
        ++polygons;
        polygon = movable_polygons[outline];
      }
    }
    if (outline_memory_.enabled()) {
      object.outline = outline_memory_.remember(object.id, object.outline, robot);
    }
    object.outline = object_seals_.grown(object.id, object.outline);
    if (polygons == 1) {
      result.polygons[polygon].vertices = object.outline;
    }
  }
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
  graph::RoutePreference preference;
  if (settings_.graph.route_preference > 0.0 && last_path_.valid && last_path_.goal_id == goal_->id) {
    preference.discount = settings_.graph.route_preference;
    preference.cap_m = settings_.graph.route_preference_cap_m;
    for (const graph::PathPoint& point : last_path_.waypoints) {
      if (point.vertex != graph::kNoVertex) {
        preference.route.push_back(point.vertex);
      }
    }
  }
  graph::WaySurcharge unseen;
  if (settings_.graph.unseen_cost > 0.0) {
    unseen = [this](const geometry::Point& from, const geometry::Point& to) {
      return settings_.graph.unseen_cost * seen_.unseenLength(from, to);
    };
  }
  // An edge the path takes may cross an obstacle seen since it was made (path_check.hpp): drop it, with
  // the other blocked edges of its two ends, and search again. Each round drops at least one edge; the
  // cap only bounds a frame's time.
  constexpr int kEdgeCheckRounds = 8;
  constexpr double kEdgeEndMarginM = 0.25;
  graph::SearchResult found;
  std::size_t dropped_edges = 0;
  for (int round = 0;; ++round) {
    const graph::SearchGraph search_graph = graph::SearchGraph::fromDvGraph(global_);
    found =
        graph::findPath(search_graph, *obstacles_, *robot_, goal_->position, scratch_, preference, unseen);
    if (found.status != graph::SearchStatus::Found || round == kEdgeCheckRounds) {
      break;
    }
    const std::vector<std::pair<graph::VertexId, graph::VertexId>> blocked =
        graph::blockedPathEdges(found.path, *obstacles_, kEdgeEndMarginM);
    if (blocked.empty()) {
      break;
    }
    // Each end once (consecutive blocked steps share one); the sweep of an end finds the path's own edge
    // again (the same test), so it needs no copy here.
    std::vector<graph::VertexId> ends;
    for (const auto& [from, to] : blocked) {
      ends.push_back(from);
      ends.push_back(to);
    }
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    for (const graph::VertexId end : ends) {
      for (const auto& [from, to] : graph::blockedEdgesOf(global_, end, *obstacles_, kEdgeEndMarginM)) {
        dropped_edges += global_.removeVisibilityEdge(from, to) ? 1 : 0;
      }
    }
  }
  if (found.status != graph::SearchStatus::Found && interaction_.liftBackoffs(&*obstacles_, global_) > 0) {
    // A back-off is for taking another way; with none, waiting gains nothing: the pushes come back now
    // (the back-offs of the goal are bounded, so this cannot repeat for ever).
    appendMessage(status.message, "no path without the objects backed off from: their pushes planned again");
    found = graph::findPath(graph::SearchGraph::fromDvGraph(global_), *obstacles_, *robot_, goal_->position,
                            scratch_, preference, unseen);
  }
  status.timings.search_ms = millisecondsSince(start);
  if (dropped_edges > 0) {
    appendMessage(status.message,
                  fmt::format("dropped {} graph edges that this frame's obstacles block", dropped_edges));
  }

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
    for (std::size_t index = 1; index < path.waypoints.size(); ++index) {
      const graph::PathPoint& point = path.waypoints[index];
      if (point.interaction == graph::kNoInteraction) {
        continue;
      }
      const StoredPush* stored = interaction_.push(point.push_plan);
      if (stored == nullptr) {
        continue;  // cannot happen: edges and plans are replaced together
      }
      PathPush push;
      push.object_id = point.object_id;
      push.from_waypoint = index - 1;
      push.to_waypoint = index;
      push.from_vertex = path.waypoints[index - 1].vertex;
      push.to_vertex = point.vertex;
      push.plan = stored->plan;
      push.affordance = stored->affordance;
      path.pushes.push_back(std::move(push));
    }
    const bool arrived = (*robot_ - found.goal).norm() <= settings_.arrival_radius_m;
    status.state = arrived ? PlannerState::Arrived : PlannerState::Planning;
  } else {
    status.state = PlannerState::NoPath;
    const std::string why = graph::describeNoPath(found);
    appendMessage(status.message,
                  std::string("search: ") + graph::toString(found.status) + (why.empty() ? "" : ": " + why));
    if (sealed_.size() > 0 || object_seals_.size() > 0) {
      // A seal is a guess from stalls (the follower may have failed at a passage the vehicle fits): with
      // no way left at all, trying a sealed passage again beats stopping. From the next frame.
      appendMessage(status.message, fmt::format("forgetting {} sealed cells of blocked passages and the "
                                                "seals kept with {} objects: no path without them",
                                                sealed_.size(), object_seals_.size()));
      sealed_ = perception::BackgroundMemory(settings_.perception.cell_size_m);
      object_seals_.clear();
    } else {
      forgetRememberedWallsForAPath(status.message);
    }
  }
  last_path_ = path;
  result.path = std::move(path);
}

void Planner::forgetRememberedWallsForAPath(std::string& message)
{
  // The walls remembered from earlier scans were drawn with the poses of their time: an estimator that
  // drifted or jumped since has them where nothing stands, and a door they close stays closed, as no
  // ray of the stopped vehicle passes through it. What the latest scan sees stays; the rest is looked at
  // again. Each time after the vehicle has moved, so a goal no way leads to ends in "no path".
  constexpr double kMovedBetweenForgetsM = 1.0;
  const bool moved =
      !last_forget_at_ || !robot_ || (*robot_ - *last_forget_at_).norm() >= kMovedBetweenForgetsM;
  if (!settings_.perception.remember_background ||
      no_path_forgets_ >= settings_.perception.no_path_forget_limit || !moved || scan_first_mark_ == 0) {
    return;
  }
  const std::size_t forgotten = background_memory_.forgetMarkedBefore(scan_first_mark_);
  if (forgotten == 0) {
    return;
  }
  ++no_path_forgets_;
  last_forget_at_ = robot_;
  appendMessage(message, fmt::format("forgetting {} remembered wall cells out of the latest scan's sight "
                                     "(time {} of {} for this goal): no path with them",
                                     forgotten, no_path_forgets_, settings_.perception.no_path_forget_limit));
}

FrameResult Planner::applyAffordance(const AffordanceUpdate& update)
{
  const Clock::time_point start = Clock::now();
  std::string problem;
  AffordanceOutcome outcome = AffordanceOutcome::UnknownObject;
  if (update.contact_not_reached) {
    return contactNotReached(update.object_id);
  }
  if (!std::isfinite(update.push_force_n) || !std::isfinite(update.affordance)) {
    problem = "affordance for object " + std::to_string(update.object_id) +
              " rejected: push_force_n and affordance must be finite";
  } else {
    interaction::ObjectPhysics physics = interaction_.physicsOf(update.object_id);
    // The mass stays the prior; the measurement moves the ground friction (what mu is).
    if (update.affordance > 0.0) {
      physics.ground_friction = update.affordance;
    } else if (update.push_force_n > 0.0 && physics.mass_kg > 0.0) {
      physics.ground_friction = update.push_force_n / (physics.mass_kg * common::kGravity);
    }
    outcome =
        interaction_.applyAffordance(update.object_id, tracker_.contains(update.object_id), update.pushable,
                                     physics, obstacles_ ? &*obstacles_ : nullptr, global_);
    if (outcome != AffordanceOutcome::UnknownObject && tracker_.contains(update.object_id)) {
      affordances_.learned(update.object_id, update.pushable, physics, tracker_.centroidOf(update.object_id));
      // Pushed, the object has moved and the gap beside it with it; unpushable, it is a wall like the seal.
      releaseObjectSeal(update.object_id, !update.pushable);
      if (!update.pushable && settings_.perception.remember_background) {
        // What the vehicle cannot move is a wall from now on, also once it is out of sight: otherwise
        // the corridor it closes looks open again from the room beside it, and the route flips each
        // time the vehicle steps through the room's door.
        background_memory_.rememberInflatedOutline(tracker_.outlineOf(update.object_id),
                                                   settings_.perception.inflation_radius_m);
      }
    }
    if (outcome == AffordanceOutcome::UnknownObject) {
      problem =
          "affordance for object " + std::to_string(update.object_id) + " rejected: no such object tracked";
    }
  }
  if (!problem.empty()) {
    ++bad_inputs_;
  }
  const double update_ms = millisecondsSince(start);
  FrameResult result = replan();
  appendMessage(result.status.message, problem);
  if (problem.empty()) {
    appendMessage(result.status.message,
                  outcome == AffordanceOutcome::Removed
                      ? "object " + std::to_string(update.object_id) + " unpushable: edges removed"
                      : "object " + std::to_string(update.object_id) + " physics updated");
  }
  result.status.timings.interaction_ms = update_ms;
  result.status.timings.total_ms += update_ms;
  return result;
}

FrameResult Planner::contactNotReached(std::int64_t object_id)
{
  // Not force evidence: the affordance, the memory of it and the object's seal stay as they are.
  const Clock::time_point start = Clock::now();
  const ContactOutcome outcome = interaction_.contactNotReached(object_id, tracker_.contains(object_id),
                                                                obstacles_ ? &*obstacles_ : nullptr, global_);
  if (outcome == ContactOutcome::UnknownObject) {
    ++bad_inputs_;
  }
  const double update_ms = millisecondsSince(start);
  FrameResult result = replan();
  appendMessage(
      result.status.message,
      outcome == ContactOutcome::UnknownObject
          ? "affordance for object " + std::to_string(object_id) + " rejected: no such object tracked"
          : "object " + std::to_string(object_id) +
                " contact not reached, still pushable: " + contactOutcomeName(outcome));
  result.status.timings.interaction_ms = update_ms;
  result.status.timings.total_ms += update_ms;
  return result;
}

FrameResult Planner::applyBlockedPassage(const BlockedPassage& passage)
{
  std::string problem;
  std::string done;
  const std::string named = fmt::format("blocked passage ({:.2f}, {:.2f}) -> ({:.2f}, {:.2f})",
                                        passage.from.x(), passage.from.y(), passage.to.x(), passage.to.y());
  if (!passage.from.allFinite() || !passage.to.allFinite()) {
    problem = "blocked passage rejected: from and to must be finite";
  } else if (!obstacles_) {
    problem = named + " rejected: no frame placed yet";
  } else if (const std::optional<PassageSeal> seal =
                 sealPassage(*obstacles_, passage.from, passage.to, settings_.perception.inflation_radius_m,
                             settings_.perception.cell_size_m)) {
    // A movable object at the vehicle's way to the point it could not reach bounds the gap: often
    // where a push left it, with its far side unseen (a face is modelled thin), so the seal can lie well
    // beyond its outline.
    std::optional<std::int64_t> beside;
    std::vector<geometry::Point> gap;
    if (settings_.interaction_enabled) {
      beside = tracker_.nearestTo(geometry::Segment{passage.from, passage.to}, kObjectBesidePassageM);
    }
    if (beside) {
      for (const geometry::Point& cell : seal->cells) {
        if (!obstacles_->isBlocked(cell)) {
          gap.push_back(cell);
        }
      }
    }
    std::string kept;
    if (beside && !gap.empty() && !interaction_.unpushable(*beside)) {
      object_seals_.bind(*beside, gap, seal->cells);
      kept = fmt::format(", kept with object {} (its outline takes in the {} free cells until it is pushed)",
                         *beside, gap.size());
    } else {
      sealed_.remember(common::Span<const geometry::Point>(seal->cells.data(), seal->cells.size()));
    }
    const std::size_t removed = removeEdgesThroughSeal(*seal, global_);
    done = fmt::format(
        "{}: sealed at ({:.2f}, {:.2f}), {:.2f} m from the nearest obstacle, {} cells, {} edges "
        "through it removed{}",
        named, seal->centre.x(), seal->centre.y(), seal->half_width_m, seal->cells.size(), removed, kept);
  } else {
    problem = named + " rejected: no free point to seal beyond the vehicle";
  }
  if (!problem.empty()) {
    ++bad_inputs_;
  }
  FrameResult result = replan();
  appendMessage(result.status.message, problem.empty() ? done : problem);
  return result;
}

void Planner::releaseObjectSeal(std::int64_t object_id, bool keep_as_wall)
{
  const std::vector<geometry::Point> cells = object_seals_.release(object_id);
  if (keep_as_wall && !cells.empty()) {
    sealed_.remember(common::Span<const geometry::Point>(cells.data(), cells.size()));
  }
}

}  // namespace ifar::planner
