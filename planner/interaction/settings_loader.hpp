#pragma once
// Reads the `interaction:` section of config/planner.yaml into InteractionSettings. The pusher part comes
// from vehicle.yaml (bumper width and friction, half width, traction limit); the section can only tune
// connectivity and search. Every key is optional with the defaults in interaction_settings.hpp.
//
//   interaction:
//     waypoint_offset_m: 0.5       # d_thres of Eq. 1
//     window_margin_m: 3.0
//     raster_resolution_m: 0.05
//     primitive_length_m: 0.4
//     heading_bins: 72
//     reference_force_n: 100.0     # J = force x distance / this + travel
//     max_expansions: 4000
//     time_budget_s: 0.05
//     default_mass_kg: 20.0        # physics prior per object until AFFORDANCE
//     default_ground_friction: 0.4
//     frame_budget_ms: 50.0        # interaction planning per frame; the rest waits (round robin)
//     track_association_m: 1.0     # object tracking across frames
//     track_drop_frames: 5

#include "common/config.hpp"
#include "common/parameters.hpp"
#include "common/vehicle.hpp"
#include "planner/interaction/interaction_settings.hpp"

namespace ifar::interaction {

/// planner.yaml `interaction:` keys of the interaction planner, every one optional.
const common::ParameterTable<InteractionSettings>& interactionParameters();

/// `node` is the `interaction` section. Unknown keys and out-of-range values throw common::ConfigError
/// naming the key.
InteractionSettings loadInteractionSettings(const common::ConfigNode& node,
                                            const common::VehicleSettings& vehicle);

}  // namespace ifar::interaction
