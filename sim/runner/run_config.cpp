#include "sim/runner/run_config.hpp"

#include <filesystem>

#include "common/config.hpp"
#include "common/daemon_main.hpp"
#include "planner/daemon/daemon_settings.hpp"
#include "planner/interaction/interaction_settings.hpp"
#include "sim/daemon/daemon_settings.hpp"

namespace ifar::runner {
namespace {

common::ConfigNode loadFrom(const std::string& directory, const std::string& file)
{
  return common::ConfigNode::loadFile((std::filesystem::path(directory) / file).string());
}

}  // namespace

RunRequest loadRunSettings(const std::string& config_directory)
{
  RunRequest request;
  request.vehicle = common::loadVehicleSettings(loadFrom(config_directory, "vehicle.yaml"));

  const common::ConfigNode planner_root = loadFrom(config_directory, "planner.yaml");
  common::readDaemonKeys(planner_root);
  const planner::PlannerConfig planner_config = planner::loadPlannerConfig(planner_root);
  request.planner = planner_config.planner;
  request.planner.vehicle = request.vehicle;
  request.planner.interaction.pusher = interaction::PusherSettings::fromVehicle(request.vehicle);
  request.planner_rate_hz = planner_config.daemon.rate_hz;
  request.path_resend_hz = planner_config.daemon.path_resend_hz;

  const common::ConfigNode executive_root = loadFrom(config_directory, "executive.yaml");
  common::readDaemonKeys(executive_root);
  // The `obstacles:` section first: loadExecutiveSettings leaves it to its own loader (required, as in
  // the executive daemon).
  request.obstacles = executive::loadObstacleSettings(executive_root.child("obstacles"));
  request.executive = executive::loadExecutiveSettings(executive_root);
  executive_root.rejectUnknownKeys();

  const common::ConfigNode sim_root = loadFrom(config_directory, "sim.yaml");
  common::readDaemonKeys(sim_root);
  request.simulator = sim::loadSimDaemonSettings(sim_root).simulator;
  sim_root.child("bus");           // required, as by ifar-sim ...
  sim_root.acceptAllUnder("bus");  // ... but the runner connects no CAN bus
  sim_root.rejectUnknownKeys();
  return request;
}

}  // namespace ifar::runner
