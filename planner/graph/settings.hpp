#pragma once
// Settings of the DV-graph: the `graph:` section of config/planner.yaml.

#include "common/config.hpp"
#include "common/parameters.hpp"

namespace ifar::graph {

struct GraphSettings {
  /// A local vertex within this distance of a global one of the same kind is the same vertex (metres).
  double association_distance_m = 0.5;
  /// A global vertex inside the sensor's view that goes unobserved this many consecutive frames is removed.
  int votes = 10;
  /// Radius around the robot inside which vertices count as "in view" for voting (metres); vertices
  /// farther away are kept as they are.
  double view_radius_m = 25.0;
  /// Side of the visibility index's buckets (metres); 0 picks one from the obstacle edges.
  double bucket_size_m = 0.0;
  /// The previous route's edges cost this fraction less in the next search (0 .. 0.5, 0 = off): a new
  /// route must be clearly shorter to replace it, so two ways of nearly equal length do not take turns.
  double route_preference = 0.0;
  /// ... but all of them together at most this many metres less, from the route's first arcs on (0: no
  /// cap): a fraction alone of a long route can hold the vehicle on it past a shorter turn.
  double route_preference_cap_m = 0.0;
  /// Each metre of a way through space no scan has looked at costs this much more (0 = off): unseen space
  /// is attemptable, but a way through it is a guess, and a seen way of the same length is not.
  double unseen_cost = 0.0;
  /// A scan looks this far (metres) for unseen_cost's map of what was seen.
  double seen_range_m = 15.0;
};

/// planner.yaml `graph:` keys, every one optional.
const common::ParameterTable<GraphSettings>& graphParameters();

/// Reads the `graph` section (`node` is that section). Every key is optional with the defaults above;
/// unknown keys and out-of-range values throw common::ConfigError naming the key.
GraphSettings loadGraphSettings(const common::ConfigNode& node);

}  // namespace ifar::graph
