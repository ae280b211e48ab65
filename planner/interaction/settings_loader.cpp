#include "planner/interaction/settings_loader.hpp"

#include <string>

namespace ifar::interaction {

namespace {

using Range = common::ParameterRange;
using Table = common::ParameterTable<InteractionSettings>;

void addConnectivity(Table& table)
{
  const auto add = [&table](const std::string& key, double ConnectivitySettings::*member, const char* unit,
                            Range range, const std::string& meaning) {
    table.add(
        key, [member](auto& s) -> auto& { return s.connectivity.*member; }, unit, range, meaning);
  };
  using C = ConnectivitySettings;
  add("waypoint_offset_m", &C::waypoint_offset_m, "m", Range::positive(),
      "d_thres of Eq. 1: how far a topological waypoint sits from the object, so the vehicle ends a push "
      "clear "
      "of a doorway and can turn round the pushed object");
  add("window_margin_m", &C::window_margin_m, "m", Range::positive(),
      "free space is analysed in the object's box grown by this");
  add("raster_resolution_m", &C::raster_resolution_m, "m", Range::positive(),
      "cell of the free-space raster telling components apart");
  add("minimum_stretch_m", &C::minimum_stretch_m, "m", Range::positive(),
      "free boundary stretches shorter than this get no waypoint");
  add("local_layer_size_m", &C::local_layer_size_m, "m", Range::positive(), "larger objects are rejected");
}

void addSearch(Table& table)
{
  const auto add = [&table](const std::string& key, auto member, const char* unit, Range range,
                            const std::string& meaning) {
    table.add(
        key, [member](auto& s) -> auto& { return s.search.*member; }, unit, range, meaning);
  };
  using S = SearchSettings;
  add("primitive_length_m", &S::primitive_length_m, "m", Range::positive(),
      "arc length of one push primitive");
  add("position_resolution_m", &S::position_resolution_m, "m", Range::positive(),
      "object position cell for duplicate detection");
  add("heading_bins", &S::heading_bins, "", Range::atLeast(1), "object heading cells over a full turn");
  add("push_speed_mps", &S::push_speed_mps, "m/s", Range::positive(), "vehicle speed while pushing");
  add("travel_speed_mps", &S::travel_speed_mps, "m/s", Range::positive(),
      "vehicle speed for contact switches (duration only)");
  add("reference_force_n", &S::reference_force_n, "N", Range::positive(),
      "J = force x distance / this + travel");
  add("search_radius_m", &S::search_radius_m, "m", Range::positive(),
      "the object centroid never leaves this disc around its start");
  add("extended_search_radius_m", &S::extended_search_radius_m, "m", Range::nonNegative(),
      "a pair the near search proves impossible is searched again within this radius (0 = never; else above "
      "search_radius_m): a box plugging a passage goes out of its far end");
  add("corridor_push_length_m", &S::corridor_push_length_m, "m", Range::nonNegative(),
      "then one straight push up to this far (0 = never; else above search_radius_m): an object filling a "
      "corridor goes along it, out past the next junction");
  add("analytic_max_distance_m", &S::analytic_max_distance_m, "m", Range::positive(),
      "longest straight push tried by the analytic expansion");
  add("analytic_interval", &S::analytic_interval, "", Range::atLeast(1),
      "analytic expansion every this many expansions");
  add("max_expansions", &S::max_expansions, "", Range::atLeast(1),
      "push search expansions per waypoint pair");
  add("time_budget_s", &S::time_budget_s, "s", Range::positive(), "push search time per waypoint pair");
  add("passage_margin_m", &S::passage_margin_m, "m", Range::nonNegative(),
      "room left beyond the half width when the passage counts as open");
  add("unseen_depth_m", &S::unseen_depth_m, "m", Range::nonNegative(),
      "an object seen only by a face is taken to be this deep behind it (less where a wall stands there) "
      "when a "
      "push could run it into a wall (0: as thin as the face seen)");
}

void addLoop(Table& table)
{
  table
      .add(
          "default_mass_kg", [](auto& s) -> auto& { return s.loop.default_physics.mass_kg; }, "kg",
          Range::positive(), "physics prior of every object until AFFORDANCE")
      .add(
          "default_ground_friction", [](auto& s) -> auto& { return s.loop.default_physics.ground_friction; },
          "", Range::positive(), "prior object-ground friction coefficient (AFFORDANCE replaces it)")
      .add(
          "frame_budget_ms", [](auto& s) -> auto& { return s.loop.frame_budget_ms; }, "ms", Range::positive(),
          "interaction planning per frame; objects not reached wait (round robin)")
      .add(
          "reach_m", [](auto& s) -> auto& { return s.loop.reach_m; }, "m", Range::positive(),
          "objects farther from the vehicle get no push plans and block like walls: well beyond "
          "graph.view_radius_m, so an object plugging a corridor far ahead gets its push before the route "
          "turns away")
      .add(
          "track_association_m", [](auto& s) -> auto& { return s.loop.track_association_m; }, "m",
          Range::positive(), "largest centroid jump of one object between frames")
      .add(
          "track_drop_frames", [](auto& s) -> auto& { return s.loop.track_drop_frames; }, "",
          Range::atLeast(1),
          "frames unseen while in view (within graph.view_radius_m, no wall between) before an object and "
          "its "
          "edges go")
      .add(
          "outline_memory_restart_m", [](auto& s) -> auto& { return s.loop.outline_memory_restart_m; }, "m",
          Range::nonNegative(),
          "experimental, 0 = off: an object keeps the hull of its outlines (parts hidden in one view show in "
          "another) until the vehicle comes this close")
      .add(
          "contact_retries", [](auto& s) -> auto& { return s.loop.contact_retries; }, "",
          Range::nonNegative(),
          "a contact the vehicle did not reach is planned again at once this many times (the object stays "
          "pushable); the next report backs off")
      .add(
          "contact_backoff_s", [](auto& s) -> auto& { return s.loop.contact_backoff_s; }, "s",
          Range::positive(), "an object whose contacts were not reached gets no push plans for this long")
      .add(
          "contact_backoffs", [](auto& s) -> auto& { return s.loop.contact_backoffs; }, "",
          Range::nonNegative(),
          "back-offs per object and goal; then the object gets no push plans until the next goal");
}

Table makeInteractionParameters()
{
  Table table;
  addConnectivity(table);
  addSearch(table);
  addLoop(table);
  return table;
}

/// A wider search's reach: 0 (off) or beyond the near search's radius.
void checkOffOrBeyond(const common::ConfigNode& node, const std::string& key, double value,
                      double search_radius_m)
{
  if (!(value == 0.0 || value > search_radius_m)) {
    node.fail(key, "must be 0 (off) or larger than search_radius_m");
  }
}

}  // namespace

const common::ParameterTable<InteractionSettings>& interactionParameters()
{
  static const Table table = makeInteractionParameters();
  return table;
}

InteractionSettings loadInteractionSettings(const common::ConfigNode& node,
                                            const common::VehicleSettings& vehicle)
{
  InteractionSettings settings;
  settings.pusher = PusherSettings::fromVehicle(vehicle);
  interactionParameters().read(node, settings);
  checkOffOrBeyond(node, "extended_search_radius_m", settings.search.extended_search_radius_m,
                   settings.search.search_radius_m);
  checkOffOrBeyond(node, "corridor_push_length_m", settings.search.corridor_push_length_m,
                   settings.search.search_radius_m);
  node.rejectUnknownKeys();
  return settings;
}

}  // namespace ifar::interaction
