#include "planner/interaction/settings_loader.hpp"

#include <cmath>
#include <string>

namespace ifar::interaction {

namespace {

void readPositive(const common::ConfigNode& node, const std::string& key, double& value)
{
  value = node.optional<double>(key, value);
  if (!(std::isfinite(value) && value > 0.0)) {
    node.fail(key, "must be a positive number");
  }
}

void readCount(const common::ConfigNode& node, const std::string& key, std::size_t& value)
{
  const int read = node.optional<int>(key, static_cast<int>(value));
  if (read < 1) {
    node.fail(key, "must be at least 1");
  }
  value = static_cast<std::size_t>(read);
}

/// A wider search's reach: 0 (off) or beyond the near search's radius.
void readOffOrBeyond(const common::ConfigNode& node, const std::string& key, double search_radius_m,
                     double& value)
{
  value = node.optional<double>(key, value);
  if (!(std::isfinite(value) && (value == 0.0 || value > search_radius_m))) {
    node.fail(key, "must be 0 (off) or larger than search_radius_m");
  }
}

}  // namespace

InteractionSettings loadInteractionSettings(const common::ConfigNode& node,
                                            const common::VehicleSettings& vehicle)
{
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(vehicle);
  ConnectivitySettings& connectivity = settings.connectivity;
  readPositive(node, "waypoint_offset_m", connectivity.waypoint_offset_m);
  readPositive(node, "window_margin_m", connectivity.window_margin_m);
  readPositive(node, "raster_resolution_m", connectivity.raster_resolution_m);
  readPositive(node, "minimum_stretch_m", connectivity.minimum_stretch_m);
  readPositive(node, "local_layer_size_m", connectivity.local_layer_size_m);
  SearchSettings& search = settings.search;
  readPositive(node, "primitive_length_m", search.primitive_length_m);
  readPositive(node, "position_resolution_m", search.position_resolution_m);
  readCount(node, "heading_bins", search.heading_bins);
  readPositive(node, "push_speed_mps", search.push_speed_mps);
  readPositive(node, "travel_speed_mps", search.travel_speed_mps);
  readPositive(node, "reference_force_n", search.reference_force_n);
  readPositive(node, "search_radius_m", search.search_radius_m);
  readOffOrBeyond(node, "extended_search_radius_m", search.search_radius_m, search.extended_search_radius_m);
  readOffOrBeyond(node, "corridor_push_length_m", search.search_radius_m, search.corridor_push_length_m);
  readPositive(node, "analytic_max_distance_m", search.analytic_max_distance_m);
  readCount(node, "analytic_interval", search.analytic_interval);
  readCount(node, "max_expansions", search.max_expansions);
  readPositive(node, "time_budget_s", search.time_budget_s);
  search.passage_margin_m = node.optional<double>("passage_margin_m", search.passage_margin_m);
  if (!(std::isfinite(search.passage_margin_m) && search.passage_margin_m >= 0.0)) {
    node.fail("passage_margin_m", "must be a number >= 0");
  }
  search.unseen_depth_m = node.optional<double>("unseen_depth_m", search.unseen_depth_m);
  if (!(std::isfinite(search.unseen_depth_m) && search.unseen_depth_m >= 0.0)) {
    node.fail("unseen_depth_m", "must be a number >= 0 (0: as thin as the face seen)");
  }
  PlanningLoopSettings& loop = settings.loop;
  readPositive(node, "default_mass_kg", loop.default_physics.mass_kg);
  readPositive(node, "default_ground_friction", loop.default_physics.ground_friction);
  readPositive(node, "frame_budget_ms", loop.frame_budget_ms);
  readPositive(node, "reach_m", loop.reach_m);
  readPositive(node, "track_association_m", loop.track_association_m);
  std::size_t drop_frames = static_cast<std::size_t>(loop.track_drop_frames);
  readCount(node, "track_drop_frames", drop_frames);
  loop.track_drop_frames = static_cast<int>(drop_frames);
  loop.outline_memory_restart_m =
      node.optional<double>("outline_memory_restart_m", loop.outline_memory_restart_m);
  if (!(std::isfinite(loop.outline_memory_restart_m) && loop.outline_memory_restart_m >= 0.0)) {
    node.fail("outline_memory_restart_m", "must be a number >= 0 (0: off)");
  }
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::interaction
