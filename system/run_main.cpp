// ifar-run WORLD --goal X,Y: the headless runner. The simulator and every daemon's node core in one process
// on simulated time, deterministic and faster than real time. Progress goes to stderr about once per
// simulated second; the summary to stdout (with --json as one JSON object on the last line).
// Exit code 0 when the vehicle arrived, 1 when it did not, 2 on bad input (world, goal, config), 3 when a
// picture cannot be written (docs/cli.md).

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/config_search.hpp"
#include "sim/generators/generators.hpp"
#include "sim/importers/import_command_line.hpp"
#include "sim/importers/world_loader.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/world/world_file.hpp"
#include "system/graph_picture.hpp"
#include "system/run_config.hpp"
#include "system/run_picture.hpp"
#include "system/scenario_runner.hpp"
#include "system/summary_json.hpp"

namespace {

constexpr int kExitArrived = 0;
constexpr int kExitNotArrived = 1;
constexpr int kExitBadInput = 2;

/// --print-config: every file's effective settings on stdout.
int printConfig(const std::string& config_dir)
{
  try {
    std::cout << ifar::runner::runConfigYaml(config_dir) << std::flush;
    return 0;
  } catch (const ifar::common::ConfigError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return kExitBadInput;
  }
}

/// A world file or a map the importers read (namosim .svg, MovingAI .map, map_server .yaml), else a world
/// of that name on the configuration search path (worlds/NAME.yaml), else a builtin world or a generator
/// kind of that name. The error names the input.
ifar::sim::WorldLoad loadWorld(const std::string& name, std::uint64_t seed,
                               const ifar::sim::WorldImportSettings& settings)
{
  if (const auto found = ifar::common::findNamedInput(name, "worlds")) {
    return ifar::sim::loadAnyWorld(found->path, settings);
  }
  if (!std::filesystem::exists(name)) {
    ifar::sim::WorldLoad named;
    ifar::sim::World builtin;
    if (ifar::sim::builtinWorldByName(name, builtin)) {
      named.world = ifar::sim::WorldResult::success(std::move(builtin));
      return named;
    }
    if (const auto kind = ifar::sim::parseWorldKind(name)) {
      named.world = ifar::sim::generateWorld(*kind, seed);
      return named;
    }
  }
  return ifar::sim::loadAnyWorld(name, settings);
}

/// Why a picture cannot be written to `path` (its folder missing, not a folder or not writable), checked
/// before a run of minutes whose picture would otherwise be lost at its end; empty when it can.
std::string outputPathProblem(const std::string& path)
{
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string folder = parent.empty() ? "." : parent.string();
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    return "folder '" + folder + "' does not exist or is not a folder";
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    return "folder '" + folder + "' is not writable";
  }
  return {};
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "Headless runner: the simulator and the daemons' cores (drivers, planner, executive) in one process on "
      "simulated time (deterministic, faster than real time).\nExit code 0 when the vehicle arrived, 1 when "
      "it did not, 2 on bad input, 3 when a picture cannot be written."};
  std::string world_name;
  std::vector<double> goal;  // X,Y, empty when not given
  double max_time_s = 300.0;
  bool no_interaction = false;
  bool json = false;
  std::string png_path;
  std::string graph_png_path;
  double graph_at_s = 0.0;
  std::string config_dir;  // "" = the configuration search path alone
  app.add_option(
      "world", world_name,
      "World file (YAML, docs/worlds.md), namosim .svg, MovingAI .map or map_server .yaml; else a world's "
      "name in worlds/ on the configuration search path (demo_room, office, ...), a builtin (room, "
      "push_light, push_heavy, tunnel) or a generated kind (room, room_objects, office, tunnel, demo_room)");
  ifar::sim::ImportCommandLine import_options;
  ifar::sim::addImportOptions(app, import_options);
  ifar::common::addCoordinatesOption(app, "--goal", goal, "X,Y", 2, 2,
                                     "Goal in metres (default: the world's first goal)");
  bool all_goals = false;
  app.add_flag(
      "--all-goals", all_goals,
      "Drive to every goal of the world in order, each sent when the one before is reached (a row per "
      "goal in the summary)");
  app.add_option("--max-time", max_time_s, "Simulated seconds before the run counts as failed")
      ->capture_default_str();
  app.add_flag("--no-interaction", no_interaction, "FAR mode: plan without interaction edges (never push)");
  bool known_map = false;
  app.add_flag("--known-map", known_map,
               "The planner knows the world's walls before the run (movable objects are still found by the "
               "lidar)");
  app.add_flag("--json", json, "Print the summary as one JSON object on the last line of stdout");
  app.add_option("--png", png_path, "Write a picture of the world, trajectory and final object poses");
  app.add_option(
      "--graph-png", graph_png_path,
      "Write a picture of the planner's graph, polygons and path at its last frame (or at --graph-at), "
      "with the trajectory so far");
  std::string graph_window_text;
  app.add_option("--graph-window", graph_window_text,
                 "--graph-png draws only this world rectangle: X0,Y0,X1,Y1 in metres");
  double graph_resolution_m = 0.05;
  app.add_option("--graph-resolution", graph_resolution_m, "--graph-png metres per pixel")
      ->capture_default_str();
  CLI::Option* graph_at =
      app.add_option("--graph-at", graph_at_s,
                     "Simulated seconds: --graph-png draws the first planner frame at or after this time");
  std::string log_path;
  app.add_option("--log", log_path,
                 "Write every message the nodes exchange to this LCM log (ifar replay, ifar spy, log-info)");
  app.add_option(
      "--config-dir", config_dir,
      "Folder searched first for vehicle.yaml, planner.yaml, executive.yaml, sim.yaml, can.yaml and "
      "velodyne.yaml (then IFAR_CONFIG_DIR, ~/.config/ifar, the install's share/ifar, the checkout)");
  std::string sensing;
  app.add_option("--sensing", sensing,
                 "Sensing profile of the simulator instead of sim.yaml sensing: (ideal: exact pose, lidar, "
                 "wheels and force; field: a state estimator's drift, jitter and jumps, lidar noise and "
                 "dropouts, wheel slip, force sensor noise)");
  bool print_config = false;
  app.add_flag(
      "--print-config", print_config,
      "Print the effective configuration of every file in --config-dir (YAML, each key's meaning as a "
      "comment) and exit");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  if (print_config) {
    return printConfig(config_dir);
  }
  if (world_name.empty()) {
    std::cerr << "error: WORLD is required: a world file, a builtin or a generated kind\n";
    return kExitBadInput;
  }

  ifar::runner::RunRequest request;
  try {
    request = ifar::runner::loadRunSettings(config_dir, sensing);
  } catch (const ifar::common::ConfigError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& error) {
    std::cerr << "error: --sensing: " << error.what() << "\n";
    return kExitBadInput;
  }
  if (!(std::isfinite(max_time_s) && max_time_s > 0.0)) {
    std::cerr << "error: --max-time: must be a positive number of seconds, got " << max_time_s << "\n";
    return kExitBadInput;
  }
  if ((graph_at->count() > 0 || !graph_window_text.empty()) && graph_png_path.empty()) {
    std::cerr << "error: --graph-at and --graph-window need --graph-png\n";
    return kExitBadInput;
  }
  if (graph_at->count() > 0 && !(std::isfinite(graph_at_s) && graph_at_s >= 0.0)) {
    std::cerr << "error: --graph-at: must be a number of seconds >= 0, got " << graph_at_s << "\n";
    return kExitBadInput;
  }
  if (!(std::isfinite(graph_resolution_m) && graph_resolution_m > 0.0)) {
    std::cerr << "error: --graph-resolution: must be a positive number of metres, got " << graph_resolution_m
              << "\n";
    return kExitBadInput;
  }
  ifar::viz::RenderOptions graph_options;
  graph_options.metres_per_pixel = graph_resolution_m;
  if (!graph_window_text.empty()) {
    graph_options.window = ifar::viz::parseWindow(graph_window_text);
    if (!graph_options.window) {
      std::cerr << "error: --graph-window: expected " << ifar::viz::kWindowFormat << ", got '"
                << graph_window_text << "'\n";
      return kExitBadInput;
    }
  }
  for (const auto& [option, path] :
       {std::pair<const char*, const std::string&>{"--png", png_path},
        std::pair<const char*, const std::string&>{"--graph-png", graph_png_path}}) {
    if (!path.empty()) {
      if (const std::string problem = outputPathProblem(path); !problem.empty()) {
        std::cerr << "error: " << option << ": cannot write '" << path << "': " << problem << "\n";
        return ifar::common::kOutputFailedExitCode;
      }
    }
  }
  request.max_sim_time_s = max_time_s;
  request.planner.interaction_enabled = !no_interaction;
  request.known_map = known_map;
  request.log_path = log_path;

  std::string import_problem;
  const auto import_settings =
      ifar::sim::importSettings(import_options, request.vehicle.width_m, import_problem);
  if (!import_settings) {
    std::cerr << "error: " << import_problem << "\n";
    return kExitBadInput;
  }
  ifar::sim::WorldLoad loaded = loadWorld(world_name, request.sim.simulator.seed, *import_settings);
  if (!loaded.world.ok()) {
    std::cerr << "error: world: " << loaded.world.error() << "\n";
    return kExitBadInput;
  }
  ifar::sim::printImportReport(loaded, std::cerr);
  request.world = std::move(loaded.world.world());

  if (all_goals && !goal.empty()) {
    std::cerr << "error: --all-goals drives the world's goals: give --goal or --all-goals, not both\n";
    return kExitBadInput;
  }
  if (goal.empty()) {
    if (request.world.goals.empty()) {
      std::cerr << "error: --goal: world '" << request.world.name << "' has no goal; give --goal X,Y\n";
      return kExitBadInput;
    }
    request.goal = request.world.goals.front().position;
    for (std::size_t index = 1; all_goals && index < request.world.goals.size(); ++index) {
      request.further_goals.push_back(request.world.goals[index].position);
    }
  } else {
    request.goal = ifar::geometry::Point(goal[0], goal[1]);
  }

  std::cerr << "configuration: " << ifar::common::describeFiles(ifar::runner::runConfigFiles(config_dir))
            << "\n";
  std::cerr << "world '" << request.world.name << "' from " << request.world.source << ", goal ("
            << request.goal.x() << ", " << request.goal.y() << ")"
            << (request.further_goals.empty()
                    ? std::string()
                    : " then " + std::to_string(request.further_goals.size()) + " more")
            << ", " << (request.planner.interaction_enabled ? "interaction on" : "FAR mode (no interaction)")
            << (request.known_map ? ", walls known beforehand" : "") << "\n";
  ifar::runner::GraphPicture graph_picture(
      request.world, graph_at->count() > 0 ? std::optional<double>(graph_at_s) : std::nullopt);
  ifar::runner::FrameObserver observe_frame;
  if (!graph_png_path.empty()) {
    observe_frame = [&graph_picture](const ifar::runner::FrameView& frame) { graph_picture.observe(frame); };
  }
  const ifar::runner::RunSummary summary = ifar::runner::runScenario(
      request, [](const std::string& line) { std::cerr << line << "\n"; }, observe_frame);
  if (summary.reason.rfind("bad request: ", 0) == 0) {
    std::cerr << "error: " << summary.reason << "\n";
    return kExitBadInput;
  }

  bool pictures_written = true;  // a picture asked for and not written fails the run (exit 3)
  if (!png_path.empty()) {
    const std::string error =
        ifar::runner::writeRunPicture(request.world, request.vehicle, request.goal, summary, png_path);
    if (!error.empty()) {
      std::cerr << "error: --png: " << error << "\n";
      pictures_written = false;
    } else {
      std::cerr << "picture written to " << png_path << "\n";
    }
  }
  if (!graph_png_path.empty()) {
    const std::string error = graph_picture.writePng(graph_png_path, graph_options);
    if (!error.empty()) {
      std::cerr << "error: --graph-png: " << error << "\n";
      pictures_written = false;
    } else {
      std::cerr << "planner graph at " << graph_picture.keptTimeS() << " s written to " << graph_png_path
                << "\n";
    }
  }
  if (json) {
    std::cout << ifar::runner::summaryJson(summary) << '\n' << std::flush;
  } else {
    const std::string outcome = summary.arrived ? "arrived" : "not arrived: " + summary.reason;
    std::printf(
        "%s\ndistance %.2f m, simulated time %.1f s (wall %.1f s), pushes %d, replans %d, "
        "affordance updates %d, %.2f m from the goal\n"
        "planner frames %zu: median %.2f ms, p99 %.2f ms, max %.2f ms\n"
        "interaction planning (no frame budget here): median %.2f ms, p99 %.2f ms, max %.2f ms\n",
        outcome.c_str(), summary.distance_m, summary.sim_time_s, summary.wall_time_s, summary.pushes,
        summary.replans, summary.affordance_updates, summary.goal_distance_m, summary.planner_frame.frames,
        summary.planner_frame.median_ms, summary.planner_frame.p99_ms, summary.planner_frame.max_ms,
        summary.interaction.median_ms, summary.interaction.p99_ms, summary.interaction.max_ms);
    const ifar::runner::LossAccount& losses = summary.losses;
    if (losses.valid) {
      const ifar::runner::LossBuckets& buckets = losses.buckets;
      std::printf(
          "beyond the achievable way (%.2f m, %.2f m of it left): %.2f m = exploring %.2f + attempts %.2f + "
          "route switches %.2f + route choice %.2f + execution %.2f + push overhead %.2f (routes %d, %d "
          "switched)\n",
          losses.achievable_m, losses.remaining_m, losses.excess_m, buckets.exploring_m, buckets.attempts_m,
          buckets.route_switches_m, buckets.route_choice_m, buckets.execution_m, buckets.push_overhead_m,
          summary.routes, summary.routes_switched);
    } else if (!losses.problem.empty()) {
      std::printf("no loss accounting: %s\n", losses.problem.c_str());
    }
    for (std::size_t index = 0; summary.legs.size() > 1 && index < summary.legs.size(); ++index) {
      const ifar::runner::GoalLeg& leg = summary.legs[index];
      char beyond[64] = "";
      if (leg.losses.valid) {
        std::snprintf(beyond, sizeof(beyond), ", %.2f m beyond the achievable way", leg.losses.excess_m);
      }
      std::printf("goal %zu (%.2f, %.2f): %s, %.2f m in %.1f s%s\n", index + 1, leg.goal.x(), leg.goal.y(),
                  leg.arrived ? "arrived" : "not arrived", leg.distance_m, leg.sim_time_s, beyond);
    }
  }
  if (!pictures_written) {
    return ifar::common::kOutputFailedExitCode;
  }
  return summary.arrived ? kExitArrived : kExitNotArrived;
}
