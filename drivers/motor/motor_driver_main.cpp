// ifar-motor-driver: the vehicle's two wheel drives over CANopen CiA 402. A thin adapter around
// ifar::motor::MotorDriverNode (drivers/motor/motor_driver_node.hpp), which holds the logic: the
// executive's VELOCITY_CMD in (refused when stale by its own utime, from the future or not a number;
// limited to the vehicle's speeds and accelerations), the drives configured by SDO at start-up (their
// own limits and a watchdog on this driver), this driver's CANopen heartbeat, RPDO1 every cycle on the
// configured CAN bus (SocketCAN on a vehicle, the LCM bridge beside the simulator), each drive on
// MOTOR_STATUS at 10 Hz, and the wheels' actual velocities as odometry_t on ODOMETRY every cycle.
// Everything runs on the wall clock (the clock of velocity_cmd_t.utime). On exit the drives are commanded
// to zero and disabled.

#include <chrono>
#include <filesystem>
#include <string>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/config_search.hpp"
#include "common/daemon_main.hpp"
#include "common/rate_limiter.hpp"
#include "common/time.hpp"
#include "common/vehicle.hpp"
#include "drivers/can/open_bus.hpp"
#include "drivers/force_sensor/force_sensor_config.hpp"
#include "drivers/motor/motor_config.hpp"
#include "drivers/motor/motor_driver_node.hpp"
#include "ifar/velocity_cmd_t.hpp"

namespace {

constexpr double kStatusPeriodS = 0.1;
constexpr int kShutdownCycles = 20;  // cycles of zero velocity and disable frames sent on exit

/// --print-config: the whole can.yaml this driver checks, as loaded (the wheel geometry is the vehicle's).
std::string printedConfig(const ifar::common::ConfigNode& root)
{
  ifar::common::ConfigDump dump;
  ifar::can::busParameters().dump(ifar::can::loadBusSettings(root), "bus", dump);
  ifar::can::BusChannels channels;
  ifar::can::busChannelParameters().read(root, channels);
  ifar::can::busChannelParameters().dump(channels, "", dump);
  if (root.has("force_sensor")) {
    ifar::force_sensor::forceSensorParameters().dump(ifar::force_sensor::loadForceSensorConfig(root),
                                                     "force_sensor", dump);
  }
  ifar::motor::loadMotorSection(root);
  ifar::motor::motorParameters().dump(ifar::motor::readMotorSection(root), "motor", dump);
  return dump.yaml();
}

int run(ifar::common::DaemonContext& context, const std::string& vehicle_path,
        const std::string& command_channel)
{
  // vehicle.yaml beside the config file (else on the search path) unless --vehicle names another.
  const std::string vehicle_file =
      !vehicle_path.empty()
          ? vehicle_path
          : ifar::common::resolveReferencedFile("vehicle.yaml", context.config.sourceName()).path;
  context.logger->info("vehicle {}", vehicle_file);
  const auto bus_settings = ifar::can::loadBusSettings(context.config);
  // The force sensor's section of the shared file belongs to ifar-force-driver; when there is one, it is
  // checked here too: one can.yaml stops both or neither.
  if (context.config.has("force_sensor")) {
    ifar::force_sensor::loadForceSensorConfig(context.config);
  }
  ifar::can::BusChannels channels;  // the force driver's
  ifar::can::busChannelParameters().read(context.config, channels);
  if (context.config.has("motor")) {
    // Checked before the vehicle file is read, so a bad can.yaml is reported as such.
    context.config.child("motor");
  }
  const auto vehicle = ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(vehicle_file));
  const auto motor = ifar::motor::loadMotorConfig(context.config, vehicle);
  context.config.rejectUnknownKeys();
  auto& logger = *context.logger;
  ifar::motor::MotorDriverNode node(motor, vehicle);

  ifar::bus::RunLoop loop(context.lcm_url, context.logger);
  const auto now = [] { return ifar::common::nowMicroseconds(); };
  // What the driver waits for (the drives' heartbeats) is logged as it changes; refusals have their own log.
  auto waiting = ifar::bus::loggedProblem([&] { return node.readinessProblem(now()); }, context.logger);
  ifar::bus::publishHeartbeats(loop, context.logger->name(), 1.0, [&, waiting]() {
    const std::string awaited = waiting();
    const std::string health = node.takeHealthProblem(now());
    return awaited.empty() ? health : health.empty() ? awaited : awaited + "; " + health;
  });
  auto opened = ifar::can::openBus(bus_settings, loop.lcm());
  if (!opened.bus) {
    logger.error("{}", opened.error);
    return 1;
  }
  ifar::can::CanBus& bus = *opened.bus;
  const auto& setup = node.driveSetup();
  logger.info(
      "drives: left node {}, right node {} on {}; this driver is node {} (heartbeat every {} ms); "
      "wheel limit {} (0.001 rad/s); drive watchdog: heartbeat {} ms, RPDO {} ms; commands from {}",
      motor.drive.left.node_id, motor.drive.right.node_id, bus.name(), motor.master_node_id,
      motor.master_heartbeat_period_us / 1000, node.wheelVelocityLimit(), setup.master_heartbeat_timeout_ms,
      setup.rpdo_timeout_ms, command_channel);

  loop.subscribe<ifar::velocity_cmd_t>(command_channel,
                                       [&](const ifar::velocity_cmd_t& command, std::int64_t /*receive*/) {
                                         node.onVelocityCommand(command, now());
                                       });

  ifar::common::RateLimiter error_log(ifar::common::kMicrosecondsPerSecond);
  const auto cycle = [&] {
    const std::int64_t time = now();
    for (int budget = 0; budget < 1000; ++budget) {
      const auto received = bus.receive(std::chrono::microseconds(0));
      if (received.status == ifar::can::IoStatus::kError && error_log.allow(time)) {
        logger.error("{}: {}", bus.name(), received.error);
      }
      if (received.status != ifar::can::IoStatus::kOk) {
        break;
      }
      node.onFrame(received.frame, time);
    }
    for (const auto& frame : node.cycle(time)) {
      const auto sent = bus.send(frame);
      if (sent.status != ifar::can::IoStatus::kOk && error_log.allow(time)) {
        logger.error("{}: cannot send 0x{:03X}: {}", bus.name(), frame.id, sent.error);
      }
    }
    loop.publish(motor.odometry_channel, node.odometry(time));
  };
  loop.every(static_cast<double>(motor.cycle_us) * 1e-6, cycle);

  bool was_running = false;
  loop.every(kStatusPeriodS, [&] {
    const std::int64_t time = now();
    for (const auto& message : node.statusMessages(time)) {
      loop.publish(motor.status_channel, message);
    }
    if (const auto report = node.takeRefusalReport(time)) {
      logger.warn("{}", *report);
    }
    const bool running = node.running(time);
    if (running != was_running) {
      logger.info("drives {} ({} commands taken, {} refused so far)", running ? "running" : "stopped",
                  node.commandCounters().accepted, node.commandCounters().refused());
      was_running = running;
    }
  });

  const int result = loop.run();
  // Leave the drives standing and disabled, not coasting on the last command.
  node.stopAndDisable();
  for (int index = 0; index < kShutdownCycles; ++index) {
    cycle();
    loop.spinOnce(static_cast<int>(motor.cycle_us / 1000));
  }
  logger.info("drives commanded to zero and disabled");
  return result;
}

}  // namespace

int main(int argc, char** argv)
{
  std::string vehicle_path;
  std::string command_channel = "VELOCITY_CMD";
  return ifar::common::runDaemon(
      argc, argv,
      {"motor-driver", "Wheel drives over CANopen CiA 402: VELOCITY_CMD in, MOTOR_STATUS and ODOMETRY out",
       "can.yaml", printedConfig},
      [&](ifar::common::DaemonContext& context) { return run(context, vehicle_path, command_channel); },
      [&](CLI::App& app) {
        app.add_option("--vehicle", vehicle_path,
                       "vehicle description (wheel track and radius); default: vehicle.yaml beside --config, "
                       "else on the "
                       "configuration search path");
        app.add_option("--command-channel", command_channel, "velocity_cmd_t channel")->capture_default_str();
      });
}
