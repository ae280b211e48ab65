// ifar plan: the prior-map planner. Builds the DV-graph of a MovingAI .map or map_server PGM+YAML and
// answers .scen queries or one --start/--goal query. Exit codes: those of graph::exitCodeOf for the first
// query not found, else 2 on bad input or a --check mismatch, 3 when the graph could not be saved.

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/grid_map/readers.hpp"
#include "planner/graph/graph_file.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double peakMemoryMegabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in kilobytes on Linux
}

std::string number(double value)
{
  if (!std::isfinite(value)) {
    return "null";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.9f", value);
  return text;
}

std::string pointJson(const ifar::geometry::Point& point)
{
  return "[" + number(point.x()) + ", " + number(point.y()) + "]";
}

struct Query {
  ifar::geometry::Point start;
  ifar::geometry::Point goal;
  double expected = NAN;  // from the .scen file
};

constexpr int kSaveFailedExitCode = ifar::common::kOutputFailedExitCode;

const char* boolean(bool value)
{
  return value ? "true" : "false";
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Prior-map planner: builds the DV-graph of a grid map and answers path queries.\n"
      "Zero inflation follows the GPPC any-angle rules (exact cell-boundary polygons)."};
  std::string map_path;
  std::string scen_path;
  std::vector<double> start;
  std::vector<double> goal;
  double inflate = 0.0;
  bool json = false;
  bool unknown_blocked = false;
  double tolerance = 1e-6;
  std::string save_path;
  bool check = false;
  bool snap = false;
  app.add_option("--map", map_path, "MovingAI .map or map_server .yaml")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--scen", scen_path, "MovingAI .scen queries (lattice points)")->check(CLI::ExistingFile);
  ifar::common::addCoordinatesOption(app, "--start", start, "X,Y", 2, 2, "start (map units / metres)");
  ifar::common::addCoordinatesOption(app, "--goal", goal, "X,Y", 2, 2, "goal (map units / metres)");
  app.add_option("--inflate", inflate, "inflate obstacles by this radius (map units / metres)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--json", json, "one JSON object per query, then a summary line");
  app.add_flag("--unknown-blocked", unknown_blocked, "treat unknown map_server cells as blocked");
  app.add_flag("--check", check, "compare with the .scen optimal lengths; exit 2 on a mismatch");
  app.add_option("--tolerance", tolerance, "relative tolerance for --check")->check(CLI::PositiveNumber);
  app.add_option("--save-graph", save_path, "also save the built DV-graph (prior map) to this file");
  app.add_flag("--snap", snap,
               "move a start or goal inside an obstacle to the nearest free point (default: report\n"
               "start_in_obstacle / goal_in_obstacle, exit 4 / 5)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  if (scen_path.empty() && (start.size() != 2 || goal.size() != 2)) {
    std::cerr << "ifar plan: give --scen FILE or both --start X,Y and --goal X,Y\n";
    return ifar::common::kBadInputExitCode;
  }
  const auto map_result = ifar::grid_map::readGridMapFile(map_path);
  if (!map_result.ok()) {
    std::cerr << "ifar plan: " << map_result.error << "\n";
    return ifar::common::kBadInputExitCode;
  }
  std::vector<Query> queries;
  if (!scen_path.empty()) {
    const auto scenarios = ifar::grid_map::readMovingAiScenarios(scen_path);
    if (!scenarios.ok()) {
      std::cerr << "ifar plan: " << scenarios.error << "\n";
      return ifar::common::kBadInputExitCode;
    }
    for (const auto& scenario : scenarios.scenarios) {
      if (scenario.map_width != map_result.map.width() || scenario.map_height != map_result.map.height()) {
        std::cerr << "ifar plan: " << scen_path << ": query " << queries.size() << " is for a "
                  << scenario.map_width << "x" << scenario.map_height << " map, " << map_path << " is "
                  << map_result.map.width() << "x" << map_result.map.height() << "\n";
        return ifar::common::kBadInputExitCode;
      }
      // Scenario coordinates are grid lattice points; map them into the map's world frame.
      queries.push_back(Query{map_result.map.cornerToWorld(scenario.start.x(), scenario.start.y()),
                              map_result.map.cornerToWorld(scenario.goal.x(), scenario.goal.y()),
                              scenario.optimal_length * map_result.map.resolution()});
    }
  }
  if (start.size() == 2 && goal.size() == 2) {
    queries.push_back(
        Query{ifar::geometry::Point(start[0], start[1]), ifar::geometry::Point(goal[0], goal[1])});
  }

  const auto build_start = Clock::now();
  int last_percent = -1;
  const auto progress = [&](double fraction) {
    const int percent = static_cast<int>(fraction * 100.0);
    // Only long builds report, and only every 10 %.
    const double elapsed = std::chrono::duration<double>(Clock::now() - build_start).count();
    if (!json && elapsed > 1.0 && percent / 10 != last_percent / 10) {
      std::cerr << "building graph: " << percent << "%\n";
      last_percent = percent;
    }
  };
  const auto policy =
      unknown_blocked ? ifar::grid_map::UnknownPolicy::AsBlocked : ifar::grid_map::UnknownPolicy::AsFree;
  const ifar::graph::PriorMap prior = ifar::graph::buildPriorMap(map_result.map, inflate, policy, progress);
  const ifar::graph::SearchGraph search_graph =
      ifar::graph::SearchGraph::fromCompleteGraph(prior.graph, prior.obstacles);
  const double build_seconds = std::chrono::duration<double>(Clock::now() - build_start).count();
  if (!json) {
    std::cout << "graph: " << prior.graph.vertexCount() << " vertices, " << prior.graph.visibilityEdgeCount()
              << " edges, " << prior.obstacles.loops().size() << " obstacle loops, built in " << build_seconds
              << " s\n";
  }

  if (!save_path.empty()) {
    const std::string error = ifar::graph::saveGraph(prior.graph, save_path);
    if (!error.empty()) {
      std::cerr << "ifar plan: " << error << "\n";
      return kSaveFailedExitCode;
    }
  }

  const auto inside = snap ? ifar::graph::InsideObstacle::Snap : ifar::graph::InsideObstacle::Refuse;
  ifar::graph::SearchScratch scratch;
  int mismatches = 0;
  int failed_query_exit_code = 0;  // of the first query not found
  for (std::size_t index = 0; index < queries.size(); ++index) {
    const Query& query = queries[index];
    const auto query_start = Clock::now();
    const auto result = ifar::graph::findPath(search_graph, prior.obstacles, query.start, query.goal, scratch,
                                              {}, {}, inside);
    const double microseconds = std::chrono::duration<double, std::micro>(Clock::now() - query_start).count();
    const bool found = result.status == ifar::graph::SearchStatus::Found;
    if (!found && failed_query_exit_code == 0) {
      failed_query_exit_code = ifar::graph::exitCodeOf(result.status);
    }
    const double length = found ? result.length : NAN;
    bool matches = true;
    if (std::isfinite(query.expected)) {
      matches = found && std::abs(length - query.expected) <= tolerance * std::max(1.0, query.expected);
      if (!matches) {
        ++mismatches;
      }
    }
    if (json) {
      std::cout << "{\"index\": " << index << ", \"start\": " << pointJson(query.start)
                << ", \"goal\": " << pointJson(query.goal) << ", \"status\": \"" << toString(result.status)
                << "\", \"length\": " << number(length) << ", \"microseconds\": " << number(microseconds);
      if (std::isfinite(query.expected)) {
        std::cout << ", \"expected\": " << number(query.expected);
      }
      std::cout << ", \"start_snapped\": " << boolean(result.start_snapped)
                << ", \"goal_snapped\": " << boolean(result.goal_snapped) << "}\n";
    } else {
      std::cout << "query " << index << ": (" << query.start.x() << ", " << query.start.y() << ") -> ("
                << query.goal.x() << ", " << query.goal.y() << "): " << toString(result.status);
      if (found) {
        std::cout << " length " << number(length) << " via " << result.path.size() << " points, "
                  << result.expansions << " expansions, " << result.start_links << "+" << result.goal_links
                  << " links";
      }
      if (std::isfinite(query.expected)) {
        std::cout << " (expected " << number(query.expected) << (matches ? ", ok" : ", MISMATCH") << ")";
      }
      if (result.start_snapped) {
        std::cout << " [start snapped to free space]";
      }
      if (result.goal_snapped) {
        std::cout << " [goal snapped to free space]";
      }
      std::cout << " in " << microseconds << " us\n";
    }
  }
  if (json) {
    std::cout << "{\"build_seconds\": " << number(build_seconds)
              << ", \"vertices\": " << prior.graph.vertexCount()
              << ", \"edges\": " << prior.graph.visibilityEdgeCount()
              << ", \"peak_memory_mb\": " << number(peakMemoryMegabytes()) << "}\n";
  } else {
    std::cout << "peak memory " << peakMemoryMegabytes() << " MB";
    if (!scen_path.empty()) {
      std::cout << ", " << (queries.size() - static_cast<std::size_t>(mismatches)) << " of " << queries.size()
                << " lengths match the .scen file";
    }
    std::cout << "\n";
  }
  if (failed_query_exit_code != 0) {
    return failed_query_exit_code;
  }
  return check && mismatches > 0 ? ifar::common::kBadInputExitCode : 0;
}
