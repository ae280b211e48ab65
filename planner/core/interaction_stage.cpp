#include "planner/core/interaction_stage.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "planner/interaction/graph_edges.hpp"

namespace ifar::planner {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

const char* contactOutcomeName(ContactOutcome outcome)
{
  switch (outcome) {
    case ContactOutcome::Retried:
      return "planned again";
    case ContactOutcome::BackedOff:
      return "no push plans for a while";
    case ContactOutcome::SuspendedGoal:
      return "no push plans until the next goal";
    case ContactOutcome::Unpushable:
      return "already unpushable";
    case ContactOutcome::UnknownObject:
      return "no such object tracked";
  }
  return "unknown";
}

InteractionStage::InteractionStage(const interaction::InteractionSettings& settings, double outline_cell_m)
    : settings_(settings), cache_(settings, outline_cell_m)
{
}

InteractionStage::ObjectState& InteractionStage::stateOf(std::int64_t object_id)
{
  const auto found = objects_.find(object_id);
  if (found != objects_.end()) {
    return found->second;
  }
  ObjectState state;
  state.physics = settings_.loop.default_physics;
  return objects_.emplace(object_id, state).first->second;
}

interaction::ObjectPhysics InteractionStage::physicsOf(std::int64_t object_id) const
{
  const auto found = objects_.find(object_id);
  return found != objects_.end() ? found->second.physics : settings_.loop.default_physics;
}

bool InteractionStage::unpushable(std::int64_t object_id) const
{
  const auto found = objects_.find(object_id);
  return found != objects_.end() && found->second.unpushable;
}

bool InteractionStage::suspendedAt(const ObjectState& state, std::int64_t utime) const
{
  return state.suspended_for_goal || utime < state.suspended_until_us;
}

bool InteractionStage::suspended(std::int64_t object_id) const
{
  const auto found = objects_.find(object_id);
  return found != objects_.end() && suspendedAt(found->second, last_frame_ ? last_frame_->utime : 0);
}

std::size_t InteractionStage::liftBackoffs(const graph::ObstacleSet* obstacles, graph::DvGraph& graph)
{
  const std::int64_t now_us = last_frame_ ? last_frame_->utime : 0;
  std::vector<std::int64_t> lifted;
  for (auto& [object_id, state] : objects_) {
    if (!state.unpushable && !state.suspended_for_goal && now_us < state.suspended_until_us) {
      state.suspended_until_us = 0;
      lifted.push_back(object_id);
    }
  }
  for (const std::int64_t object_id : lifted) {
    reprocess(object_id, obstacles, graph);
  }
  return lifted.size();
}

void InteractionStage::startGoal()
{
  for (auto& [object_id, state] : objects_) {
    state.contacts_not_reached = 0;
    state.backoffs = 0;
    state.suspended_until_us = 0;
    state.suspended_for_goal = false;
  }
}

std::size_t InteractionStage::plansMade(std::int64_t object_id) const
{
  const auto found = objects_.find(object_id);
  return found != objects_.end() ? found->second.plans_made : 0;
}

const StoredPush* InteractionStage::push(std::uint32_t handle) const
{
  const auto found = pushes_.find(handle);
  return found != pushes_.end() ? &found->second : nullptr;
}

void InteractionStage::removeFromGraph(ObjectState& state, std::int64_t object_id, graph::DvGraph& graph)
{
  graph.removeInteractionEdges(object_id);
  for (const graph::VertexId vertex : state.waypoints) {
    graph.removeVertex(vertex);
  }
  for (const std::uint32_t handle : state.handles) {
    pushes_.erase(handle);
  }
  state.waypoints.clear();
  state.handles.clear();
  state.inserted = false;
}

void InteractionStage::drop(std::int64_t object_id, graph::DvGraph& graph)
{
  const auto found = objects_.find(object_id);
  if (found != objects_.end()) {
    removeFromGraph(found->second, object_id, graph);
    // An unpushable object stays known so its id is never planned for again.
    if (!found->second.unpushable) {
      objects_.erase(found);
    }
  }
  cache_.forget(object_id);
}

void InteractionStage::link(const ObjectState& state, const graph::ObstacleSet& obstacles,
                            graph::DvGraph& graph) const
{
  const double reach_m = settings_.loop.reach_m;
  for (const graph::VertexId waypoint : state.waypoints) {
    const graph::Vertex* from = graph.vertex(waypoint);
    if (from == nullptr) {
      continue;
    }
    const geometry::Point position = from->position;
    // Links are redone from scratch: the corners around the waypoint change as the map grows.
    const std::vector<graph::VisibilityLink> old_links = graph.visibilityLinks(waypoint);
    for (const graph::VisibilityLink& old_link : old_links) {
      graph.removeVisibilityEdge(waypoint, old_link.other);
    }
    graph::BlockerCache blockers;
    for (const graph::Vertex& other : graph.vertexSlots()) {
      if (!other.alive || other.id == waypoint || (other.position - position).norm() > reach_m) {
        continue;
      }
      if (other.kind == graph::VertexKind::Corner &&
          !graph::isTangent(graph::LoopCorner{other.position, other.previous, other.next, 0},
                            other.position - position)) {
        continue;
      }
      if (obstacles.visible(position, other.position, blockers)) {
        graph.addVisibilityEdge(waypoint, other.id);
      }
    }
  }
}

void InteractionStage::process(const InteractionFrame& frame, std::size_t index,
                               const graph::ObstacleSet& obstacles, graph::DvGraph& graph,
                               InteractionStats& stats)
{
  const std::int64_t object_id = frame.objects[index].id;
  ObjectState& state = stateOf(object_id);
  if (state.unpushable) {
    return;
  }
  if (suspendedAt(state, frame.utime)) {
    if (state.inserted) {
      removeFromGraph(state, object_id, graph);
    }
    return;
  }
  ++stats.processed;
  bool replanned = false;
  const interaction::ObjectInteractions& interactions =
      cache_.interactionsFor(object_id, frame.scene, index, state.physics, replanned);
  if (replanned) {
    ++stats.replanned;
    ++state.plans_made;
  }
  const bool waypoints_alive = std::all_of(state.waypoints.begin(), state.waypoints.end(),
                                           [&](graph::VertexId vertex) { return graph.contains(vertex); });
  if (replanned || !state.inserted || !waypoints_alive) {
    removeFromGraph(state, object_id, graph);
    const std::uint32_t first_handle = next_handle_;
    const interaction::InsertedInteractions inserted =
        interaction::insertInteractions(graph, object_id, interactions, first_handle);
    next_handle_ += static_cast<std::uint32_t>(interactions.plans.size());
    for (std::size_t plan = 0; plan < interactions.plans.size(); ++plan) {
      if (interactions.plans[plan].plan.status == interaction::PlanStatus::Found) {
        const std::uint32_t handle = first_handle + static_cast<std::uint32_t>(plan);
        pushes_[handle] = StoredPush{object_id, interactions.plans[plan].plan, state.physics.ground_friction};
        state.handles.push_back(handle);
      }
    }
    state.waypoints = inserted.waypoint_vertices;
    state.inserted = true;
    ++stats.reinserted;
  }
  link(state, obstacles, graph);
}

InteractionStats InteractionStage::update(const InteractionFrame& frame, const graph::ObstacleSet& obstacles,
                                          graph::DvGraph& graph)
{
  const Clock::time_point start = Clock::now();
  InteractionStats stats;
  // The merge votes on every vertex in view, and nothing observes a waypoint: keep them alive here.
  for (auto& [object_id, state] : objects_) {
    for (const graph::VertexId vertex : state.waypoints) {
      if (graph.contains(vertex)) {
        graph.setUnseenVotes(vertex, 0);
      } else {
        state.inserted = false;
      }
    }
  }
  std::vector<std::size_t> order;
  for (std::size_t index = 0; index < frame.objects.size(); ++index) {
    if ((frame.objects[index].centroid - frame.robot).norm() <= settings_.loop.reach_m &&
        !unpushable(frame.objects[index].id)) {
      order.push_back(index);
    }
  }
  stats.candidates = order.size();
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return frame.objects[a].id < frame.objects[b].id; });
  // Round robin: start where the last frame's budget ran out.
  const auto first = std::find_if(order.begin(), order.end(),
                                  [&](std::size_t index) { return frame.objects[index].id >= next_object_; });
  std::rotate(order.begin(), first, order.end());
  next_object_ = 0;
  for (std::size_t position = 0; position < order.size(); ++position) {
    if (position > 0 && millisecondsSince(start) >= settings_.loop.frame_budget_ms) {
      next_object_ = frame.objects[order[position]].id;
      break;
    }
    process(frame, order[position], obstacles, graph, stats);
  }
  last_frame_ = frame;
  return stats;
}

AffordanceOutcome InteractionStage::applyAffordance(std::int64_t object_id, bool known, bool pushable,
                                                    const interaction::ObjectPhysics& physics,
                                                    const graph::ObstacleSet* obstacles,
                                                    graph::DvGraph& graph)
{
  if (!known && objects_.count(object_id) == 0) {
    return AffordanceOutcome::UnknownObject;
  }
  ObjectState& state = stateOf(object_id);
  if (!pushable) {
    removeFromGraph(state, object_id, graph);
    state.unpushable = true;
    cache_.forget(object_id);
    return AffordanceOutcome::Removed;
  }
  if (state.unpushable) {
    return AffordanceOutcome::Removed;  // never pushable again: a later estimate does not bring it back
  }
  state.physics = physics;
  reprocess(object_id, obstacles, graph);
  return AffordanceOutcome::Updated;
}

void InteractionStage::reprocess(std::int64_t object_id, const graph::ObstacleSet* obstacles,
                                 graph::DvGraph& graph)
{
  cache_.invalidate(object_id);
  removeFromGraph(stateOf(object_id), object_id, graph);
  if (last_frame_ && obstacles != nullptr) {
    for (std::size_t index = 0; index < last_frame_->objects.size(); ++index) {
      if (last_frame_->objects[index].id == object_id) {
        InteractionStats stats;
        process(*last_frame_, index, *obstacles, graph, stats);
        break;
      }
    }
  }
}

ContactOutcome InteractionStage::contactNotReached(std::int64_t object_id, bool known,
                                                   const graph::ObstacleSet* obstacles, graph::DvGraph& graph)
{
  if (!known && objects_.count(object_id) == 0) {
    return ContactOutcome::UnknownObject;
  }
  ObjectState& state = stateOf(object_id);
  if (state.unpushable) {
    return ContactOutcome::Unpushable;
  }
  const interaction::PlanningLoopSettings& loop = settings_.loop;
  ++state.contacts_not_reached;
  if (state.contacts_not_reached <= loop.contact_retries) {
    // A new plan from the scene as it is now: the vehicle has moved, and the search may take another face.
    reprocess(object_id, obstacles, graph);
    return ContactOutcome::Retried;
  }
  state.contacts_not_reached = 0;
  removeFromGraph(state, object_id, graph);
  cache_.invalidate(object_id);
  if (state.backoffs >= loop.contact_backoffs) {
    state.suspended_for_goal = true;
    return ContactOutcome::SuspendedGoal;
  }
  ++state.backoffs;
  const std::int64_t now_us = last_frame_ ? last_frame_->utime : 0;
  state.suspended_until_us = now_us + static_cast<std::int64_t>(loop.contact_backoff_s * 1e6);
  return ContactOutcome::BackedOff;
}

}  // namespace ifar::planner
