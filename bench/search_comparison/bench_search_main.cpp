// ifar bench-search: runs grid A*, RRT*, BIT* and ours (the DV-graph search, FAR mode on a static map)
// on the same queries of one map and prints per query and planner: success, length, exact optimum and
// time; then median and p99 per planner (Table I). With --gppc-suite: ours on the GPPC maps and their
// .scen lengths instead, per map exactness, query and build times and memory (gppc_suite.hpp).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/baselines/cpu_clock.hpp"
#include "bench/baselines/grid_astar.hpp"
#include "bench/baselines/sampling_planners.hpp"
#include "bench/search_comparison/gppc_suite.hpp"
#include "bench/search_comparison/map_scale.hpp"
#include "bench/search_comparison/query_set.hpp"
#include "common/command_line.hpp"
#include "common/grid_map/readers.hpp"
#include "common/json_text.hpp"
#include "common/percentile.hpp"
#include "planner/graph/prior_map.hpp"
#include "planner/graph/search.hpp"
#include "sim/generators/generators.hpp"
#include "sim/world/world_raster.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace baselines = ifar::baselines;

const std::vector<std::string> kPlanners{"grid_astar", "rrt_star", "bit_star", "ours"};

struct Row {
  std::string planner;
  std::string task;
  bool success = false;
  double length = NAN;
  double optimal = NAN;
  double milliseconds = 0.0;  // planner-thread CPU time
  double wall_milliseconds = 0.0;
  std::string status;
  std::string reason;
};

std::string number(double value)
{
  if (!std::isfinite(value)) {
    return "null";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f", value);
  return text;
}

std::string baseName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

std::vector<std::string> splitList(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty()) {
      items.push_back(item);
    }
  }
  return items;
}

// The maps of --gppc-suite under the shared data folder: GPPC's own, then the three gppc-extra ones.
const std::vector<std::string> kGppcMaps{"gppc/AcrosstheCape.map", "gppc-extra/den520d.map",
                                         "gppc-extra/ArcticStation.map", "gppc-extra/Nightshade.map"};

// The map-scale row: the densest of them (most corners per cell) repeated to 1024 x 1024 cells, the size
// of large field maps, queried between seeded free cells (no reference lengths exist for it).
const std::string kMapScaleTile = "gppc-extra/ArcticStation.map";
constexpr int kMapScaleCells = 1024;
constexpr std::size_t kMapScaleQueries = 1000;
constexpr std::uint32_t kMapScaleSeed = 1;

ifar::bench::GppcMapResult runMapScaleRow(const std::string& data_folder)
{
  const std::string tile_path = data_folder + "/" + kMapScaleTile;
  const auto tile = ifar::grid_map::readMovingAiMap(tile_path);
  if (!tile.ok()) {
    ifar::bench::GppcMapResult result;
    result.map = kMapScaleTile + " repeated";
    result.error = tile.error;
    return result;
  }
  const auto map = ifar::bench::tiledMap(tile.map, kMapScaleCells, kMapScaleCells);
  std::ostringstream name;
  name << baseName(kMapScaleTile) << " repeated to " << kMapScaleCells << "x" << kMapScaleCells;
  return ifar::bench::runGppcQueries(
      name.str(), map, ifar::bench::seededFreeCellQueries(map, kMapScaleQueries, kMapScaleSeed), false);
}

std::string firstValueOf(const std::string& path, const std::string& key)
{
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? "" : line.substr(colon + 2);
    }
  }
  return "";
}

/// "CPU model, N cores, load average L; YYYY-MM-DD HH:MM UTC": what the times were measured on.
std::string machineAndDate()
{
  const unsigned cores = std::thread::hardware_concurrency();
  double load = NAN;
  std::ifstream("/proc/loadavg") >> load;
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char date[32];
  std::strftime(date, sizeof(date), "%Y-%m-%d %H:%M UTC", &parts);
  std::ostringstream text;
  text << firstValueOf("/proc/cpuinfo", "model name") << ", " << cores << " cores, load average " << load
       << " at the start; " << date;
  return text.str();
}

/// --gppc-suite: every map in kGppcMaps under `data_folder`, results into `results_folder`/gppc.md and
/// gppc.jsonl. Exit 0 when every query is exact, 1 when one is not, 2 when a file is missing or bad.
int runGppcSuite(const std::string& data_folder, const std::string& results_folder, const std::string& commit,
                 const std::string& command)
{
  const std::string header = machineAndDate();
  std::vector<ifar::bench::GppcMapResult> results;
  bool every_file = true;
  bool every_query_exact = true;
  for (const std::string& map : kGppcMaps) {
    std::cerr << "ifar bench-search: " << map << " ...\n";
    std::string map_path = data_folder;
    map_path.append("/").append(map);
    results.push_back(ifar::bench::runGppcMap(map_path));
    const auto& result = results.back();
    if (!result.error.empty()) {
      std::cerr << "ifar bench-search: " << result.error << "\n";
      every_file = false;
    }
    every_query_exact = every_query_exact && result.exact == result.queries;
  }
  std::cerr << "ifar bench-search: " << kMapScaleTile << " repeated to " << kMapScaleCells << "x"
            << kMapScaleCells << " ...\n";
  results.push_back(runMapScaleRow(data_folder));
  if (!results.back().error.empty()) {
    std::cerr << "ifar bench-search: " << results.back().error << "\n";
    every_file = false;
  }
  std::ostringstream markdown;
  markdown << "# GPPC any-angle maps: exactness, query and build time, memory\n\n"
           << "Machine: " << header << ". Commit: " << commit << ".\nCommand: `" << command << "`\n\n"
           << "Exact: within a relative 1e" << std::lround(std::log10(ifar::bench::kExactRelativeTolerance))
           << " of the .scen length. Query times: one graph::findPath, CPU time of the planning thread "
              "(wall time beside it; nearest-rank percentiles). Build: grid to prior map (every core) to "
              "search snapshot, wall. Graph MB: heap held by the obstacle set, the DV-graph and its search "
              "snapshot. The last row has no .scen: "
           << kMapScaleQueries
           << " queries between free cells "
              "drawn with seed "
           << kMapScaleSeed << ", counted as found or not.\n\n"
           << ifar::bench::gppcTable(results);
  std::cout << markdown.str();
  std::error_code error;
  std::filesystem::create_directories(results_folder, error);
  std::ofstream table_file(results_folder + "/gppc.md");
  std::ofstream json_file(results_folder + "/gppc.jsonl");
  table_file << markdown.str();
  for (const auto& result : results) {
    json_file << ifar::bench::gppcJsonLine(result) << "\n";
  }
  if (!table_file || !json_file) {
    std::cerr << "ifar bench-search: --results: cannot write into '" << results_folder << "'\n";
    return ifar::common::kBadInputExitCode;
  }
  std::cerr << "ifar bench-search: wrote " << results_folder << "/gppc.md and gppc.jsonl\n";
  if (!every_file) {
    return ifar::common::kBadInputExitCode;
  }
  return every_query_exact ? 0 : 1;
}

Row fromBaseline(const std::string& planner, const std::string& task, double optimal,
                 const baselines::BaselineResult& result)
{
  return Row{planner,
             task,
             result.solved(),
             result.length,
             optimal,
             result.milliseconds,
             result.wall_milliseconds,
             baselines::toString(result.status),
             result.reason};
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Search-time comparison on one map: grid A* (8-connected, dense grid), OMPL RRT* and BIT*\n"
      "(exact segment collision checks, run until within --factor of the optimum or --time-cap),\n"
      "and ours (DV-graph A* on the prior map). The optimum is the exact zero-inflation length."};
  std::string map_path;
  std::string world_kind_text;
  std::uint64_t world_seed = 1;
  double resolution = 0.15;
  std::string scen_path;
  int query_count = 10;
  std::uint64_t seed = 1;
  std::string planner_list = "grid_astar,rrt_star,bit_star,ours";
  bool json = false;
  double inflate = 0.0;
  double min_length = 0.0;
  bool unknown_free = false;
  bool gppc_suite = false;
  std::string data_folder = "../shared/data";
  std::string results_folder = "bench/results/search";
  std::string commit = "unknown";
  baselines::SamplingSettings sampling;
  auto* map_option =
      app.add_option("--map", map_path, "MovingAI .map or map_server .yaml")->check(CLI::ExistingFile);
  auto* world_option = app.add_option("--world", world_kind_text,
                                      "generated world instead of a map: room | office | tunnel ...");
  map_option->excludes(world_option);
  app.add_option("--world-seed", world_seed, "generator seed for --world")->capture_default_str();
  app.add_option("--resolution", resolution, "cell size (m) for rasterising --world")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--scen", scen_path, "MovingAI .scen queries (lattice points) instead of random ones")
      ->check(CLI::ExistingFile);
  app.add_option("--queries", query_count,
                 "number of queries (first N of --scen, or random; a --world adds its own start->goal tasks)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--seed", seed, "seed for random queries and OMPL")->capture_default_str();
  app.add_option("--planners", planner_list, "comma-separated: grid_astar,rrt_star,bit_star,ours")
      ->capture_default_str();
  app.add_flag("--json", json, "one JSON object per row on stdout (summary table goes to stderr)");
  app.add_option("--inflate", inflate, "inflate obstacles by this radius (m) for every planner")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--min-length", min_length, "random queries: minimum optimal length (m)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--time-cap", sampling.time_cap_s, "RRT*/BIT* time cap per query (s)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--factor", sampling.optimum_factor, "RRT*/BIT* stop within this factor of the optimum")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  app.add_flag("--unknown-free", unknown_free, "treat unknown map_server cells as free (default: blocked)");
  auto* gppc_option = app.add_flag(
      "--gppc-suite", gppc_suite,
      "instead: ours on the GPPC map and the three gppc-extra maps with their .scen lengths; per map\n"
      "exact count, worst relative error, median/p99 query time, build time, graph memory; then\n"
      "ArcticStation repeated to 1024x1024 with seeded queries (build time and memory at map scale);\n"
      "writes gppc.md and gppc.jsonl into --results (exit 1 when a query is not exact)");
  gppc_option->excludes(map_option)->excludes(world_option);
  app.add_option("--data", data_folder, "--gppc-suite: the shared data folder (gppc/, gppc-extra/)")
      ->capture_default_str();
  app.add_option("--results", results_folder, "--gppc-suite: folder for gppc.md and gppc.jsonl")
      ->capture_default_str();
  app.add_option("--commit", commit, "--gppc-suite: commit named in gppc.md")->capture_default_str();
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  if (gppc_suite) {
    std::ostringstream command;
    for (int index = 0; index < argc; ++index) {
      command << (index == 0 ? "" : " ") << argv[index];
    }
    return runGppcSuite(data_folder, results_folder, commit, command.str());
  }

  const std::vector<std::string> planners = splitList(planner_list);
  for (const std::string& planner : planners) {
    if (std::find(kPlanners.begin(), kPlanners.end(), planner) == kPlanners.end()) {
      std::cerr << "ifar bench-search: --planners: unknown planner '" << planner
                << "' (known: grid_astar, rrt_star, bit_star, ours)\n";
      return 1;
    }
  }
  const auto policy =
      unknown_free ? ifar::grid_map::UnknownPolicy::AsFree : ifar::grid_map::UnknownPolicy::AsBlocked;

  // The map every planner sees.
  ifar::grid_map::GridMap map;
  std::string world_name;
  std::vector<ifar::bench::Query> world_tasks;  // a generated world's own start -> goal tasks
  if (!map_path.empty()) {
    auto read = ifar::grid_map::readGridMapFile(map_path);
    if (!read.ok()) {
      std::cerr << "ifar bench-search: " << read.error << "\n";
      return 1;
    }
    map = std::move(read.map);
    world_name = baseName(map_path);
  } else if (!world_kind_text.empty()) {
    const auto kind = ifar::sim::parseWorldKind(world_kind_text);
    if (!kind) {
      std::cerr << "ifar bench-search: --world: unknown kind '" << world_kind_text << "'\n";
      return 1;
    }
    const ifar::sim::WorldResult world = ifar::sim::generateWorld(*kind, world_seed);
    if (!world.ok()) {
      std::cerr << "ifar bench-search: " << world.error() << "\n";
      return 1;
    }
    map = ifar::sim::rasterizeStaticObstacles(world.world(), resolution);
    world_name = world_kind_text + "-" + std::to_string(world_seed);
    for (const ifar::sim::Goal& goal : world.world().goals) {
      world_tasks.push_back(
          ifar::bench::Query{"goal:" + goal.name, world.world().start.position(), goal.position, NAN});
    }
  } else {
    std::cerr << "ifar bench-search: give --map FILE or --world KIND\n";
    return 1;
  }

  const auto build_began = Clock::now();
  const ifar::graph::PriorMap exact = ifar::graph::buildPriorMap(map, 0.0, policy);
  std::optional<ifar::graph::PriorMap> inflated_prior;
  if (inflate > 0.0) {
    inflated_prior.emplace(ifar::graph::buildPriorMap(map, inflate, policy));
  }
  const ifar::graph::PriorMap& planning = inflated_prior ? *inflated_prior : exact;
  const ifar::graph::SearchGraph planning_graph = ifar::graph::SearchGraph::fromDvGraph(planning.graph);
  const double build_seconds = std::chrono::duration<double>(Clock::now() - build_began).count();
  const ifar::grid_map::GridMap planning_grid = inflate > 0.0 ? map.inflated(inflate, policy) : map;
  std::cerr << world_name << ": " << map.width() << " x " << map.height() << " cells of " << map.resolution()
            << " m; DV-graph " << planning.graph.vertexCount() << " vertices, "
            << planning.graph.visibilityEdgeCount() << " edges (built in " << build_seconds << " s)\n";

  std::vector<ifar::bench::Query> queries;
  bool queries_missing = false;
  if (!scen_path.empty()) {
    const auto scenarios = ifar::grid_map::readMovingAiScenarios(scen_path);
    if (!scenarios.ok()) {
      std::cerr << "ifar bench-search: " << scenarios.error << "\n";
      return 1;
    }
    for (std::size_t index = 0; index < scenarios.scenarios.size() && static_cast<int>(index) < query_count;
         ++index) {
      const auto& scenario = scenarios.scenarios[index];
      const ifar::geometry::Point start = map.cornerToWorld(scenario.start.x(), scenario.start.y());
      const ifar::geometry::Point goal = map.cornerToWorld(scenario.goal.x(), scenario.goal.y());
      queries.push_back(ifar::bench::Query{"scen" + std::to_string(index), start, goal,
                                           ifar::bench::exactOptimum(exact, start, goal)});
    }
  } else {
    // The world's own tasks first (their optimum on the rasterised static map), then random ones.
    for (ifar::bench::Query& task : world_tasks) {
      task.optimal = ifar::bench::exactOptimum(exact, task.start, task.goal);
      queries.push_back(task);
    }
    ifar::bench::RandomQuerySettings settings;
    settings.count = query_count;
    settings.seed = seed;
    settings.min_length = min_length;
    const std::vector<ifar::bench::Query> random =
        ifar::bench::randomQueries(planning_grid, policy, planning, exact, settings);
    queries.insert(queries.end(), random.begin(), random.end());
    if (static_cast<int>(random.size()) < query_count) {
      queries_missing = true;
      std::cerr << "ifar bench-search: only " << random.size() << " of " << query_count
                << " random queries found (connected, optimum >= " << min_length << " m)\n";
    }
  }

  baselines::seedSamplingPlanners(seed);
  baselines::GridAStar grid_search(planning_grid, policy);
  ifar::graph::SearchScratch scratch;
  // One untimed run of the deterministic searches first, so the first timed query does not pay for
  // cold caches and first-touch page faults of the search arrays.
  if (!queries.empty()) {
    grid_search.findPath(queries.front().start, queries.front().goal);
    ifar::graph::findPath(planning_graph, planning.obstacles, queries.front().start, queries.front().goal,
                          scratch);
  }
  std::vector<Row> rows;
  bool planner_error = false;
  for (const ifar::bench::Query& query : queries) {
    // The sampling planners' target: the factor times the optimum on the map they plan in.
    double planning_optimum = query.optimal;
    if (inflate > 0.0) {
      planning_optimum =
          ifar::graph::findPath(planning_graph, planning.obstacles, query.start, query.goal, scratch).length;
    }
    for (const std::string& planner : planners) {
      Row row;
      if (planner == "ours") {
        const auto began = Clock::now();
        const double began_cpu = baselines::threadCpuMilliseconds();
        const auto result =
            ifar::graph::findPath(planning_graph, planning.obstacles, query.start, query.goal, scratch);
        const double milliseconds = baselines::threadCpuMilliseconds() - began_cpu;
        const double wall = std::chrono::duration<double, std::milli>(Clock::now() - began).count();
        const bool found = result.status == ifar::graph::SearchStatus::Found;
        row = Row{planner,
                  query.task,
                  found,
                  found ? result.length : NAN,
                  query.optimal,
                  milliseconds,
                  wall,
                  found ? "solved" : ifar::graph::toString(result.status),
                  ""};
      } else if (planner == "grid_astar") {
        const auto began = Clock::now();
        const double began_cpu = baselines::threadCpuMilliseconds();
        baselines::BaselineResult result = grid_search.findPath(query.start, query.goal);
        result.milliseconds = baselines::threadCpuMilliseconds() - began_cpu;
        result.wall_milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - began).count();
        row = fromBaseline(planner, query.task, query.optimal, result);
      } else {
        const auto algorithm = planner == "rrt_star" ? baselines::SamplingAlgorithm::RrtStar
                                                     : baselines::SamplingAlgorithm::BitStar;
        const auto result = baselines::planSampling(algorithm, planning.obstacles, query.start, query.goal,
                                                    planning_optimum, sampling);
        row = fromBaseline(planner, query.task, query.optimal, result);
      }
      planner_error = planner_error || row.status == "error";
      if (json) {
        std::cout << "{\"planner\": " << ifar::common::jsonString(row.planner)
                  << ", \"world\": " << ifar::common::jsonString(world_name)
                  << ", \"task\": " << ifar::common::jsonString(row.task)
                  << ", \"success\": " << (row.success ? "true" : "false")
                  << ", \"length\": " << number(row.length) << ", \"optimal\": " << number(row.optimal)
                  << ", \"ms\": " << number(row.milliseconds)
                  << ", \"wall_ms\": " << number(row.wall_milliseconds)
                  << ", \"status\": " << ifar::common::jsonString(row.status)
                  << ", \"reason\": " << ifar::common::jsonString(row.reason) << "}\n";
      } else {
        std::printf("%-6s %-10s %-7s length %10s optimal %10s %10.3f ms %s\n", row.task.c_str(),
                    row.planner.c_str(), row.success ? "ok" : row.status.c_str(), number(row.length).c_str(),
                    number(row.optimal).c_str(), row.milliseconds, row.reason.c_str());
      }
      std::cout.flush();
      rows.push_back(row);
    }
  }

  // Summary (CPU ms of the planner thread): times over every query (a failure counts with the time it used,
  // e.g. the cap), and the mean length over the optimum on the solved ones.
  std::ostream& summary = json ? std::cerr : std::cout;
  char line[256];
  std::snprintf(line, sizeof(line), "\n%-10s %8s %12s %12s %12s %10s\n", "planner", "success", "median ms",
                "p99 ms", "max ms", "len/opt");
  summary << world_name << ", " << queries.size() << " queries, planner-thread CPU time" << line;
  for (const std::string& planner : planners) {
    std::vector<double> times;
    int successes = 0;
    double ratio_sum = 0.0;
    int ratio_count = 0;
    for (const Row& row : rows) {
      if (row.planner != planner) {
        continue;
      }
      times.push_back(row.milliseconds);
      if (row.success) {
        ++successes;
        if (std::isfinite(row.optimal) && row.optimal > 0.0) {
          ratio_sum += row.length / row.optimal;
          ++ratio_count;
        }
      }
    }
    const std::string success_text = std::to_string(successes) + "/" + std::to_string(times.size());
    std::snprintf(
        line, sizeof(line), "%-10s %8s %12.3f %12.3f %12.3f %10.3f\n", planner.c_str(), success_text.c_str(),
        ifar::common::nearestRankPercentile(times, 50.0), ifar::common::nearestRankPercentile(times, 99.0),
        ifar::common::nearestRankPercentile(times, 100.0), ratio_count > 0 ? ratio_sum / ratio_count : NAN);
    summary << line;
  }
  if (planner_error) {
    return 2;
  }
  return queries_missing ? 3 : 0;
}
