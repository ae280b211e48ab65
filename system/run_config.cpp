#include "system/run_config.hpp"

#include <filesystem>

#include "common/config.hpp"
#include "common/daemon_main.hpp"
#include "drivers/can/open_bus.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "planner/node/node_settings.hpp"
#include "sim/node/node_settings.hpp"

namespace ifar::runner {
namespace {

common::ConfigNode loadFrom(const std::string& directory, const std::string& file)
{
  return common::ConfigNode::loadFile((std::filesystem::path(directory) / file).string());
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

void loadSimulator(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "sim.yaml");
  common::readDaemonKeys(root);
  request.sim = sim::loadSimNodeSettings(root);
  root.child("bus");           // required, as by ifar-sim ...
  root.acceptAllUnder("bus");  // ... but the simulated bus is in process
  root.rejectUnknownKeys();
}

void loadCan(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "can.yaml");
  common::readDaemonKeys(root);
  request.can_channel = can::loadBusSettings(root).lcm_channel;
  root.optional<std::string>("raw_channel", "");
  root.optional<std::string>("status_channel", "");
  request.force_sensor = force_sensor::loadForceSensorConfig(root);
  request.motor = motor::loadMotorConfig(root, request.vehicle);
  root.rejectUnknownKeys();
}

void loadVelodyne(const std::string& config_directory, RunRequest& request)
{
  const common::ConfigNode root = loadFrom(config_directory, "velodyne.yaml");
  common::readDaemonKeys(root);
  request.velodyne = velodyne::loadDriverSettings(root);
  root.rejectUnknownKeys();
}

}  // namespace

RunRequest loadRunSettings(const std::string& config_directory)
{
  RunRequest request;
  request.vehicle = common::loadVehicleSettings(loadFrom(config_directory, "vehicle.yaml"));
  loadPlanner(config_directory, request);
  loadExecutive(config_directory, request);
  loadSimulator(config_directory, request);
  loadCan(config_directory, request);
  loadVelodyne(config_directory, request);
  return request;
}

}  // namespace ifar::runner
