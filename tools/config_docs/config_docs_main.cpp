// ifar-config-docs: docs/configuration.md, the reference of every config key, written from the parameter
// declarations (common/parameters.hpp) so it cannot drift from what the loaders read. --check compares
// the committed file instead and fails, naming the command to regenerate it, when they differ.

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/command_line.hpp"
#include "common/daemon_main.hpp"
#include "common/parameters.hpp"
#include "common/vehicle.hpp"
#include "drivers/can/open_bus.hpp"
#include "drivers/force_sensor/force_sensor_config.hpp"
#include "drivers/motor/motor_config.hpp"
#include "drivers/velodyne/driver_settings.hpp"
#include "executive/modes/executive_settings.hpp"
#include "executive/obstacles/local_obstacles.hpp"
#include "planner/graph/settings.hpp"
#include "planner/interaction/settings_loader.hpp"
#include "planner/node/node_settings.hpp"
#include "planner/perception/perception_settings.hpp"
#include "sim/node/node_settings.hpp"

namespace {

template <typename Settings>
std::string section(const std::string& title, const std::string& about,
                    const ifar::common::ParameterTable<Settings>& table)
{
  return "### " + title + "\n\n" + about + "\n\n" + table.markdown() + "\n";
}

std::string plannerFile()
{
  namespace planner = ifar::planner;
  // `interaction:` holds the planner's own switch and the interaction planner's keys: one table.
  auto infos = planner::plannerInteractionParameters().infos();
  auto defaults = planner::plannerInteractionParameters().values(planner::PlannerSettings{});
  for (const auto& info : ifar::interaction::interactionParameters().infos()) {
    infos.push_back(info);
  }
  for (const auto& value :
       ifar::interaction::interactionParameters().values(ifar::interaction::InteractionSettings{})) {
    defaults.push_back(value);
  }
  return "## config/planner.yaml\n\nThe planner daemon and the headless runner; every section but "
         "`perception:` is "
         "optional.\n\n" +
         section("Top level and `daemon:`", "Rate, input ages, channels and the vehicle file.",
                 planner::nodeParameters()) +
         section(
             "`perception:`",
             "Points to obstacle outlines in the local layer; which returns are obstacles is vehicle.yaml "
             "`lidar:`. Every key is required.",
             ifar::perception::perceptionParameters()) +
         section("`graph:`", "DV-graph merge, voting and search (docs/graph.md).",
                 ifar::graph::graphParameters()) +
         "### `interaction:`\n\nTopological waypoints and push plans (docs/interaction.md); the pusher "
         "(bumper, "
         "half width, traction) is vehicle.yaml's.\n\n" +
         ifar::common::parameterMarkdown(infos, defaults) + "\n";
}

std::string canFile()
{
  return "## config/can.yaml\n\nThe vehicle's CAN bus, read by ifar-force-driver, ifar-motor-driver and the "
         "simulator (sim.yaml `can_config`): the one home of the bus, the drive node ids and the force frame "
         "id. Frame layouts: docs/can_frames.md.\n\n" +
         section("`bus:`", "Which bus the CAN daemons and the simulator use.", ifar::can::busParameters()) +
         section("Top level", "Where the bus is republished.", ifar::can::busChannelParameters()) +
         section("`force_sensor:`", "The bumper force sensor.", ifar::force_sensor::forceSensorParameters()) +
         section("`motor:`", "The wheel drives (CANopen CiA 402) and the driver's timing.",
                 ifar::motor::motorParameters());
}

const char* const kSeparateOnPurpose = R"(## One home per fact

- Which lidar returns are obstacles (ground clearance, height, least range, reflectivity of movable
  objects) is the vehicle's sensor and mount: vehicle.yaml `lidar:`, read by the planner's perception and
  the executive's obstacle points alike.
- The CAN bus, the drives' node ids and the force sensor's frame id: can.yaml, read by both drivers and
  by the simulator (sim.yaml `can_config`; the headless runner reads can.yaml from its config directory).
- Kept apart on purpose:
  - planner.yaml `daemon.arrival_radius_m` (0.5) and executive.yaml `goal_tolerance_m` (0.3): the first
    is what PLANNER_STATUS reports as arrived (the planner keeps publishing the path), the second where
    the executive stops the vehicle; the planner's report comes a little before the stop.
  - executive.yaml `obstacles.max_range_m` (15 m) and the lidar's range (sim.yaml `lidar.max_range_m`,
    100 m): the follower only looks a few metres round the vehicle; the planner uses the whole range.
  - planner.yaml `perception.inflation_radius_m` is half of vehicle.yaml `width_m`, and
    `perception.layer_size_m` twice the lidar's range: both are stated where they are used.
  - The VLP-16 data port appears three times (sim.yaml `lidar.port`, velodyne.yaml `data_port`,
    planner.yaml `daemon.data_port`): three processes' views of one UDP port; the simulator stands in for
    the sensor, whose port is set in the sensor itself. config/launch/sim_demo.yaml gives all three the
    value of IFAR_LIDAR_PORT with `--set` (every daemon takes `--set KEY=VALUE` over its file's key).
)";

std::string document()
{
  std::ostringstream out;
  out << "# Configuration reference\n\n"
         "Every key of config/*.yaml: its type, unit, default, allowed range and what it does. Generated "
         "from "
         "the declarations the loaders read with (common/parameters.hpp); do not edit by hand, run\n"
         "`build/bin/ifar-config-docs --out docs/configuration.md`. Unknown keys are an error; a required "
         "key "
         "shows `required` as its default. Every daemon prints its effective configuration with "
         "`--print-config`, and `ifar run --print-config` prints all six files.\n\n";
  out << "## config/vehicle.yaml\n\nThe vehicle: dimensions, limits, lidar mount and filter, force sensor. "
         "Read "
         "by the simulator, planner, executive and motor driver. Every key is required.\n\n"
      << ifar::common::vehicleParameters().markdown() << "\n";
  out << plannerFile();
  out << "## config/executive.yaml\n\nThe executive (docs/executive.md). Every key is required.\n\n"
      << section("Top level and parts", "Path following, doorways, pushing, tactile adaptation.",
                 ifar::executive::executiveParameters())
      << section("`obstacles:`", "The executive's own lidar points, decoded per packet.",
                 ifar::executive::obstacleParameters());
  out << "## config/sim.yaml\n\nThe simulator daemon (docs/simulator.md). Every key is optional.\n\n"
      << ifar::sim::simNodeParameters().markdown() << "\n";
  out << canFile();
  out << "## config/velodyne.yaml\n\nThe VLP-16 driver (docs/velodyne.md). Every key is optional.\n\n"
      << ifar::velodyne::driverParameters().markdown() << "\n";
  out << "## Every daemon's file\n\nMay hold these at its top level too.\n\n"
      << ifar::common::daemonKeyParameters().markdown() << "\n";
  out << kSeparateOnPurpose;
  return out.str();
}

}  // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Writes docs/configuration.md from the parameter declarations", "ifar-config-docs"};
  std::string out_path;
  std::string check_path;
  app.add_option("--out", out_path, "write the reference to this file (default: stdout)");
  app.add_option("--check", check_path, "compare with this file instead; exit 1 when it differs");
  if (const auto exit_code = ifar::common::parseCommandLine(app, argc, argv)) {
    return *exit_code;
  }
  const std::string text = document();
  if (!check_path.empty()) {
    std::ifstream in(check_path);
    std::ostringstream committed;
    committed << in.rdbuf();
    if (committed.str() != text) {
      std::cerr << check_path << " is not what the declarations give; regenerate it with\n"
                << "  build/bin/ifar-config-docs --out docs/configuration.md\n";
      return 1;
    }
    return 0;
  }
  if (out_path.empty()) {
    std::cout << text;
    return 0;
  }
  std::ofstream(out_path) << text;
  return 0;
}
