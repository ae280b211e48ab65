#pragma once
// Plain settings structs for interaction planning. Units are SI; distances are metres in the world
// frame of the local layer. Defaults match config/vehicle.yaml and the paper.

#include <cstddef>

#include "common/vehicle.hpp"

namespace ifar::interaction {

/// Connectivity analysis around one movable polygon (paper V.B).
struct ConnectivitySettings {
  /// d_thres of Eq. 1: the farthest a topological waypoint sits from the movable polygon.
  double waypoint_offset_m = 0.5;
  /// Free space is analysed in the movable polygon's bounding box grown by this margin.
  double window_margin_m = 3.0;
  /// Cell size of the free-space raster used to tell components apart.
  double raster_resolution_m = 0.05;
  /// Free boundary stretches shorter than this do not get a waypoint.
  double minimum_stretch_m = 0.05;
  /// Side of the square local layer; larger objects are rejected.
  double local_layer_size_m = 60.0;
  /// Polygons thinner than this (rotating-calipers width) or smaller in area count as degenerate.
  double minimum_width_m = 0.02;
  double minimum_area_m2 = 1e-3;
};

/// What the planner believes about one object (its push affordance), from perception and pushes.
struct ObjectPhysics {
  double ground_friction = 0.4;  ///< object-ground Coulomb coefficient
  double mass_kg = 20.0;
};

/// The pusher: a flat bumper on a differential-drive vehicle.
struct PusherSettings {
  double bumper_width_m = 0.7;
  double bumper_friction = 0.5;
  /// Distance from the bumper face back to the vehicle's reference point, the centre of the footprint on
  /// the wheel axle (vehicle.yaml); the instantaneous centre of rotation lies on the axle line.
  double bumper_to_axle_m = 0.45;
  /// Obstacles in the local layer are inflated by this (the vehicle's half width).
  double inflation_m = 0.35;
  /// Largest push force the wheels deliver before slipping.
  double max_push_force_n = 549.0;

  static PusherSettings fromVehicle(const common::VehicleSettings& vehicle);
};

/// Hybrid A* push search (paper VI.C, Problem 3).
struct SearchSettings {
  double primitive_length_m = 0.4;     ///< arc length of the vehicle reference point per push
  double position_resolution_m = 0.1;  ///< object position cell for duplicate detection
  std::size_t heading_bins = 72;       ///< object heading cells over a full turn
  double push_speed_mps = 0.3;         ///< v of the push controls
  double travel_speed_mps = 0.5;       ///< speed assumed for contact switches (duration only)
  double reference_force_n = 100.0;    ///< J = force x distance / reference force + travel, in metres
  double search_radius_m = 4.0;        ///< object centroid never leaves this disc around its start
  /// A waypoint pair the search within search_radius_m proves impossible (exhausted) is searched again
  /// within this radius; 0 = never. An object plugging a passage longer than search_radius_m can only be
  /// pushed out of its far end: inside the passage it closes the way on wherever it stands.
  double extended_search_radius_m = 0.0;
  /// A pair the searches above prove impossible (exhausted) is tried once more with one straight push per
  /// reachable contact edge, up to this far (0 = never): an object filling a corridor (a bar nearly as long
  /// as the corridor is wide) can only be pushed along it, out past the next junction, tens of metres on.
  double corridor_push_length_m = 0.0;
  /// Set by corridorSearch() only: plan() pushes straight, and the way on counts as open where the vehicle
  /// behind the pushed object can leave the object's surroundings by a second way (the object may close
  /// the branch it is pushed into).
  bool corridor = false;
  double analytic_max_distance_m = 4.0;   ///< longest straight push tried by the analytic expansion
  std::size_t analytic_interval = 4;      ///< analytic expansion every this many expansions
  double collision_step_m = 0.2;          ///< object motion between collision checks along a primitive
  double boundary_sample_m = 0.1;         ///< spacing of footprint boundary points checked for contact
  double contact_clearance_m = 0.05;      ///< vehicle keeps this from the inflated object when driving round
  double penetration_tolerance_m = 0.03;  ///< rasterisation slack when deciding the object hits a wall
  /// An object seen only as a face is taken to be this deep beyond the face (less where a wall stands
  /// behind it) when deciding whether a push runs it into a wall; 0: as thin as the face seen.
  double unseen_depth_m = 0.5;
  /// The passage counts as open only with this much room beyond the vehicle's half width: the lidar sees
  /// an object's near faces only (its hidden depth is modelled thin) and an open-loop push slips a little.
  double passage_margin_m = 0.15;
  std::size_t max_expansions = 4000;
  double time_budget_s = 0.05;
};

/// How the planner runs interaction planning each frame (planner/core).
struct PlanningLoopSettings {
  ObjectPhysics default_physics;  ///< prior for every object until AFFORDANCE says otherwise
  double frame_budget_ms = 50.0;  ///< objects not reached within this per frame are done next frame
  /// Movable objects farther than this from the vehicle get no waypoints and push plans: they block like
  /// walls until the vehicle comes this close. Beyond the graph's 25 m view radius, so a box plugging a
  /// tunnel seen 40 m up it is a push, not a dead end the vehicle turns away from for good.
  double reach_m = 50.0;
  double track_association_m = 1.0;  ///< largest centroid jump of one object between frames
  int track_drop_frames = 5;         ///< frames unseen while in view before an object is dropped
  /// An object keeps the convex hull of its outlines (a part hidden in one view shows in another) until
  /// the vehicle comes this close to it; 0: every frame's outline as seen (planner/core/outline_memory.hpp).
  double outline_memory_restart_m = 0.0;
  /// A contact the vehicle did not reach (no force evidence: the object stays pushable) is planned again at
  /// once this many times; the next report suspends the object's pushes for contact_backoff_s.
  int contact_retries = 1;
  /// How long an object whose contacts were not reached gets no push plans: time for the surroundings
  /// to change (a person, another object) or for the route round it; at the 0.5 m/s cruise about 10 m.
  double contact_backoff_s = 20.0;
  /// Back-offs per object and goal; after them the object gets no push plans until the next goal.
  int contact_backoffs = 2;
};

/// Everything one object's interaction planning needs.
struct InteractionSettings {
  ConnectivitySettings connectivity;
  PusherSettings pusher;
  SearchSettings search;
  PlanningLoopSettings loop;
};

/// The settings of the second search with extended_search_radius_m as its radius (and no further one).
SearchSettings extendedSearch(const SearchSettings& search);

/// The settings of the last search, straight pushes along a corridor up to corridor_push_length_m.
SearchSettings corridorSearch(const SearchSettings& search);

/// How far beyond the pushed object's bounds the push search's onward check looks: past the farthest a
/// push takes the object (its centroid stays within search_radius_m), so a corridor it is pushed along is
/// still closed at the edge of what is checked.
double surroundingsReach(const ConnectivitySettings& connectivity, const SearchSettings& search);

/// How far beyond the pushed object's bounds a push search with these settings looks at obstacles: the
/// surroundings, plus the vehicle standing behind the object pushed to their edge.
double obstacleReach(const ConnectivitySettings& connectivity, const SearchSettings& search,
                     const PusherSettings& pusher);

/// How far beyond the objects' bounds the scene's background must reach: the obstacle reach of the
/// widest search (the corridor or the extended one when on). A scene cut off closer leaves open space along
/// the surroundings' edge, through which every side of the object looks connected.
double sceneMargin(const InteractionSettings& settings);

}  // namespace ifar::interaction
