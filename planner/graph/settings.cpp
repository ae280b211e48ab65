#include "planner/graph/settings.hpp"

#include <cmath>

namespace ifar::graph {

GraphSettings loadGraphSettings(const common::ConfigNode& node)
{
  GraphSettings settings;
  settings.association_distance_m =
      node.optional<double>("association_distance_m", settings.association_distance_m);
  settings.votes = node.optional<int>("votes", settings.votes);
  settings.view_radius_m = node.optional<double>("view_radius_m", settings.view_radius_m);
  settings.bucket_size_m = node.optional<double>("bucket_size_m", settings.bucket_size_m);
  settings.route_preference = node.optional<double>("route_preference", settings.route_preference);
  settings.route_preference_cap_m =
      node.optional<double>("route_preference_cap_m", settings.route_preference_cap_m);
  settings.unseen_cost = node.optional<double>("unseen_cost", settings.unseen_cost);
  settings.seen_range_m = node.optional<double>("seen_range_m", settings.seen_range_m);
  if (!(std::isfinite(settings.association_distance_m) && settings.association_distance_m > 0.0)) {
    node.fail("association_distance_m", "must be a positive number of metres");
  }
  if (settings.votes < 1) {
    node.fail("votes", "must be at least 1");
  }
  if (!(std::isfinite(settings.view_radius_m) && settings.view_radius_m > 0.0)) {
    node.fail("view_radius_m", "must be a positive number of metres");
  }
  if (!(std::isfinite(settings.bucket_size_m) && settings.bucket_size_m >= 0.0)) {
    node.fail("bucket_size_m", "must be 0 (automatic) or a positive number of metres");
  }
  if (!(std::isfinite(settings.route_preference) && settings.route_preference >= 0.0 &&
        settings.route_preference <= 0.5)) {
    node.fail("route_preference", "must be a fraction from 0 (none) to 0.5");
  }
  if (!(std::isfinite(settings.route_preference_cap_m) && settings.route_preference_cap_m >= 0.0)) {
    node.fail("route_preference_cap_m", "must be 0 (no cap) or a positive number of metres");
  }
  if (!(std::isfinite(settings.unseen_cost) && settings.unseen_cost >= 0.0 && settings.unseen_cost <= 10.0)) {
    node.fail("unseen_cost", "must be 0 (off) or a positive factor up to 10");
  }
  if (!(std::isfinite(settings.seen_range_m) && settings.seen_range_m > 0.0 &&
        settings.seen_range_m <= 200.0)) {
    node.fail("seen_range_m", "must be a positive number of metres up to 200");
  }
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::graph
