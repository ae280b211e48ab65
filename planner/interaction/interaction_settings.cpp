#include "planner/interaction/interaction_settings.hpp"

#include <algorithm>

namespace ifar::interaction {

PusherSettings PusherSettings::fromVehicle(const common::VehicleSettings& vehicle)
{
  PusherSettings pusher;
  pusher.bumper_width_m = vehicle.bumper_width_m;
  pusher.bumper_friction = vehicle.bumper_friction;
  // vehicle.yaml puts the reference point at the centre of the footprint, on the wheel axle.
  pusher.bumper_to_axle_m = vehicle.length_m / 2.0;
  pusher.inflation_m = vehicle.width_m / 2.0;
  pusher.max_push_force_n = vehicle.maxPushForce();
  return pusher;
}

SearchSettings extendedSearch(const SearchSettings& search)
{
  SearchSettings extended = search;
  extended.search_radius_m = std::max(search.search_radius_m, search.extended_search_radius_m);
  extended.extended_search_radius_m = 0.0;
  extended.corridor_push_length_m = 0.0;
  return extended;
}

SearchSettings corridorSearch(const SearchSettings& search)
{
  SearchSettings corridor = extendedSearch(search);
  corridor.search_radius_m = std::max(corridor.search_radius_m, search.corridor_push_length_m);
  corridor.corridor = true;
  return corridor;
}

double surroundingsReach(const ConnectivitySettings& connectivity, const SearchSettings& search)
{
  if (search.corridor) {
    // The way on is judged round the object where the push leaves it, twice the connectivity window out:
    // past a junction about as wide as the object is long.
    return search.search_radius_m + 2.0 * connectivity.window_margin_m;
  }
  return std::max(connectivity.window_margin_m, search.search_radius_m + 1.0);
}

double obstacleReach(const ConnectivitySettings& connectivity, const SearchSettings& search,
                     const PusherSettings& pusher)
{
  return surroundingsReach(connectivity, search) + pusher.bumper_to_axle_m + pusher.inflation_m;
}

double sceneMargin(const InteractionSettings& settings)
{
  const double widest =
      obstacleReach(settings.connectivity, extendedSearch(settings.search), settings.pusher);
  if (settings.search.corridor_push_length_m <= 0.0) {
    return widest;
  }
  return std::max(widest,
                  obstacleReach(settings.connectivity, corridorSearch(settings.search), settings.pusher));
}

}  // namespace ifar::interaction
