// ifar-velodyne-driver: VLP-16 packets from UDP (or a pcap file) onto LCM, raw, with a 1 Hz status; or,
// with --pcap FILE --points OUT, a capture's points in a CSV or PCD file (no bus).

#include <poll.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "bus/heartbeat.hpp"
#include "bus/run_loop.hpp"
#include "common/command_line.hpp"
#include "common/daemon_main.hpp"
#include "common/input_silence.hpp"
#include "common/time.hpp"
#include "drivers/velodyne/capture_points.hpp"
#include "drivers/velodyne/driver_settings.hpp"
#include "drivers/velodyne/packet_forwarder.hpp"
#include "drivers/velodyne/pcap_reader.hpp"
#include "drivers/velodyne/point_file.hpp"
#include "drivers/velodyne/udp_receiver.hpp"

namespace ifar::velodyne {
namespace {

struct ReplayOptions {
  std::string pcap_path;    // "" = live UDP
  double speed = 1.0;       // 0 = as fast as possible
  std::string points_path;  // "" = replay onto LCM; else write the pcap's points to this file instead
};

// Bounds how long the loop sleeps in poll() so timers and signals are served promptly.
constexpr int kPollTimeoutMs = 20;

class StatusClock {
 public:
  double takeInterval()
  {
    const std::int64_t now = common::monotonicMicroseconds();
    const double interval = common::microsecondsToSeconds(now - last_us_);
    last_us_ = now;
    return interval;
  }

 private:
  std::int64_t last_us_ = common::monotonicMicroseconds();
};

/// Checks one datagram and publishes it when it passes; true when it was published.
bool forwardDatagram(bus::RunLoop& loop, PacketForwarder& forwarder, std::uint16_t port,
                     common::ByteView payload, std::int64_t receive_time_us)
{
  if (const std::optional<ForwardedPacket> forwarded = forwarder.onDatagram(port, payload, receive_time_us)) {
    loop.publish(forwarded->channel, forwarded->packet);
    forwarder.notePublished(receive_time_us, common::nowMicroseconds());
    return true;
  }
  return false;
}

void publishStatus(bus::RunLoop& loop, const DriverSettings& settings, PacketForwarder& forwarder,
                   StatusClock& status_clock)
{
  loop.publish(settings.status_channel,
               forwarder.statusReport(status_clock.takeInterval(), common::nowMicroseconds()));
}

/// How long without a data packet from the sensor counts as waiting for it (a VLP-16 sends 754 a second).
constexpr double kAwaitedPacketsS = 1.0;

int runUdp(const DriverSettings& settings, bus::RunLoop& loop, PacketForwarder& forwarder,
           common::InputSilence& silence, spdlog::logger& logger)
{
  std::vector<UdpReceiver> receivers;
  receivers.emplace_back(settings.data_port, settings.bind_address,
                         static_cast<std::size_t>(settings.receive_buffer_bytes));
  if (settings.position_packets) {
    receivers.emplace_back(settings.position_port, settings.bind_address,
                           static_cast<std::size_t>(settings.receive_buffer_bytes));
  }
  for (const auto& receiver : receivers) {
    if (!receiver.isOpen()) {
      logger.error("{}", receiver.lastError());
      return 1;
    }
  }
  logger.info("receiving VLP-16 data on {}:{}{}{}", settings.bind_address, settings.data_port,
              settings.sensor_address.empty() ? std::string(" from any source")
                                              : " from the sensor at " + settings.sensor_address,
              settings.position_packets
                  ? " and position packets on port " + std::to_string(settings.position_port)
                  : std::string());
  std::vector<pollfd> descriptors;
  descriptors.reserve(receivers.size());
  for (const auto& receiver : receivers) {
    descriptors.push_back(pollfd{receiver.fd(), POLLIN, 0});
  }
  common::RateLimiter error_log_limiter(common::kMicrosecondsPerSecond);
  ReceivedDatagram datagram;
  while (!loop.stopping()) {
    for (auto& descriptor : descriptors) {
      descriptor.revents = 0;
    }
    poll(descriptors.data(), descriptors.size(), kPollTimeoutMs);
    for (auto& receiver : receivers) {
      // Drain what is pending, but hand control back to LCM and timers now and then.
      for (int count = 0; count < 64; ++count) {
        const ReceiveStatus status = receiver.receive(datagram);
        if (status == ReceiveStatus::kWouldBlock) {
          break;
        }
        if (status == ReceiveStatus::kError) {
          if (error_log_limiter.allow(common::monotonicMicroseconds())) {
            logger.warn("{}", receiver.lastError());
          }
          break;
        }
        if (datagram.wire_size > datagram.payload.size()) {
          forwarder.onOversizedDatagram(receiver.port(), datagram.wire_size, common::nowMicroseconds());
          continue;
        }
        if (forwarder.acceptsSource(datagram.source_address, common::nowMicroseconds()) &&
            forwardDatagram(loop, forwarder, receiver.port(), datagram.payload, datagram.receive_time_us) &&
            receiver.port() == settings.data_port) {
          silence.arrived(0, common::monotonicMicroseconds());
        }
      }
    }
    loop.spinOnce(0);
  }
  return 0;
}

int runPcap(const ReplayOptions& replay, const DriverSettings& settings, bus::RunLoop& loop,
            PacketForwarder& forwarder, spdlog::logger& logger)
{
  PcapReader reader = PcapReader::open(replay.pcap_path);
  if (reader.error() != PcapError::kNone) {
    logger.error("cannot replay '{}': {}", replay.pcap_path, reader.errorText());
    return common::kBadInputExitCode;
  }
  logger.info("replaying '{}' at {}", replay.pcap_path,
              replay.speed > 0.0 ? std::to_string(replay.speed) + "x real time" : std::string("full speed"));
  UdpDatagram datagram;
  bool have_first = false;
  std::int64_t first_capture_us = 0;
  std::int64_t start_monotonic_us = 0;
  CaptureCounts counts;
  bool file_ended = false;  // not stopped by a signal: the whole file was offered
  while (!loop.stopping()) {
    const PcapRecord record = reader.next(datagram);
    if (record == PcapRecord::kEndOfFile) {
      file_ended = true;
      break;
    }
    if (record == PcapRecord::kTruncatedFile) {
      logger.warn("'{}' ends inside a record: stopping the replay there", replay.pcap_path);
      file_ended = true;
      break;
    }
    ++counts.records;
    if (record != PcapRecord::kUdpDatagram) {
      ++counts.skipped;
      continue;
    }
    if (datagram.destination_port != settings.data_port &&
        !(settings.position_packets && datagram.destination_port == settings.position_port)) {
      ++counts.skipped;
      continue;
    }
    if (!have_first) {
      have_first = true;
      first_capture_us = datagram.capture_time_us;
      start_monotonic_us = common::monotonicMicroseconds();
    }
    if (replay.speed > 0.0) {
      // Pace by the capture timestamps, scaled; keep serving LCM and timers while waiting.
      const auto due_us =
          start_monotonic_us +
          static_cast<std::int64_t>(static_cast<double>(datagram.capture_time_us - first_capture_us) /
                                    replay.speed);
      for (std::int64_t now = common::monotonicMicroseconds(); now < due_us && !loop.stopping();
           now = common::monotonicMicroseconds()) {
        loop.spinOnce(static_cast<int>(std::min<std::int64_t>((due_us - now) / 1000, kPollTimeoutMs)));
      }
    }
    // Host receive time of a replayed packet is the time it is sent on, as for a live sensor.
    if (forwardDatagram(loop, forwarder, datagram.destination_port, datagram.payload,
                        common::nowMicroseconds())) {
      ++counts.published;
    }
    loop.spinOnce(0);
  }
  logger.info("replay finished: {} packets published, {} bad, {} records skipped", counts.published,
              forwarder.monitor().counts().bad_packets, counts.skipped);
  // A capture that gives nothing is an input to fix, not a replay that worked: scripts must see it fail.
  if (file_ended && counts.published == 0) {
    logger.error("{}", nothingToPublishMessage(replay.pcap_path, counts, forwarder, settings.data_port));
    return 1;
  }
  return 0;
}

}  // namespace
}  // namespace ifar::velodyne

int main(int argc, char** argv)
{
  namespace common = ifar::common;
  namespace bus = ifar::bus;
  namespace velodyne = ifar::velodyne;
  velodyne::ReplayOptions replay;
  return common::runDaemon(
      argc, argv,
      {"velodyne-driver", "VLP-16 driver: data packets from UDP or a pcap file onto LCM (VELODYNE_PACKET)",
       "velodyne.yaml",
       [](const common::ConfigNode& config) {
         return velodyne::driverParameters().yaml(velodyne::loadDriverSettings(config));
       }},
      [&replay](common::DaemonContext& context) {
        const velodyne::DriverSettings settings = velodyne::loadDriverSettings(context.config);
        context.config.rejectUnknownKeys();
        if (!replay.points_path.empty()) {
          return velodyne::writeCapturePoints(replay.pcap_path, replay.points_path, settings, context.logger);
        }
        bus::RunLoop loop(context.lcm_url, context.logger);
        // Live, the heartbeat and the log say when the sensor's packets do not come.
        common::InputSilence silence(common::monotonicMicroseconds(), velodyne::kAwaitedPacketsS);
        silence.watch(velodyne::awaitedPackets(settings));
        const bool live = replay.pcap_path.empty();
        bus::publishHeartbeats(loop, context.logger->name(), 1.0,
                               bus::loggedProblem(
                                   [&silence, live] {
                                     return live ? silence.problem(common::monotonicMicroseconds())
                                                 : std::string();
                                   },
                                   context.logger));
        velodyne::PacketForwarder forwarder(settings, context.logger);
        velodyne::StatusClock status_clock;
        loop.every(settings.status_period_s,
                   [&] { velodyne::publishStatus(loop, settings, forwarder, status_clock); });
        const int result = live ? velodyne::runUdp(settings, loop, forwarder, silence, *context.logger)
                                : velodyne::runPcap(replay, settings, loop, forwarder, *context.logger);
        velodyne::publishStatus(loop, settings, forwarder, status_clock);
        return result;
      },
      [&replay](CLI::App& app) {
        CLI::Option* pcap =
            app.add_option("--pcap", replay.pcap_path,
                           "replay this capture (pcap or pcapng; Ethernet, Linux cooked, raw IP "
                           "or loopback frames) instead of listening on UDP")
                ->check(CLI::ExistingFile);
        app.add_option(
               "--points", replay.points_path,
               "with --pcap: write the points the driver would publish (its checks and sensor_model) to "
               "this file instead of replaying, then exit (no LCM); .csv: a header row, then "
               "x,y,z,intensity,ring,azimuth,distance,return_index,time_us per point; .pcd: ASCII PCD "
               "with the same fields. x forward, y left, z up in metres, azimuth in degrees, time_us "
               "in device microseconds past the hour")
            ->type_name("FILE.csv|FILE.pcd")
            ->needs(pcap)
            ->check(CLI::Validator(
                [](const std::string& path) {
                  return velodyne::pointFileFormat(path) ? std::string()
                                                         : "'" + path + "' must end in .csv or .pcd";
                },
                "", ""));
        app.add_option("--speed", replay.speed, "replay speed factor for --pcap (0 = as fast as possible)")
            ->check(CLI::NonNegativeNumber)
            ->capture_default_str();
      });
}
