#include "planner/graph/settings.hpp"

namespace ifar::graph {

const common::ParameterTable<GraphSettings>& graphParameters()
{
  using S = GraphSettings;
  using Range = common::ParameterRange;
  static const auto table =
      common::ParameterTable<S>()
          .add("association_distance_m", &S::association_distance_m, "m", Range::positive(),
               "a local vertex this close to a global one of the same kind is it")
          .add("votes", &S::votes, "", Range::atLeast(1),
               "consecutive frames unseen while in view before a vertex is removed")
          .add("view_radius_m", &S::view_radius_m, "m", Range::positive(),
               "around the vehicle: vertices inside count as in view for voting")
          .add("bucket_size_m", &S::bucket_size_m, "m", Range::nonNegative(),
               "visibility index bucket side; 0 = chosen from the edge lengths")
          .add("route_preference", &S::route_preference, "", Range::between(0.0, 0.5),
               "experimental, 0 = off: the previous route's edges cost this fraction less, so a new route "
               "must "
               "be clearly shorter to replace it")
          .add("route_preference_cap_m", &S::route_preference_cap_m, "m", Range::nonNegative(),
               "... and the whole route at most this many metres less (0 = no cap)")
          .add("unseen_cost", &S::unseen_cost, "", Range::between(0.0, 10.0),
               "experimental, 0 = off: each metre of a way through space no scan has looked at costs this "
               "much "
               "more")
          .add("seen_range_m", &S::seen_range_m, "m", Range::interval(0.0, false, 200.0, true),
               "a scan looks this far, in sight of the vehicle, for unseen_cost");
  return table;
}

GraphSettings loadGraphSettings(const common::ConfigNode& node)
{
  return graphParameters().load(node);
}

}  // namespace ifar::graph
