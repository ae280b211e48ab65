#pragma once
// The GPPC exactness run of `ifar bench-search --gppc-suite`: a MovingAI map and its .scen queries, the
// zero-inflation prior map built once, every query planned against the .scen length, and per map the
// exact count, the worst relative error, query times, build time and the graph's memory. The same run
// takes a grid and queries without reference lengths (the map-scale row: map_scale.hpp).

#include <cstddef>
#include <string>
#include <vector>

#include "common/grid_map/grid_map.hpp"
#include "common/grid_map/readers.hpp"

namespace ifar::bench {

/// A length within this relative error of the .scen value counts as exact (the files give 9 decimals).
inline constexpr double kExactRelativeTolerance = 1e-9;

struct GppcQueryMiss {
  std::size_t index = 0;  // query of the .scen file, from 0
  std::string status;     // "found" (another length) or the search status
  double length = 0.0;    // NaN when not found
  double expected = 0.0;
};

struct GppcMapResult {
  std::string map;  // file name without ".map"
  int width = 0;
  int height = 0;
  std::size_t queries = 0;
  bool reference = true;  // the queries carry optimal lengths; without them only `found` counts
  std::size_t found = 0;
  std::size_t exact = 0;
  double worst_relative_error = 0.0;  // over the queries found
  std::vector<GppcQueryMiss> misses;  // the queries that are not exact
  double median_us = 0.0;             // one query (graph::findPath): CPU time of the planning thread
  double p99_us = 0.0;
  double max_us = 0.0;
  double wall_median_us = 0.0;  // the same in wall time (a loaded machine stretches it)
  double wall_p99_us = 0.0;
  // Per query, on average: vertices expanded, and lines tested for visibility from the start and to
  // the goal (where the time goes besides the expansions).
  double mean_expansions = 0.0;
  double mean_start_tests = 0.0;
  double mean_goal_tests = 0.0;
  double build_seconds = 0.0;  // wall time: grid to prior map to search snapshot
  std::size_t vertices = 0;
  std::size_t edges = 0;
  double graph_mb = 0.0;  // heap held by the obstacle set, the DV-graph and its search snapshot
  std::string error;      // a file missing or unreadable: nothing else is set
};

/// Runs every query of `map_path` + ".scen" on the zero-inflation prior map of `map_path`.
GppcMapResult runGppcMap(const std::string& map_path);

/// Runs `queries` on the zero-inflation prior map of `map`, named `name` in the result. Without
/// `reference` the queries' optimal lengths are ignored: nothing is exact or missed, `found` counts.
GppcMapResult runGppcQueries(const std::string& name, const grid_map::GridMap& map,
                             const std::vector<grid_map::Scenario>& queries, bool reference);

/// The results as a markdown table, with a list of the queries that are not exact.
std::string gppcTable(const std::vector<GppcMapResult>& results);

/// One map's result as one JSON object (one line, no newline).
std::string gppcJsonLine(const GppcMapResult& result);

}  // namespace ifar::bench
