#pragma once
// A pcap capture through the driver's own checks without a bus: the counts a replay reports when the file
// gives nothing to publish, and --points (what the driver would publish, decoded into a CSV or PCD file).

#include <cstdint>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>

#include "drivers/velodyne/driver_settings.hpp"
#include "drivers/velodyne/packet_forwarder.hpp"

namespace ifar::velodyne {

/// One pass over a capture's records.
struct CaptureCounts {
  std::int64_t records = 0;    // pcap records read
  std::int64_t skipped = 0;    // records that are not a UDP datagram to a port the driver reads
  std::int64_t published = 0;  // datagrams the forwarder accepted
};

/// The error for a capture that gave nothing to publish: records read, skipped, refused and why, e.g.
/// "'a.pcap' gave no packet to publish: 84 records read, 0 of them not UDP to port 2368, 84 refused
/// (84 x data packet (1206 bytes): product byte 0x21 (expected 0x22, VLP-16); set ...)".
std::string nothingToPublishMessage(const std::string& pcap_path, const CaptureCounts& counts,
                                    const PacketForwarder& forwarder, std::uint16_t data_port);

/// Decodes every data packet of `pcap_path` that the driver would publish under `settings` (the same
/// checks, sensor_model included) and writes the points to `out_path` (.csv or .pcd, see point_file.hpp).
/// Refused packets are counted and logged as in the driver. Returns the exit code: 0 when points were
/// written, 1 when the capture gives no packet to publish, 2 when it cannot be read, 3 when the points
/// cannot be written (each logged).
/// `logger` must not be null.
int writeCapturePoints(const std::string& pcap_path, const std::string& out_path,
                       const DriverSettings& settings, const std::shared_ptr<spdlog::logger>& logger);

}  // namespace ifar::velodyne
