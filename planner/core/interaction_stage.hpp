#pragma once
// The planner's interaction step (paper Algorithm 1, lines 4-10) between the merge and the search: for
// the tracked movable objects within reach, ask the InteractionCache for their push plans within a
// per-frame time budget (round robin over frames), put the waypoints and interaction edges into the
// global graph, link the waypoints to the vertices they see, and keep the push plans beside the graph
// under the handles the edges carry. Also the object's physics estimate (AFFORDANCE) and the objects
// found unpushable.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "common/geometry/point.hpp"
#include "planner/core/object_tracker.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/interaction/connectivity.hpp"
#include "planner/interaction/interaction_cache.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_plan.hpp"

namespace ifar::planner {

/// A push plan kept beside the graph; InteractionEdge::push_plan is its handle.
struct StoredPush {
  std::int64_t object_id = 0;
  interaction::PushPlan plan;
  double affordance = 0.0;  // ground friction coefficient the plan assumed
};

/// One frame's input: the objects seen and the scene they lie in (scene.movable[i] is objects[i]).
struct InteractionFrame {
  std::vector<TrackedObject> objects;
  interaction::LocalScene scene;
  geometry::Point robot = geometry::Point::Zero();
  std::int64_t utime = 0;  // the scan's time, microseconds: back-offs run on it
};

struct InteractionStats {
  std::size_t candidates = 0;  // objects within reach
  std::size_t processed = 0;   // asked the cache this frame (the rest wait for the next frame)
  std::size_t replanned = 0;   // cache misses whose new plans were taken
  std::size_t reinserted = 0;  // edges put into the graph again
};

enum class AffordanceOutcome { Updated, Removed, UnknownObject };

/// What the planner did with a contact the vehicle did not reach.
enum class ContactOutcome {
  Retried,        ///< planned again at once (another contact when the search finds one)
  BackedOff,      ///< no push plans for contact_backoff_s
  SuspendedGoal,  ///< no push plans until the next goal (contact_backoffs used up)
  Unpushable,     ///< already known unpushable: nothing changes
  UnknownObject,
};

const char* contactOutcomeName(ContactOutcome outcome);

class InteractionStage {
 public:
  /// `outline_cell_m`: the raster cell the objects' and obstacles' outlines are traced on.
  InteractionStage(const interaction::InteractionSettings& settings, double outline_cell_m);

  /// After the merge: keeps the waypoints alive, plans within the budget, updates the graph.
  InteractionStats update(const InteractionFrame& frame, const graph::ObstacleSet& obstacles,
                          graph::DvGraph& graph);

  /// Removes everything of an object the tracker dropped (waypoints, edges, plans, cache entry).
  void drop(std::int64_t object_id, graph::DvGraph& graph);

  /// Changes the object's physics (or removes it for good when not pushable) and redoes its edges from
  /// the last frame's scene at once. `known` tells whether the caller tracks the id.
  AffordanceOutcome applyAffordance(std::int64_t object_id, bool known, bool pushable,
                                    const interaction::ObjectPhysics& physics,
                                    const graph::ObstacleSet* obstacles, graph::DvGraph& graph);

  /// The vehicle did not reach a contact of the object (AFFORDANCE "contact not reached"): a reachability
  /// failure, so the object stays pushable. Plans again at once loop.contact_retries times, then backs
  /// off (no push plans for loop.contact_backoff_s), at most loop.contact_backoffs times per goal.
  ContactOutcome contactNotReached(std::int64_t object_id, bool known, const graph::ObstacleSet* obstacles,
                                   graph::DvGraph& graph);
  /// A new goal: objects suspended for the last one get push plans again.
  void startGoal();
  /// Ends every running back-off (not the suspensions until the next goal) and plans those objects again
  /// from the last frame's scene, when there is one. Returns how many.
  std::size_t liftBackoffs(const graph::ObstacleSet* obstacles, graph::DvGraph& graph);
  /// True while the object gets no push plans after contacts not reached.
  bool suspended(std::int64_t object_id) const;

  /// The physics the planner currently assumes for the object (the prior for unknown ids).
  interaction::ObjectPhysics physicsOf(std::int64_t object_id) const;
  bool unpushable(std::int64_t object_id) const;
  const StoredPush* push(std::uint32_t handle) const;
  /// Plans the cache has taken so far for the object (cache misses, less the replans it kept plans against).
  std::size_t plansMade(std::int64_t object_id) const;

 private:
  struct ObjectState {
    interaction::ObjectPhysics physics;
    std::vector<graph::VertexId> waypoints;
    std::vector<std::uint32_t> handles;
    bool inserted = false;
    bool unpushable = false;
    std::size_t plans_made = 0;
    int contacts_not_reached = 0;         // since the last back-off
    int backoffs = 0;                     // this goal
    std::int64_t suspended_until_us = 0;  // no push plans before this scan time
    bool suspended_for_goal = false;      // no push plans until the next goal
  };

  /// Replans the object from the last frame's scene (after its estimate changed), when there is one.
  void reprocess(std::int64_t object_id, const graph::ObstacleSet* obstacles, graph::DvGraph& graph);
  bool suspendedAt(const ObjectState& state, std::int64_t utime) const;

  /// Asks the cache for objects[index] and puts the result into the graph when it changed.
  void process(const InteractionFrame& frame, std::size_t index, const graph::ObstacleSet& obstacles,
               graph::DvGraph& graph, InteractionStats& stats);
  void removeFromGraph(ObjectState& state, std::int64_t object_id, graph::DvGraph& graph);
  /// Visibility edges from the object's waypoints to every vertex they see within loop.reach_m.
  void link(const ObjectState& state, const graph::ObstacleSet& obstacles, graph::DvGraph& graph) const;
  ObjectState& stateOf(std::int64_t object_id);

  interaction::InteractionSettings settings_;
  interaction::InteractionCache cache_;
  std::map<std::int64_t, ObjectState> objects_;
  std::map<std::uint32_t, StoredPush> pushes_;
  std::uint32_t next_handle_ = 0;
  std::int64_t next_object_ = 0;  // round robin: the first object id to visit next frame
  std::optional<InteractionFrame> last_frame_;
};

}  // namespace ifar::planner
