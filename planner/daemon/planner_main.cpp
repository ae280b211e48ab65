// ifar-planner: the LCM adapter around the planner node (planner/node). Packets and poses are checked and
// gathered into revolutions on the LCM thread; at the configured rate the latest revolution (and any goal
// change) goes to a worker thread, so a slow frame never blocks the loop. A revolution ready while the
// worker is busy waits for the next tick and is counted as dropped; revolutions between ticks are
// skipped by design (their input flags carry over).

#include <string>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/config_search.hpp"
#include "common/daemon_main.hpp"
#include "common/vehicle.hpp"
#include "planner/core/planner.hpp"
#include "planner/daemon/planner_daemon.hpp"
#include "planner/node/node_settings.hpp"

namespace ifar::planner {
namespace {

int runPlanner(common::DaemonContext& context)
{
  const common::ConfigNode& config = context.config;
  const PlannerConfig loaded = loadPlannerConfig(config);
  PlannerSettings settings = loaded.planner;
  const NodeSettings& node_settings = loaded.node;
  const std::string vehicle_file =
      common::resolveReferencedFile(node_settings.vehicle_config, config.sourceName()).path;
  settings.vehicle = common::loadVehicleSettings(common::ConfigNode::loadFile(vehicle_file));
  const auto& logger = context.logger;
  logger->info("vehicle {}", vehicle_file);

  Planner planner(settings);
  if (!node_settings.prior_graph.empty()) {
    const std::string error = planner.loadPriorGraph(node_settings.prior_graph);
    if (error.empty()) {
      logger->info("prior graph {}: {} vertices", node_settings.prior_graph, planner.graph().vertexCount());
    } else {
      // A prior map asked for and missing is a bad config: starting empty would plan without it unnoticed.
      config.child("daemon").fail("prior_graph", "cannot load the prior graph: " + error);
    }
  }

  bus::RunLoop loop(context.lcm_url, logger);
  PlannerDaemon daemon(loop, node_settings, std::move(planner), logger, WorkerThreading::OwnThread);
  daemon.setJournalSettings(context.effective_config());
  bus::publishHeartbeats(loop, logger->name(), 1.0,
                         [&daemon, &loop] { return daemon.node().healthProblem(loop.now()); });

  const PlannerChannels& channels = node_settings.channels;
  logger->info("planning at {} Hz on {}; publishing {}, {}, {}", node_settings.rate_hz,
               channels.velodyne_packet, channels.dv_graph, channels.global_path, channels.planner_status);
  const int code = loop.run();
  const PlannerNode& node = daemon.node();
  logger->info("stopped: {} updates published, {} frames dropped, {} revolutions skipped, {} inputs refused",
               node.published(), node.droppedFrames(), node.skippedRevolutions(), node.refusedInputs());
  return code;
}

}  // namespace
}  // namespace ifar::planner

int main(int argc, char** argv)
{
  return ifar::common::runDaemon(
      argc, argv,
      {"planner",
       "DV-graph planner: VELODYNE_PACKET, POSE, GOAL in; DV_GRAPH, "
       "GLOBAL_PATH, PLANNER_STATUS out",
       "planner.yaml",
       [](const ifar::common::ConfigNode& config) {
         return ifar::planner::plannerConfigYaml(ifar::planner::loadPlannerConfig(config));
       }},
      ifar::planner::runPlanner);
}
