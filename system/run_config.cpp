#include "system/run_config.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "common/config.hpp"
#include "common/config_search.hpp"
#include "common/daemon_main.hpp"
#include "drivers/can/open_bus.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/node/node_settings.hpp"
#include "sim/node/node_settings.hpp"

namespace ifar::runner {
namespace {

/// The configuration search path with `directory` (--config-dir; must be a folder) first; "" = the standard
/// one.
common::ConfigSearchPath searchPath(const std::string& directory)
{
  if (directory.empty()) {
    return common::ConfigSearchPath::standard();
  }
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) {
    throw common::ConfigError("--config-dir '" + directory + "': no such folder");
  }
  return common::ConfigSearchPath::standard().withFirst(directory, "--config-dir");
}

common::ConfigNode loadFrom(const std::string& directory, const std::string& file)
{
  return common::ConfigNode::loadFile(searchPath(directory).locate(file).path);
}

void loadPlanner(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "planner.yaml");
  common::readDaemonKeys(root);
  const planner::PlannerConfig config = planner::loadPlannerConfig(root);
  request.planner = config.planner;
  request.planner.vehicle = request.vehicle;
  request.planner.interaction.pusher = interaction::PusherSettings::fromVehicle(request.vehicle);
  request.planner_node = config.node;
}

void loadExecutive(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "executive.yaml");
  common::readDaemonKeys(root);
  // The `obstacles:` section first: loadExecutiveSettings leaves it to its own loader (required, as in
  // the executive daemon).
  request.obstacles = executive::loadObstacleSettings(root.child("obstacles"));
  request.executive = executive::loadExecutiveSettings(root);
  root.rejectUnknownKeys();
}

void loadSimulator(const std::string& config_directory, const std::string& sensing, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "sim.yaml");
  common::readDaemonKeys(root);
  request.sim = sim::loadSimNodeSettings(
      root,
      sensing.empty() ? std::nullopt : std::optional<sim::SensingProfile>(sim::parseSensingProfile(sensing)));
  root.rejectUnknownKeys();
}

void loadCan(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "can.yaml");
  common::readDaemonKeys(root);
  request.can_channel = can::loadBusSettings(root).lcm_channel;
  can::BusChannels channels;  // read and unused: the simulated bus is in process
  can::busChannelParameters().read(root, channels);
  request.force_sensor = force_sensor::loadForceSensorConfig(root);
  request.motor = motor::loadMotorConfig(root, request.vehicle);
  // The simulator's emulated drives and force sensor answer to the ids the drivers use: one home, can.yaml
  // (the `can_config` path inside sim.yaml names it for the daemon).
  request.sim.can_nodes = sim::loadCanNodes(root, request.sim.can_nodes);
  root.rejectUnknownKeys();
}

void loadVelodyne(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "velodyne.yaml");
  common::readDaemonKeys(root);
  request.velodyne = velodyne::loadDriverSettings(root);
  root.rejectUnknownKeys();
}

/// One file's document of the dump: its daemon keys and `body`.
std::string document(const std::string& directory, const std::string& file, const std::string& body)
{
  const common::ConfigNode root = loadFrom(directory, file);
  return "--- # " + root.sourceName() + "\n" +
         common::daemonKeyParameters().yaml(common::readDaemonKeys(root)) + body;
}

std::string canYaml(const std::string& directory, const RunRequest& request)
{
  const common::ConfigNode root = loadFrom(directory, "can.yaml");
  common::ConfigDump dump;
  can::busParameters().dump(can::loadBusSettings(root), "bus", dump);
  can::BusChannels channels;
  can::busChannelParameters().read(root, channels);
  can::busChannelParameters().dump(channels, "", dump);
  force_sensor::forceSensorParameters().dump(request.force_sensor, "force_sensor", dump);
  motor::motorParameters().dump(motor::readMotorSection(root), "motor", dump);
  return dump.yaml();
}

}  // namespace

std::string runConfigYaml(const std::string& config_directory)
{
  const RunRequest request = loadRunSettings(config_directory);
  std::string text = "# ifar run: effective configuration\n";
  text += "--- # " + loadFrom(config_directory, "vehicle.yaml").sourceName() + "\n" +
          common::vehicleParameters().yaml(request.vehicle);
  planner::PlannerConfig planner{request.planner, request.planner_node};
  text += document(config_directory, "planner.yaml", planner::plannerConfigYaml(planner));
  common::ConfigDump executive;
  executive::executiveParameters().dump(request.executive, "", executive);
  executive::obstacleParameters().dump(request.obstacles, "obstacles", executive);
  text += document(config_directory, "executive.yaml", executive.yaml());
  text += document(config_directory, "sim.yaml", sim::simNodeParameters().yaml(request.sim));
  text += document(config_directory, "can.yaml", canYaml(config_directory, request));
  text += document(config_directory, "velodyne.yaml", velodyne::driverParameters().yaml(request.velodyne));
  return text;
}

std::vector<common::FoundConfig> runConfigFiles(const std::string& config_directory)
{
  std::vector<common::FoundConfig> files;
  const common::ConfigSearchPath search = searchPath(config_directory);
  for (const char* name :
       {"vehicle.yaml", "planner.yaml", "executive.yaml", "sim.yaml", "can.yaml", "velodyne.yaml"}) {
    files.push_back(search.locate(name));
  }
  return files;
}

std::vector<std::string> sensingProfileNames()
{
  return sim::sensingProfileNames();
}

RunRequest loadRunSettings(const std::string& config_directory, const std::string& sensing)
{
  RunRequest request;
  request.vehicle = common::loadVehicleSettings(loadFrom(config_directory, "vehicle.yaml"));
  loadPlanner(config_directory, request);
  loadExecutive(config_directory, request);
  loadSimulator(config_directory, sensing, request);
  loadCan(config_directory, request);
  loadVelodyne(config_directory, request);
  return request;
}

}  // namespace ifar::runner
