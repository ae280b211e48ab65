// ifar bench: the scenario suite and its generalization kinds. Per kind (room, room_objects,
// office, willow, tunnel, blocked_office, blocked_tunnel, namosim, willow_pairs) it builds the worlds,
// selects the tasks, runs every planner on them (Tables I and II, planned paths) and, through the headless
// runner, FAR mode and ours in closed loop (Tables II and III, driven). Writes every row as a JSON line,
// the tables as Markdown and the PNG plots. Exit status: 0 all rows present and no planner error; 2 a
// planner errored; 3 rows are missing (a kind gave fewer tasks than asked).

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/baselines/sampling_planners.hpp"
#include "bench/scenarios/clear_pairs.hpp"
#include "bench/scenarios/driven_outcome.hpp"
#include "bench/scenarios/forked_items.hpp"
#include "bench/scenarios/generalization_tables.hpp"
#include "bench/scenarios/goal_sequence_tasks.hpp"
#include "bench/scenarios/plots.hpp"
#include "bench/scenarios/result_row.hpp"
#include "bench/scenarios/scenario_kind.hpp"
#include "bench/scenarios/scenario_maps.hpp"
#include "bench/scenarios/scenario_worlds.hpp"
#include "bench/scenarios/search_suite.hpp"
#include "bench/scenarios/sim_time_budget.hpp"
#include "bench/scenarios/system_runs.hpp"
#include "bench/scenarios/tables.hpp"
#include "bench/scenarios/task_selection.hpp"
#include "common/command_line.hpp"
#include "common/config.hpp"
#include "common/vehicle.hpp"
#include "planner/interaction/settings_loader.hpp"
#include "sim/world/world_file.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace scenarios = ifar::scenarios;

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

std::string firstLineStartingWith(const std::string& path, const std::string& prefix)
{
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind(prefix, 0) == 0) {
      return line;
    }
  }
  return "";
}

std::string machineDescription()
{
  std::string model = firstLineStartingWith("/proc/cpuinfo", "model name");
  const auto colon = model.find(':');
  model = colon == std::string::npos ? "unknown CPU" : model.substr(colon + 2);
  int processors = 0;
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    processors += line.rfind("processor", 0) == 0 ? 1 : 0;
  }
  std::ifstream loadavg("/proc/loadavg");
  double load = NAN;
  loadavg >> load;
  std::ostringstream text;
  text << model << ", " << processors << " cores, load average " << load << " at the start";
  return text.str();
}

std::string utcNow()
{
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%d %H:%M UTC", &parts);
  return text;
}

scenarios::ResultRow systemRow(scenarios::ScenarioKind kind, const std::string& world,
                               const scenarios::Task& task, const std::string& planner,
                               const std::string& sensing, std::uint64_t sensing_seed,
                               const scenarios::SystemRun& run)
{
  scenarios::ResultRow row;
  row.table = "system";
  row.planner = planner;
  row.kind = scenarios::kindName(kind);
  row.world = world;
  row.task = task.id;
  row.optimal = task.optimal;
  row.achievable = task.achievable;
  row.without_pushing = task.without_pushing;
  row.success = run.ran && run.arrived && task.reachable_with_pushing;
  row.length = run.ran ? run.distance_m : NAN;
  row.ms = run.ran ? 1000.0 * run.wall_time_s : NAN;
  row.sim_time_s = run.sim_time_s;
  row.pushes = run.pushes;
  row.frame_median_ms = run.frame_median_ms;
  row.frame_p99_ms = run.frame_p99_ms;
  row.frame_max_ms = run.frame_max_ms;
  row.interaction_max_ms = run.interaction_max_ms;
  row.sensing = sensing;
  row.sensing_seed = static_cast<int>(sensing_seed);
  row.undecided_saturated_pushes = run.undecided_saturated_pushes;
  row.escalations = run.escalations;
  row.excess_m = run.excess_m;
  row.losses = run.losses;
  if (!run.ran) {
    row.status = "runner_unavailable";
    row.reason = run.reason;
  } else if (!run.failure_status.empty()) {
    row.status = run.failure_status;
    row.reason = run.reason;
  } else if (!task.reachable_with_pushing) {
    row.status = "unreachable";
    row.reason = "unreachable even with pushing (runner: " + run.reason + ")";
  } else {
    row.status = scenarios::drivenStatus(run.arrived, run.reason, planner == "far", task.without_pushing);
    row.reason = run.arrived ? "" : run.reason;
  }
  return row;
}

scenarios::ResultRow skippedRow(scenarios::ScenarioKind kind, const std::string& world,
                                const scenarios::Task& task, const std::string& planner,
                                const std::string& sensing, std::uint64_t sensing_seed)
{
  scenarios::ResultRow row;
  row.table = "system";
  row.planner = planner;
  row.sensing = sensing;
  row.sensing_seed = static_cast<int>(sensing_seed);
  row.kind = scenarios::kindName(kind);
  row.world = world;
  row.task = task.id;
  row.optimal = task.optimal;
  row.achievable = task.achievable;
  row.without_pushing = task.without_pushing;
  row.length = NAN;
  row.ms = NAN;
  row.status = "skipped";
  row.reason = "not run: the suite's --system-budget was spent";
  return row;
}

/// One closed-loop run to do after the search part: a task of a world, with FAR mode and ours.
struct SystemJob {
  scenarios::ScenarioKind kind;
  std::size_t world;  // index into the kept worlds
  scenarios::Task task;
};

/// One runner run of a job: FAR mode or ours under one sensing profile, filled in as its child process
/// answers.
struct SystemSlot {
  std::size_t job;  // index into the jobs
  std::string sensing;
  std::uint64_t sensing_seed;
  bool first_draw;  // the first of the profile's sensing seeds (the one the plots show)
  bool ours;        // false: FAR mode
  scenarios::SystemRun run;
  bool skipped;  // the --system-budget was spent before it started
};

struct KeptWorld {
  std::string name;
  ifar::sim::World world;
};

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{
      "The scenario suite: worlds and tasks per kind, Table I (search time: grid A*, RRT*,\n"
      "BIT*, FAR mode, ours), Table II (SPL) and Table III (system level, headless runner)."};
  std::string kind_list =
      "room,room_objects,office,willow,tunnel,blocked_office,blocked_tunnel,namosim,willow_pairs";
  int tasks = 10;
  std::uint64_t seed = 1;
  std::string planner_list = "grid_astar,rrt_star,bit_star,far,ours";
  ifar::baselines::SamplingSettings sampling;
  const char* shared = std::getenv("IFAR_SHARED_DATA");
  const std::string shared_data = shared != nullptr ? shared : "../shared/data";
  std::string willow = shared_data + "/maps/willow-full.yaml";
  std::string namosim_folder = shared_data + "/namosim";
  int namosim_goals = 0;
  int willow_pairs = 20;
  std::string config_dir = "config";
  std::string jsonl_path = "bench/results/latest.jsonl";
  std::string tables_path = "bench/results/tables.md";
  std::string plot_dir = "bench/results";
  bool no_plots = false;
  bool no_system = false;
  bool smoke = false;
  std::string system_kind_list =
      "office,tunnel,room_objects,willow,room,blocked_office,blocked_tunnel,namosim,willow_pairs";
  std::string sensing_list = "ideal,field";
  std::string sensing_seed_list;
  std::string system_planner_list = "far,ours";
  int system_tasks = 3;
  scenarios::SimTimeBudget budget;  // the runner's stop: 60 s + 4 s/m, at most 1,800 s
  double strict_per_metre_s = 2.0;
  double system_budget_minutes = 0.0;
  std::string commit = "unknown";
  std::string task_world_dir;
  const unsigned hardware_threads = std::thread::hardware_concurrency();
  int jobs_count = hardware_threads > 0 ? static_cast<int>(hardware_threads) : 1;
  app.add_option("--kinds", kind_list, "comma-separated kinds (docs/benchmarks.md)")->capture_default_str();
  app.add_option("--tasks", tasks, "tasks per kind")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option(
         "--seed", seed,
         "seed of worlds, tasks and OMPL (docs/benchmarks.md: 1 tunes, 2 validates; no two seeds share "
         "a world)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--planners", planner_list, "comma-separated: grid_astar,rrt_star,bit_star,far,ours")
      ->capture_default_str();
  app.add_option("--time-cap", sampling.time_cap_s, "RRT*/BIT* CPU cap per query (s)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  int timing_repeats = 5;
  app.add_option("--timing-repeats", timing_repeats,
                 "runs of each grid A*, FAR mode and ours query; the median CPU time is reported")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  double query_deadline_s = 60.0;
  app.add_option("--query-deadline", query_deadline_s,
                 "wall seconds one search query (with its timing repeats) may take in its child process "
                 "before it is killed and recorded as a timeout")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--factor", sampling.optimum_factor, "RRT*/BIT* stop within this factor of the optimum")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  app.add_option("--willow", willow, "Willow Garage map_server .yaml (absent: the willow kind is skipped)")
      ->capture_default_str();
  app.add_option("--namosim", namosim_folder,
                 "folder of namosim scenario SVGs (absent or empty: the namosim kind is skipped)")
      ->capture_default_str();
  app.add_option("--namosim-goals", namosim_goals,
                 "the namosim kind's first N goals, over its files in name order (0: every goal)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--pairs", willow_pairs,
                 "start/goal pairs of the willow_pairs kind (>= 1 m clearance; seed s takes the s-th block)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--config", config_dir, "folder with vehicle.yaml and the runner's configs")
      ->capture_default_str();
  app.add_option("--out", jsonl_path, "JSON lines, one per row")->capture_default_str();
  app.add_option("--tables", tables_path, "Markdown tables")->capture_default_str();
  app.add_option("--plots", plot_dir, "folder for the PNG plots")->capture_default_str();
  app.add_flag("--no-plots", no_plots, "write no PNGs");
  app.add_flag("--no-system", no_system, "skip the headless-runner runs (Table II driven, Table III)");
  app.add_option("--system-kinds", system_kind_list, "kinds driven in the runner, in this order")
      ->capture_default_str();
  app.add_option(
         "--sensing", sensing_list,
         "comma-separated sensing profiles every driven task is run under (sim.yaml sensing:): ideal, "
         "field")
      ->capture_default_str();
  app.add_option("--sensing-seeds", sensing_seed_list,
                 "comma-separated seeds the sensor models draw from; every driven task is run once per seed "
                 "under each profile that draws random numbers (field), once under one that draws none "
                 "(ideal). Empty: sim.yaml's seed. The worlds and tasks stay those of --seed")
      ->capture_default_str();
  app.add_option("--system-planners", system_planner_list, "comma-separated modes driven: far, ours")
      ->capture_default_str();
  app.add_option("--system-tasks", system_tasks, "the first N tasks of each kind are driven")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--sim-base", budget.base_s, "simulated seconds per run: base ...")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--sim-per-metre", budget.per_metre_s,
                 "... plus this per metre of the optimum (of the achievable way where that is longer)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-sim-time", budget.max_s, "... at most this (s)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option(
         "--strict-per-metre", strict_per_metre_s,
         "Table II also counts the same runs' arrivals within --sim-base plus this per metre (0: not; "
         "at least --sim-per-metre: not)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option(
         "--system-budget", system_budget_minutes,
         "wall minutes for the whole suite; runner runs that would start later are recorded as skipped "
         "(0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--jobs", jobs_count,
                 "runner runs driven at once (each is deterministic in simulated time; wall times grow when "
                 "the cores are shared)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--commit", commit, "commit named in the tables' header")->capture_default_str();
  app.add_option("--task-worlds", task_world_dir,
                 "write each driven task as a world file (its start and goal) into this folder, to drive it "
                 "again with ifar-run");
  app.add_flag(
      "--smoke", smoke,
      "CI subset: one task per kind, 0.3 s sampling cap; the runner drives the room and blocked office "
      "tasks only, 60 s simulated");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  if (smoke) {
    tasks = 1;
    sampling.time_cap_s = std::min(sampling.time_cap_s, 0.3);
    system_kind_list = "room,blocked_office";
    system_tasks = 1;
    namosim_goals = 1;
    willow_pairs = 1;
    budget.max_s = std::min(budget.max_s, 60.0);
  }

  // Output folders are made now: a missing one found after an hour of driving would lose the results.
  for (const auto& [option, folder] :
       {std::pair<std::string, std::string>{"--out",
                                            std::filesystem::path(jsonl_path).parent_path().string()},
        {"--tables", std::filesystem::path(tables_path).parent_path().string()},
        {"--plots", no_plots ? std::string() : plot_dir},
        {"--task-worlds", task_world_dir}}) {
    std::error_code error;
    if (!folder.empty() && !std::filesystem::create_directories(folder, error) && error) {
      std::cerr << "ifar bench: " << option << ": cannot create folder '" << folder
                << "': " << error.message() << "\n";
      return 1;
    }
  }

  std::vector<scenarios::ScenarioKind> kinds;
  std::vector<scenarios::ScenarioKind> system_kinds;
  for (auto [list, target] : {std::pair{&kind_list, &kinds}, std::pair{&system_kind_list, &system_kinds}}) {
    for (const std::string& name : splitList(*list)) {
      const auto kind = scenarios::parseKind(name);
      if (!kind) {
        std::string known;
        for (const scenarios::ScenarioKind each : scenarios::allKinds()) {
          known += (known.empty() ? "" : ", ") + scenarios::kindName(each);
        }
        std::cerr << "ifar bench: unknown kind '" << name << "' (known: " << known << ")\n";
        return 1;
      }
      target->push_back(*kind);
    }
  }
  scenarios::SearchSuiteSettings search_settings;
  search_settings.planners = splitList(planner_list);
  search_settings.sampling = sampling;
  search_settings.timing_repeats = timing_repeats;
  search_settings.query_deadline =
      std::chrono::milliseconds(static_cast<long long>(std::ceil(query_deadline_s * 1000.0)));
  for (const std::string& planner : search_settings.planners) {
    if (std::find(scenarios::searchPlanners().begin(), scenarios::searchPlanners().end(), planner) ==
        scenarios::searchPlanners().end()) {
      std::cerr << "ifar bench: --planners: unknown planner '" << planner << "'\n";
      return 1;
    }
  }

  const std::vector<std::string> sensing_profiles = splitList(sensing_list);
  for (const std::string& sensing : sensing_profiles) {
    const std::vector<std::string> known = scenarios::sensingProfileNames();
    if (std::find(known.begin(), known.end(), sensing) == known.end()) {
      std::cerr << "ifar bench: --sensing: unknown profile '" << sensing << "'\n";
      return 1;
    }
  }
  if (sensing_profiles.empty()) {
    std::cerr << "ifar bench: --sensing: name at least one profile\n";
    return 1;
  }
  const std::vector<std::string> system_planners = splitList(system_planner_list);
  for (const std::string& planner : system_planners) {
    if (planner != "far" && planner != "ours") {
      std::cerr << "ifar bench: --system-planners: unknown mode '" << planner << "' (far, ours)\n";
      return 1;
    }
  }
  const auto drives = [&system_planners](const char* planner) {
    return std::find(system_planners.begin(), system_planners.end(), planner) != system_planners.end();
  };
  std::vector<std::uint64_t> sensing_seeds;
  for (const std::string& text : splitList(sensing_seed_list)) {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value == 0 || value > 2147483647ULL || text.front() == '-') {
      std::cerr << "ifar bench: --sensing-seeds: '" << text << "' is not a seed from 1 to 2147483647\n";
      return 1;
    }
    sensing_seeds.push_back(value);
  }

  ifar::common::VehicleSettings vehicle;
  const std::string vehicle_path = config_dir + "/vehicle.yaml";
  if (std::ifstream(vehicle_path).good()) {
    try {
      vehicle = ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(vehicle_path));
    } catch (const std::exception& error) {
      std::cerr << "ifar bench: " << error.what() << "\n";
      return 1;
    }
  } else {
    std::cerr << "ifar bench: " << vehicle_path << " not found, using the default vehicle\n";
  }
  // A scenario's goal counts as reached within the executive's tolerance: goals nearer than that to an
  // obstacle are still reachable, ones under a movable object are not without pushing.
  double goal_tolerance_m = 0.3;
  const std::string executive_path = config_dir + "/executive.yaml";
  if (std::ifstream(executive_path).good()) {
    try {
      goal_tolerance_m = ifar::common::ConfigNode::loadFile(executive_path)
                             .optional<double>("goal_tolerance_m", goal_tolerance_m);
    } catch (const std::exception& error) {
      std::cerr << "ifar bench: " << error.what() << "\n";
      return 1;
    }
  }
  scenarios::MapSettings map_settings;
  map_settings.vehicle = vehicle;
  map_settings.inflation_m = 0.5 * vehicle.width_m;
  map_settings.interaction.pusher = ifar::interaction::PusherSettings::fromVehicle(vehicle);
  // The planned rows of ours search with the interaction settings the driven runs use.
  const std::string planner_path = config_dir + "/planner.yaml";
  if (std::ifstream(planner_path).good()) {
    try {
      const ifar::common::ConfigNode planner_root = ifar::common::ConfigNode::loadFile(planner_path);
      if (planner_root.has("interaction")) {
        const ifar::common::ConfigNode interaction = planner_root.child("interaction");
        interaction.optional<bool>("enabled", true);  // the suite runs FAR mode and ours either way
        map_settings.interaction = ifar::interaction::loadInteractionSettings(interaction, vehicle);
      }
    } catch (const std::exception& error) {
      std::cerr << "ifar bench: " << error.what() << "\n";
      return 1;
    }
  } else {
    std::cerr << "ifar bench: " << planner_path << " not found, using the default interaction settings\n";
  }
  // A planned row must not depend on machine load: the push searches stop on their expansion limit only.
  // With the time budget, a wider search that ran out of time under load was not "exhausted", so the next
  // one never ran and a planned length depended on the load. The driven runs keep the budget.
  map_settings.interaction.search.time_budget_s = std::numeric_limits<double>::infinity();

  // Read before the search part, so a bad runner config stops the suite at once, and only once.
  std::unique_ptr<scenarios::SystemRunner> runner;
  if (!no_system) {
    try {
      runner = std::make_unique<scenarios::SystemRunner>(config_dir, sensing_profiles);
    } catch (const std::exception& error) {
      std::cerr << "ifar bench: " << error.what() << "\n";
      return 1;
    }
  }

  ifar::baselines::seedSamplingPlanners(seed);
  const std::string machine = machineDescription();
  const Clock::time_point began = Clock::now();
  std::vector<scenarios::ResultRow> rows;
  std::vector<std::string> notes;
  bool missing = false;
  std::vector<KeptWorld> kept;  // worlds the runner drives in
  std::vector<SystemJob> jobs;
  std::map<scenarios::ScenarioKind, std::size_t> plotted_world;  // kind -> kept world of its path plot
  std::map<std::size_t, std::vector<scenarios::PathPair>> planned_pairs;  // kept world -> planned paths

  // Part 1: Tables I and II (planned), every kind and planner.
  for (const scenarios::ScenarioKind kind : kinds) {
    const std::string kind_name = scenarios::kindName(kind);
    const bool goal_sequences = kind == scenarios::ScenarioKind::Namosim;
    const bool drawn_pairs = kind == scenarios::ScenarioKind::WillowPairs;
    const int kind_tasks = drawn_pairs ? willow_pairs : tasks;
    const scenarios::WorldSetResult worlds =
        scenarios::scenarioWorlds(kind, {seed, kind_tasks, willow, namosim_folder, vehicle.width_m});
    if (!worlds.ok()) {
      std::cerr << "ifar bench: " << kind_name << ": " << worlds.error << "\n";
      notes.push_back(kind_name + ": no worlds: " + worlds.error);
      missing = true;
      continue;
    }
    for (const std::string& note : worlds.notes) {
      notes.push_back(std::string(kind_name).append(": ").append(note));
    }
    int carry = 0;
    int driven = 0;
    int goals_left = namosim_goals > 0 ? namosim_goals : std::numeric_limits<int>::max();
    for (std::size_t index = 0; index < worlds.worlds.size(); ++index) {
      const scenarios::ScenarioWorld& world = worlds.worlds[index];
      if (goal_sequences && goals_left <= 0) {
        break;
      }
      const int quota = world.task_quota + carry;
      const Clock::time_point world_began = Clock::now();
      const scenarios::ScenarioMaps maps = scenarios::buildScenarioMaps(world.world, map_settings);
      scenarios::TaskSelectionSettings selection;
      selection.count = quota;
      selection.seed = seed * 1000003ULL + index;
      selection.min_optimal = scenarios::minimumOptimalLength(kind);
      std::vector<scenarios::Task> world_tasks;
      if (goal_sequences) {
        world_tasks = scenarios::goalSequenceTasks(world.world, maps, goal_tolerance_m);
        if (static_cast<int>(world_tasks.size()) > goals_left) {
          world_tasks.resize(static_cast<std::size_t>(goals_left));
        }
        goals_left -= static_cast<int>(world_tasks.size());
      } else if (drawn_pairs) {
        scenarios::ClearPairSettings pairs;
        pairs.count = quota;
        pairs.seed = seed;
        pairs.min_optimal = selection.min_optimal;
        world_tasks = scenarios::sampleClearPairs(world.world, maps, pairs);
      } else {
        world_tasks = scenarios::selectTasks(world.world, maps, selection);
      }
      carry = goal_sequences ? 0 : quota - static_cast<int>(world_tasks.size());
      if (carry > 0) {
        notes.push_back(kind_name + ": " + world.name + " gave " + std::to_string(world_tasks.size()) +
                        " of " + std::to_string(quota) + " tasks with optimum > " +
                        std::to_string(static_cast<int>(selection.min_optimal)) + " m" +
                        (index + 1 < worlds.worlds.size() ? "; the rest come from the next world" : ""));
      }
      std::cerr << kind_name << " " << world.name << ": " << maps.far.map.graph.vertexCount()
                << " vertices (FAR), " << maps.ours.map.graph.interactionEdgeCount()
                << " interaction edges from " << maps.interaction.splitting << "/" << maps.interaction.objects
                << " objects (" << maps.interaction.milliseconds << " ms); maps in " << maps.build_seconds
                << " s; " << world_tasks.size() << " tasks\n";
      scenarios::PlannedPaths planned;
      const std::vector<scenarios::ResultRow> search_rows =
          scenarios::runSearchSuite(kind, world.name, maps, world_tasks, search_settings, &planned);
      rows.insert(rows.end(), search_rows.begin(), search_rows.end());

      const bool drive =
          !no_system && std::find(system_kinds.begin(), system_kinds.end(), kind) != system_kinds.end();
      const bool plot = !no_plots && plotted_world.count(kind) == 0 && !world_tasks.empty();
      if ((drive && driven < system_tasks) || plot) {
        kept.push_back({world.name, world.world});
      }
      if (plot) {
        plotted_world[kind] = kept.size() - 1;
        for (std::size_t task_index = 0; task_index < world_tasks.size(); ++task_index) {
          planned_pairs[kept.size() - 1].push_back({planned.far[task_index], planned.ours[task_index],
                                                    world_tasks[task_index].start,
                                                    world_tasks[task_index].goal});
        }
      }
      for (const scenarios::Task& task : world_tasks) {
        if (drive && driven < system_tasks) {
          jobs.push_back({kind, kept.size() - 1, task});
          ++driven;
        }
      }
      std::cerr << "  " << world.name << " done in "
                << std::chrono::duration<double>(Clock::now() - world_began).count() << " s\n";
    }
    if (carry > 0) {
      missing = true;
      notes.push_back(kind_name + ": " + std::to_string(carry) + " of " + std::to_string(kind_tasks) +
                      " tasks missing: no more start/goal pairs with optimum > " +
                      std::to_string(static_cast<int>(scenarios::minimumOptimalLength(kind))) + " m");
    }
  }
  const double search_seconds = std::chrono::duration<double>(Clock::now() - began).count();

  // Part 2: Tables II (driven) and III through the headless runner, kinds in --system-kinds order.
  std::stable_sort(jobs.begin(), jobs.end(), [&system_kinds](const SystemJob& a, const SystemJob& b) {
    return std::find(system_kinds.begin(), system_kinds.end(), a.kind) <
           std::find(system_kinds.begin(), system_kinds.end(), b.kind);
  });
  // Task worlds first (cheap, and an unwritable folder stops the suite before hours of driving).
  if (!task_world_dir.empty()) {
    for (const SystemJob& job : jobs) {
      const KeptWorld& world = kept[job.world];
      const std::string path = task_world_dir + "/" + world.name + "-" + job.task.id + ".yaml";
      const std::string error = ifar::sim::saveWorldFile(scenarios::taskWorld(world.world, job.task), path);
      if (!error.empty()) {
        std::cerr << "ifar-bench: --task-worlds: " << error << "\n";
        return 2;
      }
    }
  }
  // Every (task, mode) run is independent and deterministic in simulated time: they start in order, and
  // the rows keep that order whatever finishes first.
  std::vector<SystemSlot> slots;
  for (const std::string& sensing : runner ? sensing_profiles : std::vector<std::string>{}) {
    std::vector<std::uint64_t> draws = sensing_seeds;
    if (draws.empty()) {
      draws.push_back(runner->configuredSensingSeed());
    }
    if (!runner->drawsFromSeed(sensing)) {
      draws.resize(1);  // exact sensors: every seed drives the same run
    }
    for (std::size_t draw = 0; draw < draws.size(); ++draw) {
      for (std::size_t job = 0; job < jobs.size(); ++job) {
        for (const bool ours : {false, true}) {
          if (drives(ours ? "ours" : "far")) {
            slots.push_back({job, sensing, draws[draw], draw == 0, ours, {}, false});
          }
        }
      }
    }
  }
  // Each run is driven in a child process of its own, `jobs_count` at once, so a runner that crashes or
  // hangs costs its own row (status error or timeout, with the reason), not the suite.
  scenarios::ForkedItems runs;
  runs.count = slots.size();
  runs.parallel = jobs_count;
  runs.answer = [&](std::size_t index) {
    const SystemSlot& slot = slots[index];
    const SystemJob& job = jobs[slot.job];
    return scenarios::toAnswer(runner->run(kept[job.world].world, job.task, slot.ours, slot.sensing,
                                           slot.sensing_seed, budget.seconds(job.task.budgetLength())));
  };
  // Wall time: on a quiet machine the runner runs several times faster than simulated time, but on cores
  // shared with other work it runs up to about twice slower; three times the simulated cap leaves only a
  // hung run to meet this.
  runs.deadline = [&](std::size_t index) {
    const double seconds = 120.0 + 3.0 * budget.seconds(jobs[slots[index].job].task.budgetLength());
    return std::chrono::milliseconds(static_cast<long long>(1000.0 * seconds));
  };
  runs.skip = [&](std::size_t) {
    const double used_minutes = std::chrono::duration<double>(Clock::now() - began).count() / 60.0;
    return system_budget_minutes > 0.0 && used_minutes > system_budget_minutes &&
           scenarios::systemRunnerAvailable();
  };
  runs.finished = [&](std::size_t index, const scenarios::ForkedOutcome& outcome) {
    SystemSlot& slot = slots[index];
    const SystemJob& job = jobs[slot.job];
    if (outcome.status == "skipped") {
      slot.skipped = true;
      return;
    }
    const std::optional<scenarios::SystemRun> run =
        outcome.answered ? scenarios::systemRunFromAnswer(outcome.answer) : std::nullopt;
    if (run) {
      slot.run = *run;
    } else {
      slot.run.ran = true;
      slot.run.failure_status = outcome.answered ? "error" : outcome.status;
      slot.run.reason = "runner " + (outcome.answered ? "answer could not be read" : outcome.reason);
    }
    const scenarios::ResultRow row =
        systemRow(job.kind, kept[job.world].name, job.task, slot.ours ? "ours" : "far", slot.sensing,
                  slot.sensing_seed, slot.run);
    std::cerr << scenarios::kindName(job.kind) << " " << kept[job.world].name << " " << job.task.id << " "
              << row.planner << " (" << slot.sensing << ", sensing seed " << slot.sensing_seed
              << "): " << row.status << " " << row.reason << " (" << slot.run.distance_m << " m, "
              << slot.run.sim_time_s << " s simulated, " << slot.run.wall_time_s << " s wall)\n";
  };
  scenarios::runForked(runs);
  std::map<std::size_t, std::vector<scenarios::PathPair>> driven_pairs;  // kept world -> trajectories
  int skipped = 0;
  for (std::size_t job_index = 0; job_index < jobs.size(); ++job_index) {
    const SystemJob& job = jobs[job_index];
    scenarios::PathPair pair{{}, {}, job.task.start, job.task.goal};
    for (const SystemSlot& slot : slots) {
      if (slot.job != job_index) {
        continue;
      }
      const std::string planner = slot.ours ? "ours" : "far";
      if (slot.skipped) {
        rows.push_back(
            skippedRow(job.kind, kept[job.world].name, job.task, planner, slot.sensing, slot.sensing_seed));
        ++skipped;
        continue;
      }
      rows.push_back(systemRow(job.kind, kept[job.world].name, job.task, planner, slot.sensing,
                               slot.sensing_seed, slot.run));
      if (slot.sensing != sensing_profiles.front() || !slot.first_draw) {
        continue;  // the plots show the trajectories of the first profile's first draw
      }
      std::vector<ifar::geometry::Point>& line = slot.ours ? pair.ours : pair.far;
      for (const ifar::geometry::Pose2& pose : slot.run.trajectory) {
        line.push_back(pose.position());
      }
    }
    if (!pair.far.empty() || !pair.ours.empty()) {
      driven_pairs[job.world].push_back(pair);
    }
  }
  if (skipped > 0) {
    notes.push_back(std::to_string(skipped) + " runner runs skipped: --system-budget " +
                    std::to_string(static_cast<int>(system_budget_minutes)) + " min spent");
  }
  const double wall_seconds = std::chrono::duration<double>(Clock::now() - began).count();

  std::ofstream jsonl(jsonl_path);
  if (!jsonl) {
    std::cerr << "ifar bench: cannot write " << jsonl_path << "\n";
    return 1;
  }
  bool planner_error = false;
  for (const scenarios::ResultRow& row : rows) {
    jsonl << scenarios::toJsonLine(row) << "\n";
    planner_error = planner_error || row.status == "error";
  }
  std::ostringstream command;
  for (int index = 0; index < argc; ++index) {
    command << (index > 0 ? " " : "") << argv[index];
  }
  std::optional<scenarios::SimTimeBudget> stricter;
  if (strict_per_metre_s > 0.0 && strict_per_metre_s < budget.per_metre_s) {
    stricter = budget;
    stricter->per_metre_s = strict_per_metre_s;
  }
  std::ostringstream tables_text;
  tables_text << "Machine: " << machine << ". Commit: " << commit << ". Date: " << utcNow()
              << ". Wall time: " << static_cast<int>(std::lround(wall_seconds)) << " s (search part "
              << static_cast<int>(std::lround(search_seconds)) << " s).\n"
              << "Command: `" << command.str() << "`\n\n"
              << scenarios::tableOneSearchTime(rows) << "\n"
              << scenarios::tableTwoSpl(rows, stricter) << "\n"
              << scenarios::tableThreeSystem(rows) << "\n"
              << scenarios::tablePlannerFrames(rows, jobs_count) << "\n"
              << scenarios::tableLosses(rows) << "\n"
              << scenarios::tableGeneralization(rows) << "\n"
              << "Targets:\n\n"
              << scenarios::targetCheck(rows);
  if (!notes.empty()) {
    tables_text << "\nNotes:\n\n";
    for (const std::string& note : notes) {
      tables_text << "- " << note << "\n";
    }
  }
  std::ofstream tables_file(tables_path);
  tables_file << tables_text.str();
  std::cout << tables_text.str();
  if (!no_plots) {
    std::vector<std::string> errors;
    errors.push_back(scenarios::writeTimeVsGraphSizePlot(rows, plot_dir + "/search_time_vs_graph_size.png"));
    for (const auto& [kind, world_index] : plotted_world) {
      const KeptWorld& world = kept[world_index];
      const std::string kind_name = scenarios::kindName(kind);
      std::string title = kind_name;
      title.append(" (").append(world.name).append("): planned paths, FAR mode blue, ours green");
      std::string file = plot_dir;
      file.append("/paths_").append(kind_name).append(".png");
      errors.push_back(scenarios::writePathPlot(world.world, planned_pairs[world_index], title, file));
    }
    for (const auto& [world_index, pairs] : driven_pairs) {
      const KeptWorld& world = kept[world_index];
      errors.push_back(scenarios::writePathPlot(
          world.world, pairs,
          world.name + ": driven trajectories (headless runner), FAR mode blue, ours green",
          plot_dir + "/trajectories_" + world.name + ".png"));
    }
    for (const scenarios::ScenarioKind kind : scenarios::allKinds()) {
      const std::string kind_name = scenarios::kindName(kind);
      std::string file = plot_dir;
      file.append("/losses_").append(kind_name).append(".png");
      errors.push_back(scenarios::writeLossPlot(rows, kind_name, file));
    }
    for (const std::string& error : errors) {
      if (!error.empty()) {
        std::cerr << "ifar bench: " << error << "\n";
      }
    }
  }
  if (planner_error) {
    std::cerr << "ifar bench: a planner reported an error (status \"error\" in " << jsonl_path << ")\n";
    return 2;
  }
  if (missing) {
    std::cerr << "ifar bench: rows are missing (see the notes)\n";
    return 3;
  }
  return 0;
}
