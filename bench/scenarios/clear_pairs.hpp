#pragma once
// Start/goal pairs in open space on a map nobody here made: both ends at least `min_clearance_m` from the
// nearest obstacle (measured on the rasterised static obstacles, whose cells cover every obstacle, so the
// true clearance is never less), a known-map path between them (the achievable way) and an exact optimum
// longer than `min_optimal`.
//
// Seeding: every suite seed draws from one fixed stream of candidate pairs, and seed s takes the qualifying
// pairs (s-1) x count .. s x count - 1 of it, as the generated kinds take world seeds 2s-1 and 2s: at the
// same count no two seeds share a pair, so seed 2 validates on pairs seed 1 never tuned on, and a seed's
// pairs depend only on the seed, the count and the map.

#include <cstdint>
#include <vector>

#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/task_selection.hpp"
#include "sim/world/world.hpp"

namespace ifar::scenarios {

struct ClearPairSettings {
  int count = 20;
  std::uint64_t seed = 1;  // suite seed, >= 1
  double min_clearance_m = 1.0;
  double min_optimal = 10.0;  // strictly longer than this
  int max_attempts_per_pair = 2000;
};

/// Up to `count` pairs (fewer when the map runs out within the attempts), ids "t0", "t1", ...
std::vector<Task> sampleClearPairs(const sim::World& world, const ScenarioMaps& maps,
                                   const ClearPairSettings& settings);

}  // namespace ifar::scenarios
