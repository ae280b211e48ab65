#include "bench/scenarios/clear_pairs.hpp"

namespace ifar::scenarios {
namespace {

// The one stream every suite seed draws its block from; any fixed value would do.
constexpr std::uint64_t kPairStream = 20261202ULL;

}  // namespace

std::vector<Task> sampleClearPairs(const sim::World& world, const ScenarioMaps& maps,
                                   const ClearPairSettings& settings)
{
  if (settings.count <= 0 || settings.seed == 0) {
    return {};
  }
  const std::uint64_t blocks_before = settings.seed - 1;
  TaskSelectionSettings selection;
  selection.count = settings.count;
  selection.seed = kPairStream;
  selection.min_optimal = settings.min_optimal;
  selection.min_clearance_m = settings.min_clearance_m;
  selection.include_world_task = false;
  selection.require_achievable = true;
  selection.skip_first = static_cast<int>(blocks_before) * settings.count;
  // The blocks before this seed's are drawn too, so the attempts grow with the seed.
  selection.max_attempts = settings.max_attempts_per_pair * settings.count * static_cast<int>(settings.seed);
  return selectTasks(world, maps, selection);
}

}  // namespace ifar::scenarios
