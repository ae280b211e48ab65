#pragma once
// Hybrid A* push search for one object (paper VI.C, Problem 3). State: object pose (x, y, heading,
// discretised for duplicate detection) x contact edge. Actions: stable push primitives of fixed length
// (straight, arcs at the edge's smallest stable radius) and contact switches (drive round the object,
// collision-checked against the obstacles). Goal: the passage between the two waypoints, widened by the
// vehicle's half width, is clear of the object, the object leaves the way on open (pushed along a
// corridor it would close the corridor further on: where either side's free space reached beyond the
// surroundings before the push, the start waypoint must still reach it), and the object never ran into
// an obstacle on the way.
// Heuristic: width of the heuristic polygon (object inside the passage) by rotating calipers, plus an
// analytic straight push to the goal tried at regular intervals.
//
// With SearchSettings::corridor (corridorSearch) the search is one straight push per reachable contact
// edge, as far as the settings allow, ending where the way on beyond the object opens (wayOnBeyond).
//
// A PushPlanner is built once per object and answers the n(n-1) waypoint pairs; plan() is const.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "common/geometry/polygon.hpp"
#include "planner/interaction/convex_polygon.hpp"
#include "planner/interaction/free_space_raster.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/interaction/object_model.hpp"
#include "planner/interaction/push_plan.hpp"
#include "planner/interaction/stable_push.hpp"

namespace ifar::interaction {

struct PushProblemObject {
  geometry::Polygon object;                  ///< inflated world polygon of the pushed object
  std::vector<geometry::Polygon> obstacles;  ///< inflated world polygons it must not run into
  ObjectPhysics physics;
};

class PushPlanner {
 public:
  PushPlanner(const PushProblemObject& problem, const PusherSettings& pusher, const SearchSettings& search,
              const ConnectivitySettings& limits);

  /// Found when the object can be planned for; otherwise every plan() returns this status.
  PlanStatus status() const { return status_; }
  const ObjectModel& model() const { return model_; }
  const std::vector<EdgePushOptions>& edgeOptions() const { return options_; }

  /// Searches a push plan that opens the passage from `start` to `goal` (topological waypoints).
  PushPlan plan(const geometry::Point& start, const geometry::Point& goal) const;

 private:
  struct SwitchPath {
    std::vector<geometry::Point> samples;  ///< body frame, vehicle reference point positions
    double length = 0.0;
  };
  struct Passage;
  /// A wall perceived as a single raster cell becomes, inflated, a rectangle only about twice the
  /// inflation wide (the layer's 0.15 m cells and 0.35 m inflation: 0.75 m). No point of it lies deeper
  /// than allowed_depth_m_, so the depth test alone lets the object through it (driven Willow t0: a box
  /// turned through the corridor's east wall, seen as one cell from inside). For these the test is
  /// whether a footprint point crosses the rectangle's middle line: the face as perceived.
  struct ThinWall {
    Bounds bounds;
    geometry::Point centre;
    geometry::Vector across;  ///< unit, along the rectangle's short side
    geometry::Vector along;   ///< unit, along its long side
    double reach = 0.0;       ///< how far from the centre along the middle line the face reaches
    /// exempt[side][sample]: collision_samples_[side][sample] is not held to this face.
    std::array<std::vector<bool>, 2> exempt;
  };
  /// `obstacle` as a thin wall: a rectangle whose half width lies between `inflation` and `allowed_depth`.
  static std::optional<ThinWall> thinWall(const geometry::Polygon& obstacle, double inflation,
                                          double allowed_depth);
  /// A contact edge the vehicle reaches from the start waypoint in a straight line.
  struct Contact {
    std::size_t edge = 0;
    double approach_m = 0.0;
  };

  std::vector<Contact> reachableContacts(const geometry::Point& start) const;
  /// A control ending with the object at `end_pose`; `radius` is infinite for a straight push.
  PushControl makeControl(ControlKind kind, std::size_t edge, double distance, double radius, double force,
                          const geometry::Pose2& end_pose) const;
  /// Fills a found plan: first contact on `edge` of the unmoved object, its controls, distances and cost.
  void completePlan(PushPlan& plan, std::size_t edge, double approach_m,
                    std::vector<PushControl> controls) const;
  /// The cheapest straight push from one of `contacts` after which the passage is clear and wayOnBeyond.
  PushPlan corridorPush(PushPlan plan, const std::vector<Contact>& contacts, const Passage& passage,
                        std::size_t depth_side) const;
  /// Corridor search goal: the vehicle standing behind the object pushed from `edge` reaches at least
  /// two stretches of the edge of the object's surroundings (where it came from and a way on), so the
  /// object closes at most the branch it was pushed into.
  bool wayOnBeyond(const geometry::Pose2& pose, std::size_t edge) const;

  /// An object seen only as a face reaches `unseen_depth_m` (less where a wall stands behind its face)
  /// on either side of the face, in collision_outlines_ and collision_samples_.
  void addUnseenDepth(double unseen_depth_m, double sample_spacing_m);
  /// Whether the object moving from `from` to `to` enters an obstacle: deeper than allowed_depth_m_ at
  /// `to`, or through a thin wall's face on the way (thin_walls_); `depth_side` picks the side of the
  /// face its unseen depth lies on (0: along face_normal_).
  bool objectCollides(const geometry::Pose2& from, const geometry::Pose2& to, std::size_t depth_side) const;
  /// An object seen only as a face, with both ends of the face close to walls at `pose` and a probe
  /// length further along `depth_direction` (body frame): no arcs, they would sweep the unseen depth.
  bool turnConfined(const geometry::Pose2& pose, const geometry::Vector& depth_direction) const;
  /// Whether `world` lies inside an (inflated) obstacle, farther than `depth` from its boundary.
  bool insideDeeperThan(const geometry::Point& world, double depth) const;
  bool pointBlocked(const geometry::Point& world) const;
  bool switchFree(const geometry::Pose2& pose, const SwitchPath& path) const;
  geometry::Point standingPoint(std::size_t edge) const;
  geometry::Pose2 vehiclePose(const geometry::Pose2& object_pose, std::size_t edge) const;
  double heuristic(const geometry::Pose2& pose, const Passage& passage) const;
  /// How far the object's footprint must stay from the passage: the vehicle's half width and a margin.
  double objectClearance() const;
  bool passageClear(const geometry::Pose2& pose, const Passage& passage) const;
  /// Each stretch of the window's edge where the free space on either side of the unmoved object
  /// leaves the window: the pushed object must leave every one reachable from the start waypoint, and
  /// not much farther than with the object gone.
  void findOutlets(Passage& passage) const;
  /// How many raster cells round a waypoint findOutlets and onwardOpen look for its free cell.
  int waypointSearchCells() const;
  /// How many raster steps longer than with the object gone the way to an outlet may be: round the
  /// object and a slack.
  int onwardDetourSteps() const;
  bool onwardOpen(const geometry::Pose2& pose, const Passage& passage) const;
  bool goalReached(const geometry::Pose2& pose, const Passage& passage) const;

  PlanStatus status_ = PlanStatus::Found;
  PusherSettings pusher_;
  SearchSettings search_;
  ObjectModel model_;
  LimitSurface limit_surface_;
  std::vector<EdgePushOptions> options_;
  std::vector<geometry::Polygon> obstacles_;
  std::vector<Bounds> obstacle_bounds_;
  /// What collides, body frame: the footprint, with an object seen only as a face taken to be
  /// unseen_depth_m deep beyond the face along face_normal_ ([0]) or against it ([1]).
  std::array<geometry::Polygon, 2> collision_outlines_;
  std::array<std::vector<geometry::Point>, 2> collision_samples_;
  /// The obstacles around the object, out to beyond the farthest push, for the onward check.
  std::optional<FreeSpaceRaster> surroundings_;
  /// How deep a footprint point may sit inside an inflated obstacle.
  double allowed_depth_m_ = 0.0;
  /// The obstacles no point of which lies deeper than allowed_depth_m_: walls perceived one cell thick.
  std::vector<ThinWall> thin_walls_;
  /// Corridor search: wayOnBeyond looks this far round the object.
  double junction_margin_m_ = 0.0;
  /// Object seen only as a face: the face's two ends, body frame (turnConfined).
  std::array<geometry::Point, 2> face_ends_{};
  geometry::Vector face_normal_ = geometry::Vector::UnitY();  ///< body frame, one of the face's normals
  double heuristic_per_metre_ = 0.0;
  /// switch_paths_[from][to][direction]: driving counter-clockwise (0) or clockwise (1).
  std::vector<std::vector<std::array<SwitchPath, 2>>> switch_paths_;
};

}  // namespace ifar::interaction
