// ifar-motor-driver: the vehicle's two wheel drives over CANopen CiA 402. Takes the executive's
// VELOCITY_CMD (v, omega), runs one motor client per drive on the configured CAN bus (SocketCAN on a
// vehicle, the LCM bridge beside the simulator), and reports each drive on MOTOR_STATUS at 10 Hz. The
// clients stop the drives by themselves on a fault, a lost heartbeat or a command older than the
// timeout (config/can.yaml motor:), so a dead executive stops the vehicle; on exit the drives are
// commanded to zero and disabled.

#include <chrono>
#include <filesystem>
#include <string>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/daemon_main.hpp"
#include "common/rate_limiter.hpp"
#include "common/time.hpp"
#include "common/vehicle.hpp"
#include "drivers/can/open_bus.hpp"
#include "drivers/force_sensor/force_sensor_config.hpp"
#include "drivers/motor/differential_drive.hpp"
#include "drivers/motor/motor_config.hpp"
#include "drivers/motor/motor_status_message.hpp"
#include "ifar/velocity_cmd_t.hpp"

namespace {

constexpr double kStatusPeriodS = 0.1;
constexpr int kShutdownCycles = 20;  // cycles of zero velocity and disable frames sent on exit

int run(ifar::common::DaemonContext& context, const std::string& vehicle_path,
        const std::string& command_channel)
{
  // vehicle.yaml sits beside the config file unless --vehicle names another.
  const std::string vehicle_file =
      !vehicle_path.empty()
          ? vehicle_path
          : (std::filesystem::path(context.config.sourceName()).parent_path() / "vehicle.yaml").string();
  const auto bus_settings = ifar::can::loadBusSettings(context.config);
  // The force sensor's section of the shared file belongs to ifar-force-driver; when there is one, it is
  // checked here too: one can.yaml stops both or neither.
  if (context.config.has("force_sensor")) {
    ifar::force_sensor::loadForceSensorConfig(context.config);
  }
  context.config.optional<std::string>("raw_channel", "");
  context.config.optional<std::string>("status_channel", "");
  if (context.config.has("motor")) {
    // Checked before the vehicle file is read, so a bad can.yaml is reported as such.
    context.config.child("motor");
  }
  const auto motor = ifar::motor::loadMotorConfig(
      context.config, ifar::common::loadVehicleSettings(ifar::common::ConfigNode::loadFile(vehicle_file)));
  context.config.rejectUnknownKeys();
  auto& logger = *context.logger;

  ifar::bus::RunLoop loop(context.lcm_url, context.logger);
  ifar::bus::publishHeartbeats(loop, context.logger->name());
  auto opened = ifar::can::openBus(bus_settings, loop.lcm());
  if (!opened.bus) {
    logger.error("{}", opened.error);
    return 1;
  }
  ifar::can::CanBus& bus = *opened.bus;
  ifar::motor::DifferentialDrive drive(motor.drive);
  logger.info("drives: left node {}, right node {} on {}; commands from {}", motor.drive.left.node_id,
              motor.drive.right.node_id, bus.name(), command_channel);

  ifar::common::RateLimiter error_log(ifar::common::kMicrosecondsPerSecond);
  std::int64_t commands = 0;
  loop.subscribe<ifar::velocity_cmd_t>(command_channel, [&](const ifar::velocity_cmd_t& command,
                                                            std::int64_t /*receive*/) {
    drive.command(command.linear_velocity, command.angular_velocity, ifar::common::monotonicMicroseconds());
    ++commands;
  });

  const auto cycle = [&] {
    const std::int64_t now = ifar::common::monotonicMicroseconds();
    for (int budget = 0; budget < 1000; ++budget) {
      const auto received = bus.receive(std::chrono::microseconds(0));
      if (received.status == ifar::can::IoStatus::kError && error_log.allow(now)) {
        logger.error("{}: {}", bus.name(), received.error);
      }
      if (received.status != ifar::can::IoStatus::kOk) {
        break;
      }
      drive.onFrame(received.frame, now);
    }
    for (const auto& frame : drive.update(now)) {
      const auto sent = bus.send(frame);
      if (sent.status != ifar::can::IoStatus::kOk && error_log.allow(now)) {
        logger.error("{}: cannot send 0x{:03X}: {}", bus.name(), frame.id, sent.error);
      }
    }
  };
  loop.every(static_cast<double>(motor.cycle_us) * 1e-6, cycle);

  bool was_running = false;
  loop.every(kStatusPeriodS, [&] {
    const std::int64_t now = ifar::common::monotonicMicroseconds();
    const std::int64_t utime = ifar::common::nowMicroseconds();
    const auto left = drive.leftStatus(now);
    const auto right = drive.rightStatus(now);
    loop.publish(motor.status_channel, ifar::motor::toMessage(left, utime));
    loop.publish(motor.status_channel, ifar::motor::toMessage(right, utime));
    const bool running = drive.running(now);
    if (running != was_running) {
      logger.info("drives {} ({} commands so far)", running ? "running" : "stopped", commands);
      was_running = running;
    }
  });

  const int result = loop.run();
  // Leave the drives standing and disabled, not coasting on the last command.
  drive.command(0.0, 0.0, ifar::common::monotonicMicroseconds());
  drive.setEnabled(false);
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
      {"motor-driver", "Wheel drives over CANopen CiA 402: VELOCITY_CMD in, MOTOR_STATUS out",
       "config/can.yaml"},
      [&](ifar::common::DaemonContext& context) { return run(context, vehicle_path, command_channel); },
      [&](CLI::App& app) {
        app.add_option("--vehicle", vehicle_path,
                       "vehicle description (wheel track and radius); default: vehicle.yaml beside --config");
        app.add_option("--command-channel", command_channel, "velocity_cmd_t channel")->capture_default_str();
      });
}
