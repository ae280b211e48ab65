// ifar-sim WORLD.yaml: the simulator in real time, indistinguishable from the vehicle on the wire.
// VLP-16 data packets by UDP (754/s), the force sensor and the two wheel drives on the configured CAN bus
// (velocity commands arrive as RPDO1 frames), POSE at 50 Hz and SIM_GROUND_TRUTH for evaluation.
// With `commands: source: lcm` it follows velocity_cmd_t on VELOCITY_CMD instead of the drives. The
// simulation itself is the simulator node (sim/node), which the headless runner steps as well.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/config_search.hpp"
#include "common/daemon_main.hpp"
#include "common/rate_limiter.hpp"
#include "common/time.hpp"
#include "common/vehicle.hpp"
#include "drivers/can/open_bus.hpp"
#include "ifar/velocity_cmd_t.hpp"
#include "sim/generators/generators.hpp"
#include "sim/lidar/udp_sender.hpp"
#include "sim/node/node_settings.hpp"
#include "sim/node/simulator_node.hpp"
#include "sim/simulator/builtin_worlds.hpp"
#include "sim/simulator/simulator.hpp"
#include "sim/world/world_file.hpp"

namespace {

struct CommandLine {
  std::string world_path;
  std::string builtin;
  std::string generate;
  std::string sensing;  // --sensing: a profile instead of the config's sensing.profile
};

/// The config's settings, with the command line's sensing profile when given.
ifar::sim::SimNodeSettings loadSettings(const ifar::common::ConfigNode& config,
                                        const CommandLine& command_line)
{
  std::optional<ifar::sim::SensingProfile> profile;
  if (!command_line.sensing.empty()) {
    profile = ifar::sim::parseSensingProfile(command_line.sensing);
  }
  return ifar::sim::loadSimNodeSettings(config, profile);
}

int runSimulator(ifar::common::DaemonContext& context, const CommandLine& command_line)
{
  auto& logger = *context.logger;
  auto settings = loadSettings(context.config, command_line);
  context.config.rejectUnknownKeys();
  const std::string vehicle_file =
      ifar::common::resolveReferencedFile(settings.vehicle_config, context.config.sourceName()).path;
  const auto vehicle = ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(vehicle_file));
  // The bus, the drives' node ids and the force frame id are the vehicle's CAN configuration: the file
  // the CAN drivers read.
  const std::string can_file =
      ifar::common::resolveReferencedFile(settings.can_config, context.config.sourceName()).path;
  const auto can_config = ifar::common::ConfigNode::loadFile(can_file);
  logger.info("vehicle {}, CAN {}", vehicle_file, can_file);
  const auto bus_settings = ifar::can::loadBusSettings(can_config);
  settings.can_nodes = ifar::sim::loadCanNodes(can_config, settings.can_nodes);

  ifar::sim::World world;
  // A world is a file, or a name on the configuration search path (demo_room: worlds/demo_room.yaml).
  std::string world_path = command_line.world_path.empty() ? settings.world : command_line.world_path;
  if (!world_path.empty()) {
    if (const auto found = ifar::common::findNamedInput(world_path, "worlds")) {
      world_path = found->path;
    }
  }
  if (!command_line.generate.empty()) {
    const auto kind = ifar::sim::parseWorldKind(command_line.generate);
    if (!kind) {
      logger.error("--generate: unknown world kind '{}' (room, room_objects, office, tunnel, demo_room)",
                   command_line.generate);
      return 2;
    }
    auto generated = ifar::sim::generateWorld(*kind, settings.simulator.seed);
    if (!generated.ok()) {
      logger.error("{}", generated.error());
      return 2;
    }
    world = std::move(generated.world());
  } else if (!command_line.builtin.empty()) {
    if (!ifar::sim::builtinWorldByName(command_line.builtin, world)) {
      logger.error("unknown builtin world '{}' (room, push_light, push_heavy, tunnel)", command_line.builtin);
      return 2;
    }
  } else if (!world_path.empty()) {
    auto loaded = ifar::sim::loadWorldFile(world_path);
    if (!loaded.ok()) {
      logger.error("{}", loaded.error());
      return 2;
    }
    world = std::move(loaded.world());
  } else {
    logger.error("no world: give WORLD.yaml, --generate KIND, --builtin NAME, or `world:` in the config");
    return 2;
  }

  ifar::bus::RunLoop loop(context.lcm_url, context.logger);
  ifar::bus::publishHeartbeats(loop, context.logger->name());
  auto opened = ifar::can::openBus(bus_settings, loop.lcm());
  if (!opened.bus) {
    logger.error("CAN bus: {}", opened.error);
    return 2;
  }
  auto& bus = *opened.bus;
  ifar::sim::UdpSender lidar_sender(settings.lidar_host, settings.lidar_port);
  settings.simulator.epoch_utime = ifar::common::nowMicroseconds();
  ifar::sim::SimulatorNode node(world, vehicle, settings);
  logger.info(
      "world '{}' from {}: {} obstacles, {} movable objects; lidar to {}:{}, CAN on {}, commands from {}, "
      "sensing {}",
      world.name, world.source, world.obstacles.size(), world.objects.size(), settings.lidar_host,
      settings.lidar_port, bus.name(),
      settings.command_source == ifar::sim::CommandSource::kCan ? "the drives (RPDO1)"
                                                                : settings.velocity_channel,
      ifar::sim::sensingProfileName(settings.simulator.sensing.profile));

  if (settings.command_source == ifar::sim::CommandSource::kLcm) {
    loop.subscribe<ifar::velocity_cmd_t>(
        settings.velocity_channel,
        [&node](const ifar::velocity_cmd_t& message, std::int64_t) { node.onVelocityCommand(message); });
  }

  std::int64_t start_monotonic = ifar::common::monotonicMicroseconds();
  constexpr std::int64_t kMaxCatchUpNs = 200'000'000;
  std::int64_t frames_in = 0;
  std::int64_t can_send_errors = 0;
  ifar::common::RateLimiter warn_limiter(5'000'000);
  ifar::common::RateLimiter status_limiter(10'000'000);

  loop.every(settings.simulator.physics.step_seconds, [&] {
    const std::int64_t now_monotonic = ifar::common::monotonicMicroseconds();
    // Catch up with the wall clock (whole physics steps; the remainder carries over).
    std::int64_t behind_ns = (now_monotonic - start_monotonic) * 1000 - node.simulator().timeNanoseconds();
    if (behind_ns > kMaxCatchUpNs) {
      // The process was stalled (suspended, overloaded): skip the gap instead of bursting packets.
      start_monotonic += (behind_ns - kMaxCatchUpNs) / 1000;
      behind_ns = kMaxCatchUpNs;
      if (warn_limiter.allow(now_monotonic)) {
        logger.warn("running behind real time; skipped ahead");
      }
    }
    // Frames from the bus to the emulated drives, stamped with when they arrive on the simulated clock
    // (the wall clock's simulated equivalent, not the time the simulation has reached): after a stall of
    // this process, the drives must not take frames that waited in its queue for a silent motor driver.
    const std::int64_t arrival_us = node.nowUtime() + std::max<std::int64_t>(behind_ns / 1000, 0);
    while (true) {
      const auto received = bus.receive(std::chrono::microseconds(0));
      if (received.status != ifar::can::IoStatus::kOk) {
        if (received.status == ifar::can::IoStatus::kError && warn_limiter.allow(now_monotonic)) {
          logger.warn("CAN bus {}: {}", bus.name(), received.error);
        }
        break;
      }
      if (!received.frame.error()) {
        node.onFrame(received.frame, arrival_us);
        ++frames_in;
      }
    }
    if (behind_ns <= 0) {
      return;
    }
    const ifar::sim::SimulatorStep step = node.step(static_cast<double>(behind_ns) * 1e-9);
    const ifar::sim::StepOutput& output = step.output;
    for (const auto& packet : output.packets) {
      if (!lidar_sender.send(ifar::common::ByteView(packet)) && warn_limiter.allow(now_monotonic)) {
        logger.warn("lidar packets to {}:{} failing ({} so far)", settings.lidar_host, settings.lidar_port,
                    lidar_sender.failures());
      }
    }
    for (const auto& frame : step.frames) {
      if (bus.send(frame).status != ifar::can::IoStatus::kOk) {
        ++can_send_errors;
      }
    }
    if (step.pose) {
      loop.publish(settings.pose_channel, *step.pose);
    }
    if (step.ground_truth) {
      loop.publish(settings.ground_truth_channel, *step.ground_truth);
    }
    if (status_limiter.allow(now_monotonic)) {
      logger.info("t={:.1f}s packets sent {} (failed {}), CAN frames in {} (send errors {}), drives {}",
                  static_cast<double>(output.time_ns) * 1e-9, lidar_sender.sent(), lidar_sender.failures(),
                  frames_in, can_send_errors, node.canNodes().drivesEnabled() ? "enabled" : "not enabled");
    }
  });
  return loop.run();
}

}  // namespace

int main(int argc, char** argv)
{
  CommandLine command_line;
  return ifar::common::runDaemon(
      argc, argv,
      {"sim", "Simulator: VLP-16 packets by UDP, CAN force sensor and drives, POSE", "sim.yaml",
       [&command_line](const ifar::common::ConfigNode& config) {
         const auto settings = loadSettings(config, command_line);
         const auto can_config = ifar::common::ConfigNode::loadFile(
             ifar::common::resolveReferencedFile(settings.can_config, config.sourceName()).path);
         ifar::can::loadBusSettings(can_config);
         ifar::sim::loadCanNodes(can_config);
         return ifar::sim::simNodeParameters().yaml(settings);
       }},
      [&](ifar::common::DaemonContext& context) { return runSimulator(context, command_line); },
      [&](CLI::App& app) {
        app.add_option("world", command_line.world_path,
                       "World file (YAML, docs/worlds.md), or a world's name on the configuration search "
                       "path (demo_room)");
        app.add_option(
            "--generate", command_line.generate,
            "Generate the world (seed from the config): room, room_objects, office, tunnel, demo_room");
        app.add_option("--builtin", command_line.builtin,
                       "Use a built-in world instead of a file: room, push_light, push_heavy, tunnel");
        app.add_option(
               "--sensing", command_line.sensing,
               "Sensing profile instead of the config's sensing.profile: ideal (exact sensors) or field "
               "(docs/simulator.md); the config's other sensing keys still apply")
            ->check(CLI::IsMember(ifar::sim::sensingProfileNames()));
      });
}
