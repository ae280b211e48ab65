#pragma once
// The planner frame pipeline without LCM: one frame (a revolution placed by its poses) in; perception
// polygons, the local DV-graph merged into the global one, and the global path out, with a status that
// carries per-stage timings and input flags. Deterministic: the same frames and goals give the same graph
// and path. Not thread safe: one thread owns a Planner (the daemon's worker).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/point.hpp"
#include "common/geometry/polygon.hpp"
#include "common/span.hpp"
#include "common/vehicle.hpp"
#include "planner/core/affordance_memory.hpp"
#include "planner/core/frame_assembler.hpp"
#include "planner/core/interaction_stage.hpp"
#include "planner/core/object_seals.hpp"
#include "planner/core/object_tracker.hpp"
#include "planner/core/outline_memory.hpp"
#include "planner/core/planner_status.hpp"
#include "planner/core/seen_space.hpp"
#include "planner/graph/dv_graph.hpp"
#include "planner/graph/obstacle_set.hpp"
#include "planner/graph/search.hpp"
#include "planner/graph/settings.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/push_plan.hpp"
#include "planner/perception/background_memory.hpp"
#include "planner/perception/local_layer.hpp"
#include "planner/perception/perception_pipeline.hpp"
#include "planner/perception/perception_settings.hpp"

namespace ifar::planner {

struct PlannerSettings {
  perception::PerceptionSettings perception;
  graph::GraphSettings graph;
  common::VehicleSettings vehicle;               // the lidar mount and point filter come from here
  double arrival_radius_m = 0.5;                 // the vehicle this close to the goal has arrived
  interaction::InteractionSettings interaction;  // from planner.yaml `interaction:` section
  bool interaction_enabled = true;               // false = "FAR mode": no interaction edges at all
};

struct Goal {
  std::int64_t id = 0;
  geometry::Point position = geometry::Point::Zero();  // world frame, metres
};

/// One interaction edge used by a path: push `object_id` from waypoint `from_waypoint` to `to_waypoint`.
struct PathPush {
  std::int64_t object_id = -1;  // stable id of the tracked movable object (same across frames)
  std::size_t from_waypoint =
      0;  // index in PlannedPath::waypoints of the topological waypoint where pushing starts
  std::size_t to_waypoint =
      0;  // index of the topological waypoint reached when the passage is open (from + 1)
  graph::VertexId from_vertex = graph::kNoVertex;
  graph::VertexId to_vertex = graph::kNoVertex;
  interaction::PushPlan plan;  // status Found; world frame
  double affordance = 0.0;     // mu the plan assumed (friction force / weight)
};

struct PlannedPath {
  bool valid = false;
  std::int64_t goal_id = 0;
  std::vector<graph::PathPoint> waypoints;  // robot first, goal last
  double length_m = 0.0;
  double cost = 0.0;
  std::vector<PathPush> pushes;  // in path order; waypoints[to_waypoint].interaction != kNoInteraction
};

struct AffordanceUpdate {
  std::int64_t object_id = -1;
  bool pushable = true;       // false: remove the object's interaction edges for good
  double push_force_n = 0.0;  // measured force to keep it sliding (<= 0: unknown)
  double affordance = 0.0;    // measured mu (<= 0: unknown)
  // The vehicle did not reach the contact: no estimate, the object stays pushable and is tried again.
  bool contact_not_reached = false;
};

/// A passage the vehicle could not get through (the executive's BLOCKED_PASSAGE): from where it stalled
/// toward the waypoint it could not reach, world frame.
struct BlockedPassage {
  geometry::Point from = geometry::Point::Zero();
  geometry::Point to = geometry::Point::Zero();
};

struct FrameResult {
  PlannerStatus status;
  std::vector<perception::LayerPolygon> polygons;  // this frame's local polygons, world frame
  std::vector<std::int64_t> polygon_ids;  // per polygon: the tracked object's stable id, 0 = background
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

  /// Walls known before the run (a map made before): the planner holds their outlines as if seen, from
  /// the next frame on, whatever `perception.remember_background` says. Movable objects do not belong
  /// here: they are tracked as seen. Their extent counts as observed map (kFlagGoalOffMap). Returns how
  /// many layer cells that was.
  std::size_t rememberKnownObstacles(common::Span<const geometry::Polygon> outlines);

  /// Updates the object's physics estimate or marks it unpushable, redoes/removes its edges and
  /// searches again at once (no frame needed). Unknown object id: counted as bad input, message says so.
  /// A contact not reached changes no estimate: see InteractionStage::contactNotReached.
  FrameResult applyAffordance(const AffordanceUpdate& update);

  /// Seals the narrowest point between passage.from and passage.to (see passage_seal.hpp): from the next
  /// frame the layer holds it like a wall and the graph routes around it. Where a movable object bounds
  /// the gap, the seal is kept with the object instead (object_seals.hpp). Searches again at once.
  /// Non-finite points, no frame yet or no free point to seal: counted as bad input, the message says why.
  FrameResult applyBlockedPassage(const BlockedPassage& passage);
  /// Background cells sealed so far (blocked passages not kept with an object).
  std::size_t sealedCells() const { return sealed_.size(); }
  /// Whether a blocked passage beside the object is kept with it (object_seals.hpp).
  bool holdsObjectSeal(std::int64_t object_id) const { return object_seals_.holds(object_id); }

  const graph::DvGraph& graph() const { return global_; }
  /// The obstacles of the last frame (what the search attaches the robot and checks paths against);
  /// empty before the first frame.
  const std::optional<graph::ObstacleSet>& observedObstacles() const { return obstacles_; }
  std::int64_t badInputs() const { return bad_inputs_; }
  /// The physics the planner assumes for a movable object (the configured prior until AFFORDANCE).
  interaction::ObjectPhysics objectPhysics(std::int64_t object_id) const
  {
    return interaction_.physicsOf(object_id);
  }
  /// How often the object got new interaction plans (cache misses taken), for diagnostics and tests.
  std::size_t interactionPlans(std::int64_t object_id) const { return interaction_.plansMade(object_id); }
  /// Whether the object is marked unpushable (by force evidence only).
  bool objectUnpushable(std::int64_t object_id) const { return interaction_.unpushable(object_id); }
  /// Whether the object's pushes are suspended after contacts not reached.
  bool objectSuspended(std::int64_t object_id) const { return interaction_.suspended(object_id); }

 private:
  /// The vehicle did not reach a contact of the object: retry or back off, then search again.
  FrameResult contactNotReached(std::int64_t object_id);
  /// Search and state for the current robot position; fills result.path and the status.
  void search(FrameResult& result);
  void fillSizes(PlannerStatus& status) const;
  /// Forgets the remembered background the scan's rays saw through, then remembers what they hit.
  void updateBackgroundMemory(const perception::PerceptionResult& perceived, FrameWork& work);
  /// With no path left: forgets the remembered walls out of the latest scan's sight when the settings allow
  /// it once more for this goal; what it did goes in `message`.
  void forgetRememberedWallsForAPath(std::string& message);
  /// Replaces each seen object's outline (and its polygon of the frame) with what the outline memory
  /// keeps of it, grown by the seal kept with it.
  void shapeOutlines(TrackingResult& tracked, const std::vector<std::size_t>& movable_polygons,
                     const geometry::Point& robot, FrameResult& result);
  /// Drops the seal kept with the object; `keep_as_wall`: its cells become an ordinary seal.
  void releaseObjectSeal(std::int64_t object_id, bool keep_as_wall);
  /// Grows the observed map's extent (kFlagGoalOffMap) to take in the box [minimum, maximum].
  void extendKnownMap(const geometry::Point& minimum, const geometry::Point& maximum);
  bool goalOnKnownMap(const geometry::Point& goal) const;

  PlannerSettings settings_;
  graph::DvGraph global_;
  ObjectTracker tracker_;
  InteractionStage interaction_;
  perception::BackgroundMemory background_memory_;
  perception::BackgroundMemory sealed_;  // passages the vehicle could not get through: walls for good
  perception::BackgroundMemory known_;   // walls known before the run (rememberKnownObstacles)
  ObjectSeals object_seals_;             // ... beside a movable object: kept with the object
  AffordanceMemory affordances_;
  OutlineMemory outline_memory_;                 // partly seen objects: the most of each one seen
  SeenSpace seen_;                               // where the scans have looked (graph.unseen_cost)
  std::optional<graph::ObstacleSet> obstacles_;  // last frame's observed obstacles, for attachment
  std::optional<Goal> goal_;
  std::optional<geometry::Point> robot_;
  // Extent of every local layer so far: the "known map" for the off-map flag.
  std::optional<std::pair<geometry::Point, geometry::Point>> known_extent_;
  graph::SearchScratch scratch_;
  PlannedPath last_path_;
  // Remembered walls forgotten for want of a path (perception.no_path_forget_limit): the first mark of the
  // latest scan (what it saw stays), how often for this goal, and where the vehicle stood the last time.
  std::uint32_t scan_first_mark_ = 0;
  int no_path_forgets_ = 0;
  std::optional<geometry::Point> last_forget_at_;
  std::int64_t frames_ = 0;
  std::int64_t bad_inputs_ = 0;
  std::int64_t last_frame_utime_ = 0;
};

}  // namespace ifar::planner
