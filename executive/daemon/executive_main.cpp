// ifar-executive: the executive daemon (docs/executive.md). Steps the executive node (executive/node) at
// 50 Hz on the LCM bus; on exit it publishes a zero command.
//
// Obstacle points for the follower come from the executive's own decoding of VELODYNE_PACKET
// (executive/obstacles), so it reacts to a new obstacle within a packet, not a planner frame.

#include <cstdint>
#include <filesystem>
#include <string>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/config_search.hpp"
#include "common/daemon_main.hpp"
#include "common/time.hpp"
#include "common/vehicle.hpp"
#include "executive/daemon/executive_daemon.hpp"

namespace {

/// Publishes zero velocity three times when it goes out of scope.
struct StopOnExit {
  ifar::executive::ExecutiveDaemon& daemon;
  spdlog::logger& logger;
  StopOnExit(const StopOnExit&) = delete;
  StopOnExit(StopOnExit&&) = delete;
  StopOnExit& operator=(const StopOnExit&) = delete;
  StopOnExit& operator=(StopOnExit&&) = delete;
  ~StopOnExit()
  {
    for (int repeat = 0; repeat < 3; ++repeat) {
      daemon.publishStop();
    }
    logger.info("executive stopped; zero velocity published");
  }
};

int runExecutive(ifar::common::DaemonContext& context, const std::string& vehicle_path)
{
  // The executive's own file first, so its errors are reported whatever the vehicle file says.
  // The obstacles section before the rest: loadExecutiveSettings marks it all read.
  const ifar::executive::ObstacleSettings obstacles =
      ifar::executive::loadObstacleSettings(context.config.child("obstacles"));
  const ifar::executive::ExecutiveSettings settings = ifar::executive::loadExecutiveSettings(context.config);
  // Without --vehicle, vehicle.yaml is taken from beside the executive's config file, else the search path.
  const std::string vehicle_file =
      vehicle_path.empty()
          ? ifar::common::resolveReferencedFile("vehicle.yaml", context.config.sourceName()).path
          : vehicle_path;
  context.logger->info("vehicle {}", vehicle_file);
  const ifar::common::VehicleSettings vehicle =
      ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(vehicle_file));

  ifar::bus::RunLoop loop(context.lcm_url, context.logger);
  ifar::executive::ExecutiveDaemon daemon(loop, settings, obstacles, vehicle, context.logger);
  daemon.setJournalSettings(context.effective_config());
  ifar::bus::publishHeartbeats(loop, context.logger->name(), 1.0,
                               [&daemon] { return daemon.node().healthProblem(); });

  context.logger->info("executive running at {:.0f} Hz", 1.0 / ifar::executive::kControlPeriodS);
  // Leaving, by a signal or by an exception on its way out of the loop, the last command anyone hears is
  // a stop (the motor driver would stop the drives on the stale command anyway, 200 ms later).
  const StopOnExit stop_on_exit{daemon, *context.logger};
  return loop.run();
}

}  // namespace

int main(int argc, char** argv)
{
  std::string vehicle_path;
  return ifar::common::runDaemon(
      argc, argv,
      {"executive", "Executes GLOBAL_PATH: follows, pushes, adapts from touch, stops on stale input",
       "executive.yaml",
       [](const ifar::common::ConfigNode& config) {
         const auto obstacles = ifar::executive::loadObstacleSettings(config.child("obstacles"));
         ifar::common::ConfigDump dump;
         ifar::executive::executiveParameters().dump(ifar::executive::loadExecutiveSettings(config), "",
                                                     dump);
         ifar::executive::obstacleParameters().dump(obstacles, "obstacles", dump);
         return dump.yaml();
       }},
      [&vehicle_path](ifar::common::DaemonContext& context) { return runExecutive(context, vehicle_path); },
      [&vehicle_path](CLI::App& app) {
        app.add_option("--vehicle", vehicle_path,
                       "vehicle description (default: vehicle.yaml beside --config, else on the "
                       "configuration search path)");
      });
}
