// ifar-force-driver: reads the bumper force sensor's frames from the configured CAN bus (SocketCAN, the
// LCM bridge, or a candump log), publishes force_t on FORCE for every valid frame (and while the sensor
// is silent, every timeout period with STATUS_SILENT), republishes raw frames from a SocketCAN/candump
// bus as can_frame_t, and reports the bus's health on CAN_STATUS once a second.

#include <chrono>
#include <cstdint>
#include <string>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/daemon_main.hpp"
#include "common/input_silence.hpp"
#include "common/rate_limiter.hpp"
#include "common/time.hpp"
#include "drivers/can/error_frame.hpp"
#include "drivers/can/lcm_bridge_bus.hpp"
#include "drivers/can/open_bus.hpp"
#include "drivers/force_sensor/force_driver_node.hpp"
#include "drivers/force_sensor/force_sensor_config.hpp"
#include "drivers/motor/motor_config.hpp"
#include "ifar/can_bus_status_t.hpp"

namespace {

/// How long without a valid force frame counts as waiting for the sensor.
constexpr double kAwaitedFramesS = 1.0;

struct DriverSettings {
  ifar::can::BusSettings bus;
  std::string raw_channel;
  std::string status_channel;
  std::string force_channel;
  ifar::force_sensor::ForceMonitorSettings monitor;
};

DriverSettings loadSettings(const ifar::common::ConfigNode& root)
{
  DriverSettings settings;
  settings.bus = ifar::can::loadBusSettings(root);
  ifar::can::BusChannels channels;
  ifar::can::busChannelParameters().read(root, channels);
  settings.raw_channel = channels.raw_channel;
  settings.status_channel = channels.status_channel;
  const ifar::force_sensor::ForceSensorConfig sensor = ifar::force_sensor::loadForceSensorConfig(root);
  settings.monitor = sensor.monitor;
  settings.force_channel = sensor.channel;
  // The motor driver's section of the shared file, when there is one, checked here too: one can.yaml
  // stops both or neither.
  if (root.has("motor")) {
    ifar::motor::loadMotorSection(root);
  }
  return settings;
}

/// --print-config: the whole can.yaml this driver checks, as loaded.
std::string printedConfig(const ifar::common::ConfigNode& root)
{
  const DriverSettings settings = loadSettings(root);
  ifar::common::ConfigDump dump;
  ifar::can::busParameters().dump(settings.bus, "bus", dump);
  ifar::can::BusChannels channels;
  channels.raw_channel = settings.raw_channel;
  channels.status_channel = settings.status_channel;
  ifar::can::busChannelParameters().dump(channels, "", dump);
  ifar::force_sensor::forceSensorParameters().dump(ifar::force_sensor::loadForceSensorConfig(root),
                                                   "force_sensor", dump);
  if (root.has("motor")) {
    ifar::motor::motorParameters().dump(ifar::motor::readMotorSection(root), "motor", dump);
  }
  return dump.yaml();
}

std::int8_t toLcmState(ifar::can::BusState state)
{
  switch (state) {
    case ifar::can::BusState::kActive:
      return ifar::can_bus_status_t::STATE_ACTIVE;
    case ifar::can::BusState::kWarning:
      return ifar::can_bus_status_t::STATE_WARNING;
    case ifar::can::BusState::kPassive:
      return ifar::can_bus_status_t::STATE_PASSIVE;
    case ifar::can::BusState::kBusOff:
      return ifar::can_bus_status_t::STATE_BUS_OFF;
  }
  return ifar::can_bus_status_t::STATE_ACTIVE;
}

int run(ifar::common::DaemonContext& context)
{
  const DriverSettings settings = loadSettings(context.config);
  context.config.rejectUnknownKeys();
  auto& logger = *context.logger;

  ifar::bus::RunLoop loop(context.lcm_url, context.logger);
  auto opened = ifar::can::openBus(settings.bus, loop.lcm());
  if (!opened.bus) {
    logger.error("{}", opened.error);
    return 1;
  }
  ifar::can::CanBus& bus = *opened.bus;
  // The heartbeat and the log say when the sensor's frames do not come (it sends 100 a second).
  ifar::common::InputSilence silence(ifar::common::monotonicMicroseconds(), kAwaitedFramesS);
  silence.watch(fmt::format("force frames (id 0x{:03X}) on {}", settings.monitor.frame_id, bus.name()));
  ifar::bus::publishHeartbeats(
      loop, context.logger->name(), 1.0,
      ifar::bus::loggedProblem([&silence] { return silence.problem(ifar::common::monotonicMicroseconds()); },
                               context.logger));
  logger.info("force sensor id 0x{:03X} on {} ({})", settings.monitor.frame_id, bus.name(),
              ifar::can::toString(settings.bus.kind));
  const bool republish_raw = settings.bus.kind != ifar::can::BusKind::kLcm;

  ifar::force_sensor::ForceDriverNode node(settings.monitor, context.logger);
  ifar::common::RateLimiter bus_error_log(ifar::common::kMicrosecondsPerSecond);
  ifar::can::BusState last_bus_state = bus.state();
  // A replayed log is paced as it was recorded: frame time + offset = wall time.
  std::int64_t replay_offset_us = 0;
  bool replay_started = false;
  bool replay_pending = false;
  ifar::can::Frame replay_frame;

  const auto handleFrame = [&](const ifar::can::Frame& received) {
    const std::int64_t now_us = ifar::common::nowMicroseconds();
    ifar::can::Frame frame = received;
    if (settings.bus.kind != ifar::can::BusKind::kSocketCan) {
      frame.timestamp_us = now_us;  // kernel timestamps only come from SocketCAN
    }
    if (republish_raw) {
      loop.publish(settings.raw_channel, ifar::can::toLcm(frame));
    }
    if (frame.error()) {
      if (bus.state() != last_bus_state) {
        logger.warn("{}: {} ({})", bus.name(), ifar::can::toString(bus.state()),
                    ifar::can::describeErrorFrame(frame));
        last_bus_state = bus.state();
      }
      return;
    }
    if (const auto force = node.onFrame(frame, now_us)) {
      loop.publish(settings.force_channel, *force);
      silence.arrived(0, ifar::common::monotonicMicroseconds());
    }
  };

  const auto drain = [&] {
    const std::int64_t now_us = ifar::common::nowMicroseconds();
    for (int budget = 0; budget < 1000; ++budget) {
      if (settings.bus.kind == ifar::can::BusKind::kCandump) {
        if (!replay_pending) {
          const auto result = bus.receive(std::chrono::microseconds(0));
          if (result.status != ifar::can::IoStatus::kOk) {
            if (result.status == ifar::can::IoStatus::kEndOfStream) {
              logger.info("{}: end of log", bus.name());
              loop.stop();
            }
            break;
          }
          replay_frame = result.frame;
          replay_pending = true;
          if (!replay_started) {
            replay_offset_us = now_us - replay_frame.timestamp_us;
            replay_started = true;
          }
        }
        if (replay_frame.timestamp_us + replay_offset_us > now_us) {
          break;
        }
        replay_pending = false;
        handleFrame(replay_frame);
        continue;
      }
      const auto result = bus.receive(std::chrono::microseconds(0));
      if (result.status == ifar::can::IoStatus::kError) {
        if (bus_error_log.allow(now_us)) {
          logger.error("{}", result.error);
        }
        break;
      }
      if (result.status != ifar::can::IoStatus::kOk) {
        break;
      }
      handleFrame(result.frame);
    }
    if (const auto silent = node.silenceReport(now_us)) {
      loop.publish(settings.force_channel, *silent);
    }
  };

  loop.every(0.001, drain);
  loop.every(1.0, [&] {
    const auto counters = bus.counters();
    ifar::can_bus_status_t status{};
    status.utime = ifar::common::nowMicroseconds();
    status.bus_name = bus.name();
    status.state = toLcmState(bus.state());
    status.frames_received = counters.frames_received;
    status.frames_sent = counters.frames_sent;
    status.error_frames = counters.error_frames;
    status.write_errors = counters.write_errors;
    status.bad_frames = counters.bad_frames + node.sample(status.utime).frames_bad + node.unknownFrames();
    loop.publish(settings.status_channel, status);
    const auto suppressed = node.takeSuppressedWarnings();
    if (suppressed > 0) {
      logger.warn("{} more bad-frame reports suppressed", suppressed);
    }
  });
  return loop.run();
}

}  // namespace

int main(int argc, char** argv)
{
  return ifar::common::runDaemon(
      argc, argv,
      {"force-driver", "Bumper force sensor driver: CAN frames to force_t", "can.yaml", printedConfig}, run);
}
