// ifar run-summary LOG --goal X,Y: what a recorded run achieved, from its LCM log: arrived or not, distance
// driven and time (simulator ground truth, else POSE), pushes and replans (EXEC_STATUS), affordance
// updates, blocked passages, planner frame times (PLANNER_STATUS), and the executive's last reason.
// --json prints it as one JSON line in the schema of `ifar run --json` (system/summary_json.hpp, written by
// the same code; docs/cli.md says which keys a log cannot give). --png with --world draws the run as
// `ifar run --png` does: the world, the trajectory (ground truth, else POSE) and the objects where the log
// last saw them (SIM_GROUND_TRUTH), with the outcome in the legend. A corrupt log is summarised from the
// events that could be read, with a warning on stderr naming the first bad byte; a log in which no event
// can be read is an error.

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/config_search.hpp"
#include "common/lcm_log/log_reader.hpp"
#include "ifar/affordance_t.hpp"
#include "ifar/exec_status_t.hpp"
#include "ifar/path_t.hpp"
#include "ifar/planner_status_t.hpp"
#include "ifar/pose_t.hpp"
#include "ifar/world_state_t.hpp"
#include "lcmtypes/checked_decode.hpp"
#include "sim/world/world_file.hpp"
#include "system/frame_times.hpp"
#include "system/run_picture.hpp"
#include "system/summary_json.hpp"

namespace {

struct Track {
  bool has_position = false;
  double x = 0.0;
  double y = 0.0;
  double distance_m = 0.0;
  std::int64_t first_utime = 0;
  std::int64_t last_utime = 0;

  void add(double new_x, double new_y, std::int64_t utime)
  {
    if (has_position) {
      distance_m += std::hypot(new_x - x, new_y - y);
    } else {
      first_utime = utime;
    }
    has_position = true;
    x = new_x;
    y = new_y;
    last_utime = utime;
  }
};

template <typename Message>
bool decode(const ifar::lcm_log::LogEvent& event, Message& message)
{
  return ifar::lcmtypes::decodeLcm(message, event.data.data(), event.data.size()).bytes ==
         static_cast<int>(event.data.size());
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Summarises a recorded run: arrival, distance, time, pushes, replans, affordance updates"};
  std::string path;
  std::vector<double> goal;
  double tolerance = 0.5;
  bool json = false;
  app.add_option("log", path, "the .lcmlog file")->required()->check(CLI::ExistingFile);
  ifar::common::addCoordinatesOption(app, "--goal", goal, "X,Y", 2, 2, "the run's goal in metres")
      ->required();
  app.add_option("--tolerance", tolerance, "arrival radius, metres")->capture_default_str();
  app.add_flag("--json", json, "one JSON line instead of text, in the schema of ifar run --json");
  std::string world_path;
  std::string png_path;
  app.add_option("--world", world_path,
                 "the world the run was in (for --png): a file, or a name on the configuration search path");
  app.add_option(
      "--png", png_path,
      "draw the run as ifar run --png does: world, trajectory, objects where they ended (needs --world)");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }

  if (!png_path.empty() && world_path.empty()) {
    std::fprintf(stderr, "ifar run-summary: error: --png needs --world\n");
    return ifar::common::kBadInputExitCode;
  }
  ifar::sim::World world;
  if (!world_path.empty()) {
    const std::optional<ifar::common::FoundConfig> found = ifar::common::findNamedInput(world_path, "worlds");
    if (!found) {
      std::fprintf(stderr,
                   "ifar run-summary: error: --world: '%s' is neither a file nor a world on the "
                   "configuration search path\n",
                   world_path.c_str());
      return ifar::common::kBadInputExitCode;
    }
    ifar::sim::WorldResult loaded = ifar::sim::loadWorldFile(found->path);
    if (!loaded.ok()) {
      std::fprintf(stderr, "ifar run-summary: error: --world: %s\n", loaded.error().c_str());
      return ifar::common::kBadInputExitCode;
    }
    world = std::move(loaded.world());
  }

  ifar::lcm_log::LogReader log = ifar::lcm_log::LogReader::open(path);
  if (!log.openError().empty()) {
    std::fprintf(stderr, "ifar run-summary: error: cannot read an LCM log: %s\n", log.openError().c_str());
    return ifar::common::kBadInputExitCode;
  }
  Track truth;
  Track pose;
  std::vector<ifar::geometry::Pose2> truth_poses;
  std::vector<ifar::geometry::Pose2> estimated_poses;
  std::map<std::int64_t, ifar::geometry::Pose2> last_objects;  // by world-file id
  ifar::exec_status_t last_status{};
  bool has_status = false;
  bool arrived_mode = false;
  int affordance_updates = 0;
  int blocked_passages = 0;
  int paths = 0;
  ifar::runner::PlannerFrameRecord frames;
  std::int64_t first_event_us = -1;
  std::int64_t last_event_us = 0;
  int undecodable = 0;
  ifar::lcm_log::LogEvent event;
  while (log.next(event)) {
    first_event_us = first_event_us < 0 ? event.timestamp_us : first_event_us;
    last_event_us = event.timestamp_us;
    if (event.channel == "SIM_GROUND_TRUTH") {
      ifar::world_state_t state{};
      if (decode(event, state)) {
        truth.add(state.vehicle_x, state.vehicle_y, state.utime);
        truth_poses.push_back({state.vehicle_x, state.vehicle_y, state.vehicle_heading});
        for (const ifar::object_state_t& object : state.objects) {
          last_objects[object.id] = {object.x, object.y, object.heading};
        }
      } else {
        ++undecodable;
      }
    } else if (event.channel == "POSE") {
      ifar::pose_t message{};
      if (decode(event, message)) {
        pose.add(message.position[0], message.position[1], message.utime);
        estimated_poses.push_back({message.position[0], message.position[1], 0.0});
      } else {
        ++undecodable;
      }
    } else if (event.channel == "EXEC_STATUS") {
      if (decode(event, last_status)) {
        has_status = true;
        arrived_mode = arrived_mode || last_status.mode == ifar::exec_status_t::MODE_ARRIVED;
      } else {
        ++undecodable;
      }
    } else if (event.channel == "AFFORDANCE") {
      ++affordance_updates;
    } else if (event.channel == "BLOCKED_PASSAGE") {
      ++blocked_passages;
    } else if (event.channel == "PLANNER_STATUS") {
      ifar::planner_status_t status{};
      if (decode(event, status)) {
        frames.add(ifar::planner::StageTimings{status.perception_ms, status.local_graph_ms, status.merge_ms,
                                               status.interaction_ms, status.search_ms, status.total_ms});
      } else {
        ++undecodable;
      }
    } else if (event.channel == "GLOBAL_PATH") {
      ++paths;
    }
  }
  if (!log.clean()) {
    if (log.eventCount() == 0) {
      std::fprintf(stderr, "ifar run-summary: error: '%s': no LCM event could be read: %s\n", path.c_str(),
                   log.problemSummary().c_str());
      return ifar::common::kBadInputExitCode;
    }
    std::fprintf(
        stderr, "ifar run-summary: warning: '%s' is corrupt, summarised from the %llu events read: %s\n",
        path.c_str(), static_cast<unsigned long long>(log.eventCount()), log.problemSummary().c_str());
  }
  const Track& track = truth.has_position ? truth : pose;
  if (!track.has_position) {
    std::fprintf(stderr, "ifar run-summary: error: '%s' has neither SIM_GROUND_TRUTH nor POSE\n",
                 path.c_str());
    return ifar::common::kBadInputExitCode;
  }
  const double goal_x = goal[0];
  const double goal_y = goal[1];
  const double remaining = std::hypot(goal_x - track.x, goal_y - track.y);
  const bool arrived = remaining <= tolerance || arrived_mode;
  const double seconds = static_cast<double>(track.last_utime - track.first_utime) * 1e-6;
  const int pushes = has_status ? last_status.pushes : 0;
  const int replans = has_status ? last_status.replans : 0;
  const std::string reason = has_status ? last_status.reason : "no EXEC_STATUS in the log";
  if (!png_path.empty()) {
    ifar::runner::RunSummary run;
    run.arrived = arrived;
    run.reason = reason;
    run.distance_m = track.distance_m;
    run.sim_time_s = seconds;
    run.pushes = pushes;
    run.replans = replans;
    run.trajectory = truth.has_position ? truth_poses : estimated_poses;
    for (const ifar::sim::MovableObject& object : world.objects) {
      const auto seen = last_objects.find(object.id);
      run.final_objects.push_back(seen != last_objects.end() ? seen->second : object.pose);
    }
    const std::string problem = ifar::runner::writeRunPicture(
        world, ifar::common::VehicleSettings{}, ifar::geometry::Point(goal_x, goal_y), run, png_path);
    if (!problem.empty()) {
      std::fprintf(stderr, "ifar run-summary: error: --png: %s\n", problem.c_str());
      return 1;
    }
  }
  if (json) {
    // What the log holds, in the runner's schema; saturated pushes, routes and the loss accounting need the
    // runner's ground truth and stay at their "none" values.
    ifar::runner::RunSummary summary;
    summary.arrived = arrived;
    summary.reason = arrived ? "arrived" : "not arrived: " + reason;
    summary.distance_m = track.distance_m;
    summary.sim_time_s = seconds;
    summary.wall_time_s = static_cast<double>(last_event_us - first_event_us) * 1e-6;
    summary.pushes = pushes;
    summary.replans = replans;
    summary.affordance_updates = affordance_updates;
    summary.blocked_passages = blocked_passages;
    summary.goal_distance_m = remaining;
    summary.planner_frame = frames.total();
    summary.interaction = frames.interaction();
    summary.stages = frames.stages();
    summary.losses.problem = "not computed from a log (ifar run computes it)";
    std::printf("%s\n", ifar::runner::summaryJson(summary).c_str());
  } else {
    std::printf("arrived:            %s (%.2f m from the goal (%.2f, %.2f))\n", arrived ? "yes" : "no",
                remaining, goal_x, goal_y);
    std::printf("distance driven:    %.2f m in %.1f s (%s)\n", track.distance_m, seconds,
                truth.has_position ? "simulator ground truth" : "POSE");
    std::printf(
        "pushes / replans:   %d / %d; affordance updates %d; blocked passages %d; %d paths published\n",
        pushes, replans, affordance_updates, blocked_passages, paths);
    std::printf("executive at end:   %s\n", reason.c_str());
    if (undecodable > 0) {
      std::printf("skipped:            %d messages that did not decode\n", undecodable);
    }
  }
  return 0;
}
