#include "bench/search_comparison/gppc_suite.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bench/baselines/cpu_clock.hpp"
#include "common/grid_map/readers.hpp"
#include "common/json_text.hpp"
#include "common/percentile.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace ifar::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kBytesPerMegabyte = 1024.0 * 1024.0;

std::string baseName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.rfind(".map");
  return dot == std::string::npos ? name : name.substr(0, dot);
}

/// `value` with `digits` decimals, in scientific notation when `scientific`; `missing` when not finite
/// ("null" in JSON, "-" in the table).
std::string formatted(double value, int digits, const char* missing = "null", bool scientific = false)
{
  if (!std::isfinite(value)) {
    return missing;
  }
  char text[64];
  if (scientific) {
    std::snprintf(text, sizeof(text), "%.*e", digits, value);
  } else {
    std::snprintf(text, sizeof(text), "%.*f", digits, value);
  }
  return text;
}

}  // namespace

GppcMapResult runGppcMap(const std::string& map_path)
{
  GppcMapResult result;
  result.map = baseName(map_path);
  const auto map = grid_map::readMovingAiMap(map_path);
  if (!map.ok()) {
    result.error = map.error;
    return result;
  }
  const auto scenarios = grid_map::readMovingAiScenarios(map_path + ".scen");
  if (!scenarios.ok()) {
    result.error = scenarios.error;
    return result;
  }
  return runGppcQueries(result.map, map.map, scenarios.scenarios, true);
}

GppcMapResult runGppcQueries(const std::string& name, const grid_map::GridMap& map,
                             const std::vector<grid_map::Scenario>& queries, bool reference)
{
  GppcMapResult result;
  result.map = name;
  result.reference = reference;
  result.worst_relative_error = reference ? 0.0 : NAN;
  result.width = map.width();
  result.height = map.height();

  const auto build_began = Clock::now();
  const graph::PriorMap prior = graph::buildPriorMap(map, 0.0);
  const graph::SearchGraph search_graph = graph::SearchGraph::fromCompleteGraph(prior.graph, prior.obstacles);
  result.build_seconds = std::chrono::duration<double>(Clock::now() - build_began).count();
  result.vertices = prior.graph.vertexCount();
  result.edges = prior.graph.visibilityEdgeCount();
  result.graph_mb = static_cast<double>(prior.obstacles.memoryBytes() + prior.graph.memoryBytes() +
                                        search_graph.memoryBytes()) /
                    kBytesPerMegabyte;

  graph::SearchScratch scratch;
  const auto plan = [&](const grid_map::Scenario& scenario) {
    // .scen coordinates are lattice points (the map's world frame: resolution 1, origin 0 for a .map).
    return graph::findPath(search_graph, prior.obstacles,
                           map.cornerToWorld(scenario.start.x(), scenario.start.y()),
                           map.cornerToWorld(scenario.goal.x(), scenario.goal.y()), scratch, {}, {},
                           graph::InsideObstacle::Refuse);
  };
  if (!queries.empty()) {
    plan(queries.front());  // untimed: the scratch grows and the arrays are touched once
  }
  std::vector<double> cpu_microseconds;
  std::vector<double> wall_microseconds;
  cpu_microseconds.reserve(queries.size());
  wall_microseconds.reserve(queries.size());
  for (std::size_t index = 0; index < queries.size(); ++index) {
    const auto& scenario = queries[index];
    const auto began = Clock::now();
    const double began_cpu_ms = baselines::threadCpuMilliseconds();
    const graph::SearchResult found = plan(scenario);
    result.mean_expansions += static_cast<double>(found.expansions);
    result.mean_start_tests += static_cast<double>(found.start_tests);
    result.mean_goal_tests += static_cast<double>(found.goal_tests);
    cpu_microseconds.push_back(1e3 * (baselines::threadCpuMilliseconds() - began_cpu_ms));
    wall_microseconds.push_back(std::chrono::duration<double, std::micro>(Clock::now() - began).count());
    const bool solved = found.status == graph::SearchStatus::Found;
    result.found += solved ? 1 : 0;
    if (!reference) {
      continue;
    }
    const double expected = scenario.optimal_length;
    const double relative_error =
        solved ? std::abs(found.length - expected) / std::max(expected, 1e-12) : INFINITY;
    if (solved) {
      result.worst_relative_error = std::max(result.worst_relative_error, relative_error);
    }
    if (relative_error <= kExactRelativeTolerance) {
      ++result.exact;
    } else {
      result.misses.push_back(
          GppcQueryMiss{index, graph::toString(found.status), solved ? found.length : NAN, expected});
    }
  }
  result.queries = queries.size();
  if (result.queries > 0) {
    const double count = static_cast<double>(result.queries);
    result.mean_expansions /= count;
    result.mean_start_tests /= count;
    result.mean_goal_tests /= count;
  }
  result.median_us = common::nearestRankPercentile(cpu_microseconds, 50.0);
  result.p99_us = common::nearestRankPercentile(cpu_microseconds, 99.0);
  result.max_us = common::nearestRankPercentile(cpu_microseconds, 100.0);
  result.wall_median_us = common::nearestRankPercentile(wall_microseconds, 50.0);
  result.wall_p99_us = common::nearestRankPercentile(wall_microseconds, 99.0);
  return result;
}

std::string gppcTable(const std::vector<GppcMapResult>& results)
{
  std::ostringstream table;
  table << "| map | size | queries | exact | worst relative error | median µs | p99 µs | max µs | wall "
           "median / "
           "p99 µs | build s | vertices | edges | graph MB |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const GppcMapResult& result : results) {
    if (!result.error.empty()) {
      table << "| " << result.map << " | " << result.error << " ||||||||||||\n";
      continue;
    }
    const std::string exact = result.reference ? std::to_string(result.exact)
                                               : "no reference, " + std::to_string(result.found) + " found";
    table << "| " << result.map << " | " << result.width << "x" << result.height << " | " << result.queries
          << " | " << exact << " | " << formatted(result.worst_relative_error, 1, "-", true) << " | "
          << formatted(result.median_us, 1, "-") << " | " << formatted(result.p99_us, 1, "-") << " | "
          << formatted(result.max_us, 1, "-") << " | " << formatted(result.wall_median_us, 1, "-") << " / "
          << formatted(result.wall_p99_us, 1, "-") << " | " << formatted(result.build_seconds, 3, "-")
          << " | " << result.vertices << " | " << result.edges << " | " << formatted(result.graph_mb, 1, "-")
          << " |\n";
  }
  for (const GppcMapResult& result : results) {
    for (const GppcQueryMiss& miss : result.misses) {
      table << "\nNot exact: " << result.map << " query " << miss.index << ": " << miss.status << ", length "
            << formatted(miss.length, 9) << ", expected " << formatted(miss.expected, 9) << "\n";
    }
  }
  return table.str();
}

std::string gppcJsonLine(const GppcMapResult& result)
{
  std::ostringstream line;
  line << "{\"map\": " << common::jsonString(result.map);
  if (!result.error.empty()) {
    line << ", \"error\": " << common::jsonString(result.error) << "}";
    return line.str();
  }
  line << ", \"width\": " << result.width << ", \"height\": " << result.height
       << ", \"queries\": " << result.queries << ", \"found\": " << result.found
       << ", \"exact\": " << (result.reference ? std::to_string(result.exact) : "null")
       << ", \"worst_relative_error\": " << formatted(result.worst_relative_error, 3, "null", true)
       << ", \"median_us\": " << formatted(result.median_us, 3)
       << ", \"p99_us\": " << formatted(result.p99_us, 3) << ", \"max_us\": " << formatted(result.max_us, 3)
       << ", \"wall_median_us\": " << formatted(result.wall_median_us, 3)
       << ", \"wall_p99_us\": " << formatted(result.wall_p99_us, 3)
       << ", \"mean_expansions\": " << formatted(result.mean_expansions, 1)
       << ", \"mean_start_tests\": " << formatted(result.mean_start_tests, 1)
       << ", \"mean_goal_tests\": " << formatted(result.mean_goal_tests, 1)
       << ", \"build_seconds\": " << formatted(result.build_seconds, 4)
       << ", \"vertices\": " << result.vertices << ", \"edges\": " << result.edges
       << ", \"graph_mb\": " << formatted(result.graph_mb, 3) << ", \"not_exact\": [";
  for (std::size_t slot = 0; slot < result.misses.size(); ++slot) {
    const GppcQueryMiss& miss = result.misses[slot];
    line << (slot == 0 ? "" : ", ") << "{\"index\": " << miss.index
         << ", \"status\": " << common::jsonString(miss.status)
         << ", \"length\": " << formatted(miss.length, 9) << ", \"expected\": " << formatted(miss.expected, 9)
         << "}";
  }
  line << "]}";
  return line.str();
}

}  // namespace ifar::bench
